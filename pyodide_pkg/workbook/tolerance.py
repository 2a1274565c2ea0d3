"""When a typed number counts as the key (GUIDE §2).

- Relative tolerance 1e-3 by default: the derivations print 4 significant
  figures or more, and a chained answer may differ in its last digit.
- Engineers round to 3 significant figures: a value typed to n ≥ 3
  significant figures is also right when it lies within half a unit of its
  last typed digit of the key (``0.123`` for 0.1234, but not ``0.1238``).
- An absolute floor applies only where the key is zero, and keys are cleaned
  of float noise first, so a key of 2e-16 from cos(90°) *is* zero.
- Counts and other integers are exact (``exact=True``).
- "Close" is a 2 % band around a non-zero key. A zero key has no scale, so a
  value is only called close when it is within 5 floors of it; and the "wrong
  sign" slip never fires for a zero key (−0 and 0 are the same answer).

>>> agrees(0.1438, 1 / 7)      # the old absolute floor of 1e-3 accepted this
False
>>> agrees(0.123, 0.1234), agrees(0.123, 0.1234, half_unit=0.0005), agrees(0.122, 0.1234, half_unit=0.0005)
(False, True, False)
>>> agrees(0.1429, 1 / 7), agrees(7493, 7500, exact=True), agrees(7500, 7500.0, exact=True)
(True, False, True)
"""

from __future__ import annotations

import math
from decimal import ROUND_HALF_EVEN, ROUND_HALF_UP, Decimal

REL = 1e-3
FIGURES = 3  # a value typed to this many significant figures or more may use its own rounding
ZERO_FLOOR = 1e-3  # |value| accepted for a key of zero (a key has no scale there; 4-decimal rounding stays inside)
CLOSE = 0.02
NOISE = 1e-12


def clean(x: float) -> float:
    """A key without float noise: |x| < 1e-12 is 0.0, else x rounded to 12 significant digits.

    >>> clean(math.cos(math.pi / 2)), clean(-1e-17), clean(0.1 + 0.2), clean(2.0)
    (0.0, 0.0, 0.3, 2.0)
    >>> clean(1e-9), clean(float("inf"))
    (1e-09, inf)
    """
    if not math.isfinite(x):
        return x
    if abs(x) < NOISE:
        return 0.0
    return float(f"{x:.12g}")


def agrees(value: float, key: float, rel: float = REL, exact: bool = False, half_unit: float | None = None,
           floor: float = 0.0) -> bool:
    """True when ``value`` counts as ``key``.

    Relative: |value − key| ≤ rel·|key|. A zero key (after :func:`clean`) takes
    |value| ≤ 1e-3 instead. ``exact`` (counts, integers): equal after cleaning.
    ``half_unit``, for a value typed to at least :data:`FIGURES` significant
    figures: half a unit of its last digit; within that of the key is right too.
    ``floor``: an absolute tolerance from the scale of the question, for a key that
    cancels to near zero where the question's numbers do not (a carried answer).

    >>> agrees(0.7071, math.sqrt(2) / 2), agrees(0.707, math.sqrt(2) / 2), agrees(0.70, math.sqrt(2) / 2)
    (True, True, False)
    >>> agrees(0.0004, math.cos(math.pi / 2)), agrees(0.002, 0.0), agrees(-0.0, 0.0)
    (True, False, True)
    >>> agrees(2e-7, 1e-7)          # a small key is not zero: still relative
    False
    >>> agrees(3.0000000000001, 3, exact=True), agrees(3.01, 3, exact=True)
    (True, False)
    >>> agrees(0.0, 3e-9), agrees(0.0, 3e-9, floor=0.002)   # a key that cancels, on a scale of 2
    (False, True)
    """
    if not (math.isfinite(value) and math.isfinite(key)):
        return False
    if exact:
        return clean(value) == clean(key)
    if half_unit is not None and abs(value - key) <= half_unit * (1 + 1e-9):
        return True
    if abs(value - key) <= floor:
        return True
    if abs(key) < NOISE:  # clean(key) == 0; rounding to 12 digits cannot matter at 1e-3
        return abs(value) <= ZERO_FLOOR
    return abs(value - key) <= rel * abs(key) * (1 + 1e-12)


def is_close_miss(value: float, key: float, rel: float = REL, figures: int | None = None) -> bool:
    """Not accepted, but within 2 % of a non-zero key (or 5 floors of a zero key), or the key rounded to
    the significant figures typed (``figures``, however few: :func:`is_rounding`).

    >>> is_close_miss(0.1438, 1 / 7), is_close_miss(0.1429, 1 / 7), is_close_miss(0.2, 1 / 7)
    (True, False, False)
    >>> is_close_miss(0.12, 0.12341), is_close_miss(0.12, 0.12341, figures=2)  # 2 figures, rounded right
    (False, True)
    >>> is_close_miss(1.0, math.sqrt(0.5), figures=1)  # 0.7071 to 1 figure is 0.7, not 1
    False
    >>> is_close_miss(-0.1429, 1 / 7)  # a sign slip is not "close"
    False
    >>> is_close_miss(0.003, 0.0), is_close_miss(0.02, 1e-17), is_close_miss(0.0005, 0.0)
    (True, False, False)
    >>> is_close_miss(0.0, -0.1, figures=1)  # 0 is no rounding of −0.1
    False
    """
    if not (math.isfinite(value) and math.isfinite(key)) or agrees(value, key, rel):
        return False
    key = clean(key)
    if figures is not None and is_rounding(value, key, figures):
        return True
    if key == 0.0:
        return abs(value) <= 5 * ZERO_FLOOR
    return abs(value - key) <= CLOSE * abs(key)


def is_rounding(value: float, key: float, figures: int | None) -> bool:
    """``value`` is ``key`` rounded to ``figures`` significant figures (half up, or half to even): not
    zero, and the key's sign. ``1`` is no rounding of 0.7071 (to 1 figure it is 0.7); 0 is none of −0.1.

    >>> is_rounding(0.12, 0.12341, 2), is_rounding(0.7, 0.7071, 1), is_rounding(1.0, 0.7071, 1)
    (True, True, False)
    >>> is_rounding(0.0, -0.1, 1), is_rounding(0.1, -0.1, 1), is_rounding(-0.1, -0.1234, 1)
    (False, False, True)
    >>> is_rounding(1.0, 0.97, 1), is_rounding(0.13, 0.125, 2), is_rounding(0.12, 0.125, 2), is_rounding(1200, 1234, 2)
    (True, True, True, True)
    """
    key = clean(key)
    if not figures or figures < 1 or key == 0.0 or value == 0.0 or (value > 0) != (key > 0) \
            or not (math.isfinite(value) and math.isfinite(key)):
        return False
    digits = Decimal(repr(key))
    step = Decimal(1).scaleb(digits.adjusted() - (figures - 1))
    return any(math.isclose(value, float(digits.quantize(step, rounding=way)), rel_tol=1e-9)
               for way in (ROUND_HALF_UP, ROUND_HALF_EVEN))


def is_sign_slip(value: float, key: float, rel: float = REL) -> bool:
    """The size is right and the sign is wrong; never for a zero key.

    >>> is_sign_slip(-0.5, 0.5), is_sign_slip(0.5, 0.5), is_sign_slip(-1e-4, 2e-16)
    (True, False, False)
    """
    key = clean(key)
    return key != 0.0 and not agrees(value, key, rel) and agrees(-value, key, rel)
