"""From a tree to a quantity: the value in SI with its dimension, and the angle unit typed.

A quantity is ``(si value, dimension or None when no unit was written, angle
unit shown or None)``. Products and quotients combine dimensions, sums need
equal ones, trigonometric functions take angles or bare numbers; every refusal
is an :class:`~.grammar.InvalidAnswer` with a message for the learner.

>>> from workbook.expr.parsing import parse_tree
>>> evaluate(parse_tree("10 m / 5 s"))
(2.0, (0, 1, -1), None)
>>> evaluate(parse_tree("90°"))[1:]
((1, 0, 0), 'deg')
>>> evaluate(parse_tree("1 m + 20"))
Traceback (most recent call last):
...
workbook.expr.InvalidAnswer: Give every term its unit, or none: 1 m + 20 cm, not 1 m + 20.
"""

from __future__ import annotations

import math

from .. import units as U
from .grammar import CONSTANTS, FUNCTIONS, MAX_EXPONENT, TRIG, InvalidAnswer


def _dims(a: U.Dim | None, b: U.Dim | None, sign: int) -> U.Dim | None:
    """The dimension of a product (sign 1) or quotient (sign -1); None when neither side has a unit."""
    if a is None and b is None:
        return None
    a, b = a or U.NONE, b or U.NONE
    return (a[0] + sign * b[0], a[1] + sign * b[1], a[2] + sign * b[2])


def bare(dim: U.Dim | None) -> bool:
    """No unit written, or units that cancel: a plain number."""
    return dim is None or dim == U.NONE


def evaluate(node: tuple) -> tuple[float, U.Dim | None, str | None]:
    """The quantity of a tree from :func:`~.parsing.parse_tree`, or :class:`InvalidAnswer` saying why not."""
    kind = node[0]
    if kind == "num":
        return node[1], None, None
    if kind == "const":
        return CONSTANTS[node[1]], None, None
    if kind == "neg":
        v, d, a = evaluate(node[1])
        return -v, d, a
    if kind == "unit":
        v, d, a = evaluate(node[1])
        factor, dim, _label, angle = node[2]
        return v * factor, _dims(d, dim, 1), angle or a
    if kind == "bin":
        op = node[1]
        v1, d1, a1 = evaluate(node[2])
        v2, d2, a2 = evaluate(node[3])
        angle = a1 or a2
        if op in "+-":
            if d1 != d2:
                if bare(d1) and bare(d2):
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
        if not bare(d2):
            raise InvalidAnswer("An exponent cannot have a unit.")
        if abs(v2) > MAX_EXPONENT:
            raise InvalidAnswer("That exponent is too large.")
        if v1 < 0 and v2 != int(v2):
            raise InvalidAnswer("A negative number to a fractional power is not a real number.")
        if d1 is not None and not bare(d1):
            if v2 != int(v2):
                raise InvalidAnswer("A quantity with a unit can only be raised to a whole power.")
            d1 = (d1[0] * int(v2), d1[1] * int(v2), d1[2] * int(v2))
        if v1 == 0 and v2 < 0:
            raise InvalidAnswer("That divides by zero.")
        return math.pow(v1, v2), d1, a1
    if kind == "call":
        return _call(node[1], [evaluate(a) for a in node[2]])
    raise InvalidAnswer("That is not a number or an arithmetic expression.")  # pragma: no cover


def _call(name: str, args: list) -> tuple[float, U.Dim | None, str | None]:
    """A function applied to evaluated arguments, checking that their units suit it."""
    values = [a[0] for a in args]
    dims = [a[1] for a in args]
    out_dim: U.Dim | None = None if all(d is None for d in dims) else U.NONE
    if name in TRIG:
        if dims[0] not in (None, U.NONE, U.ANGLE):
            raise InvalidAnswer(f"{name} needs an angle, not {U.describe(dims[0])}.")
    elif name == "sqrt":
        d = dims[0]
        if not bare(d):
            if any(x % 2 for x in d):
                raise InvalidAnswer(f"The square root of {U.describe(d)} has no unit I know.")
            out_dim = (d[0] // 2, d[1] // 2, d[2] // 2)
    elif name == "abs":
        out_dim = dims[0]
    elif name == "atan2":
        if dims[0] != dims[1] and not (bare(dims[0]) and bare(dims[1])):
            raise InvalidAnswer("atan2 needs its two arguments in the same unit.")
    elif not all(bare(d) for d in dims):
        raise InvalidAnswer(f"{name} needs a plain number, not {U.describe(next(d for d in dims if not bare(d)))}.")
    try:
        value = float(FUNCTIONS[name][1](*values))
    except (ValueError, OverflowError, ZeroDivisionError):
        raise InvalidAnswer(f"{name} is not defined there (check its argument).") from None
    return value, out_dim, (args[0][2] if name == "abs" else None)
