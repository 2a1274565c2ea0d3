"""Formula answers: what a learner types for the variables, LaTeX, speed, and equivalence by evaluation."""

import math
import re

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from workbook import bank
from workbook.answer_kinds.expression.mark import equivalent
from workbook.expr import InvalidAnswer, parse_formula
from workbook.number_format import compact, prose

ARM = ("theta1", "theta2", "L1", "L2")
ARM_DOMAIN = {"theta1": (-math.pi, math.pi), "theta2": (-math.pi, math.pi), "L1": (0.2, 3.0), "L2": (0.2, 3.0)}
POINT = {"theta1": 0.3, "theta2": 0.5, "L1": 1.5, "L2": 0.7}


def arm_x(theta1, theta2, L1, L2):
    return L1 * math.cos(theta1) + L2 * math.cos(theta1 + theta2)


@pytest.mark.parametrize("text", [
    "L1 cos(theta1) + L2 cos(theta1 + theta2)", "L1*cos(θ1) + L2*cos(θ1+θ2)", "L₁ cos θ₁ + L₂ cos(θ₁ + θ₂)",
    "L_1 cos(theta_1) + L_2 cos(theta_1 + theta_2)", "L1cos(θ1)+L2cos(θ1+θ2)", "x = L1 cos θ1 + L2 cos(θ1 + θ2)",
    "L2 cos(θ2 + θ1) + cos(θ1) L1", "Θ1" and "L1 cos(Θ1) + L2 cos(Θ1 + Θ2)",
    "L1 cos θ1 + L2 (cos θ1 cos θ2 − sin θ1 sin θ2)",          # the sum formula expanded
    "L1 cos(θ1) + L2 cos(θ1) cos(θ2) - L2 sin(θ1) sin(θ2)",
    "(L1 + L2 cos θ2) cos θ1 - L2 sin θ2 sin θ1",               # factored the other way
])
def test_the_arm_formula_in_the_ways_people_write_it(text):
    f = parse_formula(text, ARM)
    assert math.isclose(f.evaluate(POINT), arm_x(**POINT), rel_tol=1e-12)
    assert equivalent(f, arm_x, ARM_DOMAIN) is True


@pytest.mark.parametrize("text,variables,names", [
    ("v Δt cos(θ)", ("v", "theta", "dt"), {"v", "dt", "theta"}), ("v*dt*cos(theta)", ("v", "theta", "dt"), {"v", "dt", "theta"}),
    ("vdt cos θ", ("v", "theta", "dt"), {"v", "dt", "theta"}), ("ω Δt", ("omega", "dt"), {"omega", "dt"}),
    ("2L1", ARM, {"L1"}), ("2(θ1 + θ2)", ARM, {"theta1", "theta2"}), ("L1(θ1)", ARM, {"L1", "theta1"}),
    ("2π θ1", ARM, {"theta1"}), ("sin²θ1 + cos²θ1", ARM, {"theta1"}),
])
def test_names_and_implicit_products(text, variables, names):
    assert parse_formula(text, variables).names == names


@pytest.mark.parametrize("text,fragment", [
    ("L1 cos(x)", "Unknown name “x”"), ("L1 cos(x)", "theta1, theta2"), ("L1 cos(x)", "θ₁"),
    ("sin θ1L1", "sin(θ1*L1) or sin(θ1)*L1"), ("cos 2 θ1^2", "parentheses"), ("sin θ1^2", "parentheses"),
    ("θ1 2", "Put *"), ("", "Type an answer"), ("L1 +", "missing"), ("L1 cos(θ1", "not closed"),
    ("L1 m", "Unknown name"), ("L1 = L2 = 2", "Type just the value"), ("[L1, L2]", "not a list"),
    ("foo(L1)", "Unknown name"),
])
def test_invalid_formulas_say_what_is_allowed(text, fragment):
    with pytest.raises(InvalidAnswer) as err:
        parse_formula(text, ARM)
    assert fragment.lower() in str(err.value).lower()


def test_an_ambiguous_run_of_letters_is_refused():
    assert parse_formula("vdt", ("v", "dt")).names == {"v", "dt"}
    with pytest.raises(InvalidAnswer, match="more than one way"):
        parse_formula("vdt", ("v", "d", "t", "dt"))


@pytest.mark.parametrize("text,latex", [
    ("L1 cos(θ1)", r"L_{1}\cos\theta_{1}"),
    ("L1 cos(θ1 + θ2)", r"L_{1}\cos\left(\theta_{1} + \theta_{2}\right)"),
    ("sqrt(L1^2 + L2^2)", r"\sqrt{L_{1}^{2} + L_{2}^{2}}"),
    ("(L1 + L2)/(L1 - L2)", r"\frac{L_{1} + L_{2}}{L_{1} - L_{2}}"),
    ("atan2(L2 sin θ2, L1 + L2 cos θ2)", r"\operatorname{atan2}\left(L_{2}\sin\theta_{2}, L_{1} + L_{2}\cos\theta_{2}\right)"),
    ("-L1 sin(θ1)", r"-L_{1}\sin\theta_{1}"), ("L1 * (-θ1)", r"L_{1} \cdot \left(-\theta_{1}\right)"),
    ("L1 - (L2 - θ1)", r"L_{1} - \left(L_{2} - \theta_{1}\right)"), ("θ1 + 90°", r"\theta_{1} + 90^{\circ}"),
    ("1 - 2sin²θ1", r"1 - 2\sin^{2}\theta_{1}"), ("(L1 + L2)^2", r"\left(L_{1} + L_{2}\right)^{2}"),
    ("2 * 3 L1", r"2 \cdot 3 L_{1}"),
])
def test_latex_shows_how_it_was_read(text, latex):
    assert parse_formula(text, ARM).latex == latex


def test_evaluate_reports_missing_variables_and_undefined_points():
    f = parse_formula("sqrt(L1 - L2)/θ1", ARM)
    with pytest.raises(ValueError, match="no value given"):
        f.evaluate({"L1": 1.0})
    with pytest.raises(ValueError):
        f.evaluate({"L1": 1.0, "L2": 2.0, "theta1": 1.0})
    with pytest.raises(ZeroDivisionError):
        f.evaluate({"L1": 2.0, "L2": 1.0, "theta1": 0.0})


def test_variable_names_must_be_ascii():
    with pytest.raises(ValueError, match="ASCII"):
        parse_formula("θ", ("θ",))


@pytest.mark.parametrize("text,reference", [
    ("sin(a)cos(b) + cos(a)sin(b)", lambda a, b: math.sin(a + b)),
    ("1 - 2 sin(a)^2", lambda a, b: math.cos(2 * a)),
    ("cos²a - sin²a", lambda a, b: math.cos(2 * a)),
    ("(a + b)^2", lambda a, b: a * a + 2 * a * b + b * b),
    ("a^2 - b^2", lambda a, b: (a - b) * (a + b)),
    ("2 sin(a) cos(a)", lambda a, b: math.sin(2 * a)),
    ("sqrt(a^2 + b^2)", lambda a, b: math.hypot(a, b)),
    ("tan(a)", lambda a, b: math.sin(a) / math.cos(a)),
])
def test_identities_are_accepted(text, reference):
    assert equivalent(parse_formula(text, ("a", "b")), reference, {"a": (-2.0, 2.0), "b": (-2.0, 2.0)}) is True


@pytest.mark.parametrize("text,reference", [
    ("2a", lambda a, b: a * a),                        # agrees at a = 0 and a = 2
    ("sin(a)", lambda a, b: a),                        # agrees at 0, and nearly so near it
    ("sin(a)cos(b) - cos(a)sin(b)", lambda a, b: math.sin(a + b)),  # agrees wherever sin(b)cos(a) = 0
    ("a + b", lambda a, b: a * b + 1),                 # agrees on a line
    ("1.01 a", lambda a, b: a),                        # 1 % off everywhere
])
def test_different_formulas_that_agree_somewhere_are_refused(text, reference):
    assert equivalent(parse_formula(text, ("a", "b")), reference, {"a": (-2.0, 2.0), "b": (-2.0, 2.0)}) is False


def test_too_few_defined_points_is_none_not_true():
    f = parse_formula("sqrt(a)", ("a",))
    assert equivalent(f, lambda a: math.sqrt(a), {"a": (-9.0, -1.0)}) is None
    # Points where one side is undefined are skipped, not counted as agreement or disagreement.
    g = parse_formula("sqrt(a)", ("a",))
    assert equivalent(g, lambda a: math.sqrt(a), {"a": (-1.0, 9.0)}) is True


def test_the_domain_must_cover_the_formula():
    with pytest.raises(ValueError, match="no range for b"):
        equivalent(parse_formula("a + b", ("a", "b")), lambda a: a, {"a": (0.0, 1.0)})


COEFF = st.integers(min_value=-9, max_value=9)


@settings(max_examples=150, deadline=None)
@given(COEFF.filter(bool), COEFF, COEFF)
def test_a_factored_quadratic_and_its_expansion_agree_and_a_changed_coefficient_does_not(p, q, r):
    # p(x - q)(x - r) = p x² - p(q + r) x + p q r
    factored = parse_formula(f"{p}*(x - ({q}))*(x - ({r}))", ("x",))
    expanded = lambda x: p * x * x - p * (q + r) * x + p * q * r  # noqa: E731
    assert equivalent(factored, expanded, {"x": (-5.0, 5.0)}) is True
    wrong = lambda x: expanded(x) + 1  # noqa: E731
    assert equivalent(factored, wrong, {"x": (-5.0, 5.0)}) is False


def test_a_formula_evaluates_fast():
    import time

    f = parse_formula("L1 cos θ1 + L2 cos(θ1 + θ2)", ARM)
    start = time.perf_counter()
    for _ in range(1000):
        f.evaluate(POINT)
    assert (time.perf_counter() - start) / 1000 < 0.005  # a generous bound, not a benchmark


FORMULA_PIECES = st.sampled_from(list("0123456789.+-*/^()[], =°θ₁²√π−") + [
    "cos", "sin ", "sqrt(", "atan2(", "L1", "L₂", "theta", "Δt", "x", "e", "**", "1e999", "sin^2", "vdt", "m"])


@settings(max_examples=400, deadline=None)
@given(st.one_of(st.text(max_size=60), st.lists(FORMULA_PIECES, max_size=30).map("".join)))
def test_any_text_gives_a_formula_or_a_message(text):
    try:
        f = parse_formula(text, ARM + ("dt", "x"))
    except InvalidAnswer as err:
        assert str(err)
    else:
        assert isinstance(f.latex, str) and f.names <= set(ARM + ("dt", "x"))


# ---------------------------------------------------------------- LaTeX, look-alikes, degrees, the printed form

from workbook.answer_kinds.expression import formula as formula_kind  # noqa: E402


def arm_x_answer():
    return formula_kind(label="x", key=lambda theta1, theta2, L1, L2: L1 * math.cos(theta1) + L2 * math.cos(theta1 + theta2),
                        variables=("theta1", "theta2", "L1", "L2"),
                        domain={"theta1": (-3.0, 3.0), "theta2": (-3.0, 3.0), "L1": (0.5, 2.0), "L2": (0.5, 2.0)},
                        answer_text="L1*cos(theta1) + L2*cos(theta1 + theta2)").build("t.1")


@pytest.mark.parametrize("text", [
    r"L_1\cos\theta_1 + L_2\cos(\theta_1 + \theta_2)",
    r"L_{1}\cos\theta_{1} + L_{2}\cos\left(\theta_{1} + \theta_{2}\right)",
    r"$L_1 \cos(\theta_1) + L_2 \cdot \cos(\theta_1+\theta_2)$",
    r"x = L_1\cos\theta_1 + L_2\cos(\theta_1 + \theta_2)",
    "L₁ cos θ₁ + L₂ cos(θ₁ + θ₂)",
])
def test_a_formula_in_latex_and_in_unicode(text):
    assert arm_x_answer().check(text).status == "correct", (text, arm_x_answer().check(text))


def test_the_delta_macos_types_and_dt():
    step = formula_kind(label="dx", key=lambda v, dt: v * dt, variables=("v", "dt"),
                        domain={"v": (0.5, 2.0), "dt": (0.1, 1.0)}, answer_text="v*dt").build("t.1")
    for text in ("v ∆t", "v Δt", "v*dt", r"v\,\Delta t", "v·Δt"):
        assert step.check(text).status == "correct", text


def test_degrees_inside_a_formula_are_named():
    verdict = arm_x_answer().check("L1*cos(theta1) + L2*sin(theta1 + theta2 + 90)")
    assert (verdict.status, verdict.tag) == ("incorrect", "degrees"), verdict
    assert arm_x_answer().check("L1*cos(theta1) + L2*sin(theta1 + theta2 + 90°)").status == "correct"


def test_the_worked_formula_typeset_is_accepted_back():
    ans = arm_x_answer()
    assert ans.check(ans.worked_tex()).status == "correct"


from workbook.expr import InvalidAnswer as _Invalid  # noqa: E402

_PIECES = st.sampled_from(["theta1", "theta2", "L1", "L2", "2", "0.5", "pi", "+", "-", "*", "/", "^2", "(", ")",
                           "cos(", "sin(", "sqrt(", " ", "atan2(theta1, L1)", "cos theta1", "sin L2"])


@settings(max_examples=400, deadline=None)
@given(st.lists(_PIECES, min_size=1, max_size=14).map("".join))
def test_any_formula_shown_as_latex_reads_back_as_the_same_formula(text):
    names = ("theta1", "theta2", "L1", "L2")
    try:
        read = parse_formula(text, names)
    except _Invalid:
        return
    again = parse_formula(read.latex, names)
    domain = {"theta1": (-3.0, 3.0), "theta2": (-3.0, 3.0), "L1": (0.5, 2.0), "L2": (0.5, 2.0)}
    same = equivalent(again, lambda **env: read.evaluate(env), domain)
    assert same is not False, (text, read.latex)


@pytest.mark.parametrize("ex_id", ["3.9", "4.8", "6.6", "7.7"])
@pytest.mark.parametrize("wrong", ["1", "2*L1", "theta1 + L2", "cos(theta)*v", "dx + dy"])
def test_a_counterexample_names_the_point_it_was_computed_at(ex_id, wrong):
    """"Not the same formula: at θ = 2.08 … yours gives 1, the answer −0.3950": evaluated at the printed point,
    the key and the learner's formula give the printed numbers, all printed by the one printer (a true minus)."""
    ex = bank.get(ex_id)
    ans = ex.answer
    try:
        formula = parse_formula(wrong, ans.variables)
    except InvalidAnswer:
        pytest.skip(f"{wrong} names a variable {ex_id} does not have")
    message = ex.check(wrong).message
    said = re.fullmatch(r"Not the same formula: at (.*) yours gives (\S+), the answer (\S+)\.", message)
    if said is None:
        assert not message.startswith("Not the same formula: at"), message
        return
    point = {}
    for pair in said[1].split(", "):
        name, value = pair.split(" = ")
        point[name] = float(value.replace("\u2212", "-"))
        assert prose(point[name]) == value
    assert said[2] == compact(formula.evaluate(point)) and said[3] == compact(ans.key(**point))
