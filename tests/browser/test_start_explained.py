"""A start that explains itself (issue 19, item 1).

* A Check pressed on a throttled first visit (the bench's emulated link, in
  scripts/site_server.py) before the grader is ready: the exercise's feedback
  says the grader is loading, with a progress bar fed by the worker's real byte
  counts through its steps (download, start, ready), and the answer is checked
  the moment the grader can.
* The offline copy is announced with its size before it starts, and can be
  declined; on a metered connection (Save-Data) it waits for consent.
"""

from __future__ import annotations

import json
import re

from playwright.sync_api import expect

from conftest import SITE
from helpers import check_while_loading, role, wait_runtime
from workbook.contract import ATTR, DATA

LONG = 180_000
PHASES = DATA["bootPhases"]
MANIFEST = json.loads(re.search(r"const FILES = (\[.*?\n\]);", (SITE / "sw.js").read_text(), re.S).group(1))
STORED_MB = sum(entry[-1] for entry in MANIFEST) / 1e6

# Every time the worker reports its start, what the exercise 0.1's loading message shows. This
# listener runs before the page's own (it is added first); a microtask reads the message once all
# of them have run. (A frame callback missed short steps when the machine was busy: frames are skipped.)
RECORD = """
window.__wbBoot = [];
document.addEventListener("workbook:boot", (event) => {
  queueMicrotask(() => {
    const box = document.querySelector('[%(ex)s="0.1"] [%(role)s="runtime-status"]');
    const bar = box && box.querySelector('[%(role)s="runtime-progress"]');
    window.__wbBoot.push({ detail: event.detail, shown: box ? { phase: box.getAttribute("%(phase)s"), value: bar.value,
      max: bar.max, text: box.textContent } : null });
  });
});
""" % {"ex": ATTR.exercise, "role": ATTR.role, "phase": ATTR.phase}
SAVE_DATA = """
Object.defineProperty(Navigator.prototype, "connection", {
  configurable: true, get: () => ({ saveData: true, effectiveType: "4g", addEventListener() {} }) });
"""


def offline_state(page) -> str | None:
    return page.evaluate("a => document.documentElement.getAttribute(a)", ATTR.offline)


def version_cache_entries(page) -> int:
    return page.evaluate("""async () => { let n = 0;
      for (const name of await caches.keys()) if (!name.endsWith(':state')) n += (await (await caches.open(name)).keys()).length;
      return n; }""")


def test_a_check_before_the_grader_is_ready_shows_the_loading_progress(browser, slow_site):
    context = browser.new_context()
    context.add_init_script(RECORD)
    page = context.new_page()
    try:
        ex = check_while_loading(page, slow_site.url)
        status = ex.locator(role("runtime-status"))
        # Shown once the page's script has taken the held Check (on a busy machine and a slow link
        # the script itself can arrive and start later than expect's default 5 s).
        expect(status).to_be_visible(timeout=LONG)
        expect(status).to_contain_text("Loading the grader")
        expect(status).to_contain_text("first visit only")
        bar = status.locator(role("runtime-progress"))
        expect(bar).to_be_visible()

        # Answered the moment the grader can: the message gives way to the verdict.
        page.wait_for_function("el => el.dataset.state === 'correct'", arg=ex.element_handle(), timeout=LONG)
        expect(ex.locator(role("runtime-status"))).to_have_count(0)
        wait_runtime(page, timeout=LONG)

        shown = [r for r in page.evaluate("window.__wbBoot") if r["shown"]]
        details = [r["detail"] for r in page.evaluate("window.__wbBoot")]
        # Real bytes: the files' sizes as built, counted up as they arrived, in the order of the steps.
        total = max(d["total"] for d in details)
        assert total > 5e6
        downloading = [d["loaded"] for d in details if d["phase"] == "download"]
        assert len(set(downloading)) >= 3 and downloading == sorted(downloading)
        order = [PHASES.index(d["phase"]) for d in details]
        assert order == sorted(order) and order[-1] == PHASES.index("ready")
        assert "start" in [d["phase"] for d in details]
        # And the page showed them: the bar moved, the message named the step.
        values = [r["shown"]["value"] for r in shown if r["shown"]["phase"] == "download"]
        assert len(set(values)) >= 3 and values == sorted(values)
        assert any(re.search(r"Downloading the Python runtime · [\d.]+ MB of [\d.]+ MB", r["shown"]["text"]) for r in shown)
        assert {r["shown"]["phase"] for r in shown} >= {"download", "start"}
        # A plain start on this link: the snapshot skipped, the standard library's core taken compiled, with
        # chapter 0's part of the grading package (it graded the Check above), and counted in the bar
        # instead of the sources.
        started = page.evaluate("[workbook.runtime.startedFrom, workbook.runtime.startStages]")
        assert started[0] == "boot" and started[1]["snapshot"] == "skipped: a slow link", started
        assert started[1]["stdlib"] == "compiled", started
        compiled = sum((SITE / "assets/vendor/pyodide" / name).stat().st_size
                       for name in ("python_stdlib.core.compiled.zip", "workbook.compiled.ch0.zip"))
        sources = (SITE / "assets/vendor/pyodide/python_stdlib.core.zip").stat().st_size
        totals = [d["total"] for d in details]
        assert compiled - sources in {b - a for a, b in zip(totals, totals[1:])}, sorted(set(totals))
    finally:
        context.close()


def test_the_offline_copy_is_announced_with_its_size_and_can_be_declined(browser, site_url):
    context = browser.new_context()
    page = context.new_page()
    try:
        page.goto(site_url + "related/")
        notice = page.locator(role("offline-notice"))
        expect(notice).to_be_visible(timeout=LONG)
        expect(notice).to_contain_text(f"{round(STORED_MB)} MB")
        assert offline_state(page) == "caching"
        notice.locator(role("offline-decline")).click()
        expect(page.locator("html")).to_have_attribute(ATTR.offline, "declined")
        page.wait_for_timeout(3000)  # longer than the copy waits after ready: nothing is stored
        assert version_cache_entries(page) == 0
        footer = page.locator(f".md-footer {role('offline-status')}")
        expect(footer).to_contain_text("Not stored for offline use")

        page.reload()  # the answer is kept
        wait_runtime(page, timeout=LONG)
        expect(page.locator("html")).to_have_attribute(ATTR.offline, "declined")
        expect(page.locator(role("offline-notice"))).to_have_count(0)
        # and can be changed from the footer
        page.locator(f".md-footer {role('offline-status')} {role('offline-store')}").click()
        expect(page.locator("html")).to_have_attribute(ATTR.offline, "ready", timeout=LONG)
        expect(page.locator(f".md-footer {role('offline-status')}")).to_contain_text("Stored for offline use")
    finally:
        context.close()


def test_on_a_metered_connection_the_copy_waits_for_consent(browser, site_url):
    context = browser.new_context()
    context.add_init_script(SAVE_DATA)
    page = context.new_page()
    try:
        page.goto(site_url + "related/")
        wait_runtime(page, timeout=LONG)
        expect(page.locator("html")).to_have_attribute(ATTR.offline, "asking")
        notice = page.locator(role("offline-notice"))
        expect(notice).to_be_visible()
        expect(notice).to_contain_text(f"{round(STORED_MB)} MB")
        expect(notice).to_contain_text("metered")
        page.wait_for_timeout(3000)  # longer than the copy waits after ready: it waits for the learner
        assert offline_state(page) == "asking"
        assert version_cache_entries(page) == 0
        notice.locator(role("offline-store")).click()
        expect(page.locator("html")).to_have_attribute(ATTR.offline, "caching")
        # A reload during the copy carries it on: no second question, and it completes.
        page.reload()
        page.wait_for_function("a => document.documentElement.getAttribute(a) !== null", arg=ATTR.offline)
        assert offline_state(page) in ("caching", "ready")
        expect(page.locator("html")).to_have_attribute(ATTR.offline, "ready", timeout=LONG)
        assert version_cache_entries(page) > len(MANIFEST)  # every file, and the seal
        expect(page.locator(role("offline-notice"))).to_have_count(0)
    finally:
        context.close()
