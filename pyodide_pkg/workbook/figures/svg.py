"""Small SVG writer for the figures: world coordinates (y up) onto a viewBox.

Colours never appear here: every shape gets CSS classes (``docs/assets/
workbook.css``, section "Figures"), which follow the light and dark palettes.
"""

from __future__ import annotations

import math
from html import escape
from typing import Iterable, Sequence

Point = tuple[float, float]


def num(v: float, digits: int = 3) -> str:
    """A number for a readout: fixed digits, a real minus sign, no "−0.000".

    >>> num(-0.00001), num(-1.5), num(2, 1)
    ('0.000', '−1.500', '2.0')
    """
    text = f"{v:.{digits}f}"
    if text.lstrip("-").strip("0.") == "":
        text = text.lstrip("-")
    return text.replace("-", "−")


def vec(values: Iterable[float], digits: int = 3) -> str:
    """A tuple of numbers for a readout.

    >>> vec([1, -0.5])
    '(1.000, −0.500)'
    """
    return "(" + ", ".join(num(v, digits) for v in values) + ")"


def matrix(rows: Sequence[Sequence[float]], digits: int = 3) -> str:
    """A matrix for a readout, one row per line, columns aligned.

    >>> print(matrix([[1, -0.5], [0, 2]]))
     1.000  −0.500
     0.000   2.000
    """
    cells = [[num(v, digits) for v in row] for row in rows]
    width = max(len(c) for row in cells for c in row)
    return "\n".join("  ".join(c.rjust(width) for c in row) for row in cells)


def _f(v: float) -> str:
    return f"{v:.1f}".rstrip("0").rstrip(".") if abs(v) < 1e6 else "0"


class Canvas:
    """An SVG picture of a region of the plane, scaled to fit ``width`` × ``height``.

    The region [xmin, xmax] × [ymin, ymax] is centred in the box inside the
    margins ``pad`` (one number, or left, top, right, bottom), keeping its
    aspect ratio unless ``aspect`` is false (a chart). ``offset`` moves the
    panel within a larger picture.

    >>> c = Canvas(200, 100, (-1, 1), (-1, 1), pad=0)
    >>> c.xy(0, 0), c.xy(1, 1)
    ((100.0, 50.0), (150.0, 0.0))
    """

    def __init__(self, width: float, height: float, xrange: tuple[float, float], yrange: tuple[float, float],
                 pad: float | tuple[float, float, float, float] = 12, offset: Point = (0.0, 0.0),
                 aspect: bool = True) -> None:
        self.width, self.height = width, height
        (x0, x1), (y0, y1) = xrange, yrange
        left, top, right, bottom = (pad,) * 4 if isinstance(pad, (int, float)) else pad
        inner_w, inner_h = width - left - right, height - top - bottom
        self.sx, self.sy = inner_w / (x1 - x0), inner_h / (y1 - y0)
        if aspect:
            self.sx = self.sy = min(self.sx, self.sy)
        self.scale = self.sx
        self.ox = offset[0] + left + inner_w / 2 - self.sx * (x0 + x1) / 2
        self.oy = offset[1] + top + inner_h / 2 + self.sy * (y0 + y1) / 2
        self.left, self.top = offset
        self.xrange, self.yrange = xrange, yrange
        self.parts: list[str] = []

    # coordinates -------------------------------------------------------------
    def xy(self, x: float, y: float) -> Point:
        return (self.ox + self.sx * x, self.oy - self.sy * y)

    def _pts(self, points: Iterable[Point]) -> str:
        return " ".join(f"{_f(sx)},{_f(sy)}" for sx, sy in (self.xy(x, y) for x, y in points))

    def frame_transform(self) -> str:
        """The SVG transform from world coordinates to the viewBox (for dragging)."""
        return f"matrix({self.scale:.6g} 0 0 {-self.scale:.6g} {self.ox:.6g} {self.oy:.6g})"

    # shapes ------------------------------------------------------------------
    def add(self, raw: str) -> None:
        self.parts.append(raw)

    def line(self, p: Point, q: Point, cls: str) -> None:
        (x1, y1), (x2, y2) = self.xy(*p), self.xy(*q)
        self.add(f'<line x1="{_f(x1)}" y1="{_f(y1)}" x2="{_f(x2)}" y2="{_f(y2)}" class="{cls}"/>')

    def polyline(self, points: Iterable[Point], cls: str) -> None:
        self.add(f'<polyline points="{self._pts(points)}" class="{cls}"/>')

    def polygon(self, points: Iterable[Point], cls: str) -> None:
        self.add(f'<polygon points="{self._pts(points)}" class="{cls}"/>')

    def dot(self, p: Point, r: float, cls: str, extra: str = "") -> None:
        """A circle of ``r`` viewBox units (not world units) at ``p``."""
        x, y = self.xy(*p)
        self.add(f'<circle cx="{_f(x)}" cy="{_f(y)}" r="{_f(r)}" class="{cls}"{extra}/>')

    def circle(self, p: Point, radius: float, cls: str) -> None:
        """A circle of ``radius`` world units."""
        self.dot(p, radius * self.scale, cls)

    def ellipse(self, p: Point, a: float, b: float, angle: float, cls: str) -> None:
        """Semi-axes ``a``, ``b`` (world units), the ``a`` axis turned by ``angle`` radians."""
        x, y = self.xy(*p)
        deg = -math.degrees(angle)
        self.add(f'<ellipse cx="{_f(x)}" cy="{_f(y)}" rx="{self.scale * a:.2f}" ry="{self.scale * b:.2f}" '
                 f'transform="rotate({deg:.2f} {_f(x)} {_f(y)})" class="{cls}"/>')

    def arrow(self, p: Point, q: Point, cls: str, head: float = 9) -> None:
        """A line from p to q with a filled head of ``head`` viewBox units."""
        (x1, y1), (x2, y2) = self.xy(*p), self.xy(*q)
        length = math.hypot(x2 - x1, y2 - y1)
        if length < 1e-9:
            return
        ux, uy = (x2 - x1) / length, (y2 - y1) / length
        head = min(head, 0.6 * length)
        bx, by = x2 - ux * head, y2 - uy * head
        w = head * 0.45
        self.add(f'<g class="{cls}"><line x1="{_f(x1)}" y1="{_f(y1)}" x2="{_f(bx)}" y2="{_f(by)}"/>'
                 f'<polygon class="wb-fig-head" points="{_f(x2)},{_f(y2)} {_f(bx - uy * w)},{_f(by + ux * w)} '
                 f'{_f(bx + uy * w)},{_f(by - ux * w)}"/></g>')

    def text(self, p: Point, content: str, cls: str = "wb-fig-label", dx: float = 0, dy: float = 0,
             anchor: str = "middle") -> None:
        x, y = self.xy(*p)
        self.add(f'<text x="{_f(x + dx)}" y="{_f(y + dy)}" text-anchor="{anchor}" class="{cls}">{escape(content)}</text>')

    def tag(self, p: Point, content: str, cls: str = "wb-fig-label", gap: float = 9) -> None:
        """A label beside the point ``p``, on whichever side keeps it inside the picture."""
        x, y = self.xy(*p)
        right = x < self.left + 0.55 * self.width
        below = y < self.top + 24
        self.text(p, content, cls, dx=gap if right else -gap, dy=(gap + 8) if below else -gap,
                  anchor="start" if right else "end")

    def grid(self, step: float = 1.0, labels: bool = True) -> None:
        """Grid lines every ``step`` and the two axes through the origin."""
        (x0, x1), (y0, y1) = self.xrange, self.yrange
        k = math.ceil(x0 / step)
        while k * step <= x1 + 1e-9:
            self.line((k * step, y0), (k * step, y1), "wb-fig-grid")
            k += 1
        k = math.ceil(y0 / step)
        while k * step <= y1 + 1e-9:
            self.line((x0, k * step), (x1, k * step), "wb-fig-grid")
            k += 1
        if x0 <= 0 <= x1:
            self.line((0, y0), (0, y1), "wb-fig-axis")
        if y0 <= 0 <= y1:
            self.line((x0, 0), (x1, 0), "wb-fig-axis")
        if labels:
            self.text((x1, 0), "x", "wb-fig-label wb-fig-small", dx=-6, dy=14, anchor="end")
            self.text((0, y1), "y", "wb-fig-label wb-fig-small", dx=8, dy=12, anchor="start")

    def svg(self, title: str, extra_height: float = 0.0, css: str = "") -> str:
        """The finished ``<svg>`` element (the panel's viewBox, plus ``extra_height`` below)."""
        return render_svg(self.width, self.height + extra_height, title, self.parts, css)


def render_svg(width: float, height: float, title: str, parts: Iterable[str], css: str = "") -> str:
    cls = "wb-fig-svg" + (f" {css}" if css else "")
    return (f'<svg class="{cls}" viewBox="0 0 {_f(width)} {_f(height)}" width="100%" role="img" '
            f'xmlns="http://www.w3.org/2000/svg"><title>{escape(title)}</title>{"".join(parts)}</svg>')
