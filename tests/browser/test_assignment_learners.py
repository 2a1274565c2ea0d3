"""The assignment page on a shared computer, and the teacher's page: each student named on the
assignment page works in a record of their own (a second student's hand-in carries nothing of
the first's, and the first's work is still theirs when they come back); the hand-in's file name
tells two students apart whatever their names' script; ids fold as the page promises (Unicode
case folding and NFKC, as the Python does); a Build run is an attempt, handed in and counted by
the class page; an impossible due date is refused on both pages; and the teach page says when
its links would lead to this computer only, and makes them from the public address when known."""

from __future__ import annotations

import json
import re
from pathlib import Path

from playwright.sync_api import Page

from helpers import role, run_build, set_editor, wait_runtime
from test_course import CODE, LINK, SET, SLOW, shown_variants, start_assignment, typed, wait_assigned
from workbook import bank
from workbook.assignment import assigned_variant


def hand_in(page: Page, tmp_path: Path) -> tuple[str, dict]:
    with page.expect_download() as got:
        page.locator("[data-wb-action='hand-in']").click()
    name = got.value.suggested_filename
    saved = tmp_path / name
    got.value.save_as(saved)
    return name, json.loads(saved.read_text(encoding="utf-8"))


def change_student(page: Page, student: str) -> None:
    page.get_by_role("button", name="Not you? Change the name").click()
    page.locator("[data-wb-field='student']").fill(student)
    page.get_by_role("button", name="Start").click()
    page.wait_for_function("s => document.querySelector('[data-wb-student]')?.dataset.wbStudent === s", arg=student)
    wait_assigned(page)


def answer(page: Page, ex_id: str, variant: int, value, state: str) -> None:
    ex = page.locator(f"[data-wb-slot='{ex_id}'] [data-exercise-id]")
    ex.locator(role("answer")).fill(typed(ex_id, variant, value))
    ex.locator(role("check")).click()
    page.wait_for_function("([id, s]) => document.querySelector(`[data-wb-slot='${id}'] [data-exercise-id]`).dataset.state === s",
                           arg=[ex_id, state], timeout=SLOW)


def test_two_students_on_one_browser_hand_in_their_own_work(page, site_url, tmp_path):
    """Ada answers 0.1 (a slip, then right) and hands in; Grace takes the same browser: her hand-in
    holds none of Ada's attempts, slips or solves, and her 0.1 is not shown solved. Ada, back, finds
    her own work. On main, Grace's file carried Ada's two attempts and her solve."""
    ada = assigned_variant(CODE, "Ada Lovelace", "0.1")
    start_assignment(page, site_url, "Ada Lovelace")
    wait_runtime(page, timeout=SLOW)
    made = bank.variant("0.1", ada).answer
    answer(page, "0.1", ada, made.slips[0].value, "incorrect")
    answer(page, "0.1", ada, made.key, "correct")
    name_a, a = hand_in(page, tmp_path)
    assert [t["status"] for t in a["records"]["0.1"]["assigned"][CODE]["attempts"]] == ["incorrect", "correct"]
    assert a["records"]["0.1"]["solved"] is True and sum(a["records"]["0.1"]["slips"].values()) == 1

    change_student(page, "Grace Hopper")
    assert shown_variants(page)["0.1"] == assigned_variant(CODE, "Grace Hopper", "0.1")
    assert page.locator("[data-wb-slot='0.1'] [data-exercise-id]").get_attribute("data-state") != "correct"
    name_b, b = hand_in(page, tmp_path)
    assert b["student"] == "Grace Hopper" and name_b != name_a
    held = json.dumps(b["records"])
    assert b["records"] == {} or all("assigned" not in r and "slips" not in r and not r.get("solved") for r in b["records"].values()), held

    # Grace answers 0.4; a reload keeps her (the id is kept), then Ada is back with her own work only.
    grace = assigned_variant(CODE, "Grace Hopper", "0.4")
    answer(page, "0.4", grace, bank.variant("0.4", grace).answer.key, "correct")
    page.reload()
    wait_assigned(page)
    assert page.locator("[data-wb-student]").get_attribute("data-wb-student") == "Grace Hopper"
    change_student(page, "ada lovelace")  # the same student, typed otherwise
    ex = page.locator("[data-wb-slot='0.1'] [data-exercise-id]")
    assert ex.locator(role("answer")).input_value() == typed("0.1", ada, made.key)
    _, again = hand_in(page, tmp_path)
    assert [t["status"] for t in again["records"]["0.1"]["assigned"][CODE]["attempts"]] == ["incorrect", "correct"]
    assert "0.4" not in again["records"]


def test_hand_in_names_tell_students_apart_in_any_script(page, site_url, tmp_path):
    """李雷 and 王芳 both saved hand-in-<class>--.json on main; now each name carries its id's tag."""
    link = "assignment/#class=AUDIT-A2&ex=0.1"
    page.goto(site_url + link)
    page.locator("[data-wb-field='student']").fill("李雷")
    page.get_by_role("button", name="Start").click()
    page.wait_for_selector("[data-wb-slot='0.1'] [data-exercise-id][data-wb-ready]")
    first, data = hand_in(page, tmp_path)
    assert data["assignment"]["class"] == "AUDIT-A2" and re.fullmatch(r"hand-in-AUDIT-A2-[0-9a-f]{8}\.json", first), first
    assert re.fullmatch(r"\d{4}-\d\d-\d\dT\d\d:\d\d:\d\d\.\d{3}Z", data["handedIn"])
    page.get_by_role("button", name="Not you? Change the name").click()
    page.locator("[data-wb-field='student']").fill("王芳")
    page.get_by_role("button", name="Start").click()
    page.wait_for_function("() => document.querySelector('[data-wb-student]')?.dataset.wbStudent === '王芳'")
    second, _ = hand_in(page, tmp_path)
    assert second != first and re.fullmatch(r"hand-in-AUDIT-A2-[0-9a-f]{8}\.json", second)
    page.get_by_role("button", name="Not you? Change the name").click()
    page.locator("[data-wb-field='student']").fill("Émile Zola")
    page.get_by_role("button", name="Start").click()
    page.wait_for_function("() => document.querySelector('[data-wb-student]')?.dataset.wbStudent === 'Émile Zola'")
    third, _ = hand_in(page, tmp_path)
    assert re.fullmatch(r"hand-in-AUDIT-A2-Emile-Zola-[0-9a-f]{8}\.json", third), third
    # The hand-in names the grader the page graded with, when the grader says ({"op": "version"}).
    wait_runtime(page, timeout=SLOW)
    page.evaluate("""() => { const rt = window.workbook.runtime, ask = rt.request.bind(rt);
      rt.request = (r, o) => (r.op === 'version' ? Promise.resolve({ ok: true, value: { version: '9.9', bank: '0123456789ab' } }) : ask(r, o)); }""")
    _, named = hand_in(page, tmp_path)
    assert named["grader"] == {"version": "9.9", "bank": "0123456789ab"}


def test_capitals_beyond_a_to_z_fold_as_the_python_does(page, site_url):
    """ÉMILE gets émile's numbers, computed by the Python (on main the page folded A-Z only)."""
    derive = [i for i in SET if bank.get(i).kind == "derive"]
    start_assignment(page, site_url, "ÉMILE \uff24\uff35\uff30\uff2f\uff2e\uff34")
    want = {i: assigned_variant(CODE, "émile dupont", i) for i in derive}
    assert shown_variants(page) == want


def test_a_build_run_is_an_attempt_handed_in_and_counted(page, site_url, tmp_path):
    """A Build run on the assignment page is kept among the assignment's attempts with the code it
    ran; the class page counts it and runs the code that passed. On main, the hand-in held no
    attempt for a Build exercise and the class page said "0 attempts"."""
    ex_def = bank.get("0.5")
    page.goto(site_url + "assignment/#class=BUILD-1&ex=0.5")
    page.locator("[data-wb-field='student']").fill("Bo")
    page.get_by_role("button", name="Start").click()
    ex = page.locator("[data-wb-slot='0.5'] [data-exercise-id]")
    ex.wait_for()
    wait_runtime(page, timeout=SLOW)
    assert run_build(ex, timeout=SLOW) == "incorrect"  # the starter
    set_editor(page, ex, ex_def.solution)
    assert run_build(ex, timeout=SLOW) == "correct"
    _, data = hand_in(page, tmp_path)
    attempts = data["records"]["0.5"]["assigned"]["BUILD-1"]["attempts"]
    assert [t["status"] for t in attempts] == ["incorrect", "correct"] and attempts[1]["code"] == ex_def.solution
    assert all("answer" not in t for t in attempts)
    page.goto(site_url + "class/")
    page.locator("#wb-class-files").set_input_files([{"name": "bo.json", "mimeType": "application/json",
                                                      "buffer": json.dumps(data).encode()}])
    page.wait_for_function("() => document.querySelector('[data-wb-class]').dataset.wbGraded === '1'", timeout=SLOW)
    cell = page.locator("td[data-wb-exercise='0.5']")
    assert cell.get_attribute("data-wb-cell") == "verified" and "2 attempts" in cell.text_content()


def test_an_impossible_due_date_is_refused(page, site_url):
    """30 February: the teach page refuses it with a message (on main it made a link without a due
    date); an assignment link that carries it says so (on main the page took it as 2 March)."""
    page.goto(site_url + "teach/")
    page.wait_for_selector("[data-wb-teach] form")
    page.locator("[data-wb-field='class']").fill("ROB101")
    page.locator("input[data-wb-chapter]").first.check()
    due = page.locator("[data-wb-field='due']")
    due.click()
    due.press_sequentially("02302026")  # month, day, year: Chromium's date field takes day 30 in any month
    assert page.evaluate("() => document.querySelector(\"[data-wb-field='due']\").validity.badInput")
    page.get_by_role("button", name="Make the link").click()
    status = page.locator("[data-wb-teach] [role='status']")
    assert "not a day of the calendar" in status.text_content()
    assert page.locator("[data-wb-field='link']").is_hidden()
    assert due.get_attribute("aria-invalid") == "true"
    page.goto(site_url + LINK.replace("2026-12-01", "2026-02-30"))
    problem = page.locator("[data-wb-assignment] .wb-course-problem")
    problem.wait_for()
    assert "2026-02-30" in problem.text_content() and "not a day of the calendar" in problem.text_content()


def make_link(page: Page) -> str:
    page.wait_for_selector("[data-wb-teach] form")
    page.locator("[data-wb-field='class']").fill("ROB101")
    page.locator("input[data-wb-chapter]").first.check()
    page.get_by_role("button", name="Make the link").click()
    return page.locator("[data-wb-field='link']").input_value()


def test_the_teach_page_says_where_its_links_lead(page, site_url):
    """Served on 127.0.0.1 (make serve), the page warns that its links reach no one else (on main it
    said "Send it to your class"). Built with a public address (site_url), it makes links there."""
    page.goto(site_url + "teach/")
    link = make_link(page)
    warning = page.locator("[data-wb-host-warning]")
    assert warning.get_attribute("data-wb-host-warning") == "local" and "this computer only" in warning.text_content()
    assert "Hosting the workbook for a class" in warning.text_content()
    assert warning.locator("a").get_attribute("href") == site_url + "teaching/hosting/"
    assert link.startswith(site_url + "assignment/#")
    assert "Send it to your class" not in page.locator("[data-wb-teach] [role='status']").text_content()

    public = "https://teacher.example.org/workbook/"

    def with_public_address(route):
        body = route.fetch().text()
        route.fulfill(body=re.sub(r'<link rel="canonical" href="[^"]*"', f'<link rel="canonical" href="{public}teach/"', body),
                      content_type="text/html")

    page.route(site_url + "teach/", with_public_address)
    page.goto(site_url + "teach/")
    link = make_link(page)
    assert link.startswith(public + "assignment/#class=ROB101&ex=")
    assert page.locator("[data-wb-host-warning]").get_attribute("data-wb-host-warning") == "public"
    assert "Send it to your class" in page.locator("[data-wb-teach] [role='status']").text_content()


def test_answers_kept_before_records_were_per_learner_stay_with_their_student(page, site_url, tmp_path):
    """A browser whose one record holds Ada's assignment answers (the page before this change kept
    them there, for the student it knew): Ada's hand-in still carries them, once moved into her own
    record; Grace, next on that browser, starts empty."""
    scope = "robotics-workbook:" + (re.sub(r"^https?://[^/]+", "", site_url).rstrip("/") or "/")
    v = assigned_variant(CODE, "Ada Lovelace", "0.1")
    at = 1_790_000_000_000
    old = {"answer": typed("0.1", v, bank.variant("0.1", v).answer.key), "status": "correct", "at": at}
    store = {"version": 5, "exercises": {"0.1": {"updated": at, "assigned": {CODE: {"variant": v, "attempts": [old]}}}}}
    page.goto(site_url)
    page.evaluate("([scope, store]) => { localStorage.setItem(scope + ':progress', store); localStorage.setItem(scope + ':student', 'Ada Lovelace'); }",
                  [scope, json.dumps(store)])
    page.goto(site_url + LINK)
    wait_assigned(page)
    _, ada = hand_in(page, tmp_path)
    assert ada["records"]["0.1"]["assigned"][CODE]["attempts"] == [old]
    change_student(page, "Grace Hopper")
    _, grace = hand_in(page, tmp_path)
    assert "0.1" not in grace["records"]
    page.reload()  # Grace is the student the page knows now: the old record is not hers
    wait_assigned(page)
    _, again = hand_in(page, tmp_path)
    assert again["student"] == "Grace Hopper" and "0.1" not in again["records"]
