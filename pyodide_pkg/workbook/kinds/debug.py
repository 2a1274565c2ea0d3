"""Debug: click the buggy line of a short program."""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from typing import Any, ClassVar

from ..markup import check_button, form
from ..verdict import Verdict
from .base import ATTR, ROLE, Exercise, Page, escape, role_attr


@dataclass(frozen=True)
class Debug(Exercise):
    """``notes`` maps every other line number (1-based) to a word on what that
    line does right; ``bug`` explains the bug; ``fixed_line`` is the repair,
    used by the tests to prove the program then agrees with ``reference``.
    ``symptom`` names a drawing of what the bug does (``workbook.figures.symptoms``),
    built into the widget hidden and shown with the explanation once the bug is found.
    """

    code: str = ""
    bug_line: int = 0
    fixed_line: str = ""
    bug: str = ""
    notes: Mapping[int, str] = field(default_factory=dict)
    function: str = ""
    reference: Callable[..., Any] | None = None
    cases: tuple[tuple, ...] = ()
    symptom: str = ""
    kind: ClassVar[str] = "debug"

    @property
    def lines(self) -> list[str]:
        return self.code.rstrip("\n").split("\n")

    def check(self, line: object) -> Verdict:
        count = len(self.lines)
        try:
            n = int(line)  # type: ignore[call-overload]  # anything the page sent: int() decides
        except (TypeError, ValueError):
            return Verdict("invalid", "Click the line you think holds the bug, then check.")
        if not 1 <= n <= count:
            return Verdict("invalid", f"Pick a line between 1 and {count}.")
        if n == self.bug_line:
            return Verdict("correct", self.bug, data={"line": n})
        return Verdict("incorrect", f"{_fine(n, self.notes.get(n, ''))} The bug is on another line.", data={"line": n})

    def widget(self, base: str, page: Page) -> str:
        rows = "".join(
            f'<li class="wb-line" {role_attr(ROLE.line)} {ATTR.line}="{n}" role="option" aria-selected="false" '
            f'tabindex="{0 if n == 1 else -1}"><span class="wb-lineno" aria-hidden="true">{n}</span>'
            f"<code>{page.highlight(text)}</code></li>"
            for n, text in enumerate(self.lines, start=1)
        )
        return form(self.kind, (
            f'<p class="wb-label" id="{base}-lines-label">'
            f"Click the line with the bug (or move with the arrow keys and press Space).</p>"
            f'<ol class="wb-code highlight" role="listbox" aria-labelledby="{base}-lines-label" '
            f'aria-describedby="{base}-feedback">{rows}</ol>{check_button()}'
        )) + self._symptom_html(base)

    def _symptom_html(self, base: str) -> str:
        """The symptom's figure, hidden until the bug is found (build side only)."""
        if not self.symptom:
            return ""
        from ..figures.symptoms import render

        svg, text = render(self.symptom)
        return (f'<figure class="wb-symptom" {role_attr(ROLE.symptom)} id="{base}-symptom" hidden>'
                f'<div class="wb-fig-canvas">{svg}</div>'
                f'<figcaption>What the bug does: {escape(text)}</figcaption></figure>')


_VERBS = ("takes", "returns", "imports", "unpacks", "clamps", "computes", "notes", "adds", "keeps")


def _fine(n: int, note: str) -> str:
    """The sentence on a line without the bug, from its note ("correct: the derivative of the error",
    "correct once …: …", "takes the error …", or a noun phrase), read as a sentence.

    >>> _fine(2, "correct: the derivative of the error")
    'Line 2 is fine: the derivative of the error.'
    >>> _fine(4, "correct once the angle is in radians: y by r·sin")
    'Line 4 is correct once the angle is in radians: y by r·sin.'
    >>> _fine(1, "takes the pose"), _fine(7, "correct: adds Q"), _fine(3, "")
    ('Line 1 is fine: it takes the pose.', 'Line 7 is fine: it adds Q.', 'Line 3 is fine: it does what it should.')
    """
    note = note.strip().rstrip(".").removeprefix("correct: ") or "it does what it should"
    if note.startswith("correct "):
        text = f"Line {n} is {note}"
    elif note.split(" ", 1)[0] in _VERBS:
        text = f"Line {n} is fine: it {note}"
    else:
        text = f"Line {n} is fine: {note}"
    return text if text.endswith(("!", "?")) else text + "."


EXERCISE = Debug
