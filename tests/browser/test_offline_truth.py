"""Offline is said only when it is true, and only the built bytes are ever served.

* A learner who moves on (ready + 0.5 s) and reloads (ready + 1.5 s) while the
  copy has not even started: ``data-workbook-offline`` says ``ready`` only once
  Cache Storage holds every manifest entry, each with the manifest's sha256.
  Then, with the server stopped, the HTTP cache bypassed and the network off,
  every chapter (the first loaded, the rest by instant navigation), the Practise
  page and the home page (loaded) open and grade.
* A page or a script planted into Cache Storage by page script (anything on the
  origin can write it) is never served: online it is fetched again, offline it
  is refused.
"""

from __future__ import annotations

import json
import re
import time

import pytest
from playwright.sync_api import expect

from conftest import SITE
from helpers import CHAPTERS, go_instantly, network_is_off, solve, wait_runtime
from site_server import SiteServer
from workbook import bank
from workbook.contract import ATTR

pytestmark = pytest.mark.uncached  # the offline copy must not lean on the HTTP cache

LONG = 120_000
MANIFEST = json.loads(re.search(r"const FILES = (\[.*?\n\]);", (SITE / "sw.js").read_text(), re.S).group(1))

# Records, in the page, when the runtime and the offline copy became ready, and what
# Cache Storage held at the moment the page was told "ready" (every entry's sha256).
WATCH = """
(() => {
  const seen = (window.__wbSeen = { runtimeReady: null, offlineReady: null, atReady: null });
  new MutationObserver(async () => {
    const root = document.documentElement;
    if (seen.runtimeReady === null && root.getAttribute("%(runtime)s") === "ready") seen.runtimeReady = performance.now();
    if (seen.offlineReady !== null || root.getAttribute("%(offline)s") !== "ready") return;
    seen.offlineReady = performance.now();
    const held = {};
    for (const name of await caches.keys()) {
      if (name.endsWith(":state")) continue;
      const cache = await caches.open(name);
      for (const request of await cache.keys()) {
        const body = await (await cache.match(request)).arrayBuffer();
        const digest = new Uint8Array(await crypto.subtle.digest("SHA-256", body));
        held[request.url] = "sha256-" + btoa(String.fromCharCode(...digest));
      }
    }
    seen.atReady = held;
  }).observe(document, { attributes: true, subtree: true, attributeFilter: ["%(runtime)s", "%(offline)s"] });
})();
""" % {"runtime": ATTR.runtime, "offline": ATTR.offline}


def first_exercise(chapter: int):
    """The first exercise of a chapter that is graded by a Check (not a Build run)."""
    return next(ex for ex in bank.all_exercises() if ex.id.startswith(f"{chapter}.") and ex.kind != "build")


def grades_through_the_runtime(page) -> bool:
    reply = page.evaluate("workbook.runtime.request({op: 'grade', exercise: '0.1', answer: '3'})")
    return reply["ok"] and reply["value"]["status"] == "correct"


@pytest.fixture
def own_server():
    """The site on a server of its own, which the test stops."""
    server = SiteServer(SITE)
    yield server
    server.close()


def test_ready_only_when_every_file_is_stored_then_every_page_works_offline(browser, own_server):
    url = own_server.url
    context = browser.new_context()
    elsewhere: list[str] = []
    context.on("request", lambda r: elsewhere.append(r.url) if not r.url.startswith((own_server.origin, "data:", "blob:")) else None)
    context.add_init_script(WATCH)
    page = context.new_page()
    errors: list[str] = []
    page.on("pageerror", lambda err: errors.append(str(err)))
    try:
        page.goto(url + CHAPTERS[0])
        wait_runtime(page, timeout=LONG)
        page.wait_for_timeout(500)  # the learner moves on half a second after ready
        page.goto(url + CHAPTERS[1])
        wait_runtime(page, timeout=LONG)
        page.wait_for_timeout(1500)  # and reloads a second and a half after ready
        page.reload()
        started = time.perf_counter()
        page.wait_for_function(f"() => document.documentElement.getAttribute('{ATTR.offline}') === 'ready'", timeout=LONG)
        seen = page.evaluate("window.__wbSeen")
        page.wait_for_function("() => window.__wbSeen.atReady !== null", timeout=LONG)
        held = page.evaluate("window.__wbSeen.atReady")
        print(f"\noffline copy: 'ready' {(seen['offlineReady'] - seen['runtimeReady']) / 1000:.1f} s after the runtime's "
              f"ready on the last page ({time.perf_counter() - started:.1f} s after its load)")

        # At that moment Cache Storage held every manifest entry, each with the manifest's bytes.
        expected = {url + ("" if path == "./" else path): hashes for path, *hashes in MANIFEST}
        assert set(expected) <= set(held), sorted(set(expected) - set(held))[:5]
        wrong = [u for u, hashes in expected.items() if held[u] not in [h for h in hashes if isinstance(h, str)]]
        assert wrong == []

        # Offline for real: no server, no HTTP cache, no network.
        own_server.close()
        cdp = context.new_cdp_session(page)
        cdp.send("Network.clearBrowserCache")
        cdp.send("Network.setCacheDisabled", {"cacheDisabled": True})
        context.set_offline(True)
        for n, path in CHAPTERS.items():
            if n == 0:  # loaded: the service worker serves the navigation, and Python starts offline
                page.goto(url + path)
                wait_runtime(page, timeout=LONG)
            else:  # the next chapters as a learner's link takes them: the stored page, the same grader
                go_instantly(page, url, n)
            assert network_is_off(page)
            ex = first_exercise(n)
            assert solve(page, ex) == "correct", f"{ex.id} offline"
        for path in ("practise/", ""):
            page.goto(url + path)
            wait_runtime(page, timeout=LONG)
            expect(page.locator("h1").first).to_be_visible()
            assert grades_through_the_runtime(page), path or "home"
        assert errors == [] and elsewhere == []
    finally:
        context.close()


PLANTED_PAGE = "<!doctype html><title>planted</title><h1 data-planted>Planted</h1>"
PLANTED_WORKER = "self.postMessage({type: 'ready', from: 'planted', stages: {}}); self.onmessage = () => {};"
PLANT = """async ([url, body, type]) => {
  for (const name of await caches.keys()) {
    if (name.endsWith(':state')) continue;
    await (await caches.open(name)).put(url, new Response(body, { headers: { 'Content-Type': type } }));
  }
}"""


def test_a_file_planted_into_cache_storage_is_never_served(browser, site_url):
    context = browser.new_context()
    page = context.new_page()
    try:
        page.goto(site_url + "related/")
        page.wait_for_function(f"() => document.documentElement.getAttribute('{ATTR.offline}') === 'ready'", timeout=LONG)
        page.evaluate(PLANT, [site_url + "related/", PLANTED_PAGE, "text/html"])
        page.evaluate(PLANT, [site_url + "assets/dist/worker.js", PLANTED_WORKER, "text/javascript"])

        # Online: the real page and the real worker, fetched again.
        page.goto(site_url + "related/")
        expect(page.locator("[data-planted]")).to_have_count(0)
        expect(page.locator("h1").first).not_to_have_text("Planted")
        wait_runtime(page, timeout=LONG)
        assert page.evaluate("workbook.runtime.startedFrom") != "planted"
        assert grades_through_the_runtime(page)
        # The copy is repaired: ready again, with the real bytes stored.
        page.wait_for_function(f"() => document.documentElement.getAttribute('{ATTR.offline}') === 'ready'", timeout=LONG)
        stored = page.evaluate("async (u) => (await (await caches.match(u)).text())", site_url + "related/")
        assert "data-planted" not in stored and "<h1" in stored

        # Offline, without the HTTP cache: refused, never served.
        page.evaluate(PLANT, [site_url + "related/", PLANTED_PAGE, "text/html"])
        cdp = context.new_cdp_session(page)
        cdp.send("Network.clearBrowserCache")
        cdp.send("Network.setCacheDisabled", {"cacheDisabled": True})
        context.set_offline(True)
        page.goto(site_url + "related/")
        expect(page.locator("[data-planted]")).to_have_count(0)
        expect(page.locator("body")).to_contain_text("not stored in this browser, or its stored copy was damaged")
    finally:
        context.close()


PLANT_SNAPSHOT = """async ([url, other]) => {
  // A real snapshot, of another interpreter (the sandbox's: no grading package), stored as the
  // grader's would be (inflated), in every cache that holds the grader's.
  const inflated = (await fetch(other, { cache: 'no-store' })).body.pipeThrough(new DecompressionStream('gzip'));
  const bytes = await new Response(inflated).arrayBuffer();
  for (const name of await caches.keys()) {
    if (name.endsWith(':state')) continue;
    const cache = await caches.open(name);
    if (await cache.match(url)) await cache.put(url, new Response(bytes));
  }
}"""


def test_the_grader_reads_its_largest_files_from_the_copy_and_never_a_planted_one(browser, site_url):
    """On a revisit the grader's worker reads the WebAssembly and the memory snapshot from the stored
    copy itself (stored-copy.js), checked against the build's sha256: it asks neither the service worker
    nor the network for them. A snapshot planted in their place (a real one, of the sandbox's Python) is
    not used: the worker asks the service worker instead, which fetches the real one and stores it again."""
    vendor = site_url + "assets/vendor/pyodide/"
    context = browser.new_context()
    page = context.new_page()
    asked: list[str] = []
    context.on("request", lambda r: asked.append(r.url) if r.url.startswith(vendor) else None)
    try:
        page.goto(site_url + CHAPTERS[0])
        page.wait_for_function(f"() => document.documentElement.getAttribute('{ATTR.offline}') === 'ready'",
                               timeout=LONG)
        asked.clear()
        page.goto(site_url + CHAPTERS[0])
        wait_runtime(page, timeout=LONG)
        assert page.evaluate("workbook.runtime.startedFrom") == "snapshot"
        assert grades_through_the_runtime(page)
        big = [u for u in asked if u.endswith(("pyodide.asm.wasm", "workbook.snapshot.gz"))]
        assert big == [], big

        page.evaluate(PLANT_SNAPSHOT, [vendor + "workbook.snapshot.gz", vendor + "sandbox.snapshot.gz"])
        asked.clear()
        page.goto(site_url + CHAPTERS[0])
        wait_runtime(page, timeout=LONG)
        assert grades_through_the_runtime(page)  # the sandbox's Python holds no grader: not the planted one
        assert vendor + "workbook.snapshot.gz" in asked
        # The service worker deleted the planted file when it did not match, and stores the real one again
        # after it has answered (sw.js: resume(), in the background): wait until it is there.
        held = page.wait_for_function(
            "async (u) => { const r = await caches.match(u); return r ? (await r.arrayBuffer()).byteLength : 0; }",
            arg=vendor + "workbook.snapshot.gz", timeout=LONG, polling=200).json_value()
        entry = next(e for e in MANIFEST if e[0] == "assets/vendor/pyodide/workbook.snapshot.gz")
        assert held == entry[4]  # the real inflated snapshot, stored again
    finally:
        context.close()
