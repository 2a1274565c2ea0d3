"""Derive: type a number or an expression; graded against a key from the reference code."""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import ClassVar

from ..answers import InvalidAnswer, parse_answer
from ..contract import ATTR, TAG
from ..verdict import GradingError, Verdict
from .base import ROLE, Exercise, Page, check_button, escape, form, role_attr

CLOSE_FRACTION = 0.02


def fmt(x: float, digits: int = 0) -> str:
    """A number as the workbook prints it: up to 4 decimals, no trailing zeros;
    with ``digits``, at least that many significant digits for small numbers.

    >>> fmt(0.70710678), fmt(3.0), fmt(-0.0), fmt(0.000123456), fmt(0.000123456, digits=4)
    ('0.7071', '3', '0', '0.0001', '0.0001235')
    """
    decimals = 4
    if digits and x and abs(x) < 1:
        decimals = max(4, digits - 1 - math.floor(math.log10(abs(x))))
    s = f"{x:.{decimals}f}".rstrip("0").rstrip(".")
    return "0" if s in ("-0", "") else s


@dataclass(frozen=True)
class Slip:
    """A known wrong answer with its own message (matched like the key)."""

    value: float
    message: str


@dataclass(frozen=True)
class Derive(Exercise):
    """Type a number or an expression.

    ``angle`` says the answer is an angle in ``"deg"`` or ``"rad"``, so that a
    value in the other unit can be recognised and named.
    """

    key: float = 0.0
    label: str = ""
    unit: str = ""
    angle: str | None = None
    rel_tol: float = 1e-3
    abs_tol: float = 1e-3
    slips: tuple[Slip, ...] = ()
    kind: ClassVar[str] = "derive"
    answer_kind: ClassVar[str] = "number"
    reveal_label: ClassVar[str] = "Show derivation"

    def attributes(self) -> dict[str, str]:
        return {ATTR.answerKind: self.answer_kind}

    def worked_text(self) -> str:
        """The key as a learner would type it."""
        return fmt(self.key, digits=4) + ("°" if self.angle == "deg" else "")

    def worked_html(self) -> str:
        """The last line of the derivation: the answer, typed out (see CONTRACT.md)."""
        return (f'<p class="wb-worked">Type it as: <code {role_attr(ROLE.worked_answer)}>'
                f"{escape(self.worked_text())}</code></p>")

    def read(self, answer: object) -> dict:
        """How ``answer`` is read, before it is checked (the ``read`` op)."""
        try:
            return {"value": parse_answer(answer).value}
        except InvalidAnswer as err:
            return {"message": str(err)}

    def split(self, text: object) -> list[list[str]]:
        """Split a pasted vector or matrix into entries (the ``split`` op); only shaped answers have entries."""
        raise GradingError("wrong-op", f"Exercise {self.id} takes one value, not a vector or matrix.")

    def within(self, value: float, target: float) -> bool:
        return abs(value - target) <= max(self.rel_tol * abs(target), self.abs_tol)

    def check(self, answer: object) -> Verdict:
        try:
            parsed = parse_answer(answer)
        except InvalidAnswer as err:
            return Verdict("invalid", str(err))
        value, key = parsed.value, self.key
        if parsed.unit and not self.angle:
            return Verdict("invalid", "This answer is not an angle: type it without a degree or radian unit.")
        if self.angle == "deg" and parsed.unit == "rad":
            value = math.degrees(value)
        elif self.angle == "rad" and parsed.unit == "deg":
            value = math.radians(value)
        if self.within(value, key):
            return Verdict("correct", f"Correct: {fmt(key)}{self.unit if self.unit == '°' else ''}.")
        return self._diagnose(value, parsed.unit)

    def _diagnose(self, value: float, unit: str | None) -> Verdict:
        key = self.key
        for slip in self.slips:
            if self.within(value, slip.value):
                return Verdict("incorrect", slip.message, tag=TAG.slip)
        if unit is None and self.angle == "deg" and self.within(math.degrees(value), key):
            return Verdict("incorrect", "That looks like radians. This answer is in degrees: multiply by 180/π, "
                           "or type the unit, e.g. 0.9273 rad.", tag=TAG.radians)
        if unit is None and self.angle == "rad" and self.within(math.radians(value), key):
            return Verdict("incorrect", "That looks like degrees. This answer is in radians: multiply by π/180, "
                           "or type the unit, e.g. 90°.", tag=TAG.degrees)
        if key != 0 and self.within(-value, key):
            return Verdict("incorrect", "The size is right but the sign is wrong. Check which way the quantity points.",
                           tag=TAG.sign)
        if abs(value - key) <= CLOSE_FRACTION * max(abs(key), 1e-9) or (key == 0 and abs(value) <= CLOSE_FRACTION):
            return Verdict("incorrect", "Close, but not within tolerance. Carry more digits through the "
                           "intermediate steps.", tag=TAG.close)
        return Verdict("incorrect", "Not quite. Try the hint, or work the derivation one line at a time.")

    def widget(self, base: str, page: Page) -> str:
        unit = f'<span class="wb-unit" aria-hidden="true">{escape(self.unit)}</span>' if self.unit else ""
        named = " (degrees)" if self.unit == "°" else (f" ({escape(self.unit)})" if self.unit else "")
        return form(self.kind, (
            f'<label class="wb-label" for="{base}-answer">{escape(self.label)}{named}</label>'
            f'<span class="wb-answer-row"><input id="{base}-answer" class="wb-answer" {role_attr(ROLE.answer)} '
            f'type="text" inputmode="text" autocomplete="off" autocapitalize="off" spellcheck="false" '
            f'placeholder="e.g. 0.5, sqrt(2)/2, pi/4" aria-describedby="{base}-feedback">{unit}'
            f"{check_button()}</span>"
        ))


EXERCISE = Derive
ANSWER = Derive
