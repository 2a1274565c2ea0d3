"""Trace: choose one option, then read why it is (or is not) right."""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar

from ..contract import TAG
from ..markup import check_button, form
from ..math_text import math_data, pieces
from ..verdict import Verdict
from .base import ROLE, Exercise, Page, escape, role_attr


@dataclass(frozen=True)
class Option:
    """One option of a Trace exercise; ``why`` is shown once it is picked."""

    key: str
    text: str
    why: str


@dataclass(frozen=True)
class Trace(Exercise):
    options: tuple[Option, ...] = ()
    answer: str = ""
    kind: ClassVar[str] = "trace"

    def __post_init__(self) -> None:
        for o in self.options:  # every formula closed, so the page can typeset each reason
            try:
                pieces(o.text), pieces(o.why)
            except ValueError as err:
                raise ValueError(f"exercise {self.id}, option {o.key}: {err}") from None

    def check(self, choice: object) -> Verdict:
        options = {o.key: o for o in self.options}
        if not isinstance(choice, str) or choice not in options:  # a list would not even hash
            return Verdict("invalid", "Choose one of the options first.")
        why = options[choice].why
        return Verdict("correct" if choice == self.answer else "incorrect", why, tag=TAG.why, data=math_data(why))

    def widget(self, base: str, page: Page) -> str:
        items = "".join(
            f'<label class="wb-choice"><input type="radio" name="{base}-choice" value="{escape(o.key)}" '
            f'{role_attr(ROLE.choice)}><span class="wb-choice-key">{escape(o.key)}</span>'
            f'<span class="wb-choice-text">{page.inline(o.text)}</span></label>'
            for o in self.options
        )
        return form(self.kind, (
            f'<fieldset class="wb-choices" aria-describedby="{base}-feedback">'
            f'<legend class="wb-label">Choose one answer</legend>{items}</fieldset>{check_button()}'
        ))


EXERCISE = Trace
