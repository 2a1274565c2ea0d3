"""Progress is never lost (issue 21, item 4): records from two tabs, from an
import made while another tab answers, and from two devices' exports are merged
field by field; storage that is full when the page opens still shows what is
saved and says new answers are not; a record that cannot be read is kept before
anything is written; the site accepts its own export whatever the size of a
Build answer; a malformed record is reported and skipped while every widget
still works."""

from __future__ import annotations

import json
import time
from pathlib import Path

from playwright.sync_api import Page, expect

from helpers import CHAPTERS, answer_derive, editor_code, exercise, set_editor, wait_runtime
from test_progress import import_file, open_progress_page, records, stored
from workbook import bank

ONE_OF_CHAPTER_0 = f"1 of {len(bank.chapter(0))}"  # solved, of all chapter 0's exercises

FORMAT = "robotics-math-workbook-progress"
IDS = ["0.1", "0.2", "0.4", "0.6", "0.7"]


def ready(page: Page, path: str = "") -> None:
    page.goto(path)
    page.wait_for_function("() => window.workbook && window.workbook.progress")


def export_of(exercises: dict) -> str:
    return json.dumps({"format": FORMAT, "version": 2, "exported": "2025-01-01T00:00:00Z", "exercises": exercises})


# A tab "answers" as exercise.js does: a patch computed from what the tab holds in
# memory (which may lag the other tab), handed to progress.update. Both tabs are
# armed to write in the same millisecond of the system clock, for a batch of such
# instants at once: for each, a timer to just before it, then a spin to the instant.
ARM = """(writes) => {
  window.__fired = writes.map(() => null);
  writes.forEach(([id, v, at], k) => {
    const go = () => {
      while (Date.now() < at) { /* spin to the instant: the one system clock both tabs read */ }
      const started = Date.now();
      const r = workbook.progress.get(id);
      workbook.progress.update(id, { done: [...(r.done || []), v], attempts: (r.attempts || 0) + 1 });
      window.__fired[k] = started;
    };
    setTimeout(go, Math.max(0, at - Date.now() - 40));
  });
}"""
BATCH, SPACING = 10, 120  # instants armed at once, and the milliseconds between them

CONVERGED = """([ids, expected]) => {
  const mem = workbook.progress.all();
  const disk = JSON.parse(localStorage.getItem(workbook.progress.key) || '{"exercises": {}}').exercises;
  return ids.every((id) => expected[id].every((v) => (mem[id]?.done || []).includes(v) && (disk[id]?.done || []).includes(v)));
}"""


def test_two_tabs_answering_within_a_millisecond_fifty_times_lose_nothing(context, site_url):
    a, b = context.new_page(), context.new_page()
    for tab in (a, b):
        ready(tab, site_url + CHAPTERS[0])
    ids = [*IDS, "0.3", "1.1", "1.2", "1.3", "1.4"]
    expected: dict[str, list[int]] = {i: [] for i in ids}
    gaps = []
    # Both tabs write the same record at the same instant; a busy machine may start
    # one of them late, so this goes on until 50 pairs began in the same millisecond
    # (at most 200 pairs: every pair is a real test of the merge all the same).
    while sum(g == 0 for g in gaps) < 50 and len(gaps) < 200:
        start = int(time.time() * 1000) + 150
        batch = []
        for k in range(BATCH):
            n = len(gaps) + k
            ex = ids[n % len(ids)]
            expected[ex] += [2 * n + 1, 2 * n + 2]
            batch.append((ex, 2 * n + 1, 2 * n + 2, start + k * SPACING))
        a.evaluate(ARM, [[ex, va, at] for ex, va, _, at in batch])
        b.evaluate(ARM, [[ex, vb, at] for ex, _, vb, at in batch])
        for tab in (a, b):
            tab.wait_for_function("() => window.__fired.every(t => t !== null)")
        fired_a, fired_b = a.evaluate("window.__fired"), b.evaluate("window.__fired")
        gaps += [abs(x - y) for x, y in zip(fired_a, fired_b, strict=True)]
    # The tabs exchange what they wrote until both hold everything, in memory and in storage.
    for tab in (a, b):
        tab.wait_for_function(CONVERGED, arg=[ids, expected])
    for tab in (a, b):
        got = records(tab)
        for ex in ids:
            assert sorted(got[ex]["done"]) == sorted(expected[ex]), ex
    assert json.loads(stored(a))["exercises"] == json.loads(stored(b))["exercises"]
    print(f"pairs of writes: {len(gaps)}, begun in the same millisecond: {sum(g == 0 for g in gaps)}")


def test_an_import_while_another_tab_answers_loses_nothing(context, site_url):
    importer, answerer = context.new_page(), context.new_page()
    ready(answerer, site_url + CHAPTERS[0])
    open_progress_page(importer, site_url)
    for n in range(14):
        ex = IDS[n % len(IDS)]
        file = export_of({ex: {"done": [500 + n], "clean": [500 + n], "updated": 1_700_000_000_000 + n},
                          "1.1": {"done": [700 + n], "updated": 1_700_000_000_000 + n}})
        # The other tab answers the same exercise just as the file is read.
        answerer.evaluate(ARM, [[ex, 900 + n, time.time() * 1000 + 40]])
        message = import_file(importer, file)
        assert "Import refused" not in message, message
        answerer.wait_for_function("() => window.__fired.every(t => t !== null)")
    expected = {ex: [] for ex in IDS}
    for n in range(14):
        expected[IDS[n % len(IDS)]] += [500 + n, 900 + n]
    for tab in (importer, answerer):
        tab.wait_for_function(CONVERGED, arg=[IDS, expected])
        assert sorted(records(tab)["1.1"]["done"]) == [700 + n for n in range(14)]


LAPTOP = {
    "0.1": {"solved": True, "solvedAfterReveal": False, "attempts": 1, "last": "3", "variant": 0, "done": [0], "clean": [0],
            "box": 3, "due": 1_700_300_000_000, "reviewed": 1_700_000_000_000, "updated": 1_700_000_000_000},
    "0.5": {"code": "def rotate_2d(x, y, theta):\n    return laptop\n", "updated": 1_700_000_500_000},
    "0.2": {"hinted": True, "updated": 1_700_000_000_000},
}
PHONE = {
    # Later, on the phone: a wrong first answer to new numbers of 0.1.
    "0.1": {"attempts": 1, "last": "12", "variant": 517, "missed": [517], "box": 1, "due": 1_700_100_600_000,
            "reviewed": 1_700_100_000_000, "updated": 1_700_100_000_000},
    "0.5": {"code": "def rotate_2d(x, y, theta):\n    return phone\n", "updated": 1_700_000_100_000},
    "0.3": {"attempts": 2, "last": "b", "updated": 1_700_100_000_000},
}


def merged_after(page: Page, site_url: str, files: list[dict]) -> dict:
    open_progress_page(page, site_url)
    page.evaluate("workbook.progress.reset()")
    for f in files:
        assert "Import refused" not in import_file(page, export_of(f))
    return records(page)


def test_a_laptop_and_a_phone_export_merge_in_either_order(page, site_url):
    one = merged_after(page, site_url, [LAPTOP, PHONE])
    other = merged_after(page, site_url, [PHONE, LAPTOP])
    assert one == other
    r = one["0.1"]
    assert r["clean"] == [0] and r["done"] == [0] and r["solved"] is True  # the phone's miss does not un-solve it
    assert r["missed"] == [517]
    assert (r["box"], r["reviewed"]) == (1, 1_700_100_000_000)  # the schedule that moved last
    assert (r["last"], r["variant"]) == ("12", 517)  # what was on screen last
    assert r["attempts"] == 1 and r["updated"] == 1_700_100_000_000
    assert "laptop" in one["0.5"]["code"]  # the newer code
    assert one["0.2"]["hinted"] is True and one["0.3"]["last"] == "b"
    # Importing a file again changes nothing, and says so.
    assert "3 already up to date" in import_file(page, export_of(PHONE))
    # The chapter page counts 0.1 as solved.
    page.goto(site_url + CHAPTERS[0])
    expect(page.locator('[data-wb-chapter-progress] [data-wb-bar="solved"]')).to_contain_text(ONE_OF_CHAPTER_0)
    wait_runtime(page, timeout=120_000)


FILL = """(keep) => {
  // Fill this origin's local storage to the last byte, leaving `keep` alone.
  let size = 1 << 20, n = 0;
  while (size >= 1) {
    try { localStorage.setItem(`junk:${n++}`, 'x'.repeat(size)); } catch { size = Math.floor(size / 2); }
  }
  return n;
}"""
FREE = "() => Object.keys(localStorage).filter((k) => k.startsWith('junk:')).forEach((k) => localStorage.removeItem(k))"


def test_storage_full_at_load_shows_what_is_saved_and_says_so(page, site_url):
    ready(page, site_url + CHAPTERS[0])
    wait_runtime(page, timeout=120_000)
    assert answer_derive(exercise(page, "0.1"), "3") == "correct"
    page.wait_for_function("() => localStorage.getItem(workbook.progress.key)?.includes('0.1')")
    page.evaluate(FILL, None)
    page.reload()
    wait_runtime(page, timeout=120_000)
    notice = page.locator('[data-wb-notice="progress-full"]')
    expect(notice).to_contain_text("storage for this site is full")
    expect(notice).to_contain_text("new answers are not saved")
    assert exercise(page, "0.1").get_attribute("data-state") == "correct"  # what is saved is shown
    expect(page.locator('[data-wb-chapter-progress] [data-wb-bar="solved"]')).to_contain_text(ONE_OF_CHAPTER_0)
    before = stored(page)
    assert answer_derive(exercise(page, "0.6"), "5") in ("correct", "incorrect")
    assert "0.6" in records(page)  # kept in memory...
    assert stored(page) == before  # ...and nothing half-written
    with page.expect_download() as download:
        notice.locator('[data-wb-action="notice-export"]').click()
    exported = json.loads(Path(download.value.path()).read_text(encoding="utf-8"))["exercises"]
    assert {"0.1", "0.6"} <= set(exported)
    # Space freed: the next answer saves everything, and the notice goes.
    page.evaluate(FREE)
    assert answer_derive(exercise(page, "0.1"), "3") == "correct"
    page.wait_for_function("() => JSON.parse(localStorage.getItem(workbook.progress.key)).exercises['0.6']")
    expect(notice).to_have_count(0)


def test_an_unreadable_record_with_no_room_for_a_copy_is_never_overwritten(page, site_url):
    ready(page, site_url)
    key = page.evaluate("workbook.progress.key")
    page.evaluate("([k, v]) => localStorage.setItem(k, v)", [key, '{"version": 9, "exercises": {"0.1": {"future": 1}}}'])
    page.evaluate(FILL, None)
    ready(page, site_url + CHAPTERS[0])
    wait_runtime(page, timeout=120_000)
    notice = page.locator('[data-wb-notice="progress-blocked"]')
    expect(notice).to_contain_text("newer version")
    expect(notice).to_contain_text("nothing will be saved")
    with page.expect_download() as download:
        notice.locator('[data-wb-action="notice-download"]').click()
    assert Path(download.value.path()).read_text(encoding="utf-8") == '{"version": 9, "exercises": {"0.1": {"future": 1}}}'
    page.evaluate(FREE)  # even with room now: the copy is made first, then the record written
    assert answer_derive(exercise(page, "0.1"), "3") == "correct"
    page.wait_for_function("k => Object.keys(localStorage).some(n => n.startsWith(k + ':backup:'))", arg=key)
    backup = page.evaluate("k => localStorage.getItem(Object.keys(localStorage).find(n => n.startsWith(k + ':backup:')))", key)
    assert backup == '{"version": 9, "exercises": {"0.1": {"future": 1}}}'
    page.wait_for_function("() => JSON.parse(localStorage.getItem(workbook.progress.key)).exercises['0.1']?.done")


def test_a_200000_character_build_answer_survives_export_and_import(page, site_url):
    ready(page, site_url + CHAPTERS[0])
    code = "def rotate_2d(x, y, theta):\n    return (x, y)\n" + ("# a long comment line, kept as typed\n" * 5600)
    assert len(code) > 200_000
    build = exercise(page, "0.5")
    set_editor(page, build, code)
    page.wait_for_function("n => (workbook.progress.get('0.5').code || '').length === n", arg=len(code))
    open_progress_page(page, site_url)
    with page.expect_download() as download:
        page.get_by_role("button", name="Export progress").click()
    text = Path(download.value.path()).read_text(encoding="utf-8")
    page.evaluate("workbook.progress.reset()")
    assert "added" in import_file(page, text)
    assert records(page)["0.5"]["code"] == code
    page.goto(site_url + CHAPTERS[0])
    assert editor_code(exercise(page, "0.5")) == code
    wait_runtime(page, timeout=120_000)


def test_a_malformed_record_is_reported_and_skipped_and_every_widget_works(page, site_url):
    ready(page, site_url)
    key = page.evaluate("workbook.progress.key")
    bad = {"version": 2, "exercises": {
        "0.1": {"done": 5, "last": "3", "attempts": 1, "updated": 1_700_000_000_000},
        "0.3": "not a record",
        "0.2": {"clean": [0], "done": [0], "solved": True, "updated": 1_700_000_000_000}}}
    raw = json.dumps(bad)
    page.evaluate("([k, v]) => localStorage.setItem(k, v)", [key, raw])
    page.goto(site_url + CHAPTERS[0])
    notice = page.locator('[data-wb-notice="progress-set-aside"]')
    expect(notice).to_contain_text("0.1 (done)")
    expect(notice).to_contain_text("0.3")
    wait_runtime(page, timeout=120_000)
    for ex in bank_ids(page):  # every widget starts (a Build exercise has no form: its editor is there)
        exercise(page, ex).locator("form[data-wb-ready], [data-role=editor]").first.wait_for(state="attached")
    page.wait_for_function("() => [...document.querySelectorAll('[data-exercise-id] form')].every(f => f.dataset.wbReady)")
    assert exercise(page, "0.2").get_attribute("data-state") == "correct"  # the good record is shown
    assert exercise(page, "0.1").locator('[data-role="answer"]').input_value() == "3"  # the readable fields too
    assert answer_derive(exercise(page, "0.1"), "3") == "correct"
    for ex in bank_ids(page):
        assert exercise(page, ex).get_attribute("data-state") != "error", ex
    backups = page.evaluate("k => Object.keys(localStorage).filter(n => n.startsWith(k + ':backup:'))", key)
    assert [page.evaluate("k => localStorage.getItem(k)", b) for b in backups] == [raw]
    assert page.js_errors == []


def bank_ids(page: Page) -> list[str]:
    return page.locator("[data-exercise-id]").evaluate_all("els => els.map(e => e.dataset.exerciseId)")
