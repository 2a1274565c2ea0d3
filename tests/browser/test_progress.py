"""Progress: kept across reloads and instant navigation, shown at a glance
(chapter pages, the home page, a ✓ in the navigation), exported, reset and
imported back exactly; a corrupted store and a hostile import file change
nothing and say why."""

from __future__ import annotations

import json
import re
import tempfile
from pathlib import Path

from playwright.sync_api import Page, expect

from helpers import (
    answer_debug,
    answer_derive,
    answer_trace,
    editor_code,
    exercise,
    open_chapter,
    role,
    set_editor,
    solve,
    wait_runtime,
)
from workbook import bank

SOLVED_BAR = '[data-wb-chapter-progress] [data-wb-bar="solved"]'
ROTATE_OK = "import math\n\ndef rotate_2d(x, y, theta):\n    c, s = math.cos(theta), math.sin(theta)\n    return (c * x - s * y, s * x + c * y)\n"


def open_ready(page: Page, site_url: str, n: int) -> None:
    """Open chapter n and wait (generously: test machines may be busy) for the runtime."""
    open_chapter(page, site_url, n, wait_ready=False)
    wait_runtime(page, timeout=120_000)


def nav_link(page: Page, slug: str):
    return page.locator(f".md-nav--primary a.md-nav__link[href$='{slug}/']").first


def records(page: Page) -> dict:
    return page.evaluate("workbook.progress.all()")


def stored(page: Page):
    return page.evaluate("localStorage.getItem(workbook.progress.key)")


def click_nav(page: Page, slug: str) -> None:
    """Follow a navigation link; Material swaps the page without a reload."""
    nav_link(page, slug).click()
    # The theme's anchor tracking may still write the old page's heading into the new address's
    # fragment (a race inside Material): the page is the one the path names.
    page.wait_for_url(re.compile(re.escape(slug) + "/(#.*)?$"))


def solve_chapter_1(page: Page) -> None:
    for ex in bank.chapter(1):
        assert solve(page, ex) == "correct", ex.id


def test_progress_survives_reload_and_instant_navigation(page, site_url):
    open_ready(page, site_url, 0)
    summary = page.locator(SOLVED_BAR)
    expect(summary).to_contain_text(f"0 of {len(bank.chapter(0))} exercises")
    assert answer_derive(exercise(page, "0.1"), "3") == "correct"
    assert answer_trace(exercise(page, "0.3"), "a") == "incorrect"
    expect(summary).to_contain_text(f"1 of {len(bank.chapter(0))} exercises")

    page.reload()
    wait_runtime(page, timeout=120_000)
    assert exercise(page, "0.1").get_attribute("data-state") == "correct"
    # put back as each exercise starts, which may end after the grader is ready
    expect(exercise(page, "0.1").locator(role("answer"))).to_have_value("3")
    expect(exercise(page, "0.3").locator(role("choice") + '[value="a"]')).to_be_checked()
    expect(page.locator(SOLVED_BAR)).to_contain_text(f"1 of {len(bank.chapter(0))} exercises")

    # Instant navigation: the same document all along.
    page.evaluate("window.__sameDocument = true")
    click_nav(page, "01-transforms")
    expect(page.locator(SOLVED_BAR)).to_contain_text(f"0 of {len(bank.chapter(1))} exercises")
    wait_runtime(page, timeout=120_000)
    assert not nav_link(page, "01-transforms").locator(".wb-nav-done").count()
    solve_chapter_1(page)
    expect(page.locator(SOLVED_BAR)).to_contain_text(f"{len(bank.chapter(1))} of {len(bank.chapter(1))} exercises")
    expect(page.locator("[data-wb-chapter-progress]")).to_contain_text("Chapter finished")
    expect(nav_link(page, "01-transforms").locator(".wb-nav-done")).to_have_count(1)
    expect(nav_link(page, "00-rotations-2d").locator(".wb-nav-done")).to_have_count(0)

    click_nav(page, "00-rotations-2d")
    exercise(page, "0.1").wait_for()
    page.wait_for_function("() => document.querySelector('[data-exercise-id=\"0.1\"]').dataset.state === 'correct'")
    expect(page.locator(SOLVED_BAR)).to_contain_text(f"1 of {len(bank.chapter(0))} exercises")
    expect(nav_link(page, "01-transforms").locator(".wb-nav-done")).to_have_count(1)

    # The home page: the whole workbook, and one badge per chapter.
    page.locator(".md-nav--primary a.md-nav__link").first.click()
    page.wait_for_url(re.compile(r"/workbook/$"))
    total, chapters = len(bank.all_exercises()), len(bank.chapters())
    solved = 1 + len(bank.chapter(1))
    overall = page.locator("[data-wb-overall-progress]")
    expect(overall.locator('[data-wb-bar="solved"]')).to_contain_text(f"{solved} of {total} exercises")
    expect(overall.locator('[data-wb-bar="mastered"]')).to_contain_text(" that draw new numbers")
    expect(overall).to_contain_text(f"1 of {chapters} chapters finished")
    badges = page.locator(".md-content [data-wb-badge]")
    expect(badges).to_have_count(chapters)
    expect(badges.nth(0)).to_have_text(f"1 of {len(bank.chapter(0))} solved")
    expect(badges.nth(1)).to_have_text(f"✓ {len(bank.chapter(1))} of {len(bank.chapter(1))} solved")
    assert page.evaluate("window.__sameDocument === true"), "expected instant (same-document) navigations"

    # ...and after a full reload, from storage alone.
    page.reload()
    expect(page.locator("[data-wb-overall-progress]")).to_contain_text(f"{solved} of {total} exercises")
    expect(nav_link(page, "01-transforms").locator(".wb-nav-done")).to_have_count(1)


def open_progress_page(page: Page, site_url: str) -> None:
    page.goto(site_url + "progress/")
    page.locator("[data-wb-progress-panel] table").wait_for()


def import_file(page: Page, content: bytes | str, name: str = "progress.json") -> str:
    """Choose a file for the import button; return the message shown. The file is written to
    disk and chosen by its path, as a learner's is (a buffer would cross Playwright's pipe
    base64-encoded: minutes for the 33 MB file of the size limit's test)."""
    message = page.locator("[data-wb-progress-message]")
    page.evaluate("document.querySelector('[data-wb-progress-message]').replaceChildren()")
    data = content.encode() if isinstance(content, str) else content
    with tempfile.TemporaryDirectory() as folder:
        chosen = Path(folder) / name
        chosen.write_bytes(data)
        with page.expect_file_chooser() as chooser:
            page.get_by_role("button", name="Import progress…").click()
        chooser.value.set_files(chosen)
        expect(message).not_to_be_empty()
        return message.inner_text()


def make_some_progress(page: Page, site_url: str) -> None:
    open_ready(page, site_url, 0)
    assert answer_derive(exercise(page, "0.1"), "3") == "correct"
    assert answer_derive(exercise(page, "0.6"), "7") == "incorrect"
    assert answer_trace(exercise(page, "0.3"), "a") == "incorrect"
    exercise(page, "0.2").locator(role("reveal")).click()
    exercise(page, "0.2").locator(role("hint")).click()
    build = exercise(page, "0.5")
    set_editor(page, build, ROTATE_OK)
    page.wait_for_function("() => (workbook.progress.get('0.5').code || '').includes('math.cos')")
    open_ready(page, site_url, 3)
    assert answer_debug(exercise(page, "3.5"), bank.get("3.5").bug_line) == "correct"


def test_export_reset_import_restores_exactly(page, site_url):
    make_some_progress(page, site_url)
    open_progress_page(page, site_url)
    before = records(page)
    assert set(before) == {"0.1", "0.2", "0.3", "0.5", "0.6", "3.5"}
    assert before["0.2"]["revealed"] is True and before["0.5"]["code"] == ROTATE_OK
    table = page.locator("[data-wb-progress-panel] table")
    expect(table.locator("tbody tr").nth(0)).to_contain_text(f"1 of {len(bank.chapter(0))}")

    with page.expect_download() as download:
        page.get_by_role("button", name="Export progress").click()
    exported = json.loads(Path(download.value.path()).read_text(encoding="utf-8"))
    assert download.value.suggested_filename.endswith(".json")
    assert exported["format"] == "robotics-math-workbook-progress" and exported["version"] == 5
    assert exported["exercises"] == before

    # Reset asks first; cancelling changes nothing.
    page.get_by_role("button", name="Reset all progress…").click()
    dialog = page.locator("dialog.wb-confirm")
    expect(dialog).to_be_visible()
    dialog.get_by_role("button", name="Cancel").click()
    assert records(page) == before
    page.get_by_role("button", name="Reset all progress…").click()
    dialog.get_by_role("button", name="Erase everything").click()
    expect(page.locator("[data-wb-progress-message]")).to_contain_text("erased")
    assert records(page) == {}
    assert json.loads(stored(page))["exercises"] == {}
    expect(table.locator("tbody tr").nth(0)).to_contain_text(f"0 of {len(bank.chapter(0))}")

    text = import_file(page, json.dumps(exported))
    assert "6 added" in text
    assert records(page) == before
    assert json.loads(stored(page))["exercises"] == before
    expect(table.locator("tbody tr").nth(0)).to_contain_text(f"1 of {len(bank.chapter(0))}")

    # Merging again: field by field (CONTRACT.md), and the page says which records changed.
    newer = json.loads(json.dumps(exported))
    newer["exercises"]["0.6"].update(solved=True, last="1", updated=before["0.6"]["updated"] + 1000)
    newer["exercises"]["0.1"].update(attempts=99, last="0", updated=before["0.1"]["updated"] - 1000)
    text = import_file(page, json.dumps(newer))
    assert "2 combined" in text and "(0.1, 0.6)" in text and "4 already up to date" in text, text
    after = records(page)
    assert after["0.6"]["solved"] is True and after["0.6"]["last"] == "1"  # the newer record's answer
    assert after["0.1"]["attempts"] == 99 and after["0.1"]["last"] == before["0.1"]["last"]  # counters: the larger

    # The chapter page shows the restored state.
    open_chapter(page, site_url, 0, wait_ready=False)
    assert exercise(page, "0.1").get_attribute("data-state") == "correct"
    # The saved code is on screen before the editor is built, and in the editor after.
    expect(exercise(page, "0.5").locator(role("editor"))).to_contain_text("math.cos")
    assert "math.cos" in editor_code(exercise(page, "0.5"))
    wait_runtime(page, timeout=120_000)


def huge_file() -> str:
    """Larger than any export this site can write (local storage holds at most 10 MB), so refused unread."""
    return json.dumps({"format": "robotics-math-workbook-progress", "version": 1,
                       "exercises": {"0.1": {"last": "x" * 1500, "code": "#" * 33_000_000}}})


def test_malformed_or_hostile_import_is_refused_and_changes_nothing(page, site_url):
    open_ready(page, site_url, 0)
    assert answer_derive(exercise(page, "0.1"), "3") == "correct"
    open_progress_page(page, site_url)
    before, raw_before = records(page), stored(page)
    good = {"format": "robotics-math-workbook-progress", "version": 1, "exercises": {}}

    def variant(**changes):
        return json.dumps({**good, **changes})

    cases = {
        "not JSON": ("{oops", "not valid JSON"),
        "an array": ("[1, 2, 3]", "expected a JSON object"),
        "another format": (variant(format="something-else"), "not a Robotics Math Workbook progress export"),
        "a newer version": (variant(version=7), "newer version"),
        "exercises a list": (variant(exercises=[]), "no “exercises” object"),
        "__proto__ at the top": ('{"format": "robotics-math-workbook-progress", "version": 1, "exercises": {},'
                                 ' "__proto__": {"polluted": true}}', "forbidden key “__proto__”"),
        "__proto__ as an id": ('{"format": "robotics-math-workbook-progress", "version": 1,'
                               ' "exercises": {"__proto__": {"solved": true}}}', "forbidden key “__proto__”"),
        "constructor in a record": (variant(exercises={"0.2": {"constructor": {"prototype": {"polluted": True}}}}),
                                    "forbidden key “constructor”"),
        "an unknown exercise": (variant(exercises={"99.9": {"solved": True}}), "exercise “99.9”"),
        "an unknown field": (variant(exercises={"0.2": {"solved": True, "score": 100}}), "unknown field “score”"),
        "a wrong type": (variant(exercises={"0.2": {"solved": "yes"}}), "“solved” must be true or false"),
        "negative attempts": (variant(exercises={"0.2": {"attempts": -3}}), "“attempts” must be a whole number"),
        "a far-future time": (variant(exercises={"0.2": {"solved": True, "updated": 9e15}}), "not in the future"),
        "a record that is a string": (variant(exercises={"0.2": "solved"}), "not an object"),
        "huge": (huge_file(), "too large"),
    }
    for name, (content, reason) in cases.items():
        text = import_file(page, content)
        assert text.startswith("Import refused"), (name, text)
        assert reason in text, (name, text)
        assert "Nothing was changed" in text, name
        assert records(page) == before, name
        assert stored(page) == raw_before, name
    assert page.evaluate("({}).polluted === undefined && Object.prototype.polluted === undefined")
    # The refusal is announced (a live region), and a good file still imports afterwards.
    assert page.locator("[data-wb-progress-message]").get_attribute("role") == "status"
    assert "1 added" in import_file(page, variant(exercises={"0.2": {"attempts": 2, "last": "0", "updated": 1}}))


def test_corrupted_store_is_set_aside_with_a_message(page, site_url):
    page.goto(site_url)
    key = page.evaluate("workbook.progress.key")
    page.evaluate("k => localStorage.setItem(k, '{\"version\": 1, \"exercises\": ')", key)
    open_ready(page, site_url, 0)
    notice = page.locator(".wb-notice")
    expect(notice).to_contain_text("could not be read")
    backups = page.evaluate("k => Object.keys(localStorage).filter(n => n.startsWith(k + ':backup:'))", key)
    assert len(backups) == 1
    assert page.evaluate("k => localStorage.getItem(k)", backups[0]) == '{"version": 1, "exercises": '
    assert backups[0] in notice.inner_text()
    # The page works, and saving replaces the broken value with a good record.
    assert answer_derive(exercise(page, "0.1"), "3") == "correct"
    assert json.loads(stored(page))["exercises"]["0.1"]["solved"] is True


def test_full_storage_shows_a_message_and_keeps_the_answer(page, site_url):
    open_ready(page, site_url, 0)
    page.evaluate("""() => {
      Storage.prototype.setItem = function () { throw new DOMException('quota', 'QuotaExceededError'); };
    }""")
    assert answer_derive(exercise(page, "0.1"), "3") == "correct"
    expect(page.locator(".wb-notice")).to_contain_text("storage for this site is full")
    assert records(page)["0.1"]["solved"] is True  # kept in memory: it can still be exported
    assert exercise(page, "0.1").get_attribute("data-state") == "correct"


def test_version_1_records_are_migrated_on_load_and_on_import(page, site_url):
    """Progress saved before variants (schema 1) keeps every field and gains variant 0's marks and a review box."""
    page.goto(site_url)
    key = page.evaluate("workbook.progress.key")
    old = {"version": 1, "exercises": {
        "0.1": {"solved": True, "solvedAfterReveal": False, "attempts": 1, "last": "3", "updated": 1_700_000_000_000},
        "0.2": {"solved": True, "solvedAfterReveal": True, "revealed": True, "attempts": 2, "updated": 1_700_000_000_000},
        "0.4": {"attempts": 3, "last": "1", "updated": 1_700_000_000_000}}}
    page.evaluate("([k, v]) => localStorage.setItem(k, v)", [key, json.dumps(old)])
    open_ready(page, site_url, 0)
    got = records(page)
    assert got["0.1"]["last"] == "3" and got["0.1"]["attempts"] == 1  # nothing lost
    assert got["0.1"]["clean"] == [0] and got["0.1"]["done"] == [0] and got["0.1"]["box"] == 2
    assert "clean" not in got["0.2"] and got["0.2"]["done"] == [0] and got["0.2"]["revealedIn"] == [0]
    assert got["0.4"]["missed"] == [0] and got["0.4"]["box"] == 1 and "done" not in got["0.4"]
    assert exercise(page, "0.1").get_attribute("data-state") == "correct"
    expect(page.locator(".wb-chapter-progress")).to_contain_text("1 of")
    # A version-1 export imports the same way.
    open_progress_page(page, site_url)
    page.evaluate("workbook.progress.reset()")
    assert "3 added" in import_file(page, json.dumps({"format": "robotics-math-workbook-progress", **old}))
    assert records(page)["0.1"]["clean"] == [0] and records(page)["0.4"]["box"] == 1
