"""Read a learner's typed answer: a number or a small math expression.

The text is normalised (unicode minus, ×, π, √, ^, a trailing ° or rad), parsed
with :mod:`ast`, and evaluated over a whitelist of nodes and names. Limits on
length, nesting and exponents are checked before anything is evaluated, and all
arithmetic is done in floats, so no input can run for long or use much memory.

>>> parse_answer("sqrt(2)/2").value
0.7071067811865476
>>> parse_answer("53.13°").unit
'deg'
>>> parse_answer("2,5")
Traceback (most recent call last):
...
workbook.answers.InvalidAnswer: Use a dot for decimals: write 2.5, not 2,5.
"""

from __future__ import annotations

import ast
import math
import re
import warnings
from dataclasses import dataclass

MAX_LENGTH = 200
MAX_DEPTH = 12
MAX_NODES = 100
MAX_EXPONENT = 1000.0


class InvalidAnswer(ValueError):
    """The input could not be read as one number; the message says why."""


@dataclass(frozen=True)
class Answer:
    value: float
    unit: str | None  # "deg", "rad" or None (no unit written)
    text: str


_FUNCS = {
    "sqrt": math.sqrt, "sin": math.sin, "cos": math.cos, "tan": math.tan,
    "asin": math.asin, "acos": math.acos, "atan": math.atan, "atan2": math.atan2,
    "exp": math.exp, "ln": math.log, "log": math.log, "log10": math.log10,
    "abs": abs, "sind": lambda d: math.sin(math.radians(d)),
    "cosd": lambda d: math.cos(math.radians(d)), "tand": lambda d: math.tan(math.radians(d)),
}
_CONSTS = {"pi": math.pi, "e": math.e, "tau": math.tau}
_ARITY = {"atan2": 2}

_REPLACEMENTS = (
    ("\u2212", "-"), ("\u2013", "-"), ("\u00d7", "*"), ("\u22c5", "*"), ("\u00b7", "*"),
    ("\u00f7", "/"), ("\u03c0", "pi"), ("\u03c4", "tau"), ("^", "**"), ("\u00b2", "**2"),
    ("\u00b3", "**3"), ("\u2044", "/"), ("\u00bd", "(1/2)"), ("\u00bc", "(1/4)"),
    ("\u00be", "(3/4)"), ("\u00ba", "\u00b0"),
)


def _normalise(text: str) -> tuple[str, str | None]:
    s = text.strip()
    for old, new in _REPLACEMENTS:
        s = s.replace(old, new)
    unit = None
    m = re.search(r"(?:\s*(?:°|deg(?:rees?)?|rad(?:ians?)?))$", s, re.IGNORECASE)
    if m:
        unit = "deg" if (m.group(0).strip().startswith("°") or m.group(0).strip().lower().startswith("deg")) else "rad"
        s = s[: m.start()].strip()
        if not s:
            raise InvalidAnswer("Type a number before the unit, for example 53.13°.")
    # A degree sign inside the expression converts that number: cos(60°).
    s = re.sub(r"(\d+(?:\.\d*)?|\.\d+)\s*°", r"(\1*pi/180)", s)
    if "°" in s:
        raise InvalidAnswer("Put the degree sign right after a number, for example 30°.")
    # √2, √(2), 2√2  ->  sqrt(2), sqrt(2), 2*sqrt(2)
    s = re.sub(r"(?<=[\d)])\s*√", "*√", s)
    s = re.sub(r"√\s*(\d+(?:\.\d*)?|[a-z]+)", r"sqrt(\1)", s)
    s = s.replace("√", "sqrt")
    # implicit products the way people write them: 2pi, 2(3), (1)(2), 2sqrt(3)
    s = re.sub(r"(?<![\w.])(\d+(?:\.\d*)?)\s*(?=pi\b|tau\b|sqrt|sin|cos|tan|\()", r"\1*", s)
    s = re.sub(r"\)\s*(?=[\d(a-z])", ")*", s)
    return s, unit


def _check_shape(s: str) -> None:
    depth = 0
    for ch in s:
        if ch in "([{":
            depth += 1
            if depth > MAX_DEPTH:
                raise InvalidAnswer("That expression is nested too deeply; simplify it.")
        elif ch in ")]}":
            depth -= 1
    if re.fullmatch(r"[+-]?\d+,\d+", s):
        a, b = s.split(",")
        raise InvalidAnswer(f"Use a dot for decimals: write {a}.{b}, not {a},{b}.")


def _evaluate(node: ast.AST, budget: list[int]) -> float:
    budget[0] -= 1
    if budget[0] < 0:
        raise InvalidAnswer("That expression is too long; simplify it.")
    if isinstance(node, ast.Expression):
        return _evaluate(node.body, budget)
    if isinstance(node, ast.Constant):
        if isinstance(node.value, bool) or not isinstance(node.value, (int, float)):
            raise InvalidAnswer("Only numbers can be used in an answer.")
        return float(node.value)
    if isinstance(node, ast.UnaryOp) and isinstance(node.op, (ast.UAdd, ast.USub)):
        v = _evaluate(node.operand, budget)
        return v if isinstance(node.op, ast.UAdd) else -v
    if isinstance(node, ast.BinOp):
        a = _evaluate(node.left, budget)
        b = _evaluate(node.right, budget)
        op = node.op
        if isinstance(op, ast.Add):
            return a + b
        if isinstance(op, ast.Sub):
            return a - b
        if isinstance(op, ast.Mult):
            return a * b
        if isinstance(op, ast.Div):
            if b == 0:
                raise InvalidAnswer("That divides by zero.")
            return a / b
        if isinstance(op, ast.Pow):
            if abs(b) > MAX_EXPONENT:
                raise InvalidAnswer("That exponent is too large.")
            if a < 0 and b != int(b):
                raise InvalidAnswer("A negative number to a fractional power is not a real number.")
            return math.pow(a, b)
        raise InvalidAnswer("Use only + − × / and ^ between numbers.")
    if isinstance(node, ast.Name):
        if node.id in _CONSTS:
            return _CONSTS[node.id]
        if node.id in _FUNCS:
            raise InvalidAnswer(f"{node.id} needs an argument in parentheses, for example {node.id}(2).")
        raise InvalidAnswer(f"Unknown name “{node.id}”. Use numbers, pi, e and functions such as sqrt, sin, cos, atan2.")
    if isinstance(node, ast.Call):
        if not isinstance(node.func, ast.Name) or node.func.id not in _FUNCS or node.keywords:
            name = getattr(node.func, "id", "that")
            raise InvalidAnswer(f"Unknown function “{name}”. Known: sqrt, sin, cos, tan, asin, acos, atan, atan2, exp, ln, log, abs.")
        want = _ARITY.get(node.func.id, 1)
        if len(node.args) != want:
            raise InvalidAnswer(f"{node.func.id} takes {want} argument{'s' if want > 1 else ''}.")
        args = [_evaluate(a, budget) for a in node.args]
        try:
            return float(_FUNCS[node.func.id](*args))
        except (ValueError, OverflowError):
            raise InvalidAnswer(f"{node.func.id} is not defined there (check its argument).") from None
    if isinstance(node, (ast.Tuple, ast.List, ast.Set)):
        raise InvalidAnswer("One number is expected here, not a list or a vector: type just the entry asked for.")
    raise InvalidAnswer("That is not a number or an arithmetic expression.")


def parse_answer(text: object) -> Answer:
    """Read ``text`` as one real number, or raise :class:`InvalidAnswer`."""
    if not isinstance(text, str):
        raise InvalidAnswer("Type your answer as text, for example 0.5 or sqrt(2)/2.")
    raw = text
    if not text.strip():
        raise InvalidAnswer("Type an answer first: a number such as 0.5, or an expression such as sqrt(2)/2.")
    if len(text) > MAX_LENGTH:
        raise InvalidAnswer(f"That answer is too long (more than {MAX_LENGTH} characters); one number is expected.")
    s, unit = _normalise(text)
    _check_shape(s)
    if len(s) > 2 * MAX_LENGTH:
        raise InvalidAnswer("That answer is too long; one number is expected.")
    try:
        with warnings.catch_warnings():  # e.g. "invalid escape sequence" in a quoted string
            warnings.simplefilter("ignore")
            tree = ast.parse(s, mode="eval")
    except (SyntaxError, ValueError, MemoryError, RecursionError):
        if re.fullmatch(r"[-+\d.\s]+", s) and re.search(r"\d\s+[-+]?\d", s):
            raise InvalidAnswer("One number is expected; there is a space between two numbers.") from None
        if "," in s:
            raise InvalidAnswer("One number is expected. Use a dot for decimals (2.5) and no commas.") from None
        raise InvalidAnswer("That could not be read as a number. Examples that work: 0.5, -1/2, sqrt(2)/2, pi/4, 53.13°.") from None
    try:
        value = _evaluate(tree, [MAX_NODES])
    except (OverflowError, RecursionError):
        raise InvalidAnswer("That number is too large.") from None
    if math.isnan(value) or math.isinf(value):
        raise InvalidAnswer("That is not a finite number.")
    return Answer(value=value, unit=unit, text=raw)
