"""Checkers: tolerance, the named slips, and the per-kind feedback."""

import math

import pytest

from workbook import bank
from workbook.answer_kinds.number import number
from workbook.kinds.derive import Derive


def check(ex, answer):
    return ex.check(answer)


def grade(ex_id, answer):
    return check(bank.get(ex_id), answer)


def test_policy_tolerance():
    bank.get("0.4")  # key 0 -> absolute tolerance 1e-3
    assert grade("0.4", "0.0009").status == "correct"
    assert grade("0.4", "0.0011").status == "incorrect"
    big = Derive(id="x.1", title="", spec=number(key=7500.0))
    assert check(big, "7507").status == "correct"  # 1e-3 relative
    assert check(big, "7508").tag == "close"


def test_close_but_not_within_tolerance():
    result = grade("4.2", "53.5°")
    assert (result.status, result.tag) == ("incorrect", "close")


def test_radians_for_degrees_and_explicit_units():
    assert grade("4.2", "0.9273").tag == "radians"
    assert grade("4.2", "0.9273 rad").status == "correct"
    assert grade("4.2", "atan2(4,3) rad").status == "correct"
    assert grade("4.2", "53.13").status == "correct"
    assert grade("4.2", "53.13°").status == "correct"
    assert grade("6.3", "pi/2").tag == "radians"


def test_sign_error_is_named():
    result = grade("3.3", "0.5")
    assert (result.status, result.tag) == ("incorrect", "sign")
    # where the sign comes from one known place, the exercise names it: 4.3's chain rule
    result = grade("4.3", "0.6")
    assert (result.status, result.tag) == ("incorrect", "slip") and "∂dx/∂x = −1" in result.message


def test_unit_on_a_non_angle_is_invalid():
    assert grade("0.1", "3°").status == "invalid"


@pytest.mark.parametrize("ex_id,answer", [
    ("3.4", "1.11"), ("4.4", "0.2"), ("5.3", "0.01"), ("9.5", str(0.7143 * 0.5)),
])
def test_known_slips_have_their_own_message(ex_id, answer):
    result = grade(ex_id, answer)
    assert (result.status, result.tag) == ("incorrect", "slip")
    assert result.message and "Not quite" not in result.message


def test_every_derive_with_a_classic_mistake_names_one():
    without = [e.id for e in bank.all_exercises() if e.kind == "derive" and not e.answer.slips]
    # 5.1 (a count) and 6.1 (a straight arm) are the only ones left without a named slip, if any.
    assert len(without) <= 4, without


def test_invalid_costs_nothing_and_says_why():
    result = grade("0.1", "2,5")
    assert result.status == "invalid" and "2.5" in result.message


def test_trace_feedback_explains_the_pick():
    ex = bank.get("0.3")
    wrong = next(o for o in ex.options if o.key != ex.answer)
    result = check(ex, wrong.key)
    assert (result.status, result.message) == ("incorrect", wrong.why)
    assert check(ex, "z").status == "invalid"
    assert check(ex, None).status == "invalid"


def test_debug_feedback():
    ex = bank.get("3.5")
    other = next(n for n in ex.notes)
    wrong = check(ex, other)
    assert wrong.status == "incorrect" and f"Line {other} is fine" in wrong.message
    assert check(ex, ex.bug_line).message == ex.bug
    assert check(ex, 99).status == "invalid"
    assert check(ex, "x").status == "invalid"


def test_design_feedback_counts_steps_in_place():
    ex = bank.get("9.1")
    order = list(ex.solution)
    order[1], order[2] = order[2], order[1]
    result = check(ex, order)
    assert result.status == "incorrect"
    assert result.data == {"in_place": 3, "first_wrong": 2}
    assert "3 of 5 steps are in place" in result.message
    assert check(ex, order[:-1]).status == "invalid"
    assert check(ex, order + order[:1]).status == "invalid"
    assert check(ex, "abc").status == "invalid"


def test_keys_come_from_reference_implementations():
    """Spot-check that keys are the reference functions' results, not typed numbers."""
    from workbook.reference.rotation2d import rotate_2d

    assert bank.get("0.4").answer.key == rotate_2d(1, 1, math.pi / 4)[0]
    assert math.isclose(bank.get("4.2").answer.key, math.degrees(math.atan2(4, 3)))
