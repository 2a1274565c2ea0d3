"""Build side: the static HTML of one exercise, around the widget its kind draws.

The kind's module (``workbook/kinds/K.py``) draws the answer area; this module
adds the frame every exercise shares: the heading badge, the prompt, the
feedback region, the hint and the derivation. No answer key is written in plain
HTML: the derivation travels base64-encoded and is decoded only when the learner
asks for it (a reader of the page's code can still decode it; the README says so).
"""

from __future__ import annotations

import base64
import json
from collections.abc import Callable
from dataclasses import dataclass
from html import escape

from render_steps import steps_html
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


def _variant_controls(base: str) -> str:
    """New numbers, back to the workbook's, and a link to the numbers on screen
    (docs/assets/js/variants.js drives them)."""
    return (f'<div class="wb-variant" aria-label="Numbers" role="group">'
            f'<button type="button" class="md-button wb-help-button" {role_attr(ROLE.new_variant)}>New numbers</button>'
            f'<button type="button" class="md-button wb-help-button" {role_attr(ROLE.original_variant)} hidden>'
            f"Back to the workbook's numbers</button>"
            f'<span class="wb-variant-label" {role_attr(ROLE.variant_label)} aria-live="polite">'
            f"The workbook's numbers</span>"
            f'<a class="wb-variant-link" {role_attr(ROLE.variant_link)} href="#{base}" hidden>Link to these numbers</a>'
            f"</div>")


def exercise_html(ex: Exercise, prompt_html: str, hint_html: str, solution_html: str,
                  tools: PageTools | None = None, templates: dict[str, str] | None = None) -> str:
    """The whole exercise element (CONTRACT.md lists its attributes and roles).

    ``templates`` (an exercise that draws variants): the title, prompt, hint and
    derivation with their ``{{name}}`` placeholders, for the worker's ``draw``.
    """
    tools = tools or PageTools()
    base = dom_id(ex.id)
    if solution_html:
        solution_html += ex.worked_html()
    buttons, panels = _help(ex, base, hint_html, solution_html)
    attributes = dict(ex.attributes())
    if templates is not None:
        attributes[ATTR.variant] = "0"
        attributes[ATTR.templates] = base64.b64encode(json.dumps(templates, ensure_ascii=False).encode()).decode()
        buttons += _variant_controls(base)
    extra = "".join(f' {name}="{escape(value)}"' for name, value in attributes.items())
    return (
        f'<div class="wb-exercise" id="{base}" {ATTR.exercise}="{escape(ex.id)}" {ATTR.kind}="{ex.kind}" '
        f'{ATTR.state}="{STATE.unanswered}"{extra} role="region" aria-labelledby="{base}-name">'
        '<div class="wb-head"><span class="wb-kind '
        f'wb-kind--{ex.kind}">{KIND_LABEL.get(ex.kind, ex.kind.title())}</span>'
        f'<span class="wb-status" {role_attr(ROLE.status)} aria-hidden="true"></span></div>'
        f'<div class="wb-prompt">{prompt_html}</div>'
        f"{ex.widget(base, tools)}"
        f'<div class="wb-feedback" id="{base}-feedback" {role_attr(ROLE.feedback)} role="status" '
        'aria-live="polite"></div>'
        f"{steps_html(ex, base, tools)}"
        f'<div class="wb-help">{buttons}</div>{panels}'
        f"</div>"
    )


def exercise_index_html(items: list[tuple[str, str]]) -> str:
    """The list of a page's exercises under its title: one link each, to the exercise's heading.

    docs/assets/js/jump.js makes each link put the keyboard focus on the
    exercise's first control; without the script it scrolls to the heading.
    """
    links = "".join(
        f'<li><a href="#{dom_id(i)}-title" data-wb-jump="{escape(i)}">'
        f'<span class="wb-jump-id">{escape(i)}</span> <span class="wb-jump-title" '
        f'data-wb-jump-title>{escape(title)}</span></a></li>'
        for i, title in items)
    return (f'<nav class="wb-exercise-index" id="wb-exercises" aria-labelledby="wb-exercises-title">'
            f'<p class="wb-exercise-index-title" id="wb-exercises-title">Exercises on this page</p>'
            f"<ol>{links}</ol></nav>")


def chapter_list_html(chapters: list[tuple[str, str]]) -> str:
    """The home page's chapters: each chapter's own title (with its number, as in the menu), linked."""
    items = "".join(f'<li><a href="{escape(url)}">{escape(title)}</a></li>' for url, title in chapters)
    return f'<ul class="wb-chapter-list">{items}</ul>'
