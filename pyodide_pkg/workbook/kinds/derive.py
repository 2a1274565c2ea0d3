"""Derive: type a number or an expression; graded against a key from the reference code."""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace
from typing import Any, ClassVar, Mapping

from ..answers import InvalidAnswer, parse_answer, parse_quantity
from ..contract import ATTR, TAG
from ..tolerance import agrees, clean, is_close_miss, is_sign_slip
from ..variants import Vary, VariantError, check_seed
from ..verdict import GradingError, Verdict
from .base import ROLE, Exercise, Page, check_button, escape, form, role_attr

UNITS = {"m": "m", "m/s": "m/s", "s": "s", "°": "deg", "rad": "rad"}  # the unit asked -> parse_quantity's expect


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
    """Type a number or an expression (GUIDE §2 is the grading policy).

    ``angle`` says the answer is an angle in ``"deg"`` or ``"rad"``, so that a
    value in the other unit can be recognised and named; ``unit`` is the unit the
    answer is asked in (``m``, ``m/s``, ``°``, or a word such as ``variables``).
    A key of type ``int`` (a count) must be matched exactly; ``periodic`` accepts
    an angle give or take whole turns; ``either_sign`` (the reason, in words)
    accepts the negated key too.
    """

    key: float = 0.0
    label: str = ""
    unit: str = ""
    angle: str | None = None
    rel_tol: float = 1e-3
    periodic: bool = False
    either_sign: str = ""  # why the negated key is right too (e.g. −q is the same rotation as q)
    slips: tuple[Slip, ...] = ()
    vary: Vary | None = field(default=None, compare=False, repr=False)
    seed: int = 0  # the variant: 0 is the workbook's numbers
    values: Mapping[str, str] = field(default_factory=dict, compare=False, repr=False)  # the template's fill
    params: Mapping[str, Any] = field(default_factory=dict, compare=False, repr=False)  # this variant's draw
    kind: ClassVar[str] = "derive"
    answer_kind: ClassVar[str] = "number"
    reveal_label: ClassVar[str] = "Show derivation"

    # ---- variants (workbook/variants.py) --------------------------------------
    def __post_init__(self) -> None:
        if self.vary is None:
            return
        for p in self.vary.candidates(self.id, self.seed):
            fields = dict(self.vary.make(p))
            values = {name: fmt(v) if isinstance(v, (int, float)) and not isinstance(v, bool) else str(v)
                      for name, v in p.items()}
            values.update(fields.pop("values", {}))
            for name, value in {**fields, "values": values, "params": dict(p)}.items():
                object.__setattr__(self, name, value)
            problem = self.degenerate()
            if problem is None:
                return
            if self.seed == 0:
                raise VariantError(f"exercise {self.id}: the workbook's own numbers are degenerate: {problem}")
        raise VariantError(f"exercise {self.id}: no well-posed draw for variant {self.seed}")

    def variant(self, seed: object) -> "Derive":
        """This exercise with variant ``seed``'s numbers (0: the workbook's own)."""
        seed = check_seed(seed)
        if self.vary is None or seed == self.seed:
            return self
        return replace(self, seed=seed)

    def typed(self, value: Any) -> Any:
        """A value (the key or a slip) as a learner would type it."""
        return fmt(clean(value), digits=6) + ("°" if self.angle == "deg" else "")

    def degenerate(self) -> str | None:
        """Why this variant is not well posed, or None: its worked answer must be
        accepted and each slip must be told apart from the key and from each other."""
        verdict = self.check(self.worked_text())
        if verdict.status != "correct":
            return f"its worked answer {self.worked_text()!r} is graded {verdict.status}"
        for slip in self.slips:
            said = self.check(self.typed(slip.value))
            if said.message != slip.message:
                return f"the slip {self.typed(slip.value)!r} is graded {said.status}: {said.message!r}"
        return None

    def attributes(self) -> dict[str, str]:
        return {ATTR.answerKind: self.answer_kind}

    @property
    def expect(self) -> str | None:
        """The unit ``parse_quantity`` converts to (None: a plain number)."""
        return self.angle or UNITS.get(self.unit)

    @property
    def exact(self) -> bool:
        return isinstance(self.key, int)

    def agrees(self, value: float, target: float) -> bool:
        target = clean(target)
        if self.periodic and self.angle:
            turn = 360.0 if self.angle == "deg" else math.tau
            value = target + math.remainder(value - target, turn)
        return agrees(value, target, rel=self.rel_tol, exact=self.exact)

    def check(self, answer: object) -> Verdict:
        try:
            bare = parse_answer(answer).dimension is None
            value = parse_quantity(answer, self.expect)
        except InvalidAnswer as err:
            return Verdict("invalid", str(err))
        if self.agrees(value, self.key):
            unit = f" {self.unit}" if self.unit and self.angle is None else ""
            return Verdict("correct", f"Correct: {self.worked_text()}{unit}.")
        if self.either_sign and self.agrees(-value, self.key):
            return Verdict("correct", f"Correct: {self.either_sign}")
        return self._diagnose(value, bare)

    def _diagnose(self, value: float, bare: bool) -> Verdict:
        key = clean(self.key)
        for slip in self.slips:
            if self.agrees(value, slip.value):
                return Verdict("incorrect", slip.message, tag=TAG.slip)
        if bare and self.angle == "deg" and self.agrees(math.degrees(value), key):
            return Verdict("incorrect", "That looks like radians. This answer is in degrees: multiply by 180/π, "
                           "or type the unit, e.g. 0.9273 rad.", tag=TAG.radians)
        if bare and self.angle == "rad" and self.agrees(math.radians(value), key):
            return Verdict("incorrect", "That looks like degrees. This answer is in radians: multiply by π/180, "
                           "or type the unit, e.g. 90°.", tag=TAG.degrees)
        if is_sign_slip(value, key, rel=self.rel_tol):
            return Verdict("incorrect", "The size is right but the sign is wrong. Check which way the quantity points.",
                           tag=TAG.sign)
        if not self.exact and is_close_miss(value, key, rel=self.rel_tol):
            return Verdict("incorrect", "Close, but not within tolerance. Carry more digits through the "
                           "intermediate steps.", tag=TAG.close)
        return Verdict("incorrect", "Not quite. Try the hint, or work the derivation one line at a time.")

    def worked_text(self) -> str:
        """The key as a learner would type it."""
        return fmt(clean(self.key), digits=4) + ("°" if self.angle == "deg" else "")

    def worked_html(self) -> str:
        """The last line of the derivation: the answer, typed out (see CONTRACT.md)."""
        return (f'<p class="wb-worked">Type it as: <code {role_attr(ROLE.worked_answer)}>'
                f"{escape(self.worked_text())}</code></p>")

    def read(self, answer: object) -> dict:
        """How ``answer`` is read, before it is checked (the ``read`` op)."""
        try:
            return {"value": parse_quantity(answer, self.expect)}
        except InvalidAnswer as err:
            return {"message": str(err)}

    def split(self, text: object) -> dict:
        """A pasted vector or matrix as ``{"entries": rows}`` or ``{"message": why not}`` (the ``split`` op).

        Only shaped answers have entries."""
        raise GradingError("wrong-op", f"Exercise {self.id} takes one value, not a vector or matrix.")

    def label_html(self) -> str:
        """The answer's label (it may change with the variant)."""
        named = " (degrees)" if self.unit == "°" else (f" ({escape(self.unit)})" if self.unit else "")
        return f"{escape(self.label)}{named}"

    def widget(self, base: str, page: Page) -> str:
        unit = f'<span class="wb-unit" aria-hidden="true">{escape(self.unit)}</span>' if self.unit else ""
        return form(self.kind, (
            f'<label class="wb-label" for="{base}-answer">{self.label_html()}</label>'
            f'<span class="wb-answer-row"><input id="{base}-answer" class="wb-answer" {role_attr(ROLE.answer)} '
            f'type="text" inputmode="text" autocomplete="off" autocapitalize="off" spellcheck="false" '
            f'placeholder="e.g. 0.5, sqrt(2)/2, pi/4" aria-describedby="{base}-feedback">{unit}'
            f"{check_button()}</span>"
        ))


EXERCISE = Derive
ANSWER = Derive
