"""The offline state and what the learner sees of it (docs/assets/js/offline.js).

* ``<html data-workbook-offline>`` takes only the contract's states: caching then
  ready on a first visit, ready at once when the service worker already serves
  the page, unavailable where no service worker can run.
* Once the site is stored, the footer says so with the stored size, on every
  page (instant navigation replaces the footer), and persistent storage is asked
  for once.
* Where the browser may delete stored data (WebKit, without persistent
  storage), a learner who has solved exercises is reminded to export their
  progress: dismissible, at most once a week.
"""

from __future__ import annotations

import json
import re
import time
from urllib.parse import urlsplit

import pytest
from playwright.sync_api import expect

from conftest import ROOT, SITE
from helpers import keep_to_origin
from workbook.contract import ATTR, DATA

# The offline copy must not lean on the HTTP cache; it needs its service worker.
pytestmark = [pytest.mark.uncached, pytest.mark.browser_context_args(service_workers="allow")]

LONG = 120_000
STATES = DATA["offlineStates"]
RECORD_STATES = """
window.__wbOfflineStates = [];
new MutationObserver(() => {
  const value = document.documentElement.getAttribute("%s");
  const seen = window.__wbOfflineStates;
  if (value !== null && seen[seen.length - 1] !== value) seen.push(value);
}).observe(document, { attributes: true, subtree: true, attributeFilter: ["%s"] });
""" % (ATTR.offline, ATTR.offline)
# persist() and persisted() as a browser that never grants persistent storage; calls counted across loads.
STUB_PERSIST = """
if (navigator.storage) {
  navigator.storage.persisted = async () => false;
  navigator.storage.persist = async () => {
    localStorage.setItem("__wbPersistCalls", String(Number(localStorage.getItem("__wbPersistCalls") || 0) + 1));
    return false;
  };
}
"""
SAFARI = ("Mozilla/5.0 (Macintosh; Intel Mac OS X 14_5) AppleWebKit/605.1.15 (KHTML, like Gecko) "
          "Version/17.5 Safari/605.1.15")
AXE = ROOT / "node_modules" / "axe-core" / "axe.min.js"
INDICATOR = "[data-wb-offline-indicator]"
REMINDER = "[data-wb-reminder]"


def wait_state(page, state: str) -> None:
    page.wait_for_function("([a, s]) => document.documentElement.getAttribute(a) === s", arg=[ATTR.offline, state],
                           timeout=LONG)


def states(page) -> list[str]:
    return page.evaluate("window.__wbOfflineStates")


def progress_key(site_url: str) -> str:
    return f"robotics-workbook:{urlsplit(site_url).path.rstrip('/')}:progress"


def solve_one(page, site_url: str) -> None:
    """Progress as the page saves it: exercise 0.1 solved."""
    record = {"version": 1, "exercises": {"0.1": {"solved": True, "attempts": 1, "updated": int(time.time() * 1000)}}}
    page.evaluate("([k, v]) => localStorage.setItem(k, v)", [progress_key(site_url), json.dumps(record)])


def stored_bytes() -> int:
    """What the service worker stores: every file of the manifest (the memory snapshot inflated: its stored size)."""
    files = json.loads(re.search(r"const FILES = (\[.*?\n\]);", (SITE / "sw.js").read_text(), re.S).group(1))
    return sum(entry[-1] for entry in files)


def axe_violations(page, selector: str) -> list[str]:
    """axe's serious and critical findings inside ``selector`` (the page's policy blocks a <script> tag: evaluate)."""
    if not page.evaluate("typeof window.axe === 'object'"):
        page.evaluate(AXE.read_text())
    return page.evaluate("""async (sel) => {
      const r = await axe.run(sel, { resultTypes: ['violations'] });
      return r.violations.filter(v => v.impact === 'serious' || v.impact === 'critical').map(v => v.id + ': ' + v.help);
    }""", selector)


@pytest.fixture
def recorded(page):
    page.context.add_init_script(RECORD_STATES)
    page.context.add_init_script(STUB_PERSIST)
    return page


def test_states_on_a_first_visit_and_a_return(recorded, site_url):
    page = recorded
    page.goto(site_url + "related/")
    wait_state(page, "ready")
    assert states(page) == ["caching", "ready"]
    page.reload()  # the service worker now serves the page: stored already
    wait_state(page, "ready")
    assert states(page) == ["ready"]
    assert {"caching", "ready", "unavailable", "asking", "declined"} <= set(STATES)


def test_unavailable_where_no_service_worker_can_run(browser, site_url):
    context = browser.new_context(service_workers="block")
    context.add_init_script(RECORD_STATES)
    try:
        page = context.new_page()
        page.goto(site_url + "related/")
        wait_state(page, "unavailable")
        assert states(page)[-1] == "unavailable" and "ready" not in states(page)  # register() refused
        assert page.locator(INDICATOR).count() == 0
    finally:
        context.close()


def test_the_footer_shows_the_stored_size_and_persistence_is_asked_once(recorded, site_url):
    page = recorded
    page.goto(site_url)
    wait_state(page, "ready")
    indicator = page.locator(f".md-footer {INDICATOR}")
    expect(indicator).to_be_visible(timeout=LONG)
    text = indicator.inner_text()
    match = re.fullmatch(r"Stored for offline use · ([\d.]+) MB", text)
    assert match, text
    expected_mb = stored_bytes() / 1e6
    assert expected_mb > 10
    assert abs(float(match.group(1)) - expected_mb) <= 0.5, (text, expected_mb)
    assert page.evaluate("localStorage.getItem('__wbPersistCalls')") == "1"
    assert axe_violations(page, INDICATOR) == []

    # On the next page too (instant navigation swaps the footer), from the size measured once.
    page.locator("a.md-footer__link--next").click()
    page.wait_for_url(re.compile(r"chapters/00-rotations-2d/"))
    expect(page.locator(f".md-footer {INDICATOR}")).to_have_text(text)
    # A reload does not ask again; and Chromium keeps its storage: no export reminder.
    solve_one(page, site_url)
    page.reload()
    expect(page.locator(f".md-footer {INDICATOR}")).to_have_text(text, timeout=LONG)
    assert page.evaluate("localStorage.getItem('__wbPersistCalls')") == "1"
    assert page.locator(REMINDER).count() == 0


def test_webkit_reminds_a_learner_to_export_at_most_once_a_week(browser, site_url):
    context = browser.new_context(user_agent=SAFARI)
    blocked = keep_to_origin(context, site_url)
    context.add_init_script(STUB_PERSIST)
    try:
        page = context.new_page()
        errors: list[str] = []
        page.on("pageerror", lambda err: errors.append(str(err)))
        page.goto(site_url + "related/")
        wait_state(page, "ready")
        assert page.locator(REMINDER).count() == 0  # nothing solved yet: nothing to lose

        solve_one(page, site_url)
        page.reload()
        reminder = page.locator(REMINDER)
        expect(reminder).to_be_visible()
        expect(reminder).to_contain_text("7 days")
        link = reminder.get_by_role("link", name="Export your progress")
        assert link.evaluate("a => a.href") == site_url + "progress/"
        assert axe_violations(page, REMINDER) == []
        reminder.get_by_role("button", name="Dismiss").click()
        expect(reminder).to_have_count(0)

        page.reload()  # shown this week already
        page.locator(".md-content__inner").wait_for()
        wait_state(page, "ready")
        assert page.locator(REMINDER).count() == 0

        # A week later, it comes back.
        key = f"robotics-workbook:{urlsplit(site_url).path}:offline"
        page.evaluate("""(key) => {
          const notes = JSON.parse(localStorage.getItem(key));
          notes.remindedAt -= 8 * 86400000;
          localStorage.setItem(key, JSON.stringify(notes));
        }""", key)
        page.reload()
        expect(page.locator(REMINDER)).to_be_visible()
        assert errors == [] and blocked == []
    finally:
        context.close()
