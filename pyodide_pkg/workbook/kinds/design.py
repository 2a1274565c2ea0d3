"""Design: put the steps of a pipeline in order."""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar

from ..markup import check_button, form
from ..math_text import math_data, pieces
from ..verdict import Verdict
from .base import ATTR, ROLE, Exercise, Page, escape, role_attr


@dataclass(frozen=True)
class Step:
    key: str
    text: str


@dataclass(frozen=True)
class Design(Exercise):
    """``steps`` are in the solved order; ``shown`` is the order first shown
    (a list of keys), which must never be the solved one.
    """

    steps: tuple[Step, ...] = ()
    shown: tuple[str, ...] = ()
    kind: ClassVar[str] = "design"

    def __post_init__(self) -> None:
        if tuple(self.shown) == self.solution:
            raise ValueError(f"exercise {self.id}: the order first shown is the solved order")
        if sorted(self.shown) != sorted(self.solution):
            raise ValueError(f"exercise {self.id}: the order shown must hold every step once")
        for step in self.steps:  # every formula closed, so the page can typeset a message that quotes it
            try:
                pieces(step.text)
            except ValueError as err:
                raise ValueError(f"exercise {self.id}, step {step.key}: {err}") from None

    @property
    def solution(self) -> tuple[str, ...]:
        return tuple(s.key for s in self.steps)

    def check(self, order: object) -> Verdict:
        solution = self.solution
        if not isinstance(order, (list, tuple)) or sorted(map(str, order)) != sorted(solution):
            return Verdict("invalid", "Arrange all the steps, each once, then check.")
        order = [str(k) for k in order]
        in_place = sum(a == b for a, b in zip(order, solution))
        if in_place == len(solution):
            return Verdict("correct", "Correct: every step is in place.", data={"in_place": in_place})
        first = next(i for i, (a, b) in enumerate(zip(order, solution)) if a != b)
        text = {s.key: s.text for s in self.steps}[order[first]]
        message = (f"{in_place} of {len(solution)} steps are in place. "
                   f"The first one out of place is step {first + 1}, “{text}”.")
        return Verdict(
            "incorrect", message, data={"in_place": in_place, "first_wrong": first + 1, **math_data(message)}
        )

    def widget(self, base: str, page: Page) -> str:
        text = {s.key: s.text for s in self.steps}
        rows = "".join(
            f'<li class="wb-step" {role_attr(ROLE.step)} {ATTR.step}="{escape(key)}" draggable="true">'
            f'<span class="wb-step-handle" aria-hidden="true">⋮⋮</span>'
            f'<span class="wb-step-text">{page.inline(text[key])}</span><span class="wb-step-moves">'
            f'<button type="button" class="wb-move" {role_attr(ROLE.move_up)} aria-label="Move “{escape(text[key])}” '
            'up">▲</button>'
            f'<button type="button" class="wb-move" {role_attr(ROLE.move_down)} aria-label="Move “{escape(text[key])}” '
            'down">▼</button>'
            f"</span></li>"
            for key in self.shown
        )
        return form(self.kind, (
            f'<p class="wb-label" id="{base}-steps-label">Put the steps in order: drag them, or use the arrow '
            'buttons.</p>'
            f'<ol class="wb-steps" {role_attr(ROLE.steps)} aria-labelledby="{base}-steps-label" '
            f'aria-describedby="{base}-feedback">{rows}</ol>{check_button()}'
        ))


EXERCISE = Design
