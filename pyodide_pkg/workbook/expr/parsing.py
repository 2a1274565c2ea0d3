"""From tokens to a tree: a small recursive-descent parser, with limits checked as it goes.

The tree is made of tuples::

    ("num", v) ("const", name) ("var", name) ("neg", a) ("bin", op, a, b)
    ("call", name, [args]) ("unit", a, (factor, dim, label, angle_unit))

:func:`parse_tree` is the whole road from text: it checks the length, drops a
leading ``θ2 =``, normalises, tokenizes and parses. The rules for where a unit
binds are listed in :mod:`workbook.answers`.

>>> parse_tree("2*pi")
('bin', '*', ('num', 2.0), ('const', 'pi'))
>>> parse_tree("θ2 = -x", Grammar(variables=frozenset({"x"})))
('neg', ('var', 'x'))
"""

from __future__ import annotations

import math
import re

from .. import units as U
from .grammar import (
    FUNCTIONS,
    GREEK,
    MAX_DEPTH,
    MAX_LENGTH,
    MAX_NODES,
    SCALAR,
    Grammar,
    InvalidAnswer,
    not_an_expression,
)
from .tokens import check_commas, normalise, tokenize

_MAX_RECURSION = 60  # unary minus chains, powers of powers: far below Python's limit
PREFIX = re.compile(r"\s*[^\W\d][\w']*\s*=\s*")


class Parser:
    """A recursive-descent parser over the tokens of :func:`~.tokens.tokenize`; :meth:`parse` gives the tree."""

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
            raise not_an_expression(self.g)
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
            raise not_an_expression(self.g)
        if after[0] == "num" and before[0] == "unit" and before[1] == "°":
            raise InvalidAnswer("Write an angle in degrees, minutes and seconds with their marks, 53°7′48″ "
                                "(or 53°7'48\"), or in decimal degrees: 53.13°.")
        if after[0] == "num" and before[0] in ("var", "const", "unit"):
            raise InvalidAnswer(f"Put * between “{before[1]}” and the number after it.")

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
                    raise InvalidAnswer("One number is expected here, not a list or a vector: type just the entry "
                                        "asked for.")
                if not self.is_op(self.next(), ")"):
                    raise InvalidAnswer("A “(” is not closed: add the “)”.")
                return inner
            if value in "[{":
                raise InvalidAnswer("One number is expected here, not a list or a vector: type just the entry asked "
                                    "for.")
            if value == "√":
                return self.call("sqrt", shown="√")
            if value == "°":
                raise InvalidAnswer("Type a number before the unit, for example 53.13°.")
        if kind == "end":
            raise InvalidAnswer("Something is missing at the end of the expression.")
        raise not_an_expression(self.g)

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
        elif tok[0] == "num" and self.peek(1)[0] in ("var", "const") and not self.is_op(self.peek(2), "^", "**"):
            number = self.primary()  # sin 2θ, as typeset: the number is the symbol's coefficient
            arg = self.node("bin", "*", number, self.primary())
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
        if after[0] in ("var", "const") and after[2] and arg[0] != "num":
            return self.node("neg", arg) if negative else arg  # sin θ dt, as typeset: sin(θ)·dt
        if after[0] in ("var", "const") and arg[0] in ("var", "const"):  # sin θdt: sin(θ·dt) or sin(θ)·dt?
            shown, a, b = ("√" if name == "√" else name), _name(arg[1]), _name(after[1])
            raise InvalidAnswer(f"Put the argument of {shown} in parentheses: {shown}({a}*{b}) or {shown}({a})*{b}.")
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


def _name(name: str) -> str:
    """A name as a learner types it in a message: θ for theta, θ1 for theta1."""
    greek = {word: letter for letter, word in GREEK.items() if letter not in "ϕ"}
    stem = name.rstrip("0123456789")
    return greek.get(stem, stem) + name[len(stem):]


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
    if len(text) > MAX_LENGTH * (3 if "\\" in text else 1):  # LaTeX says the same thing at greater length
        raise InvalidAnswer(f"That answer is too long (more than {MAX_LENGTH} characters); one number is expected.")
    s = normalise(text)
    m = PREFIX.match(s)
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
    check_commas(s)
    try:
        return Parser(tokenize(s, grammar), grammar).parse()
    except RecursionError:
        raise InvalidAnswer("That expression is nested too deeply; simplify it.") from None
