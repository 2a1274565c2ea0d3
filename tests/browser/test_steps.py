""""Work it in steps" in the page (CONTRACT.md, "Checked steps"): 3.8 worked in steps with a
wrong first step (a named slip) and a second step that follows from it (carried, with a link
back), kept over a reload, the step offered after a wrong final answer, a solve with steps
(solved, not clean), and new numbers that clear the steps. One page of chapter 3, one reload.

Every value typed comes from the grading package (the bank's keys, slips and carried keys).
"""

from __future__ import annotations

from playwright.sync_api import Locator, Page, expect

from helpers import exercise, fill_matrix, open_chapter, paste, role, wait_runtime
from site_audit import COLOUR_RULES, audit, set_scheme
from workbook import bank
from workbook.contract import ATTR, STATE, TAG
from workbook.number_format import fmt

EX = bank.get("3.8")


def grid_text(rows) -> list[list[str]]:
    return [[fmt(v) for v in row] for row in rows]


def step(el: Locator, name: str) -> Locator:
    return el.locator(role("work-step", f'[{ATTR.stepName}="{name}"]'))


def settled(page: Page, target: Locator) -> str:
    page.wait_for_function("el => el.dataset.state !== 'pending'", arg=target.element_handle())
    return target.get_attribute(ATTR.state)


def check_step(page: Page, el: Locator, name: str, rows) -> str:
    """Type a step's matrix and press its Check; its own state after the reply."""
    li = step(el, name)
    fill_matrix(li, grid_text(rows))
    li.locator(role("work-step-check")).click()
    return settled(page, li)


def check_final(page: Page, el: Locator, rows) -> str:
    """Type the exercise's own answer (its form, outside the steps) and press its Check."""
    own = el.locator(":scope > form")
    fill_matrix(own, grid_text(rows))
    own.locator(role("check")).click()
    return settled(page, el)


def focused_step(page: Page) -> str | None:
    """The data-step-name of the step whose input has the focus, or None."""
    return page.evaluate("a => document.activeElement?.closest(`[${a.role}=\"work-step\"]`)?.getAttribute(a.name) ?? null",
                         {"role": ATTR.role, "name": ATTR.stepName})


def record(page: Page) -> dict:
    return page.evaluate("id => workbook.progress.get(id)", EX.id)


def test_work_3_8_in_steps_with_a_wrong_step_then_solve_it(page, site_url):
    fp, fpf = EX.step_answers["FP"], EX.step_answers["FPF"]
    slip = fp.slips[0]  # P F: the product in the wrong order
    carried = EX.carried_steps({"FP": slip.value})["FPF"]  # step 2 worked from that wrong step 1
    open_chapter(page, site_url, 3)
    el = exercise(page, EX.id)
    assert el.get_attribute(ATTR.steps) == "FP FPF"
    opener = el.locator(role("work-steps-open"))
    panel = el.locator(role("work-steps"))
    assert opener.get_attribute("aria-expanded") == "false" and panel.is_hidden()
    assert el.locator(role("entry")).count() == 9  # closed: only the exercise's own answer

    # (a) opened from the keyboard; a wrong step 1 (a named slip), checked with Enter
    el.locator("form[data-wb-ready]").wait_for(state="attached")
    opener.focus()
    page.keyboard.press("Enter")
    expect(panel).to_be_visible()
    assert opener.get_attribute("aria-expanded") == "true"
    expect(el.locator(role("work-step"))).to_have_count(2)
    expect(step(el, "FP")).to_contain_text("Step 1 · F P")
    expect(step(el, "FPF")).to_contain_text("Step 2 · F P Fᵀ")
    # the whole matrix pasted into one entry: the grader splits it with the step's own answer kind
    rows = grid_text(slip.value)
    paste(step(el, "FP").locator(role("entry", '[data-row="1"][data-col="1"]')), "\n".join(" ".join(r) for r in rows))
    last = step(el, "FP").locator(role("entry", '[data-row="3"][data-col="3"]'))
    expect(last).to_have_value(rows[2][2])
    last.press("Enter")
    assert settled(page, step(el, "FP")) == STATE.incorrect
    expect(step(el, "FP").locator(role("work-step-feedback"))).to_contain_text(slip.message)
    assert el.get_attribute(ATTR.state) == STATE.unanswered  # a step is not the exercise's answer

    # a step 2 that follows from that wrong step 1: carried, with a link back to step 1
    assert check_step(page, el, "FPF", carried.key) == STATE.incorrect
    two = step(el, "FPF")
    assert two.get_attribute(ATTR.tag) == TAG.carried and two.get_attribute(ATTR.carried) == "FP"
    link = two.locator(role("carried-from"))
    expect(link).to_have_text("Back to step 1")
    link.click()
    assert focused_step(page) == "FP"

    # (b) a reload brings back both answers, their verdicts and the open panel; the record says so
    page.reload()
    wait_runtime(page)
    el = exercise(page, EX.id)
    expect(el.locator(role("work-steps"))).to_be_visible()
    expect(step(el, "FPF").locator(role("carried-from"))).to_have_text("Back to step 1")
    assert step(el, "FP").get_attribute(ATTR.state) == STATE.incorrect
    assert step(el, "FPF").get_attribute(ATTR.state) == STATE.incorrect
    assert step(el, "FPF").get_attribute(ATTR.tag) == TAG.carried
    typed = step(el, "FP").locator(role("entry")).evaluate_all("els => els.map(e => e.value)")
    assert typed == [t for row in grid_text(slip.value) for t in row]
    expect(step(el, "FP").locator(role("work-step-feedback"))).to_contain_text(slip.message)
    saved = record(page)
    assert saved["stepped"] == [0] and saved["carried"] == [0]
    assert set(saved["stepWork"]["steps"]) == {"FP", "FPF"} and saved["stepWork"]["variant"] == 0
    assert "attempts" not in saved and "missed" not in saved  # checking steps is neither an attempt nor a miss

    # (c) a wrong final answer offers the first step to look at; the offer opens the steps there
    el.locator(role("work-steps-open")).click()  # close the panel first
    expect(el.locator(role("work-steps"))).to_be_hidden()
    off = [row[:] for row in EX.answer.cleaned]
    off[1][1] += 1.5
    assert check_final(page, el, off) == STATE.incorrect
    offer = el.locator(role("work-steps-offer"))
    expect(offer).to_have_text("Work it in steps — start with step 1 (F P)")
    offer.click()
    expect(el.locator(role("work-steps"))).to_be_visible()
    page.wait_for_function("() => document.activeElement?.dataset.role === 'entry'")
    assert focused_step(page) == "FP"
    # the offer is gone while the steps are open (never beside "Hide the steps"), and back once closed
    expect(el.locator(role("work-steps-open"))).to_have_text("Hide the steps")
    expect(offer).to_be_hidden()
    el.locator(role("work-steps-open")).click()
    expect(offer).to_be_visible()
    el.locator(role("work-steps-open")).click()
    expect(offer).to_be_hidden()

    # both palettes pass the audit with the steps open, a carried step and the offer shown
    for scheme, rules in (("light", None), ("dark", COLOUR_RULES)):  # every rule in one palette; those a palette changes in the other
        set_scheme(page, scheme)
        assert audit(page, rules) == [], scheme

    # (d) steps right, then the final answer: solved, but not clean
    assert check_step(page, el, "FP", fp.key) == STATE.correct
    assert check_step(page, el, "FPF", fpf.key) == STATE.correct
    assert step(el, "FPF").get_attribute(ATTR.carried) is None
    assert check_final(page, el, EX.answer.cleaned) == STATE.correct
    saved = record(page)
    assert saved["done"] == [0] and saved["steppedDone"] == [0] and saved["solved"] is True
    assert "clean" not in saved and saved["missed"] == [0]
    expect(page.locator(".wb-chapter-progress")).to_contain_text("1 of")  # solved counts it

    # new numbers empty every step and forget the steps on screen
    el.locator(role("new-variant")).click()
    page.wait_for_function("el => el.dataset.variant !== '0'", arg=el.element_handle())
    for name in ("FP", "FPF"):
        assert step(el, name).get_attribute(ATTR.state) == STATE.unanswered
        assert step(el, name).locator(role("entry")).evaluate_all("els => els.every(e => e.value === '')")
        expect(step(el, name).locator(role("work-step-feedback"))).to_be_empty()
    assert record(page)["stepWork"] is None


def test_schema_3_is_migrated_and_steps_travel_through_export_and_import(page, site_url):
    """A schema-3 store reads as schema 4 with nothing lost; an export's steps import and merge
    (the newer steps on screen win, variant lists join); a malformed steps record is refused."""
    import json

    from test_progress import import_file, open_progress_page

    page.goto(site_url)
    key = page.evaluate("workbook.progress.key")
    v3 = {"version": 3, "exercises": {"3.8": {"carried": [0], "missed": [0], "attempts": 1, "updated": 1_700_000_000_000}}}
    page.evaluate("([k, v]) => localStorage.setItem(k, v)", [key, json.dumps(v3)])
    open_progress_page(page, site_url)
    assert page.evaluate("workbook.progress.data.version") == 5
    assert record(page) == v3["exercises"]["3.8"]

    work = {"variant": 7, "steps": {"FP": {"answer": [["1", "2", "3"], ["4", "5", "6"], ["7", "8", "9"]],
                                           "status": "incorrect", "tag": "slip", "message": "That is P F."},
                                    "FPF": {"answer": [["0"] * 3] * 3, "status": "incorrect", "tag": "carried",
                                            "message": "It follows.", "carried": {"step": "FP", "link": "Back to step 1"}}}}
    v4 = {"format": "robotics-math-workbook-progress", "version": 4, "exported": "2025-01-01T00:00:00Z",
          "exercises": {"3.8": {"stepped": [7], "carried": [7], "steppedDone": [3], "done": [3], "variant": 7,
                                "stepWork": work, "updated": 1_700_000_000_001}}}
    assert "1 combined" in import_file(page, json.dumps(v4))
    got = record(page)
    assert got["stepped"] == [7] and got["carried"] == [0, 7] and got["steppedDone"] == [3] and got["missed"] == [0]
    assert got["stepWork"] == work  # the newer copy's steps on screen
    exported = page.evaluate("workbook.progress.exportData()")
    assert exported["version"] == 5 and exported["exercises"]["3.8"]["stepWork"] == work

    before = page.evaluate("workbook.progress.all()")
    bad_steps = {
        "a forbidden step name": {"variant": 0, "steps": {"__proto__": {"answer": "1"}}},
        "an unknown status": {"variant": 0, "steps": {"FP": {"answer": "1", "status": "great"}}},
        "an unknown key": {"variant": 0, "steps": {"FP": {"answer": "1", "score": 3}}},
        "a bad variant": {"variant": -1, "steps": {}},
        "a huge message": {"variant": 0, "steps": {"FP": {"answer": "1", "message": "x" * 5000}}},
    }
    for name, bad in bad_steps.items():
        text = import_file(page, json.dumps({**v4, "exercises": {"3.8": {"stepWork": bad}}}))
        assert text.startswith("Import refused") and "stepWork" in text, (name, text)
        assert page.evaluate("workbook.progress.all()") == before, name
