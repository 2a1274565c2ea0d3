"""The standard library beyond the core is fetched on first use, not before ready.

The grader starts with the core (scripts/split_stdlib.py) and mounts the rest
the first time an import asks for it (workbook/lazy_stdlib.py); grading never
does. Build code runs in the sandbox, whose Python is the whole standard library
(python_stdlib.sandbox.zip, scripts/sandbox_files.py): an import of the rest
works there, seen by the page or not (``__import__``), and the grader still
fetches nothing.
"""

from __future__ import annotations

from helpers import exercise, open_chapter, run_build, set_editor

REST = "python_stdlib.rest.zip"
SANDBOX = "python_stdlib.sandbox.zip"
CODE = (
    "import math\n{imp}\n\n\n"
    "def rotate_2d(x, y, theta):\n"
    "    c, s = math.cos(theta), math.sin(theta)\n"
    "    return (statistics.fmean([c * x - s * y]), s * x + c * y)\n"
)


def requests_for(page, name: str, service_worker: bool = True) -> list[str]:
    """The requests for ``name``; with ``service_worker=False`` not those of the offline copy."""
    seen: list[str] = []

    def note(r):
        if r.url.endswith(name) and (service_worker or r.service_worker is None):
            seen.append(r.url)
    page.on("request", note)
    page.context.on("request", note)
    return seen


def test_an_import_of_the_rest_runs_in_the_sandbox_and_the_grader_fetches_nothing(page, site_url):
    seen = requests_for(page, REST, service_worker=False)
    sandbox = requests_for(page, SANDBOX, service_worker=False)
    open_chapter(page, site_url, 0)
    assert seen == [], "the rest of the standard library was fetched before it was needed"
    ex = exercise(page, "0.5")
    set_editor(page, ex, CODE.format(imp="import statistics"))
    assert run_build(ex) == "correct"
    set_editor(page, ex, CODE.format(imp="import statistics, fractions"))
    assert run_build(ex) == "correct"
    assert page.evaluate("workbook.runtime.request({op: 'grade', exercise: '0.1', answer: '3'})")["ok"]
    assert seen == [] and len(set(sandbox)) == 1


def test_an_import_the_page_cannot_see_still_works(page, site_url):
    open_chapter(page, site_url, 0)
    ex = exercise(page, "0.5")
    set_editor(page, ex, CODE.format(imp="statistics = __import__('statistics')"))
    assert run_build(ex) == "correct"
    assert page.js_errors == []
