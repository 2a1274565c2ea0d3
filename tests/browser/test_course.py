"""Using the workbook in a course: assignment links give each learner their own numbers
(the same in every browser for one id, different between ids, recomputed by the class page),
the hand-in carries the answers, and the class page re-grades every file: an edited file's
claimed solve is "not verified", the common mistakes are counted, the table downloads as CSV,
and a malformed or hostile file is named and skipped. A Build solve's code is run again in the
sandbox: only code that passes is verified, and code that never ends stops alone.
axe finds nothing on the new pages."""

from __future__ import annotations

import csv
import io
import json
import re
import time
from pathlib import Path

import pytest
from playwright.sync_api import Page, expect

from helpers import role, wait_runtime
from site_audit import COLOUR_RULES, OVERFLOW, audit, load_axe, set_scheme
from workbook import api, bank
from workbook.assignment import assigned_variant

SLOW = 180_000
CODE = "ROB101 week 3"
SET = ["0.1", "0.3", "0.4", "1.1"]  # three Derive exercises (their own numbers) and a Trace one
LINK = "assignment/#" + "class=ROB101+week+3&ex=" + ",".join(SET) + "&due=2026-12-01"


def start_assignment(page: Page, site_url: str, student: str) -> None:
    page.goto(site_url + LINK)
    page.locator("[data-wb-field='student']").fill(student)
    page.get_by_role("button", name="Start").click()
    wait_assigned(page)


def wait_assigned(page: Page) -> None:
    page.wait_for_function("""(n) => {
      const ex = [...document.querySelectorAll('[data-wb-slot] [data-exercise-id]')];
      return ex.length === n && ex.every(e => e.dataset.wbReady && !e.hasAttribute('aria-busy') && (e.dataset.kind !== 'derive' || e.dataset.variant !== '0'));
    }""", arg=len(SET), timeout=SLOW)


def shown_variants(page: Page) -> dict[str, int]:
    return page.evaluate("""() => Object.fromEntries([...document.querySelectorAll('[data-wb-slot] [data-exercise-id][data-kind=derive]')]
      .map(e => [e.dataset.exerciseId, Number(e.dataset.variant)]))""")


def practice_numbers(page: Page, ex_id: str) -> None:
    """Press "New numbers" on exercise ``ex_id`` of the assignment and wait until its practice numbers are shown."""
    page.locator(f"[data-wb-slot='{ex_id}'] [data-exercise-id] " + role("new-variant")).click()
    page.wait_for_function("id => document.querySelector(`[data-wb-slot='${id}'] [data-exercise-id]`).dataset.wbAssigned === 'false'", arg=ex_id)


def typed(ex_id: str, variant: int, value) -> str:
    answer = bank.variant(ex_id, variant).answer
    return str(answer.typed(value))


def test_same_id_same_numbers_in_two_browsers_and_the_class_page_recomputes_them(browser, site_url, tmp_path):
    derive = [i for i in SET if bank.get(i).kind == "derive"]
    want = {i: assigned_variant(CODE, "Ada Lovelace", i) for i in derive}
    first, second, other = (browser.new_context(accept_downloads=True) for _ in range(3))
    try:
        a, b, c = first.new_page(), second.new_page(), other.new_page()
        start_assignment(a, site_url, "Ada Lovelace")
        start_assignment(b, site_url, "  ada   LOVELACE ")  # the same student, typed otherwise
        start_assignment(c, site_url, "Grace Hopper")
        assert shown_variants(a) == want == shown_variants(b)
        theirs = shown_variants(c)
        assert theirs == {i: assigned_variant(CODE, "Grace Hopper", i) for i in derive} and theirs != want
        labels = a.locator("[data-wb-slot] " + role("variant-label")).all_text_contents()
        assert labels and all("these count" in t for t in labels)
        # The id is kept: a reload asks for nothing and shows the same numbers.
        a.reload()
        wait_assigned(a)
        assert shown_variants(a) == want
        # New numbers are practice, marked so; the button brings the assignment's back.
        ex = a.locator("[data-wb-slot='0.1'] [data-exercise-id]")
        practice_numbers(a, "0.1")
        assert "Practice numbers" in ex.locator(role("variant-label")).text_content()
        a.locator("[data-wb-slot='0.1'] [data-wb-action='assigned-numbers']").click()
        wait_assigned(a)
        assert shown_variants(a)["0.1"] == want["0.1"]
        # Answer 0.1: a slip, then the key; hand in.
        wait_runtime(a, timeout=SLOW)
        ex = a.locator("[data-wb-slot='0.1'] [data-exercise-id]")
        made = bank.variant("0.1", want["0.1"]).answer
        for value, state in ((made.slips[0].value, "incorrect"), (made.key, "correct")):
            ex.locator(role("answer")).fill(typed("0.1", want["0.1"], value))
            ex.locator(role("check")).click()
            a.wait_for_function("s => document.querySelector(\"[data-wb-slot='0.1'] [data-exercise-id]\").dataset.state === s", arg=state, timeout=SLOW)
        with a.expect_download() as got:
            a.locator("[data-wb-action='hand-in']").click()
        handed = tmp_path / got.value.suggested_filename
        got.value.save_as(handed)
        data = json.loads(handed.read_text())
        assert data["format"] == "robotics-math-workbook-hand-in" and data["version"] == 1 and data["student"] == "Ada Lovelace"
        assert data["assignment"] == {"class": CODE, "exercises": SET, "due": "2026-12-01"}
        attempts = data["records"]["0.1"]["assigned"][CODE]["attempts"]
        assert [t["status"] for t in attempts] == ["incorrect", "correct"] and attempts[0]["slip"] == made.slips[0].id  # the bank's stable slip id
        assert data["records"]["0.1"]["slips"] == {attempts[0]["slip"]: 1}
        # A reload shows the last answer given to the assignment's numbers again, solved. The chapter's
        # own last answer (to its own numbers, which chains carry forward) is not the assignment's.
        a.reload()
        wait_assigned(a)
        ex = a.locator("[data-wb-slot='0.1'] [data-exercise-id]")
        expect(ex.locator(role("answer"))).to_have_value(typed("0.1", want["0.1"], made.key))  # put back as the exercise starts
        assert ex.get_attribute("data-state") == "correct"
        assert a.evaluate("() => window.workbook.progress.get('0.1').last ?? null") is None
        # Back from practice numbers, the same.
        practice_numbers(a, "0.1")
        assert ex.locator(role("answer")).input_value() == ""
        a.locator("[data-wb-slot='0.1'] [data-wb-action='assigned-numbers']").click()
        wait_assigned(a)
        expect(ex.locator(role("answer"))).to_have_value(typed("0.1", want["0.1"], made.key))  # put back as the exercise starts
        # The class page recomputes the numbers from the class code and the id, and grades them.
        a.goto(site_url + "class/")
        a.locator("#wb-class-files").set_input_files(str(handed))
        a.wait_for_function("() => document.querySelector('[data-wb-class]').dataset.wbGraded === '1'", timeout=SLOW)
        assert a.locator("td[data-wb-exercise='0.1']").get_attribute("data-wb-cell") == "verified"
        with a.expect_download() as got:
            a.locator("[data-wb-action='csv']").click()
        rows = list(csv.DictReader(io.StringIO(Path(got.value.path()).read_text(encoding="utf-8"))))
        assert {r["exercise"]: int(r["variant"]) for r in rows if r["exercise"] in want} == want
    finally:
        for context in (first, second, other):
            context.close()


def hand_in(student: str, records: dict) -> dict:
    return {"format": "robotics-math-workbook-hand-in", "version": 1, "handedIn": "2026-11-27T00:00:00Z", "student": student,
            "assignment": {"class": CODE, "exercises": SET, "due": None}, "records": records}


def attempt(ex_id: str, student: str, value, status: str, at: int) -> dict:
    v = assigned_variant(CODE, student, ex_id)
    return {"answer": typed(ex_id, v, value), "status": status, "at": at}


def record(ex_id: str, student: str, attempts: list[dict], solved: bool) -> dict:
    v = assigned_variant(CODE, student, ex_id)
    out = {"attempts": len(attempts), "updated": attempts[-1]["at"], "variant": v,
           "assigned": {CODE: {"variant": v, "attempts": attempts}}}
    if solved:
        out.update(solved=True, done=[v], clean=[v])
    return out


def three_learners() -> list[tuple[str, bytes]]:
    now = int(time.time() * 1000) - 60_000
    ex = lambda i, s: bank.variant(i, assigned_variant(CODE, s, i)).answer  # noqa: E731
    files = []
    # Ana: 0.1 with its own first slip, then right; 0.4 right at once.
    ana = {"0.1": record("0.1", "ana", [attempt("0.1", "ana", ex("0.1", "ana").slips[0].value, "incorrect", now),
                                        attempt("0.1", "ana", ex("0.1", "ana").key, "correct", now + 1)], True),
           "0.4": record("0.4", "ana", [attempt("0.4", "ana", ex("0.4", "ana").key, "correct", now)], True)}
    files.append(("ana.json", json.dumps(hand_in("ana", ana)).encode()))
    # Ben: 0.1 twice with the same slip, never right.
    slip = ex("0.1", "ben").slips[0].value
    ben = {"0.1": record("0.1", "ben", [attempt("0.1", "ben", slip, "incorrect", now), attempt("0.1", "ben", slip, "incorrect", now + 1)], False)}
    files.append(("ben.json", json.dumps(hand_in("ben", ben)).encode()))
    # Cai edited the file: 0.1 "solved" with Ana's right answer, which is wrong for Cai's numbers.
    assert ex("0.1", "cai").key != ex("0.1", "ana").key
    forged = attempt("0.1", "ana", ex("0.1", "ana").key, "correct", now)
    cai = {"0.1": record("0.1", "cai", [forged], True)}
    files.append(("cai.json", json.dumps(hand_in("cai", cai)).encode()))
    files.append(("broken.json", b"{not json"))
    files.append(("hostile.json", json.dumps({**hand_in("eve", {}), "records": {"__proto__": {"solved": True}}}).encode()))
    files.append(("stranger.json", json.dumps(hand_in("zed", {"9.99": {"solved": True}})).encode()))
    return files


def details(cell) -> str:
    """The text of a class-page cell's details, opened by its button."""
    cell.locator("button").click()
    text = cell.locator(".wb-class-pop").text_content()
    cell.page.keyboard.press("Escape")  # closed again: its box covers the cells below it
    return text


def test_class_page_regrades_three_learners(page, site_url):
    page.goto(site_url + "class/")
    files = [{"name": n, "mimeType": "application/json", "buffer": b} for n, b in three_learners()]
    page.locator("#wb-class-files").set_input_files(files)
    page.wait_for_function("() => document.querySelector('[data-wb-class]').dataset.wbGraded === '3'", timeout=SLOW)
    cell = lambda who, i: page.locator(f"tr[data-wb-student='{who}'] td[data-wb-exercise='{i}']")  # noqa: E731
    assert cell("ana", "0.1").get_attribute("data-wb-cell") == "verified"
    assert cell("ana", "0.4").get_attribute("data-wb-cell") == "verified"
    assert cell("ben", "0.1").get_attribute("data-wb-cell") == "unsolved"
    assert cell("cai", "0.1").get_attribute("data-wb-cell") == "not-verified"
    assert "not verified" in cell("cai", "0.1").text_content()
    assert "2 attempts" in details(cell("ana", "0.1"))
    assert page.locator("td[data-wb-rate='0.1']").text_content().startswith("1 of 3")
    problems = page.locator("[data-wb-problems] li").all_text_contents()
    assert len(problems) == 3 and all(any(t.startswith(n) for t in problems) for n in ("broken.json", "hostile.json", "stranger.json"))
    # The common mistakes of 0.1: Ana's and Ben's slip, re-graded: two learners, three answers.
    slip_rows = page.locator("[data-wb-mistakes='0.1'] tbody tr")
    assert slip_rows.count() == 1
    # Counted by the bank's stable slip id (issue 46), shown in the grader's words; the names the students'
    # pages recorded join the same row.
    assert re.fullmatch(r"0\.1/[a-z0-9-]+", slip_rows.first.get_attribute("data-wb-slip"))
    assert not slip_rows.first.locator("th").text_content().startswith("slip: ")
    assert slip_rows.first.locator("td").all_text_contents()[:2] == ["2", "3"]
    # Sorting by a column, from the keyboard.
    page.locator("[data-wb-sort='score']").focus()
    page.keyboard.press("Enter")
    assert page.locator("th:has([data-wb-sort='score'])").get_attribute("aria-sort") == "ascending"
    assert page.locator("tbody tr[data-wb-student]").first.get_attribute("data-wb-student") in ("ben", "cai")
    page.keyboard.press("Enter")
    assert page.locator("tbody tr[data-wb-student]").first.get_attribute("data-wb-student") == "ana"
    with page.expect_download() as got:
        page.locator("[data-wb-action='csv']").click()
    rows = list(csv.DictReader(io.StringIO(Path(got.value.path()).read_text(encoding="utf-8"))))
    by = {(r["student"], r["exercise"]): r for r in rows}
    assert by[("cai", "0.1")]["solved (claimed)"] == "yes" and by[("cai", "0.1")]["verified"] == "no"
    assert by[("ana", "0.1")]["verified"] == "yes" and by[("ana", "0.1")]["attempts"] == "2"
    assert by[("ben", "0.1")]["verified"] == "no" and int(by[("ben", "0.1")]["variant"]) == assigned_variant(CODE, "ben", "0.1")
    assert len(rows) == 3 * len(SET)


def build_hand_in(student: str, code: str | None, claimed: bool = True) -> bytes:
    """A hand-in of 0.1 and the Build exercise 0.5, whose record holds `code` (claimed solved when `claimed`)."""
    rec: dict = {"attempts": 1, "updated": int(time.time() * 1000) - 60_000}
    if code is not None:
        rec["code"] = code
    if claimed:
        rec.update(solved=True, done=[0], clean=[0])
    data = hand_in(student, {"0.5": rec})
    data["assignment"]["exercises"] = ["0.1", "0.5"]
    return json.dumps(data).encode()


def test_class_page_runs_build_code_again(page, site_url):
    """The bank's solution is verified; the starter code, code that never ends (before a good
    file: the sandbox is replaced, the next learner's run is not touched), a claim with no code
    and the starter never claimed are not."""
    ex = bank.get("0.5")
    assert ex.kind == "build" and ex.starter != ex.solution
    files = [("loop.json", build_hand_in("lou", "while True:\n    pass\n")),
             ("starter.json", build_hand_in("sam", ex.starter)),
             ("good.json", build_hand_in("gil", ex.solution)),
             ("nocode.json", build_hand_in("nia", None)),
             ("unclaimed.json", build_hand_in("una", ex.starter, claimed=False))]
    page.goto(site_url + "class/")
    page.locator("#wb-class-files").set_input_files([{"name": n, "mimeType": "application/json", "buffer": b} for n, b in files])
    page.wait_for_function("() => document.querySelector('[data-wb-class]').dataset.wbGraded === '5'", timeout=SLOW)
    cell = lambda who: page.locator(f"tr[data-wb-student='{who}'] td[data-wb-exercise='0.5']")  # noqa: E731
    states = {who: cell(who).get_attribute("data-wb-cell") for who in ("lou", "sam", "gil", "nia", "una")}
    assert states == {"lou": "not-verified", "sam": "not-verified", "gil": "verified", "nia": "not-verified", "una": "unsolved"}
    assert "passes" in details(cell("gil"))
    starter_says = json.loads(api.handle(json.dumps({"op": "run", "exercise": "0.5", "code": ex.starter})))["value"]
    assert starter_says["status"] == "incorrect" and starter_says["message"] in details(cell("sam"))
    assert "did not finish in time" in details(cell("lou"))
    assert "no answer or code" in details(cell("nia"))
    assert page.locator("td[data-wb-rate='0.5']").text_content().startswith("1 of 5")
    assert page.evaluate("() => window.workbook.sandbox.restarts + (window.workbook.sandbox.recycles || 0)") >= 1


COURSE_PAGES = ("teach/", LINK, "class/")  # audited here; test_a11y's pages are the rest (test_csp checks the union)


@pytest.mark.parametrize("width", [1280, 360])
def test_axe_finds_nothing_on_the_course_pages(page, site_url, width):
    page.set_viewport_size({"width": width, "height": 800})
    found = {}
    for path in COURSE_PAGES:
        page.goto(site_url + path)
        if path == "teach/":
            page.wait_for_selector("[data-wb-teach] form")
            page.locator("[data-wb-field='class']").fill("ROB101")
            page.locator("input[data-wb-chapter]").first.check()
            page.get_by_role("button", name="Make the link").click()
        elif path == LINK:
            page.wait_for_selector("[data-wb-field='student']")
            problems = audit(page)
            if problems:
                found["assignment (asking)"] = problems
            page.locator("[data-wb-field='student']").fill("s1")
            page.get_by_role("button", name="Start").click()
            wait_assigned(page)
        else:
            page.locator("#wb-class-files").set_input_files([{"name": n, "mimeType": "application/json", "buffer": b} for n, b in three_learners()])
            page.wait_for_function("() => document.querySelector('[data-wb-class]').dataset.wbGraded === '3'", timeout=SLOW)
        load_axe(page)  # and stops colour transitions before the palette changes
        for scheme in ("light", "dark"):  # every rule in one palette; in the other, the rules a palette changes
            set_scheme(page, scheme)
            problems = audit(page, None if scheme == "light" else COLOUR_RULES)
            if width == 360:
                problems += page.evaluate(OVERFLOW)
            if problems:
                found[f"{path} {scheme}"] = problems
    assert found == {}, "\n".join(f"{p}:\n  " + "\n  ".join(v) for p, v in found.items())
