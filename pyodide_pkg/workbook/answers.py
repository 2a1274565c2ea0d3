"""Read a learner's typed answer: a number, a small math expression, with units.

The text is normalised (unicode minus and degree signs, ×, π, √, superscripts,
subscripts, a leading ``θ2 =``), split into tokens and parsed by a small
recursive-descent parser into a tree of tuples. Nothing is ever passed to
``eval``: only the nodes below exist, limits on length, nesting, node count and
exponents are checked while parsing, and all arithmetic is done in floats, so
no input can run for long or use much memory. :mod:`workbook.formula` uses the
same parser with variables.

Units are part of the evaluation: every value carries a dimension (see
:mod:`workbook.units`), products and quotients combine dimensions, and sums
need equal ones.

How units bind (so that each reading is the one people mean):

- A unit after a number or a closing parenthesis applies to the whole product
  or quotient before it: ``pi/2 rad`` is (π/2) rad, ``1/2 m`` is half a metre,
  ``180°/2`` is 90°. The exception: when the numerator already has a unit, a
  unit after a divisor belongs to the divisor, so ``10 m / 5 s`` is 2 m/s.
- ``m/s``, ``km/h``, ``cm/s`` (a unit, a slash, a unit) are one unit.
- ``s ms min h m cm mm km`` are units only after a number or a parenthesis.
- A bare number added to a quantity with a unit is refused (invalid, with a
  message): in ``45 + 45°`` the 45 could be degrees or radians, so the learner
  is asked to write the unit on every term. Quantities whose units cancel
  (``2 m / 1 m``) are plain numbers and mix freely.
- sin, cos and tan take an angle in radians (its SI value) or a bare number,
  read as radians; their result has no unit. Inverse trig functions return a
  bare number (radians). sind, cosd, tand read a bare number as degrees.
- A function may be written without parentheses when its argument is one
  number, name or number-with-unit: ``cos 45°``, ``√2/2``. Anything longer
  (``cos 2x``, ``sin x^2``) must use parentheses, and so must a division
  right after the argument of any function but √ (``cos pi/3`` could mean
  either); the message says so.

>>> parse_answer("sqrt(2)/2").value
0.7071067811865476
>>> parse_answer("53.13°").unit
'deg'
>>> a = parse_answer("45°+45°"); round(a.value, 12), a.unit, a.dimension
(90.0, 'deg', 'angle')
>>> a = parse_answer("20 cm"); a.si, a.dimension, a.unit
(0.2, 'length', None)
>>> parse_quantity("2.1263 m/s", "m/s")
2.1263
>>> parse_quantity("2 s", "m")
Traceback (most recent call last):
...
workbook.answers.InvalidAnswer: This answer is a length in metres; 2 s is a time.
>>> parse_answer("2,5")
Traceback (most recent call last):
...
workbook.answers.InvalidAnswer: Use a dot for decimals: write 2.5, not 2,5.
"""

from __future__ import annotations

import functools
import math
import re
import unicodedata
from dataclasses import dataclass, field
from typing import Callable

from . import units as U

MAX_LENGTH = 200
MAX_DEPTH = 12
MAX_NODES = 100
MAX_EXPONENT = 1000.0
_MAX_RECURSION = 60  # unary minus chains, powers of powers: far below Python's limit


class InvalidAnswer(ValueError):
    """The input could not be read as one number; the message says why."""


@dataclass(frozen=True)
class Answer:
    """A parsed answer.

    ``value`` is in the unit written for angles (degrees for ``53.13°``) and in
    SI for everything else; ``unit`` is ``"deg"``, ``"rad"`` or None (no angle
    unit); ``dimension`` is None when no unit was written, else ``"angle"``,
    ``"length"``, ``"time"``, ``"speed"`` (or another name), or ``""`` when the
    units cancel; ``si`` is the value in rad, m, s, m/s.
    """

    value: float
    unit: str | None
    text: str
    dimension: str | None = None
    si: float | None = field(default=None)

    def __post_init__(self) -> None:
        if self.si is None:
            object.__setattr__(self, "si", self.value)


# --------------------------------------------------------------------------- grammar

FUNCTIONS: dict[str, tuple[int, Callable[..., float]]] = {
    "sqrt": (1, math.sqrt), "sin": (1, math.sin), "cos": (1, math.cos), "tan": (1, math.tan),
    "asin": (1, math.asin), "acos": (1, math.acos), "atan": (1, math.atan), "atan2": (2, math.atan2),
    "exp": (1, math.exp), "ln": (1, math.log), "log": (1, math.log), "log10": (1, math.log10),
    "abs": (1, abs), "sind": (1, lambda d: math.sin(math.radians(d))),
    "cosd": (1, lambda d: math.cos(math.radians(d))), "tand": (1, lambda d: math.tan(math.radians(d))),
}
ALIASES = {"arcsin": "asin", "arccos": "acos", "arctan": "atan", "arctan2": "atan2", "sqr": "sqrt"}
CONSTANTS = {"pi": math.pi, "e": math.e, "tau": math.tau}
_TRIG = {"sin", "cos", "tan"}
_KNOWN_FUNCS = "sqrt, sin, cos, tan, asin, acos, atan, atan2, exp, ln, log, abs"

GREEK = {
    "α": "alpha", "β": "beta", "γ": "gamma", "δ": "delta", "ε": "epsilon", "ζ": "zeta", "η": "eta",
    "θ": "theta", "ι": "iota", "κ": "kappa", "λ": "lambda", "μ": "mu", "ν": "nu", "ξ": "xi",
    "π": "pi", "ρ": "rho", "σ": "sigma", "τ": "tau", "υ": "upsilon", "φ": "phi", "ϕ": "phi",
    "χ": "chi", "ψ": "psi", "ω": "omega", "Θ": "Theta", "Φ": "Phi", "Ψ": "Psi", "Ω": "Omega",
    "Λ": "Lambda", "Σ": "Sigma", "Γ": "Gamma",
}


@dataclass
class Grammar:
    """What names mean in one kind of answer: numbers (no variables) or a formula."""

    variables: frozenset[str] = frozenset()
    units: bool = True  # every unit of workbook.units; False: angle units only
    examples: str = "0.5, -1/2, sqrt(2)/2, pi/4, 53.13°"

    def kind(self, name: str) -> str | None:
        if name in self.variables:
            return "var"
        if name in FUNCTIONS or name in ALIASES:
            return "func"
        if name in CONSTANTS:
            return "const"
        unit = U.lookup(name)
        if unit is not None and (self.units or unit[1] == U.ANGLE):
            return "unit"
        return None

    def unknown(self, name: str, call: bool) -> InvalidAnswer:
        if name in ("True", "False", "None"):
            return InvalidAnswer("Only numbers can be used in an answer.")
        if call and not self.variables:
            return InvalidAnswer(f"Unknown function “{name}”. Known: {_KNOWN_FUNCS}.")
        if self.variables:
            names = ", ".join(sorted(self.variables, key=lambda v: (v.lower(), v)))
            return InvalidAnswer(
                f"Unknown name “{name}”. The formula may use {names}{self.typed_forms()}, "
                f"numbers, pi and the functions {_KNOWN_FUNCS}.")
        return InvalidAnswer(f"Unknown name “{name}”. Use numbers, pi, e and functions such as sqrt, sin, cos, atan2.")


    def typed_forms(self) -> str:
        """An example of the Greek and subscript spellings, for messages: " (θ1, θ₁ and theta_1 work too)"."""
        greek = {v: k for k, v in GREEK.items() if k not in "ϕπ"}
        for var in sorted(self.variables):
            m = re.fullmatch(r"([A-Za-z]+?)_?([0-9]*)", var)
            if m and m.group(1) in greek:
                g, d = greek[m.group(1)], m.group(2)
                if d:
                    sub = d.translate(str.maketrans("0123456789", "₀₁₂₃₄₅₆₇₈₉"))
                    return f" ({g}{d}, {g}{sub} and {m.group(1)}_{d} work too)"
                return f" ({g} works too)"
        return ""

    def ambiguous(self, name: str) -> InvalidAnswer:
        return InvalidAnswer(f"“{name}” can be read as names in more than one way: put * or spaces between them.")


SCALAR = Grammar()

# --------------------------------------------------------------------------- text -> tokens

_DEGREE_LIKE = str.maketrans({"\u00ba": "°", "\u02da": "°", "\u2218": "°", "\u00b0": "°"})
_FRACTIONS = {"\u00bd": "(1/2)", "\u00bc": "(1/4)", "\u00be": "(3/4)", "\u2153": "(1/3)", "\u2154": "(2/3)"}
_SUPER = str.maketrans("⁰¹²³⁴⁵⁶⁷⁸⁹⁻⁺", "0123456789-+")
_SUPER_RUN = re.compile("[⁰¹²³⁴⁵⁶⁷⁸⁹⁻⁺]+")
_AFTER_NFKC = str.maketrans({
    "\u2010": "-", "\u2011": "-", "\u2012": "-", "\u2013": "-", "\u2014": "-", "\u2212": "-",
    "\ufe63": "-", "\uff0d": "-", "\u00d7": "*", "\u22c5": "*", "\u00b7": "*", "\u2217": "*",
    "\u00f7": "/", "\u2044": "/", "\u2215": "/", "\u2248": "=",
})
_PREFIX = re.compile(r"\s*[^\W\d][\w']*\s*=\s*")
_TOKEN = re.compile(r"""\s*(?:
    (?P<num>(?:[0-9]+\.?[0-9]*|\.[0-9]+)(?:[eE][+-]?[0-9]+)?)
  | (?P<name>[^\W\d]\w*)
  | (?P<op>\*\*|[-+*/^(),°√\[\]{}=])
  | (?P<str>'[^']*'?|"[^"]*"?)
)""", re.X)
_COMMA_NUMBER = re.compile(r"([+-]?\d+),(\d+)((?:,\d+)*)\s*(?:[^\d\s,.(][^,]*)?")


def canonical_name(name: str) -> str:
    """ASCII spelling of a name a learner typed: Greek spelled out, a leading Δ as d.

    >>> canonical_name("θ1"), canonical_name("Δt"), canonical_name("ω")
    ('theta1', 'dt', 'omega')
    """
    if name.isascii():
        return name
    out = []
    for i, ch in enumerate(name):
        if ch == "Δ" and i == 0 and len(name) > 1:
            out.append("d")
        else:
            out.append(GREEK.get(ch, ch))
    return "".join(out)


def normalise(text: str) -> str:
    """Unify the many ways of typing the same symbols (minus signs, °, ×, superscripts).

    >>> normalise("θ₂ = −45º × 2²")
    'θ2 = -45° * 2^(2)'
    """
    if text.replace("°", "").isascii():  # nothing below changes ASCII text
        return text.strip()
    s = text.translate(_DEGREE_LIKE)
    if any(ch in s for ch in _FRACTIONS):  # 2½ is 2 + 1/2, ½ alone is 1/2
        s = re.sub(r"(\d)\s*([½¼¾⅓⅔])", lambda m: f"({m.group(1)}+{_FRACTIONS[m.group(2)]})", s)
        for old, new in _FRACTIONS.items():
            s = s.replace(old, new)
    s = _SUPER_RUN.sub(lambda m: "^(" + m.group(0).translate(_SUPER) + ")", s)
    s = unicodedata.normalize("NFKC", s)
    return s.translate(_AFTER_NFKC).strip()


def _generic(grammar: Grammar) -> InvalidAnswer:
    return InvalidAnswer(f"That is not a number or an arithmetic expression. Examples that work: {grammar.examples}.")


def _check_commas(s: str) -> None:
    m = _COMMA_NUMBER.fullmatch(s)
    if not m:
        return
    a, b, more = m.group(1), m.group(2), m.group(3)
    if len(b) == 3 and (not more or all(len(g) == 3 for g in more.split(",")[1:])) and len(a.lstrip("+-")) <= 3:
        whole = a + b + more.replace(",", "")
        decimal = f"{a}.{b.rstrip('0') or '0'}"
        if more:
            raise InvalidAnswer(f"Write {whole} without thousands separators.")
        raise InvalidAnswer(
            f"“{a},{b}” is ambiguous: write {whole} (no thousands separator) or {decimal} (a dot for decimals).")
    if not more:
        raise InvalidAnswer(f"Use a dot for decimals: write {a}.{b}, not {a},{b}.")


def tokenize(text: str, grammar: Grammar) -> list[tuple]:
    """Tokens ``(kind, value, space_before)``; names are classified by ``grammar``.

    Kinds: num, var, const, func, unit, op, str, end. A name that is not known is
    split into known names when that can be done in exactly one way
    (``L1cos`` -> L1, cos); otherwise it is an error naming what is allowed.
    """
    raw: list[tuple] = []
    pos, n = 0, len(text)
    while pos < n:
        m = _TOKEN.match(text, pos)
        if not m or m.end() == pos or m.lastgroup is None:
            if text[pos:].strip() == "":
                break
            raise _generic(grammar)
        space = m.start(m.lastgroup) > pos
        kind, value = m.lastgroup, m.group(m.lastgroup)
        pos = m.end()
        raw.append((kind, value, space))
    tokens: list[tuple] = []
    for k, (kind, value, space) in enumerate(raw):
        if kind == "num":
            tokens.append(("num", float(value), space))
        elif kind == "name":
            call = k + 1 < len(raw) and raw[k + 1][1] == "("
            tokens.extend(_classify(value, space, grammar, call))
        elif value == "°":
            tokens.append(("unit", "°", space))
        else:
            tokens.append((kind, value, space))
    tokens.extend([("end", None, False)] * 4)
    return tokens


def _classify(raw: str, space: bool, grammar: Grammar, call: bool) -> list[tuple]:
    name = canonical_name(raw)
    for candidate in (name, name.replace("_", "")):
        kind = grammar.kind(candidate)
        if kind:
            return [(kind, ALIASES.get(candidate, candidate), space)]
    count, pieces = _segment(name.replace("_", ""), grammar)
    if count > 1:
        raise grammar.ambiguous(raw)
    if count == 0:
        lowered = [v for v in grammar.variables if v.lower() == name.replace("_", "").lower()]
        if len(lowered) == 1:
            return [("var", lowered[0], space)]
        raise grammar.unknown(raw, call)
    out = []
    for i, (kind, value) in enumerate(pieces):
        out.append((kind, float(value) if kind == "num" else ALIASES.get(value, value), space and i == 0))
    return out


def _segment(name: str, grammar: Grammar) -> tuple[int, list[tuple[str, str]]]:
    """How many ways (0, 1, or 2 for "several") ``name`` reads as known names in a row, and one of them."""
    n = len(name)
    if n > 40:
        return 0, []
    memo: dict[tuple[int, bool], tuple[int, list]] = {}

    def ways(i: int, after_func: bool) -> tuple[int, list]:
        if i == n:
            return 1, []
        if (i, after_func) in memo:
            return memo[(i, after_func)]
        count, best = 0, []
        for j in range(i + 1, n + 1):
            piece = name[i:j]
            if piece.isdigit():
                if not after_func or (j < n and name[j].isdigit()):
                    continue
                kind = "num"
            else:
                kind = grammar.kind(piece)
                if kind is None or kind == "unit" or piece == "e":
                    continue
            c, rest = ways(j, kind == "func")
            if c:
                count += c
                best = [(kind, piece)] + rest
            if count > 1:
                break
        memo[(i, after_func)] = (min(count, 2), best)
        return memo[(i, after_func)]

    return ways(0, False)


# --------------------------------------------------------------------------- tokens -> tree
# Nodes: ("num", v) ("const", name) ("var", name) ("neg", a) ("bin", op, a, b)
#        ("call", name, [args]) ("unit", a, (factor, dim, label, angle_unit))


class Parser:
    def __init__(self, tokens: list[tuple], grammar: Grammar):
        self.t = tokens
        self.i = 0
        self.g = grammar
        self.nodes = 0
        self.depth = 0

    # helpers
    def peek(self, k: int = 0) -> tuple:
        return self.t[self.i + k]  # the token list ends with four "end" tokens

    def next(self) -> tuple:
        self.i += 1
        return self.t[min(self.i, len(self.t)) - 1]

    def is_op(self, tok: tuple, *ops: str) -> bool:
        return tok[0] == "op" and tok[1] in ops

    def node(self, *parts) -> tuple:
        self.nodes += 1
        if self.nodes > MAX_NODES:
            raise InvalidAnswer("That expression is too long; simplify it.")
        return parts

    def enter(self) -> None:
        self.depth += 1
        if self.depth > _MAX_RECURSION:
            raise InvalidAnswer("That expression is nested too deeply; simplify it.")

    def starts_value(self, tok: tuple) -> bool:
        return tok[0] in ("num", "var", "const", "func", "str") or self.is_op(tok, "(", "√", "[", "{")

    # grammar
    def parse(self) -> tuple:
        tree = self.expr()
        tok = self.peek()
        if tok[0] != "end":
            if self.is_op(tok, ","):
                raise InvalidAnswer("One number is expected. Use a dot for decimals (2.5) and no commas.")
            if self.is_op(tok, ")"):
                raise InvalidAnswer("There is a “)” without its “(”.")
            raise _generic(self.g)
        return tree

    def expr(self) -> tuple:
        self.enter()
        left = self.term()
        while self.is_op(self.peek(), "+", "-"):
            op = self.next()[1]
            left = self.node("bin", op, left, self.term())
        self.depth -= 1
        return left

    def term(self) -> tuple:
        left = self.unary()
        divided: tuple | None = None  # (numerator, divisor) when the last operation was "/"
        while True:
            tok = self.peek()
            if tok[0] == "unit":
                unit = self.unit()
                if divided is not None and _has_unit(divided[0]):
                    left = self.node("bin", "/", divided[0], self.node("unit", divided[1], unit))
                else:
                    left = self.node("unit", left, unit)
                divided = None
            elif self.is_op(tok, "*", "/"):
                op = self.next()[1]
                right = self.unary()
                divided = (left, right) if op == "/" else None
                left = self.node("bin", op, left, right)
            elif self.starts_value(tok):
                self.implicit_ok(self.t[self.i - 1], tok)
                left = self.node("bin", "*", left, self.power())
                divided = None
            else:
                return left

    def implicit_ok(self, before: tuple, after: tuple) -> None:
        if after[0] == "num" and before[0] == "num":
            if after[2]:
                raise InvalidAnswer("One number is expected; there is a space between two numbers.")
            raise _generic(self.g)
        if after[0] == "num" and before[0] in ("var", "const", "unit"):
            raise InvalidAnswer(f"Put * between “{before[1] if before[0] != 'unit' else 'the unit'}” and the number after it.")

    def unary(self) -> tuple:
        tok = self.peek()
        if self.is_op(tok, "-", "+"):
            self.next()
            self.enter()
            operand = self.unary()
            self.depth -= 1
            return self.node("neg", operand) if tok[1] == "-" else operand
        return self.power()

    def power(self) -> tuple:
        base = self.primary()
        if self.is_op(self.peek(), "^", "**"):
            self.next()
            self.enter()
            exponent = self.unary()
            self.depth -= 1
            return self.node("bin", "^", base, exponent)
        return base

    def primary(self) -> tuple:
        tok = self.next()
        kind, value = tok[0], tok[1]
        if kind == "num":
            if math.isinf(value):
                raise InvalidAnswer("That is not a finite number.")
            return self.node("num", value)
        if kind in ("const", "var"):
            return self.node(kind, value)
        if kind == "func":
            return self.call(value)
        if kind == "unit":
            raise InvalidAnswer("Type a number before the unit, for example 53.13°.")
        if kind == "str":
            raise InvalidAnswer("Only numbers can be used in an answer.")
        if kind == "op":
            if value == "(":
                inner = self.expr()
                if self.is_op(self.peek(), ","):
                    raise InvalidAnswer("One number is expected here, not a list or a vector: type just the entry asked for.")
                if not self.is_op(self.next(), ")"):
                    raise InvalidAnswer("A “(” is not closed: add the “)”.")
                return inner
            if value in "[{":
                raise InvalidAnswer("One number is expected here, not a list or a vector: type just the entry asked for.")
            if value == "√":
                return self.call("sqrt", shown="√")
            if value == "°":
                raise InvalidAnswer("Type a number before the unit, for example 53.13°.")
        if kind == "end":
            raise InvalidAnswer("Something is missing at the end of the expression.")
        raise _generic(self.g)

    def call(self, name: str, shown: str | None = None) -> tuple:
        arity = FUNCTIONS[name][0]
        power = None
        if self.is_op(self.peek(), "^", "**") and (self.peek(1)[0] == "num" or (
                self.is_op(self.peek(1), "(") and self.peek(2)[0] == "num" and self.is_op(self.peek(3), ")"))):
            self.next()  # sin^2 x, sin²(x): the power of the function's value
            power = self.primary()
        if self.is_op(self.peek(), "("):
            self.next()
            self.enter()
            args = [self.expr()]
            while self.is_op(self.peek(), ","):
                self.next()
                args.append(self.expr())
            self.depth -= 1
            if not self.is_op(self.next(), ")"):
                raise InvalidAnswer(f"The “(” after {name} is not closed: add the “)”.")
            if len(args) != arity:
                raise InvalidAnswer(f"{name} takes {arity} argument{'s' if arity > 1 else ''}.")
        elif arity == 1:
            args = [self.bare_argument(shown or name)]
        else:
            raise InvalidAnswer(f"{name} needs its arguments in parentheses, for example {name}(4, 3).")
        out = self.node("call", name, args)
        return self.node("bin", "^", out, power) if power is not None else out

    def bare_argument(self, name: str) -> tuple:
        """A function without parentheses takes one number, name or number-with-unit: cos 45°."""
        tok = self.peek()
        example = "√2" if name == "√" else f"{name}(2)"
        negative = False
        if self.is_op(tok, "-", "+") and self.peek(1)[0] in ("num", "var", "const"):
            negative = self.next()[1] == "-"
            tok = self.peek()
        if tok[0] == "func":
            self.next()
            self.enter()
            arg = self.call(tok[1])
            self.depth -= 1
        elif tok[0] in ("num", "var", "const"):
            arg = self.primary()
            if self.peek()[0] == "unit":
                arg = self.node("unit", arg, self.unit())
        else:
            raise InvalidAnswer(f"{name} needs an argument in parentheses, for example {example}.")
        after = self.peek()
        if name not in ("√", "sqrt", "abs") and self.is_op(after, "/"):
            # cos pi/3: cos(π/3) or cos(π)/3? Both are common; ask instead of guessing.
            raise InvalidAnswer(f"Put the argument of {name} in parentheses: {name}(pi/3) or {name}(pi)/3.")
        if after[0] in ("num", "var", "const") or self.is_op(after, "(", "^", "**", "[", "{"):
            shown = "√" if name == "√" else name
            raise InvalidAnswer(f"Put the argument of {shown} in parentheses, for example {shown}(2x) or {shown}(x)·y.")
        return self.node("neg", arg) if negative else arg

    def unit(self) -> tuple:
        tok = self.next()
        factor, dim = U.lookup(tok[1])  # type: ignore[misc]
        label, angle = tok[1], U.ANGLE_UNIT.get(tok[1].lower())
        after, denom = self.peek(), self.peek(1)
        if (self.is_op(after, "/") and denom[0] == "unit" and not self.is_op(self.peek(2), "(", "^")
                and denom[1] != "°"):
            self.i += 2
            f2, d2 = U.lookup(denom[1])  # type: ignore[misc]
            factor, dim, label = factor / f2, tuple(a - b for a, b in zip(dim, d2)), f"{label}/{denom[1]}"
            angle = None
        return (factor, dim, label, angle)


def _has_unit(node: tuple) -> bool:
    if node[0] == "unit":
        return True
    return any(_has_unit(part) for part in node[1:] if isinstance(part, tuple)) or (
        node[0] == "call" and any(_has_unit(a) for a in node[2]))


def parse_tree(text: str, grammar: Grammar = SCALAR) -> tuple:
    """Normalise, check the limits, tokenize and parse; the tree, or InvalidAnswer."""
    if not isinstance(text, str):
        raise InvalidAnswer("Type your answer as text, for example 0.5 or sqrt(2)/2.")
    if not text.strip():
        raise InvalidAnswer("Type an answer first: a number such as 0.5, or an expression such as sqrt(2)/2.")
    if len(text) > MAX_LENGTH:
        raise InvalidAnswer(f"That answer is too long (more than {MAX_LENGTH} characters); one number is expected.")
    s = normalise(text)
    m = _PREFIX.match(s)
    if m and "=" not in s[m.end():]:
        s = s[m.end():].strip()
        if not s:
            raise InvalidAnswer("Type the value after “=”.")
    if "=" in s:
        raise InvalidAnswer("Type just the value: at most one name and “=” in front of it, as in θ2 = 90°.")
    if len(s) > 2 * MAX_LENGTH:
        raise InvalidAnswer("That answer is too long; one number is expected.")
    depth = 0
    for ch in s if s.count("(") + s.count("[") + s.count("{") > MAX_DEPTH else "":
        if ch in "([{":
            depth += 1
            if depth > MAX_DEPTH:
                raise InvalidAnswer("That expression is nested too deeply; simplify it.")
        elif ch in ")]}":
            depth -= 1
    _check_commas(s)
    try:
        return Parser(tokenize(s, grammar), grammar).parse()
    except RecursionError:
        raise InvalidAnswer("That expression is nested too deeply; simplify it.") from None


# --------------------------------------------------------------------------- tree -> quantity
# A quantity is (si value, dimension or None when no unit was written, angle unit shown or None).


def _dims(a: U.Dim | None, b: U.Dim | None, sign: int) -> U.Dim | None:
    if a is None and b is None:
        return None
    a, b = a or U.NONE, b or U.NONE
    return (a[0] + sign * b[0], a[1] + sign * b[1], a[2] + sign * b[2])


def _bare(dim: U.Dim | None) -> bool:
    return dim is None or dim == U.NONE


def _evaluate(node: tuple) -> tuple[float, U.Dim | None, str | None]:
    kind = node[0]
    if kind == "num":
        return node[1], None, None
    if kind == "const":
        return CONSTANTS[node[1]], None, None
    if kind == "neg":
        v, d, a = _evaluate(node[1])
        return -v, d, a
    if kind == "unit":
        v, d, a = _evaluate(node[1])
        factor, dim, _label, angle = node[2]
        return v * factor, _dims(d, dim, 1), angle or a
    if kind == "bin":
        op = node[1]
        v1, d1, a1 = _evaluate(node[2])
        v2, d2, a2 = _evaluate(node[3])
        angle = a1 or a2
        if op in "+-":
            if d1 != d2:
                if _bare(d1) and _bare(d2):
                    d1 = U.NONE
                elif d1 is None or d2 is None:
                    if U.ANGLE in (d1, d2):
                        raise InvalidAnswer(
                            "Give every term its unit, or none: 45° + 45°, not 45 + 45°. A number without a unit "
                            "next to an angle could be degrees or radians (write pi/4 rad or 45°).")
                    raise InvalidAnswer("Give every term its unit, or none: 1 m + 20 cm, not 1 m + 20.")
                else:
                    raise InvalidAnswer(f"These cannot be added: {U.describe(d1)} and {U.describe(d2)}.")
            return (v1 + v2 if op == "+" else v1 - v2), d1, angle
        if op == "*":
            return v1 * v2, _dims(d1, d2, 1), angle
        if op == "/":
            if v2 == 0:
                raise InvalidAnswer("That divides by zero.")
            return v1 / v2, _dims(d1, d2, -1), angle
        # power
        if not _bare(d2):
            raise InvalidAnswer("An exponent cannot have a unit.")
        if abs(v2) > MAX_EXPONENT:
            raise InvalidAnswer("That exponent is too large.")
        if v1 < 0 and v2 != int(v2):
            raise InvalidAnswer("A negative number to a fractional power is not a real number.")
        if not _bare(d1):
            if v2 != int(v2):
                raise InvalidAnswer("A quantity with a unit can only be raised to a whole power.")
            d1 = (d1[0] * int(v2), d1[1] * int(v2), d1[2] * int(v2))
        if v1 == 0 and v2 < 0:
            raise InvalidAnswer("That divides by zero.")
        return math.pow(v1, v2), d1, a1
    if kind == "call":
        return _call(node[1], [_evaluate(a) for a in node[2]])
    raise InvalidAnswer("That is not a number or an arithmetic expression.")  # pragma: no cover


def _call(name: str, args: list) -> tuple[float, U.Dim | None, str | None]:
    values = [a[0] for a in args]
    dims = [a[1] for a in args]
    out_dim: U.Dim | None = None if all(d is None for d in dims) else U.NONE
    if name in _TRIG:
        if dims[0] not in (None, U.NONE, U.ANGLE):
            raise InvalidAnswer(f"{name} needs an angle, not {U.describe(dims[0])}.")
    elif name == "sqrt":
        d = dims[0]
        if not _bare(d):
            if any(x % 2 for x in d):  # type: ignore[union-attr]
                raise InvalidAnswer(f"The square root of {U.describe(d)} has no unit I know.")
            out_dim = (d[0] // 2, d[1] // 2, d[2] // 2)  # type: ignore[index]
    elif name == "abs":
        out_dim = dims[0]
    elif name == "atan2":
        if dims[0] != dims[1] and not (_bare(dims[0]) and _bare(dims[1])):
            raise InvalidAnswer("atan2 needs its two arguments in the same unit.")
    elif not all(_bare(d) for d in dims):
        raise InvalidAnswer(f"{name} needs a plain number, not {U.describe(next(d for d in dims if not _bare(d)))}.")
    try:
        value = float(FUNCTIONS[name][1](*values))
    except (ValueError, OverflowError, ZeroDivisionError):
        raise InvalidAnswer(f"{name} is not defined there (check its argument).") from None
    return value, out_dim, (args[0][2] if name == "abs" else None)


_PLAIN = re.compile(r"\s*[+-]?(?:[0-9]+\.?[0-9]*|\.[0-9]+)(?:[eE][+-]?[0-9]+)?\s*")


def _parse(text: object) -> tuple[Answer, U.Dim | None]:
    if isinstance(text, str) and len(text) <= MAX_LENGTH:
        if _PLAIN.fullmatch(text):  # the common case, a plain number: no parser needed
            value = float(text)
            if math.isfinite(value):
                return Answer(value=value, unit=None, text=text), None
        return _parse_cached(text)
    return _parse_text(text)


@functools.lru_cache(maxsize=512)
def _parse_cached(text: str) -> tuple[Answer, U.Dim | None]:
    return _parse_text(text)  # errors are raised, not cached


def _parse_text(text: object) -> tuple[Answer, U.Dim | None]:
    tree = parse_tree(text)  # type: ignore[arg-type]
    try:
        si, dim, angle = _evaluate(tree)
    except (OverflowError, RecursionError):
        raise InvalidAnswer("That number is too large.") from None
    if math.isnan(si) or math.isinf(si):
        raise InvalidAnswer("That is not a finite number.")
    unit = None
    value = si
    if dim == U.ANGLE:
        unit = angle or "rad"
        value = si / U.UNITS["°"][0] if unit == "deg" else si
    return Answer(value=value, unit=unit, text=text, dimension=U.dimension_name(dim), si=si), dim  # type: ignore[arg-type]


def parse_answer(text: object) -> Answer:
    """Read ``text`` as one real number (with a unit, if one is written), or raise :class:`InvalidAnswer`.

    >>> a = parse_answer("θ2 = 90°"); round(a.value, 9), a.unit
    (90.0, 'deg')
    >>> parse_answer("-0.2 m").si, parse_answer("10 m / 5 s").dimension
    (-0.2, 'speed')
    >>> round(parse_answer("cos 45°").value, 4), parse_answer("cos 45°").dimension
    (0.7071, '')
    """
    return _parse(text)[0]


def parse_quantity(text: object, expect: str | None) -> float:
    """The answer's value in the unit the exercise asks for.

    ``expect`` is one of ``"deg"``, ``"rad"``, ``"m"``, ``"m/s"``, ``"s"``, or None
    for a plain number. A plain number (no unit, or units that cancel) is
    returned as typed; a unit of the right kind is converted; a unit of the
    wrong kind is :class:`InvalidAnswer` naming the unit expected.

    >>> parse_quantity("20 cm", "m"), parse_quantity("0.5", "m")
    (0.2, 0.5)
    >>> round(parse_quantity("pi/2 rad", "deg"), 9), round(parse_quantity("90°", "rad"), 9)
    (90.0, 1.570796327)
    >>> parse_quantity("3 m", None)
    Traceback (most recent call last):
    ...
    workbook.answers.InvalidAnswer: This answer is a plain number, without a unit; 3 m is a length.
    """
    if expect is not None and expect not in U.EXPECT:
        raise ValueError(f"expect must be one of {sorted(U.EXPECT)} or None, not {expect!r}")
    answer, dim = _parse(text)
    if _bare(dim):
        return answer.value if dim is None else answer.si  # type: ignore[return-value]
    shown = str(text).strip()
    shown = shown if len(shown) <= 24 else "what you typed"
    if expect is None:
        raise InvalidAnswer(f"This answer is a plain number, without a unit; {shown} is {U.describe(dim)}.")
    factor, want, words = U.EXPECT[expect]
    if dim != want:
        raise InvalidAnswer(f"This answer is {words}; {shown} is {U.describe(dim)}.")
    return answer.si / factor  # type: ignore[operator]
