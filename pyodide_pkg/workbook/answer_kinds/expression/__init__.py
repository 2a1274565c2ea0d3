"""The formula answer: an expression in the exercise's named variables.

The key is a reference function of those variables (keyword arguments). A
learner's formula is read over the variables (``θ1``, ``theta1``, ``θ₁``, ``L₁``
and LaTeX such as ``\\theta_1`` all name ``theta1``), then compared with the key
at random points of the domain the exercise declares: an equivalent rewriting
is right, a formula that agrees at one point only is not. The reply carries the
formula as it was read, typeset (``data.latex``), so a learner sees how the
input was understood.

>>> import math
>>> ans = formula(key=lambda L1, theta1: L1 * math.cos(theta1), variables=("L1", "theta1"),
...               domain={"L1": (0.5, 2.0), "theta1": (-3.0, 3.0)}, answer_text="L1*cos(theta1)").build("x.1")
>>> ans.check("L₁ cos θ₁").status, ans.check("L1*sin(theta1 + pi/2)").status, ans.check(r"L_1\\cos\\theta_1").status
('correct', 'correct', 'correct')
>>> v = ans.check("L1 cos(θ2)"); v.status, "L1, theta1" in v.message
('invalid', True)
>>> ans.check("L1").status, ans.check("L1*sin(theta1 + 90)").tag
('incorrect', 'degrees')
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from types import ModuleType
from typing import Any, ClassVar

from ..base import AnswerKind, AnswerSpec
from . import mark, read, show


@dataclass(frozen=True)
class FormulaAnswer(AnswerKind):
    """``key`` is a function of ``variables`` (keyword arguments) over ``domain``
    (a range per variable); ``answer_text`` is the formula as a learner would
    type it (the worked answer). Slips hold functions too."""

    key: Callable[..., float] | None = None
    variables: tuple[str, ...] = ()
    domain: Mapping[str, tuple[float, float]] = field(default_factory=dict)
    answer_text: str = ""
    kind: ClassVar[str] = "expression"
    reader: ClassVar[ModuleType] = read
    marker: ClassVar[ModuleType] = mark
    shower: ClassVar[ModuleType] = show

    def __post_init__(self) -> None:
        if not callable(self.key):
            raise ValueError("a formula's key is a function of its variables")
        missing = sorted(set(self.variables) - set(self.domain))
        if missing:
            raise ValueError(f"the domain gives no range for {', '.join(missing)}")

    def degenerate(self) -> str | None:
        return mark.degenerate(self)


def formula(**options: Any) -> AnswerSpec:
    """A formula answer with these options (see :class:`FormulaAnswer`)."""
    return AnswerSpec(FormulaAnswer, options)


ANSWER = FormulaAnswer
