"""What every exercise kind shares: an id, a title, a check and a widget."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from html import escape
from typing import Any, ClassVar, Protocol

from ..contract import ATTR, ROLE, role_attr
from ..verdict import Verdict


class Page(Protocol):
    """What a widget's markup may ask of the page it is built for (build side)."""

    def inline(self, markdown: str) -> str: ...  # one line of Markdown as inline HTML
    def highlight(self, line: str) -> str: ...  # one line of Python, highlighted


class PlainPage:
    """A page without Markdown or highlighting (tests, and the worker)."""

    inline = staticmethod(escape)
    highlight = staticmethod(escape)


@dataclass(frozen=True)
class Exercise:
    """Base of every kind. Subclasses set ``kind`` and ``op`` and implement the rest.

    ``op`` is the one request that grades the kind: ``"grade"`` (an answer) or
    ``"run"`` (code, with a time limit that starts when the code starts).
    """

    id: str
    title: str
    # Why every student has the same right answer whatever their numbers (the teach page says so);
    # "" where variants give each student their own answer (workbook.copying measures it).
    same_answer: str = field(default="", kw_only=True, compare=False)
    kind: ClassVar[str] = ""
    op: ClassVar[str] = "grade"
    reveal_label: ClassVar[str] = "Show explanation"

    def check(self, answer: Any) -> Verdict:
        raise NotImplementedError

    def widget(self, base: str, page: Page) -> str:
        """The HTML of the answer area (inside the exercise element)."""
        raise NotImplementedError

    def attributes(self) -> dict[str, str]:
        """Extra attributes of the exercise element (e.g. an answer's shape)."""
        return {}

    def worked_html(self) -> str:
        """HTML that ends the revealed derivation (Derive: the answer as typed)."""
        return ""


__all__ = ["ATTR", "ROLE", "Callable", "Exercise", "Page", "PlainPage", "escape", "role_attr"]
