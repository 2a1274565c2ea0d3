"""How learners write answers, in the page: named components in any order, one expression
pasted into one box, and degrees typed inside sin or cos named in all three answer kinds.

Expected values come from the grading package (the bank and its keys).
"""

from __future__ import annotations

from helpers import answer_derive, check, entry, entry_values, exercise, fill_matrix, open_chapter, paste, role
from workbook import bank
from workbook.contract import ATTR, STATE, TAG
from workbook.number_format import fmt


def _named_vector():
    """A vector exercise whose components have names (a pose, or P, I and D)."""
    return next(ex for ex in bank.all_exercises()
                if ex.kind == "derive" and ex.answer_kind == "matrix" and ex.answer.names)


def test_a_vector_typed_with_names_in_another_order_is_right(page, site_url):
    ex = _named_vector()
    names = [n.split("|")[0] for n in ex.answer.names]
    values = [fmt(row[0]) for row in ex.answer.cleaned]
    open_chapter(page, site_url, int(ex.id.split(".")[0]))
    el = exercise(page, ex.id)
    el.scroll_into_view_if_needed()
    reversed_by_name = ", ".join(f"{n} = {v}" for n, v in reversed(list(zip(names, values))))
    paste(entry(el, 1, 1), reversed_by_name)
    page.wait_for_function("el => el.value !== ''", arg=entry(el, len(names), 1).element_handle())
    assert entry_values(el) == [[v] for v in values]  # placed by name, not by position
    assert check(el) == STATE.correct

    swapped = [[f"{n} = {v}"] for n, v in zip([names[1], names[0], *names[2:]], values)]
    fill_matrix(el, swapped)
    assert check(el) == STATE.incorrect  # wrong values under the wrong names are never accepted


def test_one_expression_pasted_into_one_box_stays_in_that_box(page, site_url):
    ex = bank.get("0.7")
    open_chapter(page, site_url, 0)
    el = exercise(page, ex.id)
    el.scroll_into_view_if_needed()
    a, b = ex.params["a"], ex.params["b"]
    expression = f"cos({a}°) * cos({b}°) - sin({a}°) * sin({b}°)"
    paste(entry(el, 1, 1), expression)
    page.wait_for_function("el => el.value !== ''", arg=entry(el, 1, 1).element_handle())
    assert entry_values(el) == [[expression, ""], ["", ""]]
    assert el.locator(role("feedback")).inner_text() == ""


def test_degrees_inside_sin_and_cos_are_named_in_every_answer_kind(page, site_url):
    open_chapter(page, site_url, 0)
    number = exercise(page, "0.2")  # the (1,1) entry of R(α)R(β): cos(α + β)
    total = bank.get("0.2").params["a"] + bank.get("0.2").params["b"]
    assert answer_derive(number, f"cos({total})") == STATE.incorrect
    assert number.get_attribute(ATTR.tag) == TAG.degrees

    matrix = exercise(page, "0.7")
    total = bank.get("0.7").params["a"] + bank.get("0.7").params["b"]
    fill_matrix(matrix, [[f"cos({total})", f"-sin({total}°)"], [f"sin({total}°)", f"cos({total}°)"]])
    assert check(matrix) == STATE.incorrect
    assert matrix.get_attribute(ATTR.tag) == TAG.degrees
    assert "(1,1)" in matrix.locator(role("feedback")).inner_text()

    open_chapter(page, site_url, 6)
    formula = exercise(page, "6.6")
    text = bank.get("6.6").answer.answer_text
    in_degrees = text.replace("theta1 + theta2", "theta1 + theta2 + 360").replace("cos(theta1)", "cos(theta1 + 360)")
    assert answer_derive(formula, in_degrees) == STATE.incorrect
    assert formula.get_attribute(ATTR.tag) == TAG.degrees
