"""Where the math is undefined: the one exception the reference raises for it, with the reason in words.

Keys never meet it (a draw whose numbers are degenerate is not offered), but a
learner's own wrong earlier value can: an offset of (0, 0) has no direction.
The grader then says, in the exception's words, why nothing can follow from it.

>>> bearing_of(0.0, 0.0)
Traceback (most recent call last):
...
workbook.reference.domain.Undefined: the offset (0, 0) has no direction, so no bearing is defined
>>> round(bearing_of(0.0, 2.0), 4)
1.5708
"""

from __future__ import annotations

import math


class Undefined(ArithmeticError):
    """A quantity these numbers leave undefined; ``str()`` says why, in a learner's words."""


def bearing_of(dx: float, dy: float) -> float:
    """atan2(dy, dx), refused where the offset has no direction (atan2(0, 0) would give 0).

    >>> round(math.degrees(bearing_of(3.0, 4.0)), 2)
    53.13
    """
    if dx == 0 and dy == 0:
        raise Undefined("the offset (0, 0) has no direction, so no bearing is defined")
    return math.atan2(dy, dx)
