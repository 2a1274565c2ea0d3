"""How precisely a number was typed: its significant figures and half a unit of its last digit.

Engineers round to 3 significant figures, so marking accepts a value typed to
n ≥ 3 figures when it lies within half a unit of its last digit of the key
(:mod:`workbook.tolerance`). That needs the digits as typed, which the value
alone has lost (``0.1430`` and ``0.143`` are the same float).

>>> from workbook.expr.parsing import parse_tree
>>> typed_precision(parse_tree("0.143"), "0.143")
(3, 0.0005)
>>> typed_precision(parse_tree("θ2 = -5.8660 m"), "θ2 = -5.8660 m")
(5, 5e-05)
>>> typed_precision(parse_tree("1200"), "1200"), typed_precision(parse_tree("1.20e3"), "1.20e3")
((2, 0.5), (3, 5.0))
>>> typed_precision(parse_tree("7 500"), "7 500")  # ISO digit groups: one number
(2, 0.5)
>>> typed_precision(parse_tree("sqrt(2)/2"), "sqrt(2)/2")
(None, None)
"""

from __future__ import annotations

import re

from .parsing import PREFIX
from .tokens import normalise, ungroup

_NUMBER = re.compile(r"(?<![\w.])([0-9]+\.?[0-9]*|\.[0-9]+)(?:[eE]([+-]?[0-9]+))?")


def _single_literal(tree: tuple) -> bool:
    """The tree is one number, perhaps negated, perhaps with a unit after it."""
    while tree[0] in ("neg", "unit"):
        tree = tree[1]
    return tree[0] == "num"


def typed_precision(tree: tuple, text: str) -> tuple[int | None, float | None]:
    """``(significant figures, half a unit of the last digit)`` of a one-number answer, else ``(None, None)``.

    The half unit is in the units typed (the caller converts it)."""
    if not _single_literal(tree):
        return None, None
    s = ungroup(normalise(text))
    m = PREFIX.match(s)
    if m:
        s = s[m.end():]
    found = _NUMBER.findall(s)
    if len(found) != 1:
        return None, None
    mantissa, exponent = found[0]
    whole, _, fraction = mantissa.partition(".")
    digits = (whole + fraction).lstrip("0")
    if "." not in mantissa:
        digits = digits.rstrip("0")
    half = 0.5 * 10.0 ** (int(exponent or 0) - len(fraction))
    return len(digits), half
