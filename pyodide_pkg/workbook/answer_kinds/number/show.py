"""Showing a number answer: the worked answer, the Answer line's TeX, the label and the input."""

from __future__ import annotations

from html import escape
from typing import TYPE_CHECKING, Any

from ...contract import ROLE, role_attr
from ...markup import check_button, form, keypad
from ...number_format import fmt
from ...tolerance import clean

if TYPE_CHECKING:
    from . import NumberAnswer


def worked_text(ans: NumberAnswer) -> str:
    """The key as a learner would type it, printed by the one number printer."""
    return fmt(clean(ans.key)) + ("°" if ans.angle == "deg" else "")


def worked_tex(ans: NumberAnswer) -> str:
    return worked_text(ans)


def typed(ans: NumberAnswer, value: Any) -> str:
    """A value as a careful learner types it (more figures than printed: slips are told apart exactly)."""
    return fmt(clean(value), significant=7) + ("°" if ans.angle == "deg" else "")


def attributes(ans: NumberAnswer) -> dict[str, str]:
    return {}


def worked_html(ans: NumberAnswer) -> str:
    return (f'<p class="wb-worked">Type it as: <code {role_attr(ROLE.worked_answer)}>'
            f"{escape(worked_text(ans))}</code></p>")


def label_html(ans: NumberAnswer) -> str:
    named = " (degrees)" if ans.unit == "°" else (f" ({escape(ans.unit)})" if ans.unit else "")
    return f"{escape(ans.label)}{named}"


def input_mode(ans: NumberAnswer) -> str:
    """The phone keyboard the box brings up: digits for a count (a whole number, nothing else fits),
    else the letters (sqrt, pi, cos(30°) are answers too; the keypad row has the symbols)."""
    return "numeric" if ans.exact and not ans.expect else "text"


def widget(ans: NumberAnswer, base: str) -> str:
    keys = keypad(units=(ans.unit,) if ans.expect else ())
    unit = f'<span class="wb-unit" aria-hidden="true">{escape(ans.unit)}</span>' if ans.unit else ""
    return form("derive", (
        f'<label class="wb-label" for="{base}-answer">{label_html(ans)}</label>'
        f'<span class="wb-answer-row"><input id="{base}-answer" class="wb-answer" {role_attr(ROLE.answer)} '
        f'type="text" inputmode="{input_mode(ans)}" enterkeyhint="go" {keys} autocomplete="off" '
        f'autocapitalize="off" spellcheck="false" placeholder="e.g. 0.5, sqrt(2)/2, pi/4" '
        f'aria-describedby="{base}-feedback">{unit}'
        f"{check_button()}</span>"
    ))
