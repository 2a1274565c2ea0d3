"""Debug: click the buggy line of a short program."""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from typing import Any, ClassVar

from ..verdict import Verdict
from .base import ATTR, ROLE, Exercise, Page, check_button, escape, form, role_attr


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
        note = self.notes.get(n, "This line does what it should.").rstrip()
        note = note if note.endswith((".", "!", "?")) else note + "."
        return Verdict("incorrect", f"Line {n} is fine: {note} The bug is on another line.", data={"line": n})

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


EXERCISE = Debug
