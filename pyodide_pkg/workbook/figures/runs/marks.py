"""What every run figure shares: the key (yours and the reference), a message on the picture,
and points kept inside it (a learner's function may return anything)."""

from __future__ import annotations

import math
from html import escape

from ..svg import Canvas

YOURS = "wb-fig-a"  # the learner's function: solid, thick
REFERENCE = "wb-fig-c wb-fig-dash"  # the reference: dashed
INPUT = "wb-fig-muted"


def inside(c: Canvas, p: tuple[float, float], margin: float = 0.0) -> tuple[float, float]:
    """``p`` moved onto the picture's edge when it lies beyond it (its drawing says so with a message).

    >>> inside(Canvas(100, 100, (-1, 1), (-1, 1)), (5.0, -0.5))
    (1.0, -0.5)
    """
    (x0, x1), (y0, y1) = c.xrange, c.yrange
    return (min(max(p[0], x0 + margin), x1 - margin), min(max(p[1], y0 + margin), y1 - margin))


def off_picture(c: Canvas, p: tuple[float, float]) -> bool:
    (x0, x1), (y0, y1) = c.xrange, c.yrange
    return not (x0 <= p[0] <= x1 and y0 <= p[1] <= y1)


def finite(*values: float) -> bool:
    return all(isinstance(v, (int, float)) and math.isfinite(v) for v in values)


def key(c: Canvas, yours: str = "yours", reference: str = "reference") -> None:
    """The two line styles, named, in the top-left corner of the plot."""
    x, y = c.xy(c.xrange[0], c.yrange[1])
    x, y = round(x + 10, 1), round(y + 14, 1)
    c.add(f'<line x1="{x}" y1="{y}" x2="{x + 22}" y2="{y}" class="{YOURS} wb-fig-thick"/>')
    c.add(f'<text x="{x + 28}" y="{y + 4}" class="wb-fig-label wb-fig-small {YOURS}">{yours}</text>')
    y += 18
    c.add(f'<line x1="{x}" y1="{y}" x2="{x + 22}" y2="{y}" class="{REFERENCE}"/>')
    c.add(f'<text x="{x + 28}" y="{y + 4}" class="wb-fig-label wb-fig-small wb-fig-c">{reference}</text>')
    c.taken.append((x - 2, y - 30, x + 120, y + 8))


def lines(text: str, width: int = 62, most: int = 2) -> list[str]:
    """``text`` in lines of at most ``width`` characters, broken between words; the last cut short.

    >>> lines("one two three", 8)
    ['one two', 'three']
    >>> lines("a " * 40, 10, 1)
    ['a a a a a…']
    """
    out: list[str] = []
    for word in text.split():
        if out and len(out[-1]) + 1 + len(word) <= width:
            out[-1] += " " + word
        else:
            out.append(word[:width])
    if len(out) > most:
        out = out[:most]
        out[-1] = out[-1][: width - 1] + "…"
    return out


def message(c: Canvas, text: str) -> float:
    """What went wrong, under the picture (three lines at most); returns the height it takes.

    Lines fit the picture's width at the largest size the labels take (15.5 px on a phone,
    about 8 px a character), so nothing is cut at either side.
    """
    rows = lines(text, width=int(c.width / 8), most=3)
    for k, row in enumerate(rows):
        y = c.top + c.height + 6 + 15 * k
        c.add(f'<text x="{c.left + c.width / 2:.1f}" y="{y:.1f}" text-anchor="middle" '
              f'class="wb-fig-label wb-fig-small wb-fig-bad">{escape(row)}</text>')
    return 15.0 * len(rows) + (6 if rows else 0)


def with_message(description: str, said: str) -> str:
    """The description, with what went wrong as a sentence of its own.

    >>> with_message("test 1: a point.", "your point lies beyond the edge")
    'test 1: a point. Your point lies beyond the edge.'
    """
    if not said:
        return description
    return f"{description} {said[0].upper()}{said[1:]}" + ("" if said.endswith(".") else ".")
