"""Formula answers: an expression in the exercise's named variables.

The key is a reference function of those variables (keyword arguments). A
learner's formula is read over the variables (``θ1``, ``theta1``, ``θ₁``, ``L₁``
all name ``theta1`` or ``L1``), then compared with the key at random points of
the domain the exercise declares: an equivalent rewriting is right, a formula
that agrees at one point only is not. The reply carries the formula as it was
read, typeset (``data.latex``), so a learner sees how the input was understood.

>>> import math
>>> ex = FormulaDerive(id="x.1", title="", key=lambda L1, theta1: L1 * math.cos(theta1),
...                    variables=("L1", "theta1"), domain={"L1": (0.5, 2.0), "theta1": (-3.0, 3.0)},
...                    answer_text="L1*cos(theta1)")
>>> ex.check("L₁ cos θ₁").status, ex.check("L1*sin(theta1 + pi/2)").status
('correct', 'correct')
>>> v = ex.check("L1 cos(θ2)"); v.status, "L1, theta1" in v.message
('invalid', True)
>>> ex.check("L1").status
'incorrect'
"""

from __future__ import annotations

import math
import random
from dataclasses import dataclass, field
from typing import Any, Callable, ClassVar, Mapping

from ..answers import InvalidAnswer
from ..contract import ATTR, ROLE
from ..formula import equivalent, parse_formula, variable_latex
from ..tolerance import agrees, clean
from ..kinds.base import Page, check_button, escape, form, role_attr
from ..kinds.derive import Derive
from ..verdict import Verdict


@dataclass(frozen=True)
class FormulaDerive(Derive):
    """``key`` is a function of ``variables`` (keyword arguments) over ``domain``;
    ``answer_text`` is the formula as a learner would type it (the worked answer).
    Slips hold functions too."""

    key: Callable[..., float] | None = None
    variables: tuple[str, ...] = ()
    domain: Mapping[str, tuple[float, float]] = field(default_factory=dict)
    answer_text: str = ""
    answer_kind: ClassVar[str] = "expression"

    def attributes(self) -> dict[str, str]:
        return {**super().attributes(), ATTR.variables: ",".join(self.variables)}

    def check(self, answer: object) -> Verdict:
        try:
            formula = parse_formula(answer, self.variables)
        except InvalidAnswer as err:
            return Verdict("invalid", str(err))
        data = {"latex": formula.latex}
        same = equivalent(formula, self.key, self.domain)
        if same is None:
            return Verdict("invalid", "Your formula cannot be evaluated at most points of the question's range "
                           "(a square root or logarithm of a negative number?).", data=data)
        if same:
            return Verdict("correct", "Correct: your formula agrees with the answer everywhere it was tried.", data=data)
        for slip in self.slips:
            if equivalent(formula, slip.value, self.domain):
                return Verdict("incorrect", slip.message, tag="slip", data=data)
        return Verdict("incorrect", self._counterexample(formula), data=data)

    def _counterexample(self, formula: Any) -> str:
        """Where the formula and the key differ, in words."""
        rng = random.Random(1)
        for _ in range(40):
            env = {name: rng.uniform(lo, hi) for name, (lo, hi) in self.domain.items()}
            try:
                want, got = float(self.key(**env)), formula.evaluate(env)
            except (ValueError, ArithmeticError, TypeError):
                continue
            if math.isfinite(want) and math.isfinite(got) and not agrees(got, clean(want)):
                where = ", ".join(f"{n} = {env[n]:.3g}" for n in self.variables)
                return f"Not the same formula: at {where} yours gives {got:.4g}, the answer {want:.4g}."
        return "Not the same formula. Check each term against the derivation."

    def read(self, answer: object) -> dict:
        try:
            return {"latex": parse_formula(answer, self.variables).latex}
        except InvalidAnswer as err:
            return {"message": str(err)}

    def worked_text(self) -> str:
        return self.answer_text

    def worked_html(self) -> str:
        return (f'<p class="wb-worked">Type it as: <code {role_attr(ROLE.worked_answer)}>'
                f"{escape(self.answer_text)}</code></p>")

    def label_html(self) -> str:
        # one math span per name: the page typesets a span whose whole text is a single inline formula
        names = ", ".join(f'<span class="arithmatex">\\({variable_latex(v)}\\)</span>' for v in self.variables)
        return f"{escape(self.label)}: a formula in {names}"

    def typed(self, value: Any) -> str:
        return self.answer_text if value is self.key else ""

    def degenerate(self) -> str | None:
        """The worked formula must be accepted, and no slip may agree with the key."""
        verdict = self.check(self.answer_text)
        if verdict.status != "correct":
            return f"its worked answer {self.answer_text!r} is graded {verdict.status}"
        formula = parse_formula(self.answer_text, self.variables)
        for slip in self.slips:
            if equivalent(formula, slip.value, self.domain) is not False:
                return f"the slip {slip.message[:40]!r} agrees with the key"
        return None

    def widget(self, base: str, page: Page) -> str:
        return form(self.kind, (
            f'<label class="wb-label" for="{base}-answer">{self.label_html()}</label>'
            f'<span class="wb-answer-row"><input id="{base}-answer" class="wb-answer wb-formula" '
            f'{role_attr(ROLE.answer)} type="text" inputmode="text" autocomplete="off" autocapitalize="off" '
            f'spellcheck="false" placeholder="e.g. L1*cos(theta1)" aria-describedby="{base}-reading {base}-feedback">'
            f"{check_button()}</span>"
            f'<p class="wb-reading" id="{base}-reading" aria-live="polite"></p>'
        ))


ANSWER = FormulaDerive
