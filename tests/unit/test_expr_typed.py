"""Answers as learners type them (issue 26): degrees-minutes-seconds, functions of one symbol as
typeset, and advice that, followed, is read."""

import math
import re

import pytest

from workbook.expr import InvalidAnswer, parse_answer
from workbook.expr.formula import parse_formula

DMS = {
    "53°7'48\"": 53.13, "53° 7′ 48″": 53.13, "53°7′48′′": 53.13, "-53°7'48''": -53.13, "53°7.8'": 53.13,
    "53°8'": 53 + 8 / 60, r"53^\circ 7' 48''": 53.13, r"53^{\circ}7^{\prime}48^{\prime\prime}": 53.13,
    "θ = 36°52'12\"": 36.87, "12°30′": 12.5, "0°0'36\"": 0.01, "53º7’48”": 53.13,  # noqa: RUF001 (a learner's curly quotes, on purpose)
}


@pytest.mark.parametrize("text,degrees", DMS.items())
def test_degrees_minutes_and_seconds_are_one_angle(text, degrees):
    answer = parse_answer(text)
    assert answer.unit == "deg" and math.isclose(answer.value, degrees, rel_tol=1e-12), (text, answer)


@pytest.mark.parametrize("text", ["53°70'", "53°7'75\""])
def test_minutes_and_seconds_of_sixty_or_more_are_refused_with_why(text):
    with pytest.raises(InvalidAnswer, match="below 60"):
        parse_answer(text)


def _quoted_forms(message: str) -> list[str]:
    """The forms a message suggests: after "write" or "for example", or listed after a colon."""
    forms = re.findall(r"(?:write|Write|example|with their marks,|or|degrees:)\s+([^\s,()]+(?:\([^)]*\)[^\s,]*)?)",
                       message)
    return [f.rstrip(".:") for f in forms if re.search(r"\d", f)]


def _follow(typed: str, message: str) -> list[str]:
    """What a learner types after reading the advice."""
    m = re.match(r"Put \* between “(.+?)” and the number after it\.", message)
    if m:
        name = re.escape(m.group(1))
        return [re.sub(rf"({name})\s*(?=\d)", r"\1 * ", typed, count=1)]
    m = re.match(r"Put the argument of (\w+) in parentheses: (\S+) or (\S+)\.", message)
    if m:
        return [m.group(2), m.group(3)]
    return _quoted_forms(message)


ADVISED = ["53°7", "53° 7 48", "2 m 3", "pi 2", "2,5", "1,250", "1,250,000", "cos pi/3", "53°7 48\"", "0,5 m"]


@pytest.mark.parametrize("typed", ADVISED)
def test_following_the_advice_is_read(typed):
    with pytest.raises(InvalidAnswer) as refused:
        parse_answer(typed)
    followed = _follow(typed, str(refused.value))
    assert followed, f"{typed!r}: the message suggests nothing to type: {refused.value}"
    for form in followed:
        parse_answer(form)  # raises if the advice leads to a second refusal


def test_following_the_advice_on_a_formula_is_read():
    grammar_vars = ("x", "theta")
    for typed in ("x 2", "theta 3 + 1"):
        with pytest.raises(InvalidAnswer) as refused:
            parse_formula(typed, grammar_vars)
        for form in _follow(typed, str(refused.value)):
            parse_formula(form, grammar_vars)


# ---------------------------------------------------------------- a function of one symbol, as typeset

def _same(a: str, b: str, variables=("v", "theta", "dt", "x", "y")) -> bool:
    fa, fb = parse_formula(a, variables), parse_formula(b, variables)
    point = {"v": 0.7, "theta": 1.3, "dt": 0.4, "x": 0.9, "y": -1.7}
    return math.isclose(fa.evaluate(point), fb.evaluate(point), rel_tol=1e-12)


@pytest.mark.parametrize("typed,meant", [
    ("-v sin θ dt", "-v*sin(theta)*dt"), (r"-v\sin\theta\,dt", "-v*sin(theta)*dt"),
    ("v cos θ dt", "v*cos(theta)*dt"), (r"v\cos\theta\,dt", "v*cos(theta)*dt"), ("sin θ y", "sin(theta)*y"),
    (r"\sin\theta\,y", "sin(theta)*y"), ("sin 2θ", "sin(2*theta)"), (r"\sin 2\theta", "sin(2*theta)"),
    ("sin 2θ dt", "sin(2*theta)*dt"), ("-sin θ cos θ", "-sin(theta)*cos(theta)"), ("cos x dt^2", "cos(x)*dt^2"),
    ("sin 30° x", "sin(pi/6)*x"), ("sin -θ dt", "sin(-theta)*dt"),
])
def test_a_function_of_one_symbol_is_read_as_the_page_typesets_it(typed, meant):
    assert _same(typed, meant), (typed, meant)


@pytest.mark.parametrize("typed,fragment", [
    ("-v sin θdt", "sin(θ*dt) or sin(θ)*dt"), ("sin θ^2", "parentheses"), ("sin θ (dt + 1)", "parentheses"),
    ("cos pi/3", "cos(pi/3) or cos(pi)/3"), ("sin 2 x^2", "parentheses"), ("sin x 2", "parentheses"),
])
def test_ambiguous_functions_still_get_a_clear_message(typed, fragment):
    with pytest.raises(InvalidAnswer) as refused:
        parse_formula(typed, ("v", "theta", "dt", "x", "y"))
    assert fragment in str(refused.value)
    for form in _follow(typed, str(refused.value)):
        parse_formula(form, ("v", "theta", "dt", "x", "y"))


def test_3_9_accepts_its_derivation_typed_and_pasted():
    from workbook import bank
    for seed in range(40):
        v = bank.get("3.9").variant(seed)
        key = v.worked_text()
        for typed in (key.replace("*sin(theta)*", " sin θ ").replace("*cos(theta)*", " cos θ "),
                      key.replace("*sin(theta)*", r"\sin\theta\,").replace("*cos(theta)*", r"\cos\theta\,")):
            assert v.check(typed).status == "correct", (seed, typed, v.check(typed).message)
