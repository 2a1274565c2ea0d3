"""The class page as a teacher of 80 uses it (docs/class.md, class-*.js): the table takes the
page's width, one compact row per student with a score, a sticky header and first column, marks
that are a symbol as well as a colour, a cell's details on demand from the keyboard, axe clean
at 1280 and 360 px in both palettes; one row per student (the same id twice, two students whose
files had one name, another class code, a progress export); the hand-in's time and a late mark;
the gradebook CSV (one row per student, cells safe in every locale); which exercises worked
(share solved, median attempts, hints, slips, discrimination, the flag on an exercise the
strongest miss more than the weakest); the grader's version named and "changed since hand-in"."""

from __future__ import annotations

import csv
import io
import json
import time
from pathlib import Path

import pytest
from playwright.sync_api import Page

from class_files import a_class, answer, derive_ids, hand_in, record
from site_audit import COLOUR_RULES, OVERFLOW, audit, load_axe, set_scheme
from workbook import bank, version
from workbook.assignment import assigned_variant

SLOW = 300_000
CODE = "ROB101"
SYMBOLS = {"verified": "✓", "not-verified": "⚠", "unsolved": "✗", "not-set": "–"}
NOW = int(time.time() * 1000) - 3_600_000


def give(page: Page, site_url: str, files: list[tuple[str, bytes]]) -> None:
    page.goto(site_url + "class/")
    page.locator("#wb-class-files").set_input_files([{"name": n, "mimeType": "application/json", "buffer": b} for n, b in files])
    page.wait_for_function("n => document.querySelector('[data-wb-class]').dataset.wbGraded === String(n)", arg=len(files), timeout=SLOW)


def download(page: Page, action: str) -> str:
    with page.expect_download() as got:
        page.locator(f"[data-wb-action='{action}']").click()
    return Path(got.value.path()).read_bytes().decode("utf-8")


@pytest.mark.parametrize("width", [1280, 360])
def test_eighty_students_by_twelve_exercises_read_at_a_glance(page, site_url, width, tmp_path):
    ids = derive_ids(12)
    page.set_viewport_size({"width": width, "height": 900})
    give(page, site_url, a_class(CODE, 80, ids, NOW))
    table = page.locator(".wb-class-table")
    assert table.locator("tbody tr").count() == 80
    assert table.locator("tbody tr").first.locator("td").count() == 2 + 12
    # The whole width: no sidebars on this page; at 1280 px the table's region spans the page, not a text column.
    region = page.locator(".wb-class-grid")
    box = region.bounding_box()
    assert box["width"] >= width - 60, box
    if width == 1280:  # (on a phone the theme's menu is a drawer, closed)
        assert not page.locator(".md-sidebar--primary").is_visible() and not page.locator(".md-sidebar--secondary").is_visible()
    # Every mark is its symbol, with its words for a screen reader; the states differ in colour too.
    marks = page.evaluate("""() => [...document.querySelectorAll('.wb-class-table td[data-wb-cell]')].map(td => [td.dataset.wbCell,
      td.querySelector('.wb-class-symbol').textContent, td.querySelector('.wb-sr-only').textContent,
      getComputedStyle(td.querySelector('.wb-class-symbol')).color])""")
    assert len(marks) == 80 * 12
    colours = {}
    for state, symbol, words, colour in marks:
        assert symbol == SYMBOLS[state] and words.endswith({"verified": "solved, verified", "not-verified": "not verified", "unsolved": "not solved",
                                                           "not-set": "not set"}[state])
        colours.setdefault(state, set()).add(colour)
    assert {"verified", "unsolved", "not-set"} <= set(colours) and len({c for s in colours.values() for c in s}) == len(colours)
    # A score per student: solved / set.
    first = table.locator("tbody tr").first
    solved = first.locator("td[data-wb-cell='verified']").count()
    assert first.locator("td.wb-class-score").text_content() == f"{solved} / 12"
    # Sticky: scrolled inside its region, the header row and the first column stay in view.
    region.evaluate("r => { r.scrollLeft = 600; r.scrollTop = 600; }")
    page.wait_for_function("() => document.querySelector('.wb-class-grid').scrollTop > 0")
    top = region.bounding_box()
    head = table.locator("thead th").nth(5).bounding_box()
    name = table.locator("tbody tr").nth(40).locator("th").bounding_box()
    assert abs(head["y"] - top["y"]) < 3, (head, top)
    assert region.evaluate("r => r.scrollLeft") > 0 or width == 1280
    assert abs(name["x"] - top["x"]) < 3, (name, top)
    region.evaluate("r => { r.scrollLeft = 0; r.scrollTop = 0; }")
    # At 360 px the table scrolls sideways inside its focusable region, not the page.
    assert region.get_attribute("tabindex") == "0" and region.get_attribute("role") == "region"
    if width == 360:
        assert region.evaluate("r => r.scrollWidth > r.clientWidth")
    # A cell's details on demand, from the keyboard.
    cell = table.locator("tbody tr").first.locator("td[data-wb-cell]:not([data-wb-cell='not-set'])").first
    opener = cell.locator("button.wb-class-open")
    opener.focus()
    page.keyboard.press("Enter")
    assert opener.get_attribute("aria-expanded") == "true"
    pop = cell.locator(".wb-class-pop")
    assert pop.is_visible() and "attempt" in pop.text_content()
    # ...wholly on screen and on top: each of its corners is the details' own (at 360 px they opened
    # past the screen's right edge, clipped by the table's sideways scroll).
    corners = pop.evaluate("""p => { const r = p.getBoundingClientRect();
      return [[r.left + 2, r.top + 2], [r.right - 2, r.top + 2], [r.left + 2, r.bottom - 2], [r.right - 2, r.bottom - 2]]
        .map(([x, y]) => x >= 0 && y >= 0 && x <= innerWidth && y <= innerHeight && p.contains(document.elementFromPoint(x, y))); }""")
    assert corners == [True] * 4, corners
    load_axe(page)
    found = {}
    for scheme in ("light", "dark"):
        set_scheme(page, scheme)
        page.screenshot(path=str(tmp_path / f"class-{width}-{scheme}.png"))
        problems = audit(page, None if scheme == "light" else COLOUR_RULES) + page.evaluate(OVERFLOW)
        if problems:
            found[scheme] = problems
    assert found == {}
    page.keyboard.press("Escape")
    assert pop.count() == 0 and opener.get_attribute("aria-expanded") == "false"
    assert page.evaluate("() => document.activeElement.classList.contains('wb-class-open')")


def progress_export(records: dict) -> bytes:
    return json.dumps({"format": "robotics-math-workbook-progress", "version": 5, "exported": "2026-11-25T09:00:00Z", "exercises": records}).encode()


def test_one_row_per_student_late_work_and_the_gradebook(page, site_url):
    ids = ["0.1", "0.2"]
    key = lambda s, i="0.1": answer(i, CODE, s, True)  # noqa: E731
    slip = lambda s, i="0.1": answer(i, CODE, s, False)  # noqa: E731
    due = "2026-11-26"
    files = [
        # The same student twice (the id typed otherwise): the newer file, solved, is the one shown.
        ("ada-old.json", hand_in(CODE, "Ada King", ids, {"0.1": record("0.1", CODE, "Ada King", [(slip("Ada King"), "incorrect")], NOW)},
                                 handed_in="2026-11-25T08:00:00Z", due=due)),
        ("ada-new.json", hand_in(CODE, "  ada   KING ", ids, {"0.1": record("0.1", CODE, "ada king", [(key("ada king"), "correct")], NOW)},
                                 handed_in="2026-11-27T08:00:00Z", due=due)),
        # Two students whose files had the same name: both kept.
        ("hand-in-ROB101--.json", hand_in(CODE, "李雷", ids, {"0.1": record("0.1", CODE, "李雷", [(key("李雷"), "correct")], NOW)}, due=due,
                                          handed_in="2026-11-26T08:00:00Z")),
        ("hand-in-ROB101--.json", hand_in(CODE, "王芳", ids, {}, due=due, handed_in="2026-11-26T09:00:00Z")),
        # Another class's hand-in; a spreadsheet-hostile name; a progress export.
        ("zed.json", hand_in("ROB999", "zed", ids, {}, due=due)),
        ("odd.json", hand_in(CODE, "a;=1+2;b", ids, {}, handed_in="2026-11-20T08:00:00Z", due=due)),
        ("formula.json", hand_in(CODE, "=1+2", ids, {}, handed_in="2026-11-20T08:00:00Z", due=due)),
        ("my-progress.json", progress_export({"0.1": {"attempts": 1, "updated": NOW, "variant": 0, "last": "3", "done": [0], "clean": [0], "solved": True}})),
    ]
    give(page, site_url, files)
    rows = page.locator(".wb-class-table tbody tr")
    students = rows.evaluate_all("rs => rs.map(r => r.dataset.wbStudent)")
    assert sorted(students) == sorted(["ada   KING", "李雷", "王芳", "zed", "a;=1+2;b", "=1+2", "my-progress"]), students
    ada = page.locator("tr[data-wb-student='ada   KING']")
    assert ada.locator("th").get_attribute("data-wb-flags") == "duplicate late"
    assert ada.locator("td[data-wb-exercise='0.1']").get_attribute("data-wb-cell") == "verified"
    ada.locator("th button").click()
    assert "ada-old.json" in ada.locator("th").text_content() and "ada-new.json" in ada.locator("th").text_content()
    assert ada.locator("td.wb-class-time").get_attribute("data-wb-late") == "true" and "late" in ada.locator("td.wb-class-time").text_content()
    for who in ("李雷", "王芳"):
        assert "same-file-name" in page.locator(f"tr[data-wb-student='{who}'] th").get_attribute("data-wb-flags")
    assert page.locator("tr[data-wb-student='李雷'] td.wb-class-time").get_attribute("data-wb-late") == "false"
    assert "other-class" in page.locator("tr[data-wb-student='zed'] th").get_attribute("data-wb-flags")
    page.locator("tr[data-wb-student='zed'] th button").click()
    assert "ROB999" in page.locator("tr[data-wb-student='zed'] th").text_content()
    export = page.locator("tr[data-wb-student='my-progress']")
    assert export.get_attribute("data-wb-kind") == "progress" and "progress" in export.locator("th").get_attribute("data-wb-flags")
    assert "by the student's clock" in page.locator("[data-wb-class]").text_content()
    # The long table: every file (both of Ada's), with its hand-in time.
    long = list(csv.DictReader(io.StringIO(download(page, "csv"), newline="")))
    assert {r["handedIn"] for r in long if r["file"] == "ada-new.json"} == {"2026-11-27T08:00:00.000Z"}
    assert {r["late"] for r in long if r["file"] == "ada-old.json"} == {"no"}
    # The gradebook: one row per student, every exercise's mark; `;` and formula cells are safe.
    text = download(page, "gradebook")
    book = list(csv.reader(io.StringIO(text, newline="")))
    assert book[0] == ["Student", "SIS User ID", "SIS Login ID", "Section", "Handed in", "Late", "Score", "Out of", "Exercise 0.1", "Exercise 0.2"]
    assert len(book) == 1 + 6  # the progress export names no student: not in the gradebook
    by = {r[1]: r for r in book[1:]}
    assert by["ada   KING"][2:] == ["ada   KING", CODE, "2026-11-27T08:00:00.000Z", "yes", "1", "2", "1", "0"]
    assert by["'=1+2"][6] == "0"
    assert '"a;=1+2;b"' in text and "\r\n" in text
    for line in text.split("\r\n")[1:]:  # read with `;` as the separator (many locales' spreadsheets), no cell splits on the name
        assert "a;=1+2;b" not in line or '"a;=1+2;b"' in line


def test_which_exercises_worked(page, site_url):
    """Twelve students, four exercises: the weakest solve only the last one, the strongest everything else."""
    ids = derive_ids(4)
    files = []
    for i in range(12):
        s = f"t{i:02d}"
        strong = i >= 6
        recs = {}
        for k, ex_id in enumerate(ids[:3]):
            solve = strong or (k == 0 and i >= 3)
            tries = [(answer(ex_id, CODE, s, False), "incorrect")] + ([(answer(ex_id, CODE, s, True), "correct")] if solve else [])
            recs[ex_id] = record(ex_id, CODE, s, tries, NOW, hinted=k == 1)
        last = ids[3]
        recs[last] = record(last, CODE, s, [(answer(last, CODE, s, not strong), "correct" if not strong else "incorrect")], NOW)
        files.append((f"{s}.json", hand_in(CODE, s, ids, recs)))
    give(page, site_url, files)
    page.wait_for_function("() => document.querySelector('[data-wb-class]').dataset.wbStatsMs !== undefined", timeout=SLOW)
    row = lambda i: page.locator(f"tr[data-wb-stats='{i}'] td").all_text_contents()  # noqa: E731
    first, hinted, flagged = row(ids[0]), row(ids[1]), row(ids[3])
    assert first[:3] == ["12", "75%", "2"]  # 9 of 12 solved, each at the second attempt
    assert hinted[3] == "100%" and first[3] == "0%"
    assert float(first[5].replace("−", "-")) > 0 and float(flagged[5].replace("−", "-")) < 0
    assert flagged[1] == "50%" and flagged[2] == "1"
    assert page.locator(f"tr[data-wb-stats='{ids[3]}']").get_attribute("data-wb-flagged") == "true"
    assert page.locator(f"tr[data-wb-stats='{ids[0]}']").get_attribute("data-wb-flagged") is None
    assert "strongest students miss it more" in page.locator(f"tr[data-wb-stats='{ids[3]}'] th").text_content()
    ex = bank.variant(ids[0], 1).answer
    if ex.slips:  # the most common named slip is listed in its own words
        assert page.locator(f"tr[data-wb-stats='{ids[0]}'] [data-wb-slip]").count() >= 1


def test_the_grader_is_named_and_a_changed_mark_is_marked(page, site_url):
    """An answer the student's page marked wrong that the grader marks right now (as after a fix):
    solved, verified, and marked "changed since hand-in"; the page names the grader's version."""
    ids = ["0.1", "0.2"]
    s = "fixed"
    recs = {"0.1": record("0.1", CODE, s, [(answer("0.1", CODE, s, True), "incorrect")], NOW),
            "0.2": record("0.2", CODE, s, [(answer("0.2", CODE, s, True), "correct")], NOW)}
    old = json.loads(hand_in(CODE, s, ids, recs))
    old["grader"] = {"version": "0.0.9", "bank": "000000000000"}  # the grader the student's page said it was
    give(page, site_url, [("fixed.json", json.dumps(old).encode())])
    changed = page.locator("td[data-wb-exercise='0.1']")
    assert changed.get_attribute("data-wb-cell") == "verified" and changed.get_attribute("data-wb-changed") == "true"
    changed.locator("button").click()
    assert "Δ" in changed.locator("button").text_content() and "changed since hand-in" in changed.text_content()
    assert "marked incorrect grades correct now" in changed.text_content()
    assert page.locator("td[data-wb-exercise='0.2']").get_attribute("data-wb-changed") is None
    v = version.describe()
    page.wait_for_function("() => document.querySelector('[data-wb-grader]').textContent !== ''")
    assert page.locator("[data-wb-grader]").text_content() == f"Re-graded here by the workbook's grader version {v['version']}, bank {v['bank']}."
    flags = page.locator("tr[data-wb-student='fixed'] th")
    assert flags.get_attribute("data-wb-flags") == "other-grader"
    assert "†" in flags.locator("button").text_content()
    flags.locator("button").click()
    assert f"by grader 0.0.9, bank 000000000000; re-graded here by {v['version']}, bank {v['bank']}" in flags.text_content()
    # One meaning per symbol in the key (Δ once meant both "changed since hand-in" and "another grader").
    key = page.evaluate("() => [...document.querySelectorAll('.wb-class-legend li > [aria-hidden]')].map(s => s.textContent)")
    assert len(key) >= 10 and len(key) == len(set(key)), key
    text = page.locator("article").text_content()
    assert "not re-run here" not in text and "run again here" in text


def test_a_class_over_a_hundred_is_paged_and_every_student_reaches_the_gradebook(page, site_url):
    ids = derive_ids(2)
    give(page, site_url, a_class(CODE, 120, ids, NOW))
    rows = page.locator(".wb-class-table tbody tr")
    assert rows.count() == 100 and page.locator(".wb-class-pager").text_content().count("Students 1–100 of 120") == 1
    first = set(rows.evaluate_all("rs => rs.map(r => r.dataset.wbStudent)"))
    assert page.locator("[data-wb-action='previous-students']").is_disabled()
    page.locator("[data-wb-action='next-students']").click()
    rest = set(rows.evaluate_all("rs => rs.map(r => r.dataset.wbStudent)"))
    assert len(rest) == 20 and not first & rest and "Students 101–120 of 120" in page.locator(".wb-class-pager").text_content()
    assert page.locator("[data-wb-action='next-students']").is_disabled()
    book = list(csv.reader(io.StringIO(download(page, "gradebook"), newline="")))
    assert {r[1] for r in book[1:]} == first | rest and len(book) == 121


def test_which_step_went_wrong_first(page, site_url):
    """Per step, over answers worked in steps: the step each wrong answer first went wrong at, by
    its label, with how many students and answers. A right step after a wrong one, and two wrong
    steps, count at the first; a right answer, one typed without steps, or one whose steps are
    right as far as the student went (all of them, with the slip in the last line), counts at none."""
    ex_id = "4.1"  # steps d (the offset) then q (its squared length)
    first_step, second = (s.name for s in bank.get(ex_id).steps)
    plans = [("bad d", 4), ("both bad", 1), ("bad q", 2), ("right", 4), ("no steps", 1), ("half", 2), ("slip at the end", 1)]
    files, worked = [], 0
    for plan, n in plans:
        for k in range(n):
            s = f"{plan.replace(' ', '-')}-{k}"
            ex = bank.variant(ex_id, assigned_variant(CODE, s, ex_id))
            ok = {st.name: ex.step_answers[st.name].worked_text() for st in ex.steps}
            wrong = {first_step: "[97; 98]", second: "12345"}
            steps = {"bad d": {**ok, first_step: wrong[first_step]}, "both bad": wrong,
                     "bad q": {**ok, second: wrong[second]}, "right": ok, "slip at the end": ok,
                     "half": {first_step: ok[first_step]}}.get(plan)
            final = ex.answer.typed(ex.answer.key) if plan == "right" else "12345"
            rec = record(ex_id, CODE, s, [(final, "correct" if plan == "right" else "incorrect")], NOW)
            if steps:
                rec["assigned"][CODE]["attempts"][0]["steps"] = steps
                worked += 1
            files.append((f"{s}.json", hand_in(CODE, s, [ex_id], {ex_id: rec})))
    give(page, site_url, files)
    page.wait_for_function("() => document.querySelector('[data-wb-class]').dataset.wbStatsMs !== undefined", timeout=SLOW)
    row = page.locator(f"tr[data-wb-stats='{ex_id}']")
    label = {st.name: st.label for st in bank.get(ex_id).steps}
    assert f"over {worked} answers worked in steps" in row.text_content()
    assert row.locator(f"[data-wb-step='{first_step}']").text_content() == f"{label[first_step]} (5 students, 5 answers)"
    assert row.locator(f"[data-wb-step='{second}']").text_content() == f"{label[second]} (2 students, 2 answers)"
    assert row.locator("[data-wb-step]").count() == 2
