"""The static HTML of each exercise widget, rendered at build time.

The MkDocs hook (``docs/hooks/exercises.py``) turns the chapter's Markdown into
HTML and passes it in; this module adds what comes from the bank: the answer
field, the options, the code lines, the steps, the editor's starter code. No
answer key is written in plain HTML: the derivation travels base64-encoded and
is decoded only when the learner asks for it, and the correct option, line or
order is never in the page.
"""

from __future__ import annotations

import base64
from html import escape
from typing import Callable

from .exercises import Build, Debug, Derive, Design, Exercise, Trace

Inline = Callable[[str], str]

REVEAL_LABEL = {"derive": "Show derivation", "build": "Show solution"}
KIND_LABEL = {"derive": "Derive", "trace": "Trace", "build": "Build", "debug": "Debug", "design": "Design"}


def dom_id(exercise_id: str) -> str:
    return "ex-" + exercise_id.replace(".", "-")


def _highlight_python(line: str) -> str:
    try:
        from pygments import highlight
        from pygments.formatters import HtmlFormatter
        from pygments.lexers import PythonLexer
    except ImportError:  # pragma: no cover - pygments ships with the docs toolchain
        return escape(line)
    return highlight(line, PythonLexer(), HtmlFormatter(nowrap=True)).rstrip("\n") or " "


def _check_button() -> str:
    return '<button type="submit" class="md-button md-button--primary wb-check" data-role="check">Check</button>'


def _derive(ex: Derive, base: str) -> str:
    unit = f'<span class="wb-unit" aria-hidden="true">{escape(ex.unit)}</span>' if ex.unit else ""
    label = escape(ex.label) + (f" ({escape(ex.unit)})" if ex.unit and ex.unit != "°" else (" (degrees)" if ex.unit == "°" else ""))
    return (
        f'<form class="wb-form wb-derive" novalidate>'
        f'<label class="wb-label" for="{base}-answer">{label}</label>'
        f'<span class="wb-answer-row"><input id="{base}-answer" class="wb-answer" data-role="answer" type="text" '
        f'inputmode="text" autocomplete="off" autocapitalize="off" spellcheck="false" '
        f'placeholder="e.g. 0.5, sqrt(2)/2, pi/4" aria-describedby="{base}-feedback">{unit}'
        f"{_check_button()}</span></form>"
    )


def _trace(ex: Trace, base: str, inline: Inline) -> str:
    items = "".join(
        f'<label class="wb-choice"><input type="radio" name="{base}-choice" value="{escape(o.key)}" data-role="choice">'
        f'<span class="wb-choice-key">{escape(o.key)}</span>'
        f'<span class="wb-choice-text">{inline(o.text)}</span></label>'
        for o in ex.options
    )
    return (
        f'<form class="wb-form wb-trace" novalidate><fieldset class="wb-choices" aria-describedby="{base}-feedback">'
        f'<legend class="wb-label">Choose one answer</legend>{items}</fieldset>{_check_button()}</form>'
    )


def _debug(ex: Debug, base: str) -> str:
    rows = "".join(
        f'<li class="wb-line" data-role="line" data-line="{n}" role="option" aria-selected="false" tabindex="{0 if n == 1 else -1}">'
        f'<span class="wb-lineno" aria-hidden="true">{n}</span><code>{_highlight_python(text)}</code></li>'
        for n, text in enumerate(ex.lines, start=1)
    )
    return (
        f'<form class="wb-form wb-debug" novalidate><p class="wb-label" id="{base}-lines-label">'
        f"Click the line with the bug (or move with the arrow keys and press Space).</p>"
        f'<ol class="wb-code highlight" role="listbox" aria-labelledby="{base}-lines-label" '
        f'aria-describedby="{base}-feedback">{rows}</ol>{_check_button()}</form>'
    )


def _design(ex: Design, base: str, inline: Inline) -> str:
    text = {s.key: s.text for s in ex.steps}
    rows = "".join(
        f'<li class="wb-step" data-role="step" data-step="{escape(key)}" draggable="true">'
        f'<span class="wb-step-handle" aria-hidden="true">⋮⋮</span>'
        f'<span class="wb-step-text">{inline(text[key])}</span>'
        f'<span class="wb-step-moves">'
        f'<button type="button" class="wb-move" data-role="move-up" aria-label="Move “{escape(text[key])}” up">▲</button>'
        f'<button type="button" class="wb-move" data-role="move-down" aria-label="Move “{escape(text[key])}” down">▼</button>'
        f"</span></li>"
        for key in ex.shown
    )
    return (
        f'<form class="wb-form wb-design" novalidate><p class="wb-label" id="{base}-steps-label">'
        f"Put the steps in order: drag them, or use the arrow buttons.</p>"
        f'<ol class="wb-steps" aria-labelledby="{base}-steps-label" aria-describedby="{base}-feedback">{rows}</ol>'
        f"{_check_button()}</form>"
    )


def _build(ex: Build, base: str) -> str:
    return (
        f'<div class="wb-build">'
        f'<p class="wb-label" id="{base}-editor-label">Your code: define <code>{escape(ex.signature)}</code>. '
        f"<kbd>Ctrl</kbd>+<kbd>Enter</kbd> runs the tests.</p>"
        f'<div class="wb-editor" data-role="editor" data-function="{escape(ex.function)}" '
        f'data-time-limit="{ex.time_limit:g}" aria-labelledby="{base}-editor-label">'
        f'<pre class="wb-starter"><code>{escape(ex.starter)}</code></pre></div>'
        f'<div class="wb-build-actions">'
        f'<button type="button" class="md-button md-button--primary" data-role="run">Run tests</button>'
        f'<button type="button" class="md-button" data-role="reset">Reset to starter</button></div>'
        f'<div class="wb-tests" data-role="tests" hidden></div>'
        f'<pre class="wb-stdout" data-role="stdout" hidden></pre>'
        f"</div>"
    )


def exercise_html(ex: Exercise, prompt_html: str, hint_html: str, solution_html: str, inline: Inline = escape) -> str:
    """The whole widget for ``ex`` (see the page contract in the guide)."""
    base = dom_id(ex.id)
    if isinstance(ex, Derive):
        body = _derive(ex, base)
    elif isinstance(ex, Trace):
        body = _trace(ex, base, inline)
    elif isinstance(ex, Debug):
        body = _debug(ex, base)
    elif isinstance(ex, Design):
        body = _design(ex, base, inline)
    elif isinstance(ex, Build):
        body = _build(ex, base)
    else:  # pragma: no cover
        raise TypeError(type(ex).__name__)
    help_buttons = []
    panels = []
    if hint_html:
        help_buttons.append(
            f'<button type="button" class="md-button wb-help-button" data-role="hint" aria-expanded="false" '
            f'aria-controls="{base}-hint">Show hint</button>'
        )
        panels.append(
            f'<div class="admonition tip wb-hint" id="{base}-hint" hidden>'
            f'<p class="admonition-title">Hint</p>{hint_html}</div>'
        )
    if solution_html:
        label = REVEAL_LABEL.get(ex.kind, "Show explanation")
        encoded = base64.b64encode(solution_html.encode("utf-8")).decode("ascii")
        help_buttons.append(
            f'<button type="button" class="md-button wb-help-button" data-role="reveal" aria-expanded="false" '
            f'aria-controls="{base}-solution">{label}</button>'
        )
        title = label.removeprefix("Show ").capitalize()
        panels.append(
            f'<div class="admonition success wb-solution" id="{base}-solution" hidden data-title="{title}" '
            f'data-content="{encoded}"></div>'
        )
    return (
        f'<div class="wb-exercise" id="{base}" data-exercise-id="{escape(ex.id)}" data-kind="{ex.kind}" '
        f'data-state="unanswered" aria-labelledby="{base}-title">'
        f'<div class="wb-head"><span class="wb-kind wb-kind--{ex.kind}">{KIND_LABEL[ex.kind]}</span>'
        f'<span class="wb-status" data-role="status" aria-hidden="true"></span></div>'
        f'<div class="wb-prompt">{prompt_html}</div>'
        f"{body}"
        f'<div class="wb-feedback" id="{base}-feedback" data-role="feedback" role="status" aria-live="polite"></div>'
        f'<div class="wb-help">{"".join(help_buttons)}</div>'
        f'{"".join(panels)}'
        f"</div>"
    )
