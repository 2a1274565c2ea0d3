"""Showing a formula answer: the worked formula, its TeX, the label (variables typeset) and the input."""

from __future__ import annotations

from html import escape
from typing import TYPE_CHECKING

from ...contract import ATTR, ROLE, role_attr
from ...expr import parse_formula
from ...expr.latex_output import variable_latex
from ...markup import check_button, form, keypad

if TYPE_CHECKING:
    from . import FormulaAnswer


def attributes(ans: FormulaAnswer) -> dict[str, str]:
    return {ATTR.variables: ",".join(ans.variables)}


def worked_text(ans: FormulaAnswer) -> str:
    return ans.answer_text


def typed(ans: FormulaAnswer, value: object) -> str:
    """Only the key has a typed form (slips are functions, typed in the tests by hand)."""
    return ans.answer_text if value is ans.key else ""


def worked_tex(ans: FormulaAnswer) -> str:
    return parse_formula(ans.answer_text, ans.variables).latex


def worked_html(ans: FormulaAnswer) -> str:
    return (f'<p class="wb-worked">Type it as: <code {role_attr(ROLE.worked_answer)}>'
            f"{escape(ans.answer_text)}</code></p>")


def label_html(ans: FormulaAnswer) -> str:
    # one math span per name: the page typesets a span whose whole text is a single inline formula
    names = ", ".join(f'<span class="arithmatex">\\({variable_latex(v)}\\)</span>' for v in ans.variables)
    return f"{escape(ans.label)}: a formula in {names}"


def placeholder(ans: FormulaAnswer) -> str:
    """An example of the notation in this exercise's own variables, shaped unlike any answer in the
    workbook: ``e.g. v^2/2 + sqrt(dt)``."""
    names = list(ans.variables) or ["x"]
    return f"e.g. {names[0]}^2/2 + sqrt({names[-1]})" if len(names) > 1 else f"e.g. {names[0]}^2/2 + 1"


def widget(ans: FormulaAnswer, base: str) -> str:
    return form("derive", (
        f'<label class="wb-label" for="{base}-answer">{label_html(ans)}</label>'
        f'<span class="wb-answer-row"><input id="{base}-answer" class="wb-answer wb-formula" '
        f'{role_attr(ROLE.answer)} type="text" inputmode="text" enterkeyhint="go" {keypad(ans.variables)} '
        f'autocomplete="off" autocapitalize="off" '
        f'spellcheck="false" placeholder="{escape(placeholder(ans))}" aria-describedby="{base}-reading '
        f'{base}-feedback">'
        f"{check_button()}</span>"
        f'<p class="wb-reading" id="{base}-reading" aria-live="polite"></p>'
    ))
