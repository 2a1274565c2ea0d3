"""Issue 28, "nothing a learner does is undone": a clock that ran ahead cannot outrank later work
and cannot survive an erase; the run after a stopped one works (one replacement per time-out);
plain code cannot change NumPy for later runs."""

from __future__ import annotations

import json
import time

from playwright.sync_api import Page

from helpers import exercise, open_chapter, run_build, set_editor, wait_runtime
from workbook import bank

LONG = 120_000
EX = bank.get("0.5")
GOOD = EX.solution
WRONG = "def rotate_2d(x, y, theta):\n    return (x, y)\n"
SLEEPS = "import time\n\ndef rotate_2d(x, y, theta):\n    time.sleep(100)\n    return (x, y)\n"
NUMPY_GOOD = ("import numpy as np\n\ndef rotate_2d(x, y, theta):\n"
              "    r = np.array([[np.cos(theta), -np.sin(theta)], [np.sin(theta), np.cos(theta)]], dtype='float64')\n"
              "    v = r @ np.array([x, y], dtype='float64')\n    return (float(v[0]), float(v[1]))\n")
TAMPER = "import numpy\nnumpy.sctypeDict['float64'] = numpy.float16\n" + WRONG
AHEAD_MS = 3 * 3600 * 1000
# A page whose clock runs ahead: every Date.now() (what progress stamps records with) is late.
CLOCK_AHEAD = f"(() => {{ const real = Date.now; Date.now = () => real() + {AHEAD_MS}; }})();"
COUNT_SANDBOXES = """(() => {
  const Real = window.Worker;
  window.sandboxesStarted = 0;
  window.Worker = function (url, options) {
    if (options && options.name === "sandbox") window.sandboxesStarted++;
    return new Real(url, options);
  };
  window.Worker.prototype = Real.prototype;
})();"""


def records(page: Page) -> dict:
    return page.evaluate("() => workbook.progress.all()")


def wait_progress(page: Page) -> None:
    page.wait_for_function("() => window.workbook && window.workbook.progress", timeout=LONG)


def test_a_clock_that_ran_ahead_neither_outranks_later_work_nor_survives_an_erase(browser, site_url):
    context = browser.new_context()
    ahead, right = context.new_page(), context.new_page()
    ahead.add_init_script(CLOCK_AHEAD)
    for page in (ahead, right):
        open_chapter(page, site_url, 0, wait_ready=False)
        wait_progress(page)
    ahead.evaluate("() => workbook.progress.update('0.1', {last: '7', code: 'old = 1\\n'})")
    right.wait_for_function("() => (workbook.progress.get('0.1').last) === '7'", timeout=LONG)  # the storage event
    right.evaluate("() => workbook.progress.update('0.1', {last: '3', code: 'new = 2\\n'})")
    for page in (right, ahead):
        page.reload()
        wait_progress(page)
        record = records(page)["0.1"]
        assert (record["last"], record["code"]) == ("3", "new = 2\n"), record
    # The next write in the tab that ran ahead is later still, and wins too.
    ahead.evaluate("() => workbook.progress.update('0.1', {last: '4'})")
    right.reload()
    wait_progress(right)
    assert records(right)["0.1"]["last"] == "4"
    # Erase everything (in the tab with the right clock) erases the record stamped in the future.
    right.evaluate("() => workbook.progress.reset()")
    for page in (right, ahead):
        page.reload()
        wait_progress(page)
        assert records(page) == {}, records(page)
        assert json.loads(page.evaluate("() => localStorage.getItem(workbook.progress.key)"))["exercises"] == {}
    context.close()


def test_an_imported_record_up_to_a_day_ahead_neither_outranks_later_work_nor_survives_an_erase(page, site_url):
    open_chapter(page, site_url, 0, wait_ready=False)
    wait_progress(page)
    future = int(time.time() * 1000) + 20 * 3600 * 1000
    page.evaluate("r => workbook.progress.merge(r)",
                  {"0.1": {"last": "7", "code": "old = 1\n", "attempts": 1, "updated": future}})
    page.evaluate("() => workbook.progress.update('0.1', {last: '3', code: 'new = 2\\n'})")
    page.reload()
    wait_progress(page)
    record = records(page)["0.1"]
    assert (record["last"], record["code"]) == ("3", "new = 2\n"), record
    page.evaluate("() => workbook.progress.reset()")
    page.reload()
    wait_progress(page)
    assert records(page) == {}


def test_the_run_after_a_time_out_works_and_each_time_out_starts_one_sandbox(browser, site_url):
    context = browser.new_context()
    page = context.new_page()
    page.set_default_timeout(LONG)
    page.add_init_script(COUNT_SANDBOXES)
    errors: list[str] = []
    page.on("pageerror", lambda err: errors.append(str(err)))
    open_chapter(page, site_url, 0)
    ex = exercise(page, "0.5")
    ex.scroll_into_view_if_needed()
    page.wait_for_function("() => window.workbook.sandbox && window.workbook.sandbox.ready", timeout=LONG)
    set_editor(page, ex, GOOD)
    assert run_build(ex, LONG) == "correct"
    started = page.evaluate("() => window.sandboxesStarted")
    for attempt in range(3):
        set_editor(page, ex, SLEEPS)
        run_build(ex, LONG)
        text = ex.locator('[data-role="feedback"]').inner_text()
        assert "did not finish in time" in text, (attempt, text)
        set_editor(page, ex, GOOD)
        assert run_build(ex, LONG) == "correct", (attempt, ex.locator('[data-role="feedback"]').inner_text())
        assert page.evaluate("() => window.sandboxesStarted") == started + attempt + 1
    assert errors == []
    context.close()


def test_plain_code_cannot_change_numpy_for_later_runs(page, site_url):
    page.set_default_timeout(LONG)
    open_chapter(page, site_url, 0)
    ex = exercise(page, "0.5")
    ex.scroll_into_view_if_needed()
    wait_runtime(page)
    for _ in range(2):  # NumPy imported by the tampering run itself, then already loaded
        set_editor(page, ex, TAMPER)
        assert run_build(ex, LONG) == "incorrect"
        set_editor(page, ex, NUMPY_GOOD)
        assert run_build(ex, LONG) == "correct", ex.locator('[data-role="feedback"]').inner_text()
