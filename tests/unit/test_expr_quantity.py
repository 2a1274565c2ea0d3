"""The Derive answer reader: forms learners type, invalid input, and safety limits."""

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from workbook.expr import MAX_LENGTH, InvalidAnswer, parse_answer

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


# --------------------------------------------------------------------------- units in the evaluation

from workbook.expr import parse_quantity  # noqa: E402

DEG = math.pi / 180


@pytest.mark.parametrize("text", ["90°", "45°+45°", "180°/2", "(90°)", "θ2 = 90°", "theta_2=90°", "θ₂ = 90 deg",
                                  "pi/2 rad", "100° - 10°", "2*45°", "45° * 2", "90 degrees", "90º", "90˚", "90∘",
                                  "x = (45° + 45°)", "1.5707963267948966 rad"])
def test_a_ninety_degree_answer_in_every_spelling(text):
    answer = parse_answer(text)
    assert answer.dimension == "angle"
    assert math.isclose(answer.si, math.pi / 2, rel_tol=1e-12)
    assert math.isclose(parse_quantity(text, "deg"), 90.0, rel_tol=1e-12)


def test_an_inner_degree_sign_no_longer_turns_into_radians_inside_a_degree_answer():
    # It used to read as 45·π/180 + 45 = 45.785 (degrees).
    answer = parse_answer("45°+45°")
    assert answer.unit == "deg" and math.isclose(answer.value, 90.0)


@pytest.mark.parametrize("text,si,dimension", [
    ("1 m", 1.0, "length"), ("-0.2 m", -0.2, "length"), ("2.1263 m/s", 2.1263, "speed"), ("20 cm", 0.2, "length"),
    ("150 mm", 0.15, "length"), ("1.2 km", 1200.0, "length"), ("0.5 s", 0.5, "time"), ("250 ms", 0.25, "time"),
    ("2 min", 120.0, "time"), ("1 h", 3600.0, "time"), ("36 km/h", 10.0, "speed"), ("50 cm/s", 0.5, "speed"),
    ("10 m / 5 s", 2.0, "speed"), ("1/2 m", 0.5, "length"), ("(1 + 1) m", 2.0, "length"), ("x = 1 m", 1.0, "length"),
    ("1 m + 20 cm", 1.2, "length"), ("2 m / 1 m", 2.0, ""), ("cos 45°", math.sqrt(2) / 2, ""),
    ("cos(45°)", math.sqrt(2) / 2, ""), ("0.5", 0.5, None), ("sin(pi/6)", 0.5, None), ("2cm", 0.02, "length"),
])
def test_values_carry_their_dimension_and_si_value(text, si, dimension):
    answer = parse_answer(text)
    assert math.isclose(answer.si, si, rel_tol=1e-12)
    assert answer.dimension == dimension
    assert answer.unit is None  # only angles have an Answer.unit


@pytest.mark.parametrize("text,value", [
    ("cos 45°", math.sqrt(2) / 2), ("sin 30° + 1", 1.5), ("2 cos 60°", 1.0), ("-cos 60°", -0.5), ("cos -60°", 0.5),
    ("sin(pi/6)", 0.5), ("sin(0.5235987755982988)", 0.5), ("sin(30°)", 0.5), ("sin(π/6 rad)", 0.5),
    ("tan 45°", 1.0), ("sind(30)", 0.5), ("√3/2", math.sqrt(3) / 2), ("sin 60° * 2", math.sqrt(3)), ("sin²(30°) + cos²(30°)", 1.0), ("1 - 2sin²(30°)", 0.5),
])
def test_trig_of_angles_and_bare_numbers(text, value):
    assert math.isclose(parse_answer(text).value, value, rel_tol=1e-12)


@pytest.mark.parametrize("minus", ["-", "\u2010", "\u2011", "\u2012", "\u2013", "\u2212", "\ufe63", "\uff0d"])
def test_every_minus_sign(minus):
    assert parse_answer(f"{minus}0.5").value == -0.5
    assert math.isclose(parse_answer(f"{minus}30°").si, -30 * DEG)
    assert parse_answer(f"1 {minus} 0.25").value == 0.75


@pytest.mark.parametrize("sign", ["°", "\u00ba", "\u02da", "\u2218"])
def test_every_degree_like_sign(sign):
    answer = parse_answer(f"53.13{sign}")
    assert answer.unit == "deg" and math.isclose(answer.value, 53.13)


@pytest.mark.parametrize("text,fragment", [
    ("7,500", "write 7500"), ("7,500", "or 7.5"), ("1,250", "1.25"), ("1,000,000", "1000000"),
    ("2,5", "write 2.5, not 2,5"), ("0,25", "write 0.25"),
    ("45 + 45°", "every term its unit"), ("1 m + 20", "every term its unit"), ("2 m + 3 s", "a length and a time"),
    ("sin(2 m)", "needs an angle"), ("exp(2 s)", "plain number"), ("°", "before the unit"), ("m", "before the unit"),
    ("cos 2x", "Unknown name"), ("cos 2 pi^2", "parentheses"), ("cos pi/3", "cos(pi/3) or cos(pi)/3"), ("sin 30 45", "parentheses"), ("x = ", "after “=”"),
    ("a = b = 2", "Type just the value"), ("2 ^ (1 m)", "exponent cannot have a unit"), ("1 M", "Unknown name"),
])
def test_unit_and_comma_mistakes_say_what_to_do(text, fragment):
    with pytest.raises(InvalidAnswer) as err:
        parse_answer(text)
    assert fragment.lower() in str(err.value).lower()


@pytest.mark.parametrize("text,expect,value", [
    ("20 cm", "m", 0.2), ("1 m", "m", 1.0), ("0.2", "m", 0.2), ("2.1263 m/s", "m/s", 2.1263),
    ("7.2 km/h", "m/s", 2.0), ("250 ms", "s", 0.25), ("0.25", "s", 0.25), ("90°", "deg", 90.0),
    ("pi/2 rad", "deg", 90.0), ("90°", "rad", math.pi / 2), ("1.5708", "rad", 1.5708), ("53.13", "deg", 53.13),
    ("7500", None, 7500.0), ("cos 45°", None, math.sqrt(2) / 2), ("4 m / 2 m", None, 2.0),
])
def test_parse_quantity_returns_the_unit_the_exercise_asks_for(text, expect, value):
    assert math.isclose(parse_quantity(text, expect), value, rel_tol=1e-12)


@pytest.mark.parametrize("text,expect,message", [
    ("2 s", "m", "This answer is a length in metres; 2 s is a time."),
    ("1 m", "deg", "This answer is an angle in degrees; 1 m is a length."),
    ("90°", "m/s", "This answer is a speed in metres per second; 90° is an angle."),
    ("2 m", "m/s", "This answer is a speed in metres per second; 2 m is a length."),
    ("3 m", "s", "This answer is a time in seconds; 3 m is a length."),
    ("3 m", None, "This answer is a plain number, without a unit; 3 m is a length."),
])
def test_a_unit_of_the_wrong_kind_names_the_unit_expected(text, expect, message):
    with pytest.raises(InvalidAnswer) as err:
        parse_quantity(text, expect)
    assert str(err.value) == message


def test_parse_quantity_refuses_an_unknown_expectation():
    with pytest.raises(ValueError, match="expect must be one of"):
        parse_quantity("1", "furlong")


UNICODE_TEXT = st.text(alphabet=st.characters(blacklist_categories=("Cs",)), max_size=60)


@settings(max_examples=400, deadline=None)
@given(st.one_of(UNICODE_TEXT, st.lists(st.sampled_from(
    ["1", "2.5", "°", "º", "m", "cm", "s", "ms", "h", "km/h", "m/s", " ", "+", "-", "\u2212", "*", "/", "(", ")",
     "cos", "sin ", "θ", "=", "x", "rad", "deg", "^", "²", "√", ",", "₁", "π", "e"]), max_size=30).map("".join)))
def test_units_and_unicode_never_raise_anything_but_invalid_answer(text):
    for expect in (None, "deg", "m"):
        try:
            parse_quantity(text, expect)
        except InvalidAnswer as err:
            assert str(err)


MINUSES = st.sampled_from(["-", "\u2212", "\u2013", "\u2010", "\uff0d", "\ufe63"])
DEGREE_SIGNS = st.sampled_from(["°", " °", "º", "˚", "∘", " deg", " degrees", "deg"])


@settings(max_examples=300, deadline=None)
@given(st.floats(min_value=-720, max_value=720, allow_nan=False).map(lambda v: round(v, 4)), MINUSES, DEGREE_SIGNS,
       st.sampled_from(["{}", "({})", "θ2 = {}", "theta_1={}", "x = {}"]))
def test_an_angle_in_any_accepted_spelling_parses_to_the_same_value(value, minus, sign, frame):
    number = repr(abs(value))
    typed = (minus if value < 0 else "") + number + sign
    halves = f"{abs(value) / 2!r}{sign} + {abs(value) / 2!r}{sign}"
    halves = f"{minus}({halves})" if value < 0 else halves
    for text in (frame.format(typed), frame.format(halves), f"{typed.strip()}"):
        got = parse_quantity(text, "deg")
        assert math.isclose(got, value, rel_tol=1e-12, abs_tol=1e-12), text
        assert math.isclose(parse_quantity(text, "rad"), math.radians(value), rel_tol=1e-12, abs_tol=1e-12)


@settings(max_examples=200, deadline=None)
@given(st.floats(min_value=-50, max_value=50, allow_nan=False).map(lambda v: round(v, 3)))
def test_a_length_in_any_accepted_spelling_parses_to_the_same_value(metres):
    spellings = [f"{metres!r} m", f"{metres!r}m", f"{metres * 100!r} cm", f"{metres * 1000!r} mm",
                 f"{metres / 1000!r} km", f"x = {metres!r} m", f"{metres!r}"]
    for text in spellings:
        assert math.isclose(parse_quantity(text, "m"), metres, rel_tol=1e-12, abs_tol=1e-12), text


def test_a_matrix_worth_of_parses_is_fast():
    import time

    start = time.perf_counter()
    for _ in range(100):
        for text in ("cos(30°)", "-sin(30°)", "0", "sin 30°", "cos 30°", "0", "0", "0", "1"):
            parse_answer(text)
    per_matrix = (time.perf_counter() - start) / 100
    assert per_matrix < 0.05  # generous bound (well under 5 ms in practice); not a benchmark


# --------------------------------------------------------------------------- tolerance (GUIDE §2)

from workbook.tolerance import agrees, clean, is_close_miss, is_sign_slip  # noqa: E402


def test_the_absolute_floor_no_longer_accepts_a_wrong_digit_of_a_small_key():
    assert not agrees(0.1438, 1 / 7)
    assert agrees(0.1429, 1 / 7) and agrees(0.142857, 1 / 7)


def test_counts_are_exact():
    assert agrees(7500, 7500, exact=True)
    assert not any(agrees(v, 7500, exact=True) for v in (7493, 7499, 7501, 7507, 7500.5))


@pytest.mark.parametrize("noise", [math.cos(math.pi / 2), -1.8369701987210297e-16, 1e-13, 0.0, -0.0])
def test_keys_of_float_noise_are_zero(noise):
    assert clean(noise) == 0.0
    assert agrees(0, noise) and agrees(0.0004, noise) and agrees(-0.0004, noise)
    assert not agrees(0.01, noise)
    assert not is_sign_slip(-0.0004, noise) and not is_sign_slip(0.5, noise)
    assert not is_close_miss(0.5, noise) and not is_close_miss(0.0004, noise)


@settings(max_examples=300, deadline=None)
@given(st.floats(min_value=-1e6, max_value=1e6, allow_nan=False).filter(lambda k: abs(k) > 1e-9),
       st.floats(min_value=-0.5, max_value=0.5))
def test_tolerance_is_relative_for_every_non_zero_key(key, fraction):
    value = key * (1 + fraction * 1e-3)  # within 0.05 %: accepted
    assert agrees(value, key)
    far = key * (1 + 0.005 + abs(fraction) * 0.01)  # 0.5 % to 1 % off: not accepted, but close
    assert not agrees(far, key) and is_close_miss(far, key)
    assert is_sign_slip(-key, key) and not is_close_miss(-key, key)
