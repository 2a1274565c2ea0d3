"""The number answer kind: precision-aware tolerance, the notations learners type, degrees in sin and cos."""

import math
import re
from decimal import ROUND_HALF_EVEN, ROUND_HALF_UP, Decimal

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import many_draws
from workbook import bank
from workbook.answer_kinds.base import Slip
from workbook.answer_kinds.number import number
from workbook.number_format import fmt
from workbook.tolerance import clean


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
    assert "you gave 2 significant figures" in two.message
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


# ---------------------------------------------------------------- "too coarse" only when it is a rounding

def test_one_for_cos_45_is_not_close_but_0_7_and_0_71_are():
    """3.2's answer is 0.7071: 1 (cos 0 for cos 45°) is no rounding of it to 1 figure, so it is plainly wrong;
    0.7 and 0.71 are, and the message counts their significant figures. 10.3's (½, ½, ½, ½) against 1s too."""
    v = bank.get("3.2")
    assert "Close" not in v.check("1").message and v.check("1").tag != "close"
    assert v.check("0.7").message.startswith("Close, but give at least 3 significant figures: you gave 1 "
                                             "significant figure.")
    assert "you gave 2 significant figures." in v.check("0.71").message
    assert v.check("0.72").tag == "close" and "you gave" not in v.check("0.72").message  # 0.71 at 2 figures
    quaternion = bank.get("10.3")
    said = quaternion.check("1, 1, 1, 1")
    assert not said.data.get("close") and "close" not in said.message and "significant" not in said.message


def _rounded(x: float, figures: int) -> str:
    """``x`` rounded to ``figures`` significant figures, written with exactly that many (-0.98 to 1 is -1)."""
    r = float(f"{x:.{figures - 1}e}")
    return f"{r:.{max(0, figures - 1 - math.floor(math.log10(abs(r))))}f}"


def _is_rounding(x: float, text: str) -> bool:
    """``text`` is ``x`` rounded to the significant figures ``text`` has (half up, or half to even)."""
    n, value = _figures(text), float(text)
    if n == 0:
        return False
    step = Decimal(1).scaleb(Decimal(repr(x)).adjusted() - (n - 1))
    return any(math.isclose(value, float(Decimal(repr(x)).quantize(step, rounding=way)), rel_tol=1e-9)
               for way in (ROUND_HALF_UP, ROUND_HALF_EVEN))


def _figures(text: str) -> int:
    whole, _, fraction = text.lstrip("-").partition(".")
    digits = (whole + fraction).lstrip("0")
    return len(digits if fraction else digits.rstrip("0"))


SCALAR_AND_VECTOR = [ex for ex in bank.all_exercises() if ex.kind == "derive" and ex.answer.kind in ("number", "matrix")]


@pytest.mark.parametrize("ex", SCALAR_AND_VECTOR, ids=[ex.id for ex in SCALAR_AND_VECTOR])
def test_too_few_figures_is_said_only_of_the_key_rounded_to_them(ex):
    """Over 200 draws of every number and matrix exercise: "give at least 3 significant figures: you gave n" is
    said only of an answer that is the key rounded to its own n figures; 1 and 2 for every entry are tried too."""
    for seed in range(many_draws.count(200)):
        v = ex.variant(seed)
        key = [[v.answer.key]] if v.answer.kind == "number" else [list(row) for row in v.answer.key]
        flat = [clean(x) for row in key for x in row]
        for figures in (1, 2, None):
            typed = [("1" if figures is None else _rounded(x, figures)) if x else "0" for x in flat]
            cols = len(key[0])
            text = typed[0] if v.answer.kind == "number" else \
                "; ".join(", ".join(typed[i * cols:(i + 1) * cols]) for i in range(len(key)))
            said = v.check(text)
            if v.answer.kind == "number":
                told = re.search(r"you gave (\d+) significant figure", said.message)
                if told:
                    assert int(told[1]) == _figures(text) < 3 and _is_rounding(flat[0], text), (seed, text, said.message)
            elif "type at least 3 significant figures" in said.message:
                few = said.data["close"]
                assert few and all(_is_rounding(flat[(i - 1) * cols + j - 1], typed[(i - 1) * cols + j - 1])
                                   for i, j in few), (seed, text, said.message)
            if figures is None:
                continue
            # the key rounded to 1 or 2 figures, where every entry is such a rounding: told so, never "not quite"
            if said.status == "incorrect" and said.tag == "close" and v.answer.kind == "number" and \
                    _is_rounding(flat[0], text):  # (a binary tie such as 3.15 may print as 3.1: no rounding)
                assert "you gave" in said.message or _figures(text) >= 3, (seed, text, said.message)


@pytest.mark.parametrize("typed,status", [
    ("7 500", "correct"), ("7\u2009500", "correct"), ("7\u202f500", "correct"), ("7 500.0", "correct"),
    ("7 500 ", "correct"), ("7 50", "invalid"), ("7 5000", "invalid"), ("75 00", "invalid"), ("0 500", "invalid"),
])
def test_iso_digit_groups_are_one_number(typed, status):
    """ISO 80000-1 groups digits in threes with a (thin) space: 7 500 is 7500. Other spacing stays "two numbers"."""
    said = answer(7500.0).check(typed)
    assert said.status == status, (typed, said.message)
    if status == "invalid":
        assert "two numbers" in said.message
    assert answer(12345678.0).check("12 345 678").status == "correct"
