"""Build side: read the ``:::`` blocks of a chapter page, strictly.

A chapter places an exercise and a figure like this::

    ::: exercise 0.1 | Rotate a point by 90°
    The prompt, in Markdown.

    ::: hint
    Optional hint.
    :::

    ::: solution
    The derivation or explanation.
    :::
    :::

    ::: figure rotation-2d

Code fences (``` or ~~~, three or more, closed by the same character at least
as long, per CommonMark) are copied through untouched, so a ``:::`` inside a
fence is text. Any other line that starts with ``:::`` is an error, and so is a
block left open: :func:`parse` raises :class:`BlockError` with the line number
rather than guess.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field

OPEN = re.compile(r"^::: exercise\s+(?P<id>\d+\.\d+)\s*(?:\|\s*(?P<title>.*?))?\s*$")
SECTION = re.compile(r"^::: (?P<name>hint|solution)\s*$")
FIGURE = re.compile(r"^::: figure\s+(?P<name>[a-z0-9-]+)\s*$")
CLOSE = re.compile(r"^:::\s*$")
FENCE = re.compile(r"^ {0,3}(?P<fence>`{3,}|~{3,})")


class BlockError(ValueError):
    """A ``:::`` line the parser does not understand, or a block left open."""


@dataclass
class ExerciseBlock:
    id: str
    title: str
    start: int  # index of the opening line
    end: int  # index of the closing line
    parts: dict[str, list[str]] = field(default_factory=lambda: {"prompt": [], "hint": [], "solution": []})

    def text(self, part: str) -> str:
        return "\n".join(self.parts[part]).strip()


@dataclass
class FigureBlock:
    name: str
    line: int


def _fence_closes(line: str, fence: str) -> bool:
    m = FENCE.match(line)
    return m is not None and m["fence"][0] == fence[0] and len(m["fence"]) >= len(fence) and not line[m.end():].strip()


def parse(text: str, where: str = "page") -> list[ExerciseBlock | FigureBlock]:
    """Every block of ``text`` in order; raises BlockError on anything unexpected."""
    lines = text.split("\n")
    out: list[ExerciseBlock | FigureBlock] = []
    current: ExerciseBlock | None = None
    section = "prompt"
    fence = ""
    for i, line in enumerate(lines):
        here = f"{where}, line {i + 1}"
        if fence:
            if _fence_closes(line, fence):
                fence = ""
        elif m := FENCE.match(line):
            fence = m["fence"]
        elif line.startswith(":::"):
            if current is None:
                if m := OPEN.match(line):
                    current, section = ExerciseBlock(m["id"], (m["title"] or "").strip(), i, -1), "prompt"
                    continue
                if m := FIGURE.match(line):
                    out.append(FigureBlock(m["name"], i))
                    continue
                raise BlockError(f"{here}: expected '::: exercise ID | Title' or '::: figure NAME', got {line!r}")
            if m := SECTION.match(line):
                if section != "prompt":
                    raise BlockError(f"{here}: '::: {m['name']}' inside '::: {section}' (close it with ':::' first)")
                if current.parts[m["name"]]:
                    raise BlockError(f"{here}: exercise {current.id} has a second '::: {m['name']}'")
                section = m["name"]
                continue
            if CLOSE.match(line):
                if section != "prompt":
                    section = "prompt"
                else:
                    current.end = i
                    out.append(current)
                    current = None
                continue
            raise BlockError(f"{here}: unexpected {line!r} inside exercise {current.id}")
        if current is not None:
            current.parts[section].append(line)
    if fence:
        raise BlockError(f"{where}: a code fence {fence!r} is never closed")
    if current is not None:
        raise BlockError(f"{where}: exercise {current.id} (line {current.start + 1}) is not closed with ':::'")
    return out
