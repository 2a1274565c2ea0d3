"""The matrix answer: a vector or matrix, one input per entry, graded together.

The key is a tuple of rows computed by the reference code (a column vector is
a key of one-entry rows). Each entry takes a number or an expression, with a
unit where the exercise gives units; a whole matrix pasted into any entry is
split by the ``split`` op; a vector's components may be written with their
names (``x = 1, y = 2``), in any order. A wrong answer marks the entries that
differ, says which are close, and names the slip across the whole matrix where
it can.

>>> ans = matrix(label="R(90°)").build("x.1", key=((0.0, -1.0), (1.0, 0.0)))
>>> ans.check([["0", "-1"], ["1", "0"]]).status
'correct'
>>> v = ans.check([["0", "1"], ["-1", "0"]]); v.tag, v.data["wrong"]
('transpose', [[1, 2], [2, 1]])
>>> ans.check([["0", ""], ["1", "0"]]).data["invalid"]
[[1, 2]]
>>> ans.split("[[0, -1], [1, 0]]"), ans.split("cos(30°) - 1")
({'entries': [['0', '-1'], ['1', '0']]}, {'cell': 'cos(30°) - 1'})
"""

from __future__ import annotations

from dataclasses import dataclass
from types import ModuleType
from typing import Any, ClassVar

from ...tolerance import clean
from ..base import AnswerKind, AnswerSpec
from ..number import UNITS
from . import mark, read, show

Rows = tuple[tuple[float, ...], ...]


@dataclass(frozen=True)
class MatrixAnswer(AnswerKind):
    """``key`` holds the rows. ``unit`` is every entry's unit, or ``units`` one per
    entry in reading order (``("m", "m", "rad")``); ``names`` are a vector's
    components (``"theta|th"`` adds other spellings), read by name in any order;
    ``rotation_angle`` (radians) is the angle a rotation key was built from, so
    that R(−θ) and degrees-for-radians can be named; ``either_sign`` (the reason)
    accepts the negated key; ``rel_tol`` is each entry's relative tolerance.
    """

    key: Rows = ()
    unit: str = ""
    units: tuple[str, ...] = ()
    names: tuple[str, ...] = ()
    rotation_angle: float | None = None
    either_sign: str = ""
    rel_tol: float = 1e-3
    kind: ClassVar[str] = "matrix"
    reader: ClassVar[ModuleType] = read
    marker: ClassVar[ModuleType] = mark
    shower: ClassVar[ModuleType] = show

    def __post_init__(self) -> None:
        if not self.key or any(len(row) != len(self.key[0]) for row in self.key):
            raise ValueError("a matrix key is a non-empty tuple of rows of equal length")
        r, c = self.shape
        if self.units and (self.unit or len(self.units) != r * c):
            raise ValueError(f"units gives one unit per entry ({r * c}), and then unit is not given")
        if self.names and (min(r, c) != 1 or len(self.names) != r * c):
            raise ValueError("names are for a vector: one per entry")
        for u in (self.unit, *self.units):
            if u and u not in UNITS:
                raise ValueError(f"an entry's unit is one of {', '.join(UNITS)}, not {u!r}")

    @property
    def shape(self) -> tuple[int, int]:
        return len(self.key), len(self.key[0])

    @property
    def cleaned(self) -> list[list[float]]:
        return [[clean(v) for v in row] for row in self.key]

    def expect(self, i: int, j: int) -> str | None:
        """The unit entry (i, j) (0-based) is read in."""
        unit = self.units[i * self.shape[1] + j] if self.units else self.unit
        return UNITS.get(unit)

    def split(self, text: object) -> dict:
        return read.split(self, text)


def matrix(**options: Any) -> AnswerSpec:
    """A matrix or vector answer with these options (see :class:`MatrixAnswer`)."""
    return AnswerSpec(MatrixAnswer, options)


ANSWER = MatrixAnswer
