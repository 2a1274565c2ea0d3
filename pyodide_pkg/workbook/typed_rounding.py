"""How far a carried key may move within the rounding of the values it is worked from.

A learner types a step to four decimals and works the next line from the unrounded value; where that line
cancels (cos 35° + cos 144° = 0.0101), the step's own rounding moves the result by more than the
tolerance. A value typed to at least 3 significant figures stands for anything within half a unit of its
last digit, so the carried key may lie anywhere the inputs' rounding takes it: :func:`spread` bounds that,
to first order, by moving each typed number by its half unit and adding up how far the key moves.

>>> from types import SimpleNamespace as R
>>> half_units([[R(value=0.809, figures=4, half_unit=5e-05)]]), half_units(R(value=0.0, figures=1, half_unit=0.5))
(((5e-05,),), 0.0)
>>> half_units(R(value=0.0012, figures=2, half_unit=5e-05)), half_units(R(value=1.5, figures=2, half_unit=0.05))
(5e-05, 0.0)
>>> [round(v, 9) for v in spread(lambda given: [10 * given["x"]], {"x": 1.0}, {"x": 0.005})]
[0.05]
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from typing import Any

from .number_format import DECIMALS
from .tolerance import FIGURES

_PRINTED = 0.5 * 10.0 ** -DECIMALS  # a number typed to the printer's 4 decimals (0.0012) is a rounding, too
Evaluate = Callable[[Mapping[str, Any]], list[float]]  # the learner's values -> the recomputed key's entries


def half_units(reading: Any) -> Any:
    """Half a unit of the last digit of each number read (a matrix's as rows), 0 where fewer than
    :data:`FIGURES` significant figures and fewer than 4 decimals were typed (``0``, ``1.5``: taken as exact)."""
    if isinstance(reading, list):
        return tuple(tuple(half_units(r) for r in row) for row in reading)
    figures, half = getattr(reading, "figures", None), getattr(reading, "half_unit", None)
    if figures is None or not half:
        return 0.0
    return float(half) if figures >= FIGURES or half <= _PRINTED else 0.0


def _nudged(value: Any, half: Any) -> list[tuple[Any, Any]]:
    """``value`` with one of its numbers moved down and up by its half unit, for each number that has one."""
    if isinstance(value, tuple):
        out = []
        for i, (row, hrow) in enumerate(zip(value, half)):
            for j, (v, h) in enumerate(zip(row, hrow)):
                if h:
                    moved = [tuple(tuple(v + s * h if (a, b) == (i, j) else x for b, x in enumerate(r))
                                   for a, r in enumerate(value)) for s in (-1, 1)]
                    out.append((moved[0], moved[1]))
        return out
    return [(value - half, value + half)] if half else []


def spread(evaluate: Evaluate, given: Mapping[str, Any], halves: Mapping[str, Any]) -> list[float] | None:
    """How far each entry of the key ``evaluate(given)`` may move while every typed number of ``given`` stays
    within its half unit (``halves``, by name): the sum, over the numbers, of the larger move either way.
    None when nothing was typed with figures to spare, or the key cannot be worked at the nudged values."""
    base = evaluate(given)
    total = [0.0] * len(base)
    moved = False
    for name, half in halves.items():
        for low, high in _nudged(given[name], half):
            try:
                ends = [evaluate({**given, name: low}), evaluate({**given, name: high})]
            except (ArithmeticError, ValueError):
                return None
            for k, b in enumerate(base):
                total[k] += max(abs(end[k] - b) for end in ends)
            moved = True
    return [t * (1 + 1e-9) for t in total] if moved else None  # a value at the end of its rounding is in it

