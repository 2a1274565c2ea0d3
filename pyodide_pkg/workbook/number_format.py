"""How the workbook prints a number: the one printer every chapter, answer kind and page uses.

The rule (stated where chapter 0 starts):

- A number that is exact at the precision printed is printed as it is, without
  trailing zeros: ``0.5``, ``3``, ``-1.25``, ``0.00125``.
- Any other number is rounded to 4 decimals, or to more where that is needed
  for at least 4 significant figures (``0.03846`` for −1/26), and keeps its
  trailing zeros (``5.8660``), so a reader can tell it was rounded.
- In a derivation, a result that does not follow exactly from the printed
  values it is computed from is written with ``≈`` (:func:`relation`).

Every other module prints through :func:`fmt` (or the TeX helpers built on it),
so the Answer line, the worked answer and "type it as" always agree.

>>> fmt(0.70710678), fmt(3.0), fmt(-0.0), fmt(-1 / 26), fmt(0.5000000000001), fmt(0.00125)
('0.7071', '3', '0', '-0.03846', '0.5', '0.00125')
>>> fmt(5.8660254), fmt(2 / 3), fmt(7500), fmt(1e-7)
('5.8660', '0.6667', '7500', '0.0000001')
"""

from __future__ import annotations

import math
from fractions import Fraction
from functools import lru_cache

SIGNIFICANT = 4  # at least this many significant figures in every printed result
DECIMALS = 4     # and at least this many decimals for a rounded number
_EXACT = 1e-9    # relative: closer than this to its printed form, a number is exact


def _clean(x: float) -> float:
    """``x`` without float noise (12 significant figures; |x| < 1e-12 is 0)."""
    if not math.isfinite(x) or abs(x) < 1e-12:
        return 0.0 if math.isfinite(x) else x
    return float(f"{x:.12g}")


def decimals(x: float, significant: int = SIGNIFICANT) -> int:
    """How many decimals :func:`fmt` rounds ``x`` to: at least 4, and enough for ``significant`` figures.

    >>> decimals(5.866), decimals(0.0385), decimals(0.000123)
    (4, 5, 7)
    """
    if x == 0 or not math.isfinite(x):
        return DECIMALS
    return max(DECIMALS, significant - 1 - math.floor(math.log10(abs(x))))


def is_exact(x: float, significant: int = SIGNIFICANT) -> bool:
    """Whether ``x`` prints without rounding (its printed form is the number itself).

    >>> is_exact(0.25), is_exact(1 / 3), is_exact(0.1 + 0.2), is_exact(12)
    (True, False, True, True)
    """
    x = _clean(float(x))
    if not math.isfinite(x):
        return False
    d = decimals(x, significant)
    return abs(round(x, d) - x) <= _EXACT * max(1.0, abs(x))


def fmt(x: float, significant: int = SIGNIFICANT) -> str:
    """``x`` as the workbook prints it (see the module's rule)."""
    return _fmt(float(x), significant)


@lru_cache(maxsize=8192)  # pages and tests print the same numbers many times over
def _fmt(x: float, significant: int) -> str:
    x = _clean(x)
    if not math.isfinite(x):
        return "∞" if x > 0 else ("−∞" if x < 0 else "NaN")
    d = decimals(x, significant)
    s = f"{x:.{d}f}"
    if is_exact(x, significant):
        s = s.rstrip("0").rstrip(".") if "." in s else s
    return "0" if s.strip("-0.") == "" else s


def shown(x: float) -> float:
    """The value a reader sees: ``x`` rounded as :func:`fmt` prints it.

    >>> shown(5.8660254), shown(-1 / 26)
    (5.866, -0.03846)
    """
    return float(fmt(x))


def half_unit(printed: str) -> float:
    """Half a unit of the last digit of a printed number: how far it may be from what it stands for.

    >>> half_unit("5.8660"), half_unit("0.5"), half_unit("3")
    (5e-05, 0.05, 0.5)
    """
    digits = printed.split(".")[1] if "." in printed else ""
    return 0.5 * 10.0 ** -len(digits)


def relation(result: float, from_printed: float | None = None) -> str:
    """``"="`` or ``"\\approx"`` (TeX) before the printed ``result`` in a derivation.

    Alone: ``"="`` when ``result`` prints exactly. With ``from_printed``, the
    value the line's printed inputs give: ``"="`` only when the printed result
    is that value at its printed precision (half a unit of its last digit; an
    exact result must equal it).

    >>> relation(0.5), relation(1 / 3), relation(4 * 2 ** 0.5, 0.7071 * 4 * 2), relation(5.8660254, 5 + 0.866)
    ('=', '\\\\approx', '\\\\approx', '=')
    """
    exact = is_exact(result)
    if from_printed is None:
        return "=" if exact else "\\approx"
    s = fmt(result)
    room = 1e-9 * max(1.0, abs(result)) if exact else half_unit(s) * (1 + 1e-9)
    return "=" if abs(float(s) - from_printed) <= room else "\\approx"


def approx(x: float) -> str:
    """``= 0.5`` when ``x`` is exact as printed, else ``\\approx 0.9063`` (TeX).

    >>> approx(0.5000000000000001), approx(math.cos(math.radians(25)))
    ('= 0.5', '\\\\approx 0.9063')
    """
    return f"{relation(x)} {fmt(x)}"


def prose(x: float) -> str:
    """A number in running text or a message, with a true minus sign: ``−0.5``.

    >>> prose(-0.5), prose(2)
    ('−0.5', '2')
    """
    return fmt(x).replace("-", "\u2212")


def compact(x: float) -> str:
    """:func:`prose` for a number of ordinary size; one beyond a million in powers of ten
    (``1.414 × 10^300``), as a learner's runaway output may be.

    >>> compact(-0.5), compact(2.5e12), compact(-1e300)
    ('−0.5', '2.500 × 10^12', '−1.000 × 10^300')
    """
    if not math.isfinite(x) or abs(x) < 1e6:
        return prose(x)
    mantissa, exponent = f"{x:.3e}".split("e")
    return f"{mantissa} × 10^{int(exponent)}".replace("-", "\u2212")


def paren(x: float) -> str:
    """A number as a factor in TeX: negative ones in parentheses.

    >>> paren(-2), paren(3), paren(-1 / 3)
    ('(-2)', '3', '(-0.3333)')
    """
    s = fmt(x)
    return f"({s})" if s.startswith("-") else s


def signed(x: float) -> str:
    """A number as a following term: ``+ 2`` or ``- 2``.

    >>> signed(-2), signed(0.5)
    ('- 2', '+ 0.5')
    """
    s = fmt(x)
    return f"- {s[1:]}" if s.startswith("-") else f"+ {s}"


def fixed(x: float, places: int) -> str:
    """``x`` to exactly ``places`` decimals, for prose that says so (an angle to 0.1°).

    >>> fixed(35.7296, 1), fixed(-0.04, 1)
    ('35.7', '0.0')
    """
    s = f"{_clean(float(x)):.{places}f}"
    return s.lstrip("-") if float(s) == 0 else s


def readout(x: float, places: int = 3) -> str:
    """A live figure's readout: exactly ``places`` decimals (the digits stay put as a slider
    moves), a true minus sign, never "−0.000".

    >>> readout(-0.00001), readout(-1.5), readout(2, 1)
    ('0.000', '−1.500', '2.0')
    """
    return fixed(x, places).replace("-", "\u2212")


def readout_vector(values, places: int = 3) -> str:
    """A tuple of readouts: ``(1.000, −0.500)``.

    >>> readout_vector([1, -0.5])
    '(1.000, −0.500)'
    """
    return "(" + ", ".join(readout(v, places) for v in values) + ")"


def readout_matrix(rows, places: int = 3) -> str:
    """A matrix of readouts, one row per line, columns aligned.

    >>> print(readout_matrix([[1, -0.5], [0, 2]]))
     1.000  −0.500
     0.000   2.000
    """
    cells = [[readout(v, places) for v in row] for row in rows]
    width = max(len(c) for row in cells for c in row)
    return "\n".join("  ".join(c.rjust(width) for c in row) for row in cells)


def pi_frac(degrees: float, tex: bool = True) -> str:
    """An angle of whole degrees as a fraction of π: TeX (``\\pi/6``) or text (``π/6``).

    >>> pi_frac(30), pi_frac(25), pi_frac(75, tex=False), pi_frac(90), pi_frac(-45), pi_frac(0)
    ('\\\\pi/6', '5\\\\pi/36', '5π/12', '\\\\pi/2', '-\\\\pi/4', '0')
    """
    f = Fraction(round(degrees), 180)
    if f == 0:
        return "0"
    pi = r"\pi" if tex else "π"
    sign = "-" if f < 0 else ""
    f = abs(f)
    top = pi if f.numerator == 1 else f"{f.numerator}{pi}"
    return sign + (top if f.denominator == 1 else f"{top}/{f.denominator}")


def bmatrix(rows) -> str:
    """A matrix (a sequence of rows) in TeX, each entry printed by :func:`fmt`.

    >>> bmatrix([[1, 0.5], [0, 1 / 3]])
    '\\\\begin{bmatrix} 1 & 0.5 \\\\\\\\ 0 & 0.3333 \\\\end{bmatrix}'
    """
    body = " \\\\ ".join(" & ".join(fmt(v) for v in row) for row in rows)
    return f"\\begin{{bmatrix}} {body} \\end{{bmatrix}}"


def relation_all(results, from_printed=None) -> str:
    """:func:`relation` for a printed vector or matrix (numbers, or rows of numbers):
    ``"="`` when every entry stands in that relation, else ``"\\approx"``.

    >>> relation_all([[0, -1], [1, 0]]), relation_all([0.5, 2 ** 0.5])
    ('=', '\\\\approx')
    >>> relation_all((3.3460252, 1), (3.346, 1)), relation_all((3.3460652, 1), (3.346, 1))
    ('=', '\\\\approx')
    """
    def flat(xs):
        return [v for x in xs for v in (flat(x) if isinstance(x, (list, tuple)) else [x])]

    values = flat(results)
    printed = flat(from_printed) if from_printed is not None else [None] * len(values)
    return "=" if all(relation(r, p) == "=" for r, p in zip(values, printed)) else "\\approx"
