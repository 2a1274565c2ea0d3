"""The Derive answer reader: forms learners type, invalid input, and safety limits."""

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from workbook.answers import MAX_LENGTH, InvalidAnswer, parse_answer

ACCEPTED = {
    "3": 3.0, "-0.5": -0.5, "−1/2": -0.5, "sqrt(2)/2": math.sqrt(2) / 2, "√2/2": math.sqrt(2) / 2,
    "√(2)/2": math.sqrt(2) / 2, "1/sqrt(2)": 1 / math.sqrt(2), "pi/4": math.pi / 4, "π/4": math.pi / 4,
    "cos(pi/6)": math.cos(math.pi / 6), "1e-3": 1e-3, "2^3": 8.0, "2**3": 8.0, "2√2": 2 * math.sqrt(2),
    "2pi": 2 * math.pi, "atan2(4, 3)": math.atan2(4, 3), "ln(e)": 1.0, "abs(-2)": 2.0, "3/4 ": 0.75,
    "cos(60°)": 0.5, "½": 0.5, "3 × 2": 6.0, "1.5e2": 150.0, "(1)(2)": 2.0, "0.7071": 0.7071,
}


@pytest.mark.parametrize("text,value", ACCEPTED.items())
def test_accepted_forms(text, value):
    answer = parse_answer(text)
    assert math.isclose(answer.value, value, rel_tol=1e-12, abs_tol=1e-12)
    assert answer.unit is None


@pytest.mark.parametrize("text,value,unit", [
    ("53.13°", 53.13, "deg"), ("53.13 deg", 53.13, "deg"), ("90 degrees", 90.0, "deg"),
    ("0.9273 rad", 0.9273, "rad"), ("pi/2 rad", math.pi / 2, "rad"), ("45º", 45.0, "deg"),
])
def test_units(text, value, unit):
    answer = parse_answer(text)
    assert math.isclose(answer.value, value) and answer.unit == unit


@pytest.mark.parametrize("text,fragment", [
    ("", "Type an answer"), ("   ", "Type an answer"), ("2,5", "dot for decimals"), ("3 4", "One number"),
    ("x", "Unknown name"), ("foo(2)", "Unknown function"), ("[1, 2]", "not a list or a vector"),
    ("(1, 2)", "not a list or a vector"), ("1/0", "divides by zero"), ("sqrt(-1)", "not defined"),
    ("9**9**9", "exponent"), ("2**10000", "exponent"), ("1e400", "finite"), ("sqrt", "needs an argument"),
    ("atan2(1)", "takes 2 arguments"), ("__import__('os')", "Unknown function"), ("'3'", "Only numbers"),
    ("True", "Only numbers"), ("°", "before the unit"), ("a.b", "not a number"), ("lambda: 1", "not a number"),
    ("(" * 40 + "1" + ")" * 40, "nested too deeply"), ("1" * (MAX_LENGTH + 1), "too long"),
    ("+".join(["1"] * 90), "too long"),
])
def test_invalid_input_says_what_is_expected(text, fragment):
    with pytest.raises(InvalidAnswer) as err:
        parse_answer(text)
    assert fragment.lower() in str(err.value).lower()


def test_non_text_is_invalid():
    for value in (None, 3, ["1"], {"a": 1}):
        with pytest.raises(InvalidAnswer):
            parse_answer(value)


ALPHABET = st.sampled_from(list("0123456789.+-*/^()eπ√°, xyzabcdfrsintqlo_[]{}'\"\\\n\t−×÷²") + ["pi", "sqrt(", "**", "rad", "deg"])


@settings(max_examples=600, deadline=None)
@given(st.lists(ALPHABET, max_size=400).map("".join))
def test_any_math_like_text_gives_a_value_or_a_message(text):
    try:
        answer = parse_answer(text)
    except InvalidAnswer as err:
        assert str(err)
    else:
        assert math.isfinite(answer.value)


@settings(max_examples=300, deadline=None)
@given(st.text(max_size=10_000))
def test_any_string_up_to_10000_characters_never_raises_anything_else(text):
    try:
        parse_answer(text)
    except InvalidAnswer:
        pass


def test_limits_are_checked_before_parsing():
    # A huge expression is refused on length alone, long before ast.parse sees it.
    with pytest.raises(InvalidAnswer, match="too long"):
        parse_answer("(" * 5000 + "1" + ")" * 5000)
    with pytest.raises(InvalidAnswer, match="too long"):
        parse_answer("9" * 10_000)
