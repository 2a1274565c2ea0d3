"""Build side: the static HTML of one exercise, around the widget its kind draws.

The kind's module (``workbook/kinds/K.py``) draws the answer area; this module
adds the frame every exercise shares: the heading badge, the prompt, the
feedback region, the hint and the derivation. No answer key is written in plain
HTML: the derivation travels base64-encoded and is decoded only when the learner
asks for it (a reader of the page's code can still decode it; the README says so).
"""

from __future__ import annotations

import base64
from dataclasses import dataclass
from html import escape
from typing import Callable

from workbook.contract import ATTR, ROLE, STATE, role_attr
from workbook.kinds.base import Exercise

KIND_LABEL = {"derive": "Derive", "trace": "Trace", "build": "Build", "debug": "Debug", "design": "Design"}


def dom_id(exercise_id: str) -> str:
    return "ex-" + exercise_id.replace(".", "-")


@dataclass
class PageTools:
    """What a kind's widget may ask of the page: inline Markdown and Python highlighting."""

    inline: Callable[[str], str] = escape

    @staticmethod
    def highlight(line: str) -> str:
        from pygments import highlight
        from pygments.formatters import HtmlFormatter
        from pygments.lexers import PythonLexer

        return highlight(line, PythonLexer(), HtmlFormatter(nowrap=True)).rstrip("\n") or " "


def _help(ex: Exercise, base: str, hint_html: str, solution_html: str) -> tuple[str, str]:
    buttons, panels = [], []
    if hint_html:
        buttons.append(f'<button type="button" class="md-button wb-help-button" {role_attr(ROLE.hint)} '
                       f'aria-expanded="false" aria-controls="{base}-hint">Show hint</button>')
        panels.append(f'<div class="admonition tip wb-hint" id="{base}-hint" {role_attr(ROLE.hint_panel)} hidden>'
                      f'<p class="admonition-title">Hint</p>{hint_html}</div>')
    if solution_html:
        label = ex.reveal_label
        encoded = base64.b64encode(solution_html.encode("utf-8")).decode("ascii")
        buttons.append(f'<button type="button" class="md-button wb-help-button" {role_attr(ROLE.reveal)} '
                       f'aria-expanded="false" aria-controls="{base}-solution">{label}</button>')
        title = label.removeprefix("Show ").capitalize()
        panels.append(f'<div class="admonition success wb-solution" id="{base}-solution" '
                      f'{role_attr(ROLE.solution_panel)} hidden data-title="{title}" data-content="{encoded}"></div>')
    return "".join(buttons), "".join(panels)


def exercise_html(ex: Exercise, prompt_html: str, hint_html: str, solution_html: str,
                  tools: PageTools | None = None) -> str:
    """The whole exercise element (CONTRACT.md lists its attributes and roles)."""
    tools = tools or PageTools()
    base = dom_id(ex.id)
    if solution_html:
        solution_html += ex.worked_html()
    buttons, panels = _help(ex, base, hint_html, solution_html)
    extra = "".join(f' {name}="{escape(value)}"' for name, value in ex.attributes().items())
    return (
        f'<div class="wb-exercise" id="{base}" {ATTR.exercise}="{escape(ex.id)}" {ATTR.kind}="{ex.kind}" '
        f'{ATTR.state}="{STATE.unanswered}"{extra} aria-labelledby="{base}-title">'
        f'<div class="wb-head"><span class="wb-kind wb-kind--{ex.kind}">{KIND_LABEL.get(ex.kind, ex.kind.title())}</span>'
        f'<span class="wb-status" {role_attr(ROLE.status)} aria-hidden="true"></span></div>'
        f'<div class="wb-prompt">{prompt_html}</div>'
        f"{ex.widget(base, tools)}"
        f'<div class="wb-feedback" id="{base}-feedback" {role_attr(ROLE.feedback)} role="status" aria-live="polite"></div>'
        f'<div class="wb-help">{buttons}</div>{panels}'
        f"</div>"
    )
