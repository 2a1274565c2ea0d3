"""The number answer kind: precision-aware tolerance, the notations learners type, degrees in sin and cos."""

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from workbook import bank
from workbook.answer_kinds.base import Slip
from workbook.answer_kinds.number import number
from workbook.number_format import fmt


def answer(key, **options):
    return number(label="x", **options).build("t.1", key=key)


# ---------------------------------------------------------------- three significant figures

@pytest.mark.parametrize("typed,status", [
    ("0.1234", "correct"), ("0.123", "correct"), ("0.12340", "correct"),  # within half a unit of the last digit
    ("0.122", "incorrect"), ("0.124", "incorrect"),  # further than half a unit of a 3-figure answer
    ("0.1238", "incorrect"),  # 4 figures: must be the 4-figure rounding (or within 1e-3 relative)
])
def test_a_value_typed_to_three_figures_may_use_its_own_rounding(typed, status):
    assert answer(0.12341).check(typed).status == status


def test_close_says_how_many_figures_are_wanted():
    two = answer(0.12341).check("0.12")
    assert (two.status, two.tag) == ("incorrect", "close") and "3 significant figures" in two.message
    assert "you typed 2" in two.message
    far = answer(0.12341).check("0.1238")
    assert far.tag == "close" and "at least 3 significant figures" in far.message


def test_integers_stay_exact_and_zero_keys_keep_their_floor():
    assert answer(7500).check("7500").status == "correct"
    assert answer(7500).check("7499").status == "incorrect"
    assert answer(7500).check("7.50e3").status == "correct"
    assert answer(0.0).check("0.000").status == "correct"


def test_the_half_unit_follows_the_unit_typed():
    metres = answer(0.12341, unit="m")
    assert metres.check("12.3 cm").status == "correct"
    assert metres.check("12.2 cm").status == "incorrect"


@settings(max_examples=300, deadline=None)
@given(st.floats(min_value=-1e4, max_value=1e4, allow_nan=False).filter(lambda x: abs(x) > 1e-6))
def test_any_printed_number_is_accepted_at_every_rounding_to_three_figures_or_more(x):
    ans = answer(x)
    assert ans.check(fmt(x)).status == "correct", fmt(x)
    for figures in (3, 4, 5, 6):
        assert ans.check(f"{x:#.{figures}g}").status == "correct", f"{x:#.{figures}g}"


# ---------------------------------------------------------------- what learners type

@pytest.mark.parametrize("typed", [
    r"\frac{\sqrt{3}}{2}", r"\dfrac{\sqrt3}{2}", r"\cos(\pi/6)", r"\cos 30^\circ", r"\sin\left(\frac{\pi}{3}\right)",
    r"$\frac{\sqrt{3}}{2}$", r"\tfrac12\sqrt{3}", r"\sqrt{3} \cdot 0.5", r"\sqrt{3}\times\frac{1}{2}",
    "√3/2", "0.866", "０.８６６", "cos(30°)", "cos 30º", "x′ = 0.866", "x' = √3 / 2", r"x' \approx 0.866",  # noqa: RUF001 (meant)
])
def test_the_notations_a_learner_types_or_copies_from_the_page(typed):
    assert answer(math.sqrt(3) / 2).check(typed).status == "correct", typed


@pytest.mark.parametrize("typed", [
    "−0.5", "‐0.5", "–0.5", "－0.5",  # noqa: RUF001 (the dashes a learner may paste, meant)
    "-1/2", "−1 ÷ 2", "-2 × 0.25", "-2 · 0.25", "-2∙0.25"])
def test_the_minus_and_times_families(typed):
    assert answer(-0.5).check(typed).status == "correct", typed


@pytest.mark.parametrize("typed,fragment", [
    (r"\infty", "does not read the LaTeX command"), ("\\", "ends the answer"), (r"\frac{1}{2", "braces do not match"),
    ("5.866 s", "a length in metres"),
])
def test_what_cannot_be_read_is_said_plainly(typed, fragment):
    verdict = answer(5.866, unit="m").check(typed)
    assert verdict.status == "invalid" and fragment in verdict.message, verdict


# ---------------------------------------------------------------- degrees typed inside sin, cos and tan

def test_cos_of_a_bare_number_in_degrees_is_named():
    key = math.cos(math.radians(60))
    verdict = answer(key).check("cos(60)")
    assert (verdict.status, verdict.tag) == ("incorrect", "degrees"), verdict
    assert "cos(90°)" in verdict.message and "radians" in verdict.message
    assert answer(key).check("cos(60°)").status == "correct"
    assert answer(key).check("cos(pi/3)").status == "correct"


def test_degrees_inside_a_longer_expression():
    key = 2 * math.sin(math.radians(30)) + 1
    assert answer(key).check("2*sin(30) + 1").tag == "degrees"
    assert answer(key).check("2 sin(15 + 15) + 1").tag == "degrees"


def test_the_workbook_s_degree_exercises_name_it():
    ex = bank.get("0.2")  # (1,1) of R(30°)R(60°) = cos 90°
    assert ex.check("cos(30+60)").tag in ("degrees", "slip")
    ex4 = bank.get("0.4").variant(next(n for n in range(1, 99) if bank.get("0.4").variant(n).params["axis"] == "y"))
    a = ex4.params["a"]
    assert ex4.check(f"{a}*cos(45) + {a}*sin(45)").tag == "degrees"


def test_a_slip_typed_to_three_figures_is_still_named():
    ans = answer(3.0, slips=(Slip(-1.23456, "That turns the other way."),))
    assert ans.check("-1.23").message == "That turns the other way."


# ---------------------------------------------------------------- "close" only for a real rounding

@settings(max_examples=300, deadline=None)
@given(st.floats(min_value=-50, max_value=50, allow_nan=False).filter(lambda k: abs(k) > 1e-3),
       st.integers(min_value=1, max_value=2))
def test_close_by_rounding_only_when_the_value_typed_is_a_rounding_of_the_key(key, figures):
    """A rounding of the key to 1 or 2 significant figures is "close"; 0, the other sign, or the rounding
    at the wrong digit never are (unless within the 2 % band, which they are not here)."""
    from workbook.answer_kinds.matrix import matrix
    ans, grid = answer(key), matrix(label="M").build("t.2", key=((key, 1.0),))
    rounded = float(f"{key:.{figures - 1}e}")
    if abs(rounded - key) > 0.02 * abs(key):  # the rounding itself is outside the 2 % band
        text = f"{rounded:.{figures - 1}e}"
        assert ans.check(text).tag == "close", (key, text)
        assert grid.check([[text, "1"]]).data.get("close") == [[1, 1]], (key, text)
    digit = 10.0 ** (math.floor(math.log10(abs(key))) - figures + 1)
    for wrong in ("0", "0.0", "-0", f"{-rounded:.{figures - 1}e}", repr(rounded + 3 * digit)):
        if abs(float(wrong) - key) <= 0.02 * abs(key):
            continue
        said = ans.check(wrong)
        assert said.tag != "close" and "Close" not in said.message, (key, wrong, said.message)
        assert not grid.check([[wrong, "1"]]).data.get("close"), (key, wrong)


def test_zero_typed_for_a_key_of_minus_a_tenth_is_plain_wrong():
    """3.8 variant 0: 0 for −0.1 was "close: round correctly to 3 significant figures"."""
    v = bank.get("3.8").variant(0)
    typed = [["0" if abs(x + 0.1) < 1e-12 else fmt(x, significant=7) for x in row] for row in v.answer.key]
    said = v.check(typed)
    assert said.status == "incorrect" and said.tag != "close" and "close" not in said.message, said.message
    assert said.data["wrong"] == [[1, 3], [3, 1]] and not said.data.get("close")
