"""Vector, matrix and formula answers in the page: keyboard, paste, marked entries,
the typeset reading of a formula, and the worked answer at the end of a derivation.

Expected values come from the grading package (the bank and its keys), never
from numbers typed here. The tests share the module's one tab (``tour``) except the one that
reloads and resets progress: each sets the answer it checks (3.8's key is carried from 3.7,
which the test before it leaves right).
"""

from __future__ import annotations

import json

from playwright.sync_api import expect

from helpers import (
    check,
    entry,
    entry_values,
    exercise,
    fill_matrix,
    focused_entry,
    formula_reading,
    marked_entries,
    open_chapter,
    paste,
    reveal,
    role,
)
from workbook import bank
from workbook.contract import ATTR, ROLE, STATE, TAG
from workbook.number_format import fmt


def grid_text(rows) -> list[list[str]]:
    return [[fmt(v) for v in row] for row in rows]


def wrong_entries(ex, rows) -> set[tuple[int, int]]:
    """The entries the grader marks wrong when ``rows`` is typed (its own judgement, not re-derived here)."""
    return {tuple(p) for p in ex.check(grid_text(rows)).data.get("wrong", [])}


def test_a_matrix_is_filled_by_keyboard_and_graded_correct(tour):
    ex = bank.get("0.7")  # R(30°)·R(60°), 2×2
    key = grid_text(ex.answer.cleaned)
    page = tour(0)
    el = exercise(page, ex.id)
    assert el.get_attribute(ATTR.answerShape) == "2x2"
    entry(el, 1, 1).click()
    page.keyboard.type(key[0][0])
    page.keyboard.press("Tab")
    assert focused_entry(page) == (1, 2)
    page.keyboard.type(key[0][1])
    page.keyboard.press("ArrowDown")
    assert focused_entry(page) == (2, 2)
    page.keyboard.type(key[1][1])
    page.keyboard.press("ArrowLeft")  # the caret is after the text: it moves inside the entry first
    assert focused_entry(page) == (2, 2)
    page.keyboard.press("Home")
    page.keyboard.press("ArrowLeft")
    assert focused_entry(page) == (2, 1)
    page.keyboard.type(key[1][0])
    page.keyboard.press("ArrowUp")
    assert focused_entry(page) == (1, 1)
    assert entry_values(el) == key
    assert check(el) == STATE.correct
    assert marked_entries(el) == set()


def test_a_wrong_matrix_marks_exactly_the_wrong_entries_and_names_the_slip(tour):
    ex = bank.get("3.7")  # F facing north, 3×3; its transpose differs in two entries
    transposed = [list(col) for col in zip(*ex.answer.cleaned)]
    expected = wrong_entries(ex, transposed)
    assert len(expected) == 2
    page = tour(3)
    el = exercise(page, ex.id)
    el.scroll_into_view_if_needed()
    fill_matrix(el, grid_text(transposed))
    assert check(el) == STATE.incorrect
    assert marked_entries(el) == expected
    assert el.get_attribute(ATTR.tag) == TAG.transpose

    slip = ex.answer.slips[1]  # dt left out: one entry differs
    fill_matrix(el, grid_text(slip.value))
    assert check(el) == STATE.incorrect
    assert marked_entries(el) == wrong_entries(ex, slip.value)
    assert el.get_attribute(ATTR.tag) == TAG.slip
    assert slip.message in el.locator(role("feedback")).inner_text()

    fill_matrix(el, grid_text(ex.answer.cleaned))
    assert check(el) == STATE.correct
    assert marked_entries(el) == set()  # the marks go once the entries are right


def test_an_empty_entry_is_marked_and_costs_no_attempt(tour):
    ex = bank.get("0.7")
    page = tour(0)
    el = exercise(page, ex.id)
    rows = grid_text(ex.answer.cleaned)
    rows[1][0] = ""
    fill_matrix(el, rows)
    assert check(el) == STATE.invalid
    assert marked_entries(el) == {(2, 1)}


def test_a_pasted_matrix_fills_the_grid(tour):
    ex = bank.get("3.8")  # P⁻, 3×3
    key = grid_text(ex.answer.cleaned)
    page = tour(3)
    el = exercise(page, ex.id)
    el.scroll_into_view_if_needed()
    empty = [[""] * 3 for _ in range(3)]

    paste(entry(el, 2, 3), "[" + ", ".join("[" + ", ".join(row) + "]" for row in key) + "]")
    page.wait_for_function("el => el.value !== ''", arg=entry(el, 3, 3).element_handle())
    assert entry_values(el) == key
    assert check(el) == STATE.correct

    fill_matrix(el, empty)
    paste(entry(el, 1, 1), "; ".join(" ".join(row) for row in key))
    page.wait_for_function("el => el.value !== ''", arg=entry(el, 3, 3).element_handle())
    assert entry_values(el) == key
    assert check(el) == STATE.correct


def test_a_pasted_vector_of_the_wrong_size_is_refused_with_a_message(tour):
    ex = bank.get("9.8")  # a 3×1 column
    page = tour(9)
    el = exercise(page, ex.id)
    el.scroll_into_view_if_needed()
    paste(entry(el, 1, 1), "1 2; 3 4")
    feedback = el.locator(role("feedback"))
    feedback.filter(has_text="3×1").wait_for()
    assert entry_values(el) == [[""], [""], [""]]


def test_a_formula_is_read_back_typeset_and_an_equivalent_form_is_right(tour):
    ex = bank.get("6.6")  # x(θ1, θ2)
    page = tour(6)
    el = exercise(page, ex.id)
    el.scroll_into_view_if_needed()
    assert el.get_attribute(ATTR.answerKind) == "expression"
    assert el.get_attribute(ATTR.variables) == ",".join(ex.answer.variables)
    label = el.locator(f'label[for="{el.locator(role("answer")).get_attribute("id")}"]')
    expect(label.locator(".katex")).to_have_count(len(ex.answer.variables))  # each variable typeset, none in error
    assert el.locator(".katex-error").count() == 0
    answer = el.locator(role("answer"))
    answer.click()
    page.keyboard.type("L₁ cos θ₁ + L2*(cos(θ1)*cos(θ2) - sin(θ1)*sin(θ2))")
    reading = formula_reading(el)
    reading.locator(".katex").wait_for()  # KaTeX's own markup, while typing, before any check
    assert "Read as" in reading.inner_text()
    assert el.get_attribute(ATTR.state) == STATE.unanswered
    assert check(el) == STATE.correct

    answer.fill("L1*cos(theta1) + L2*cos(theta2)")
    assert check(el) == STATE.incorrect
    assert el.get_attribute(ATTR.tag) == TAG.slip
    answer.fill("L1*cos(theta1) + L3")
    assert check(el) == STATE.invalid
    assert "theta1" in el.locator(role("feedback")).inner_text()


def test_a_derivation_ends_with_the_answer_as_typed(tour):
    page = tour(7)
    shaped = bank.get("7.6")
    el = exercise(page, shaped.id)
    el.scroll_into_view_if_needed()
    panel = reveal(el)
    last = panel.locator(":scope > *").last
    assert last.get_attribute(ATTR.role) == ROLE.worked_answer
    cells = last.locator(role("worked-entry")).evaluate_all(
        "(els, a) => els.map(e => [Number(e.getAttribute(a.row)), Number(e.getAttribute(a.col)), e.textContent])",
        {"row": ATTR.row, "col": ATTR.col})
    key = grid_text(shaped.answer.cleaned)
    assert cells == [[i, j, key[i - 1][j - 1]] for i in (1, 2) for j in (1, 2)]

    formula = bank.get("7.7")
    el = exercise(page, formula.id)
    el.scroll_into_view_if_needed()
    panel = reveal(el)
    last = panel.locator(":scope > *").last
    worked = last.locator(role("worked-answer"))
    assert worked.inner_text() == formula.answer.answer_text
    el.locator(role("answer")).fill(worked.inner_text())
    assert check(el) == STATE.correct


def test_a_matrix_answer_comes_back_after_a_reload_and_through_a_progress_file(page, site_url):
    ex = bank.get("0.7")
    key = grid_text(ex.answer.cleaned)
    open_chapter(page, site_url, 0)
    el = exercise(page, ex.id)
    fill_matrix(el, key)
    assert check(el) == STATE.correct
    page.reload()
    el = exercise(page, ex.id)
    assert el.get_attribute(ATTR.state) == STATE.correct
    expect(entry(el, 2, 1)).to_have_value(key[1][0])  # put back once the grid's module has loaded
    assert entry_values(el) == key

    # A progress file holding the grid is accepted on import (a fresh browser, no progress yet).
    page.evaluate("() => window.workbook.progress.reset()")
    page.goto(site_url + "progress/")
    record = {"format": "robotics-math-workbook-progress", "version": 1,
              "exercises": {ex.id: {"solved": True, "attempts": 1, "last": key, "updated": 1}}}
    message = page.locator("[data-wb-progress-message]")
    with page.expect_file_chooser() as chooser:
        page.get_by_role("button", name="Import progress…").click()
    chooser.value.set_files({"name": "progress.json", "mimeType": "application/json",
                             "buffer": json.dumps(record).encode()})
    expect(message).to_contain_text("1 added")
    open_chapter(page, site_url, 0)
    el = exercise(page, ex.id)
    assert el.get_attribute(ATTR.state) == STATE.correct
    expect(entry(el, 2, 1)).to_have_value(key[1][0])


def test_a_whole_matrix_typed_into_one_entry_is_read_as_a_paste(tour):
    """Issue 28: typing (not pasting) [[0, -1], [1, 0]] into one entry was refused, while the label invites pasting."""
    ex = bank.get("0.7")  # 2×2
    key = grid_text(ex.answer.cleaned)
    whole = "[" + ", ".join("[" + ", ".join(row) + "]" for row in key) + "]"
    page = tour(0)
    el = exercise(page, ex.id)
    el.scroll_into_view_if_needed()
    fill_matrix(el, [[""] * 2 for _ in range(2)])  # an empty grid (the tab's earlier tests answered 0.7)

    entry(el, 1, 1).click()
    page.keyboard.type(whole)
    page.keyboard.press("Tab")  # leaving the entry splits it over the grid
    page.wait_for_function("el => el.value !== ''", arg=entry(el, 2, 2).element_handle())
    assert entry_values(el) == key
    assert check(el) == STATE.correct

    fill_matrix(el, [[""] * 2 for _ in range(2)])
    transposed = [list(col) for col in zip(*key)]
    entry(el, 1, 2).click()
    page.keyboard.type("; ".join(" ".join(row) for row in transposed))
    page.keyboard.press("Enter")  # Check straight away: graded as the whole matrix, the marks where they belong
    page.wait_for_function("el => el.value !== ''", arg=entry(el, 2, 2).element_handle())
    el.locator(role("feedback")).filter(has_text="transpose").wait_for()
    assert entry_values(el) == transposed
    assert marked_entries(el) == wrong_entries(ex, [[float(v) for v in row] for row in transposed])
