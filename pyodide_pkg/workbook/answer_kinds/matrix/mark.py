"""Marking a matrix answer: entry by entry, then what the whole matrix says.

Each entry agrees with the key as a number answer's value does (the relative
tolerance, or half a unit of its last digit typed to at least 3 significant
figures). A wrong answer marks its wrong entries; then, in order: the
exercise's own slips, degrees typed inside sin, cos or tan, the whole-matrix
slips of :mod:`.slips`, and a count that tells close entries from wrong ones.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from ...contract import TAG
from ...expr import Reading
from ...tolerance import FIGURES, agrees, clean, is_close_miss
from ...verdict import Verdict
from ..base import slip_data
from ..number.mark import TRIG_DEGREES, too_coarse
from .slips import whole_matrix_slips

if TYPE_CHECKING:
    from . import MatrixAnswer

Position = list[int]


def _half(r: Reading) -> float | None:
    return r.half_unit if r.figures is not None and r.figures >= FIGURES else None


def differs(ans: MatrixAnswer, readings: list[list[Reading]], target, values=None) -> list[Position]:
    """1-based ``[row, col]`` of every entry that does not count as ``target``'s
    (``values`` overrides the readings' values)."""
    out = []
    for i, (row, want) in enumerate(zip(readings, target), 1):
        for j, (r, w) in enumerate(zip(row, want), 1):
            value = r.value if values is None else values[i - 1][j - 1]
            if not agrees(value, clean(w), rel=ans.rel_tol, half_unit=_half(r) if values is None else None):
                out.append([i, j])
    return out


def _where(positions: list[Position]) -> str:
    return ", ".join(f"({i},{j})" for i, j in positions)


def _trig_degrees(ans: MatrixAnswer, readings: list[list[Reading]], wrong: list[Position]) -> Verdict | None:
    """Every wrong entry is right once the bare numbers in its sin, cos or tan are read as degrees."""
    fixed = []
    for i, j in wrong:
        alt = readings[i - 1][j - 1].with_degree_arguments()
        if alt is None or not agrees(alt, clean(ans.key[i - 1][j - 1]), rel=ans.rel_tol):
            return None
        fixed.append([i, j])
    which = f"entry {_where(fixed)}" if len(fixed) == 1 else f"entries {_where(fixed)}"
    how = f"in {which} your angle was taken as radians"
    return Verdict("incorrect", TRIG_DEGREES.format(how=how), tag=TAG.degrees, data={"wrong": wrong})


def mark(ans: MatrixAnswer, readings: list[list[Reading]]) -> Verdict:
    key = ans.cleaned
    values = [[r.value for r in row] for row in readings]
    wrong = differs(ans, readings, key)
    if not wrong:
        return Verdict("correct", "Correct: every entry agrees.")
    if ans.either_sign and not differs(ans, readings, [[-v for v in row] for row in key]):
        return Verdict("correct", f"Correct: {ans.either_sign}")
    data: dict = {"wrong": wrong}
    for slip in ans.slips:
        if not differs(ans, readings, slip.value):
            return Verdict("incorrect", slip.message, tag=TAG.slip, data={**data, **slip_data(slip)})
    said = _trig_degrees(ans, readings, wrong)
    if said:
        return said
    names = tuple(name.split("|")[0] for name in ans.names)
    for tag, message in whole_matrix_slips(values, key, rotation_angle=ans.rotation_angle, names=names):
        return Verdict("incorrect", message, tag=tag, data=data)
    close = [[i, j] for i, j in wrong if is_close_miss(values[i - 1][j - 1], key[i - 1][j - 1], rel=ans.rel_tol,
                                                         figures=readings[i - 1][j - 1].figures)]
    n = ans.shape[0] * ans.shape[1]
    right = n - len(wrong)
    if close:
        data["close"] = close
        # "more figures" only when every close entry is the key rounded to its own few figures
        few = all(too_coarse(readings[p[0] - 1][p[1] - 1], key[p[0] - 1][p[1] - 1]) for p in close)
        advice = (f"type at least {FIGURES} significant figures" if few
                  else f"round correctly to at least {FIGURES} significant figures and carry more digits")
        others = len(wrong) - len(close)
        tail = f"; {others} more {'is' if others == 1 else 'are'} wrong" if others else ""
        word = "is" if len(close) == 1 else "are"
        return Verdict("incorrect", f"{right} of {n} entries are right; {_where(close)} {word} close: {advice}{tail}.",
                       tag=TAG.close if not others else "", data=data)
    return Verdict("incorrect", f"{right} of {n} entries are right; the marked ones are not.", data=data)
