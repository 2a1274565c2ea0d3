"""Formula answers: ``L1 cos θ1 + L2 cos(θ1 + θ2)`` read over named variables.

:func:`parse_formula` uses the answer parser of :mod:`workbook.answers` with the
exercise's variables (ASCII names such as ``theta1``, ``L1``, ``dt``) and the
forms a learner types for them: ``θ1``, ``θ₁``, ``theta_1``, ``L₁``, ``Δt`` for
``dt``, ``ω`` for ``omega``; also ``Θ1`` or ``l1`` when only one variable
matches regardless of case. The tree is compiled once into closures, so a
formula is evaluated many times quickly and never through ``eval``.

Implicit products, and what is refused (so that no reading is a guess):

- a number before a name or a parenthesis: ``2L1``, ``2(θ1 + θ2)``, ``2π``;
- names side by side, with or without a space: ``L1 L2``, ``L1cos(θ1)``,
  ``v dt``; a run of letters is split into names only when exactly one split
  exists (``vdt`` is v·dt when the variables are v and dt; if ``d`` and ``t``
  were variables too, the run is refused as ambiguous);
- a parenthesis after a name or a parenthesis: ``L1(cos θ1)``, ``(a)(b)``;
- a function without parentheses takes one name, number or number-with-unit
  (another function may follow: ``cos θ1 cos θ2``):
  ``L1 cos θ1 + L2 cos(θ1 + θ2)`` reads as it looks; ``cos 2θ``, ``sin θ L1``
  and ``sin x^2`` are refused with "put the argument in parentheses";
- a name followed by a number (``θ1 2``) is refused: write the ``*``.
- ``sin²θ`` and ``sin^2(θ)`` are (sin θ)².
- ``°`` after a number converts it to radians (``θ1 + 90°``); other units are
  not part of a formula.

>>> f = parse_formula("L₁ cos θ₁ + L2 cos(θ1 + θ2)", ("theta1", "theta2", "L1", "L2"))
>>> f.latex
'L_{1}\\\\cos\\\\theta_{1} + L_{2}\\\\cos\\\\left(\\\\theta_{1} + \\\\theta_{2}\\\\right)'
>>> sorted(f.names)
['L1', 'L2', 'theta1', 'theta2']
>>> f.evaluate({"theta1": 0.0, "theta2": 0.0, "L1": 1.0, "L2": 1.0})
2.0
>>> parse_formula("v*Δt*cos(ω)", ("v", "omega", "dt")).latex
'v\\\\Delta t\\\\cos\\\\omega'
"""

from __future__ import annotations

import math
import random
import re
from dataclasses import dataclass
from typing import Callable, Iterable, Mapping

from .answers import (CONSTANTS, FUNCTIONS, GREEK, MAX_EXPONENT, Grammar, InvalidAnswer,
                      parse_tree)
from .tolerance import agrees, clean

Env = Mapping[str, float]

_FUNC_LATEX = {
    "sin": r"\sin", "cos": r"\cos", "tan": r"\tan", "asin": r"\arcsin", "acos": r"\arccos",
    "atan": r"\arctan", "exp": r"\exp", "ln": r"\ln", "log": r"\ln", "log10": r"\log_{10}",
    "sind": r"\operatorname{sind}", "cosd": r"\operatorname{cosd}", "tand": r"\operatorname{tand}",
}
_GREEK_ASCII = set(GREEK.values()) - {"pi"}


@dataclass(frozen=True)
class Formula:
    """A parsed formula: ``evaluate(env)``, its ``latex`` and the variable ``names`` it uses."""

    text: str
    latex: str
    names: frozenset[str]
    _fn: Callable[[Env], float]

    def evaluate(self, env: Env) -> float:
        """The formula's value for the variables in ``env``.

        Raises ``ValueError`` when a variable is missing or the formula is not
        defined there (sqrt of a negative, a huge exponent), and
        ``ZeroDivisionError``/``OverflowError`` from the arithmetic.
        """
        try:
            return float(self._fn(env))
        except KeyError as err:
            raise ValueError(f"no value given for {err.args[0]}") from None


def parse_formula(text: object, variables: Iterable[str]) -> Formula:
    """Read ``text`` as a formula over ``variables`` (ASCII names), or raise InvalidAnswer.

    >>> parse_formula("2L1 + x", ["L1"])
    Traceback (most recent call last):
    ...
    workbook.answers.InvalidAnswer: Unknown name “x”. The formula may use L1, numbers, pi and the functions sqrt, sin, cos, tan, asin, acos, atan, atan2, exp, ln, log, abs.
    >>> parse_formula("1 - 2sin²θ", ["theta"]).latex
    '1 - 2\\\\sin^{2}\\\\theta'
    """
    names = tuple(variables)
    for name in names:
        if not re.fullmatch(r"[A-Za-z][A-Za-z0-9_]*", name):
            raise ValueError(f"variable names must be ASCII identifiers, not {name!r}")
    vars_ = frozenset(names)
    grammar = Grammar(variables=vars_, units=False,
                      examples=f"2*{names[0]}, sin({names[0]}), sqrt({names[0]})/2" if names else "2*pi")
    tree = parse_tree(text, grammar)  # type: ignore[arg-type]
    used: set[str] = set()
    fn = _compile(tree, used)
    return Formula(text=str(text), latex=_latex(tree, 0), names=frozenset(used), _fn=fn)


# --------------------------------------------------------------------------- tree -> closures

def _compile(node: tuple, used: set[str]) -> Callable[[Env], float]:
    kind = node[0]
    if kind in ("num", "const"):
        value = node[1] if kind == "num" else CONSTANTS[node[1]]
        return lambda env: value
    if kind == "var":
        name = node[1]
        used.add(name)
        return lambda env: env[name]
    if kind == "neg":
        f = _compile(node[1], used)
        return lambda env: -f(env)
    if kind == "unit":
        f, factor = _compile(node[1], used), node[2][0]
        return lambda env: f(env) * factor
    if kind == "bin":
        op, f, g = node[1], _compile(node[2], used), _compile(node[3], used)
        if op == "+":
            return lambda env: f(env) + g(env)
        if op == "-":
            return lambda env: f(env) - g(env)
        if op == "*":
            return lambda env: f(env) * g(env)
        if op == "/":
            return lambda env: f(env) / g(env)

        def power(env: Env) -> float:
            exponent = g(env)
            if abs(exponent) > MAX_EXPONENT:
                raise ValueError("exponent too large")
            return math.pow(f(env), exponent)  # ValueError for a negative base and a fractional power
        return power
    if kind == "call":
        fn = FUNCTIONS[node[1]][1]
        args = [_compile(a, used) for a in node[2]]
        if len(args) == 1:
            a = args[0]
            return lambda env: fn(a(env))
        a, b = args
        return lambda env: fn(a(env), b(env))
    raise InvalidAnswer("That is not a formula.")  # pragma: no cover


# --------------------------------------------------------------------------- tree -> LaTeX

def _join(left: str, right: str) -> str:
    """Two LaTeX pieces side by side; a command followed by a letter needs a space."""
    if re.search(r"\\[A-Za-z]+$", left) and right[:1].isalpha():
        return left + " " + right
    return left + right


def variable_latex(name: str) -> str:
    r"""How a variable shows: ``theta1`` → ``\theta_{1}``, ``dt`` → ``\Delta t``, ``L_2`` → ``L_{2}``.

    >>> variable_latex("theta1"), variable_latex("dt"), variable_latex("omega"), variable_latex("Kp")
    ('\\theta_{1}', '\\Delta t', '\\omega', 'K_{p}')
    """
    m = re.fullmatch(r"([A-Za-z]+?)_?([0-9]*)", name)
    if not m:
        return rf"\mathit{{{name}}}"
    base, sub = m.group(1), m.group(2)
    if base in _GREEK_ASCII:
        out = "\\" + base
    elif len(base) > 1 and base[0] == "d" and (base[1:] in _GREEK_ASCII or len(base) == 2):
        out = r"\Delta " + ("\\" + base[1:] if base[1:] in _GREEK_ASCII else base[1:])
    elif len(base) == 2 and base[0].isupper() and not sub:
        out, sub = base[0], base[1]
    elif len(base) > 1:
        out = rf"\mathit{{{base}}}"
    else:
        out = base
    return out + (f"_{{{sub}}}" if sub else "")


def _number(v: float) -> str:
    if v == int(v) and abs(v) < 1e15:
        return str(int(v))
    s = format(v, ".12g")
    if "e" in s:
        mant, exp = s.split("e")
        return rf"{mant} \times 10^{{{int(exp)}}}"
    return s


_PREC = {"+": 1, "-": 1, "*": 2, "/": 2, "neg": 3, "^": 4}


def _prec(node: tuple) -> int:
    if node[0] == "bin":
        return _PREC[node[1]]
    if node[0] == "neg":
        return 3
    if node[0] == "num" and node[1] < 0:
        return 3
    return 5


def _paren(s: str) -> str:
    return rf"\left({s}\right)"


def _latex(node: tuple, parent: int) -> str:
    out = _latex_raw(node)
    return _paren(out) if _prec(node) < parent else out


def _latex_raw(node: tuple) -> str:
    kind = node[0]
    if kind == "num":
        return _number(node[1])
    if kind == "const":
        return {"pi": r"\pi", "tau": r"\tau", "e": "e"}[node[1]]
    if kind == "var":
        return variable_latex(node[1])
    if kind == "neg":
        return "-" + _latex(node[1], 4)
    if kind == "unit":
        inner = _latex(node[1], 5)
        return inner + (r"\,\mathrm{rad}" if node[2][3] == "rad" else r"^{\circ}")
    if kind == "call":
        name, args = node[1], node[2]
        if name == "sqrt":
            return rf"\sqrt{{{_latex(args[0], 0)}}}"
        if name == "abs":
            return rf"\left|{_latex(args[0], 0)}\right|"
        if name == "atan2":
            return rf"\operatorname{{atan2}}\left({_latex(args[0], 0)}, {_latex(args[1], 0)}\right)"
        return _join(_FUNC_LATEX[name], _func_arg(args[0]))
    op, a, b = node[1], node[2], node[3]
    if op == "/":
        return rf"\frac{{{_latex(a, 0)}}}{{{_latex(b, 0)}}}"
    if op == "^":
        if a[0] == "call" and a[1] in ("sin", "cos", "tan"):
            return _join(rf"{_FUNC_LATEX[a[1]]}^{{{_latex(b, 0)}}}", _func_arg(a[2][0]))
        return f"{_latex(a, 5)}^{{{_latex(b, 0)}}}"
    if op == "*":
        left, right = _latex(a, 2), _latex(b, 3)
        if _prec(b) == 3:
            return rf"{left} \cdot {_paren(right)}"
        if b[0] == "num" or (b[0] == "unit" and b[1][0] == "num"):
            return rf"{left} \cdot {right}"
        if right.startswith("\\") and not right.startswith(r"\left"):
            return _join(left, right)
        return f"{left} {right}"
    left = _latex(a, 1)
    right = _latex(b, 2 if op == "-" else 1)
    if _prec(b) == 3:
        right = _paren(right)
    return f"{left} {op} {right}"


def _func_arg(arg: tuple) -> str:
    if arg[0] in ("var", "const", "num") and not (arg[0] == "num" and arg[1] < 0):
        return _latex(arg, 0)
    if arg[0] == "unit" and arg[1][0] in ("num", "var"):
        return _latex(arg, 0)
    return _paren(_latex(arg, 0))


# --------------------------------------------------------------------------- equivalence

def _same(value: float, key: float) -> bool:
    return agrees(value, clean(key)) or abs(value - key) <= 1e-9 * (1 + abs(key))


def equivalent(formula: Formula, reference: Callable[..., float], domain: Mapping[str, tuple[float, float]],
               points: int = 12, seed: int = 0) -> bool | None:
    """Do ``formula`` and ``reference`` agree at ``points`` random points of ``domain``?

    ``reference`` is called with the variables as keyword arguments. Points
    where either side is undefined (an exception, or not finite) are skipped;
    agreement uses the grading tolerance of :mod:`workbook.tolerance`. Returns
    None when fewer than half the points (at least 3) could be evaluated.

    >>> dom = {"x": (-3.0, 3.0)}
    >>> equivalent(parse_formula("1 - 2sin(x)^2", ["x"]), lambda x: math.cos(2 * x), dom)
    True
    >>> equivalent(parse_formula("2x", ["x"]), lambda x: x * x, dom)   # agrees at x = 0 and 2 only
    False
    >>> print(equivalent(parse_formula("sqrt(x)", ["x"]), lambda x: x ** 0.5, {"x": (-9.0, -1.0)}))
    None
    """
    missing = sorted(formula.names - set(domain))
    if missing:
        raise ValueError(f"the domain gives no range for {', '.join(missing)}")
    rng = random.Random(seed)
    bounds = list(domain.items())
    defined = 0
    for _ in range(points * 4):
        if defined >= points:
            break
        env = {name: rng.uniform(lo, hi) for name, (lo, hi) in bounds}
        try:
            key = float(reference(**env))
            value = formula.evaluate(env)
        except (ValueError, ArithmeticError, TypeError):
            continue
        if not (math.isfinite(key) and math.isfinite(value)):
            continue
        defined += 1
        if not _same(value, key):
            return False
    return True if defined >= max(3, points // 2) else None
