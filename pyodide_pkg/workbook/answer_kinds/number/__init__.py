"""The number answer: one value, typed as a number or an expression, perhaps with a unit.

>>> from workbook.answer_kinds.base import Slip
>>> ans = number(label="y", slips=(Slip(-3.0, "Clockwise."),)).build("x.1", key=3.0)
>>> ans.check("3").status, ans.check("-3").message, ans.check("2,5").status
('correct', 'Clockwise.', 'invalid')
>>> ans.worked_text(), ans.check("cos(90)").status
('3', 'incorrect')
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from types import ModuleType
from typing import Any, ClassVar

from ..base import AnswerKind, AnswerSpec
from . import mark, read, show

#: the unit an exercise asks in -> what the reader converts to
UNITS = {"m": "m", "m/s": "m/s", "s": "s", "°": "deg", "rad": "rad"}


@dataclass(frozen=True)
class NumberAnswer(AnswerKind):
    """One number (GUIDE §2 is the grading policy).

    ``unit`` is the unit asked (``m``, ``m/s``, ``°``, or a word such as
    ``variables``); ``angle`` (``"deg"`` or ``"rad"``) says the answer is an
    angle, so a value in the other unit is named; a key of type ``int`` is
    matched exactly; ``periodic`` accepts an angle give or take whole turns;
    ``either_sign`` (the reason, in words) accepts the negated key too;
    ``rel_tol`` is the relative tolerance.
    """

    key: float = 0.0
    unit: str = ""
    angle: str | None = None
    rel_tol: float = 1e-3
    periodic: bool = False
    either_sign: str = ""
    kind: ClassVar[str] = "number"
    reader: ClassVar[ModuleType] = read
    marker: ClassVar[ModuleType] = mark
    shower: ClassVar[ModuleType] = show

    def __post_init__(self) -> None:
        if self.angle not in (None, "deg", "rad"):
            raise ValueError(f"angle is 'deg' or 'rad', not {self.angle!r}")
        if self.periodic and not self.angle:
            raise ValueError("periodic needs angle='deg' or 'rad' (a whole turn in which unit?)")
        if isinstance(self.key, float) and not math.isfinite(self.key):
            raise ValueError(f"the key {self.key!r} is not a finite number")

    @property
    def expect(self) -> str | None:
        """The unit the reader converts to (None: a plain number)."""
        return self.angle or UNITS.get(self.unit)

    @property
    def exact(self) -> bool:
        return isinstance(self.key, int)


def number(**options: Any) -> AnswerSpec:
    """A number answer with these options (see :class:`NumberAnswer`)."""
    return AnswerSpec(NumberAnswer, options)


ANSWER = NumberAnswer
