"""The site's search builds its index when it is wanted, not while the grader starts
(docs/assets/js/search-start.js, search-worker.js, docs/hooks/search_worker.py): at once when
the learner opens the search, even before the grader is ready; otherwise once the page has been
idle a while after ready, without the learner doing anything.

The page's messages to the search worker are read on the same BroadcastChannel, with the moment
the grader became ready, by a script the test adds to the page."""

from __future__ import annotations

import re

from playwright.sync_api import expect

from conftest import ROOT
from helpers import CHAPTERS, wait_runtime

CHANNEL = re.search(r'SEARCH_CHANNEL = "([^"]+)"', (ROOT / "docs/assets/js/search-channel.js").read_text()).group(1)
AFTER_READY_MS = int(re.search(r"AFTER_READY_MS = ([\d_]+)", (ROOT / "docs/assets/js/search-start.js").read_text())
                     .group(1).replace("_", ""))
RECORD = """
(() => {
  const seen = (window.__searchSaid = []);
  new BroadcastChannel(%r).onmessage = (event) => seen.push({ said: event.data, at: performance.now() });
  new MutationObserver(() => {
    const state = document.documentElement.getAttribute("data-workbook-runtime");
    if (state === "ready" && window.__readyAt === undefined) window.__readyAt = performance.now();
  }).observe(document, { attributes: true, subtree: true, attributeFilter: ["data-workbook-runtime"] });
})();
""" % CHANNEL
META = ".md-search-result__meta"  # the theme's line above the results: "Initializing search" until its worker is ready


def test_the_index_is_built_a_while_after_ready_without_the_learner_asking(page, site_url):
    page.add_init_script(RECORD)
    page.goto(site_url + CHAPTERS[0])
    wait_runtime(page)
    page.wait_for_function("() => window.__searchSaid.some((m) => m.said === 'wanted')", timeout=60_000)
    said, ready_at = page.evaluate("() => [window.__searchSaid, window.__readyAt]")
    wanted = [m["at"] for m in said if m["said"] == "wanted"]
    assert wanted[0] - ready_at >= AFTER_READY_MS, (said, ready_at)  # never while the grader starts
    assert [m["said"] for m in said if m["at"] < wanted[0]] == ["asks"]  # the worker was there, waiting
    # The theme's own worker is then ready: its line above the results changes from "Initializing search".
    expect(page.locator(META)).not_to_have_text(re.compile("Initializing"), timeout=30_000)
    page.locator(".md-search__input").click()
    page.keyboard.type("quaternion")
    expect(page.locator(".md-search-result__item").first).to_be_visible()


def test_opening_the_search_builds_it_at_once_even_before_the_grader_is_ready(page, site_url):
    """The page fetches an index without its documents (a few hundred bytes, not 97 kB gzipped); the
    documents come when the search is opened, once, and a query typed while they come is answered."""
    page.add_init_script(RECORD)
    page.route("**/vendor/pyodide/**", lambda route: None)  # the grader's files never come: it never gets ready
    fetched: dict[str, list[int]] = {"search_index.json": [], "search_index.docs.json": []}

    def note(response):
        name = response.url.rsplit("/", 1)[-1]
        if name in fetched:
            fetched[name].append(len(response.body()))
    page.context.on("response", note)
    page.goto(site_url + CHAPTERS[0])
    expect(page.locator(META)).to_have_text(re.compile("Initializing search"))
    page.wait_for_timeout(500)
    assert len(fetched["search_index.json"]) == 1 and fetched["search_index.json"][0] < 1_000, fetched
    assert fetched["search_index.docs.json"] == [], fetched
    page.locator(".md-search__input").click()
    page.keyboard.type("quaternion")
    expect(page.locator(".md-search-result__item").first).to_be_visible(timeout=30_000)
    assert len(fetched["search_index.docs.json"]) == 1 and fetched["search_index.docs.json"][0] > 100_000, fetched
    assert page.evaluate("() => document.documentElement.getAttribute('data-workbook-runtime')") == "loading"
    assert "wanted" in [m["said"] for m in page.evaluate("() => window.__searchSaid")]
