"""On a first visit the grader's Python starts once the page has started (issue 48).

The page and the grader's worker start together. On two cores, Python's start (compiling
pyodide.asm.js and the WebAssembly, unpacking the snapshot) made the page's own start-up tasks
long, so on a first visit it waits until the page says it has started: after DOMContentLoaded, at
the browser's first idle moment (main.js, worker.js). On a revisit under the service worker it does
not wait: the worker's start is short there, and ready is what counts."""

from __future__ import annotations

import pytest

from helpers import open_chapter, wait_runtime

pytestmark = [pytest.mark.uncached, pytest.mark.browser_context_args(service_workers="allow")]

DCL = "performance.timeOrigin + performance.getEntriesByType('navigation')[0].domContentLoadedEventEnd"


def test_python_starts_after_the_page_on_a_first_visit_and_at_once_under_the_service_worker(page, site_url):
    open_chapter(page, site_url, 0)
    stages = page.evaluate("workbook.runtime.startStages")
    assert "held" in stages, stages
    assert stages["timeOrigin"] + stages["held"] >= page.evaluate(DCL) - 1  # clocks in whole ms
    assert page.evaluate("navigator.serviceWorker.controller") is None  # it was a first visit
    page.evaluate("() => navigator.serviceWorker.ready.then(() => true)")
    page.reload()
    wait_runtime(page)
    assert page.evaluate("Boolean(navigator.serviceWorker.controller)")
    assert "held" not in page.evaluate("workbook.runtime.startStages")
