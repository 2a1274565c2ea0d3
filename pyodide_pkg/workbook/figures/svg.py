"""Small SVG writer for the figures: world coordinates (y up) onto a viewBox.

Colours never appear here: every shape gets CSS classes (``docs/assets/
workbook.css``, section "Figures"), which follow the light and dark palettes.
"""

from __future__ import annotations

import math
from collections.abc import Iterable
from html import escape

Point = tuple[float, float]
Box = tuple[float, float, float, float]  # left, top, right, bottom (viewBox units)

# Text sizes in viewBox units, as workbook.css sets them (".wb-fig-svg text" and
# ".wb-fig-small"), and a rough box for a label's ink: 0.6 em a character (plus
# 0.1 em of side bearings) is wider than most sans-serif glyphs, so the estimate
# holds the real text; ascenders reach 0.8 em above the baseline, descenders 0.25 em.
FONT_SIZE = 15.0
SMALL_SIZE = 12.5
CHAR_EM = 0.6
PAD_EM = 0.1
ASCENT_EM = 0.8
DESCENT_EM = 0.25
# How far a placed label may move from its point (viewBox units), nearest first,
# and the directions tried at each distance (steps of 15° either side of the preferred one).
LABEL_GAPS = (7.0, 15.0, 26.0, 40.0, 56.0, 75.0, 100.0)
LABEL_TURNS = (0,) + tuple(k * sign for k in range(1, 12) for sign in (1, -1)) + (12,)
CLEARANCE = 2.5  # what a label keeps from a drawn line (half a thick stroke, and a little air)
AIR = 1.5  # what a label keeps from other texts and dots


def font_size(cls: str) -> float:
    """The font size (viewBox units) of a text with the CSS classes ``cls``."""
    return SMALL_SIZE if "wb-fig-small" in cls.split() else FONT_SIZE


def text_box(x: float, y: float, content: str, size: float, anchor: str = "middle") -> Box:
    """The box a text at (x, y) (its baseline) covers, roughly: see CHAR_EM.

    >>> text_box(100, 50, "col 1", 10)
    (84.5, 42.0, 115.5, 52.5)
    >>> text_box(100, 50, "ab", 10, anchor="end")
    (87.0, 42.0, 100.0, 52.5)
    """
    width = (len(content) * CHAR_EM + PAD_EM) * size
    left = x if anchor == "start" else x - width if anchor == "end" else x - width / 2
    return (left, y - ASCENT_EM * size, left + width, y + DESCENT_EM * size)


def boxes_overlap(a: Box, b: Box) -> bool:
    """Whether two boxes share any area (touching edges do not count).

    >>> boxes_overlap((0, 0, 2, 2), (1, 1, 3, 3)), boxes_overlap((0, 0, 1, 1), (1, 0, 2, 1))
    (True, False)
    """
    return a[0] < b[2] and b[0] < a[2] and a[1] < b[3] and b[1] < a[3]


def segment_hits_box(p: Point, q: Point, box: Box) -> bool:
    """Whether the segment p–q passes through the box's interior (Liang–Barsky clipping).

    >>> segment_hits_box((0, 5), (10, 5), (4, 4, 6, 6)), segment_hits_box((0, 0), (10, 0), (4, 4, 6, 6))
    (True, False)
    """
    if max(p[0], q[0]) <= box[0] or min(p[0], q[0]) >= box[2] or max(p[1], q[1]) <= box[1] or min(p[1], q[1]) >= box[3]:
        return False  # the segment's own box is clear of it (the usual case, and quick)
    (x, y), dx, dy = p, q[0] - p[0], q[1] - p[1]
    t0, t1 = 0.0, 1.0
    for step, room in ((-dx, x - box[0]), (dx, box[2] - x), (-dy, y - box[1]), (dy, box[3] - y)):
        if step == 0:
            if room <= 0:
                return False
            continue
        t = room / step
        if step < 0:
            t0 = max(t0, t)
        else:
            t1 = min(t1, t)
    return t0 < t1


def _grow(box: Box, by: float) -> Box:
    return (box[0] - by, box[1] - by, box[2] + by, box[3] + by)


def _f(v: float) -> str:
    return f"{v:.1f}".rstrip("0").rstrip(".") if abs(v) < 1e6 else "0"


class Canvas:
    """An SVG picture of a region of the plane, scaled to fit ``width`` × ``height``.

    The region [xmin, xmax] × [ymin, ymax] is centred in the box inside the
    margins ``pad`` (one number, or left, top, right, bottom), keeping its
    aspect ratio unless ``aspect`` is false (a chart). ``offset`` moves the
    panel within a larger picture. Texts drawn with ``label()`` are placed by
    ``svg()``, clear of the other texts, the dots, the arrows and the lines
    given to ``keep_clear()``.

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
        # What placed labels (label()) keep clear of: the boxes of texts, dots and
        # labels already placed, and the segments of arrows and keep_clear() lines.
        self.taken: list[Box] = []
        self.segments: list[tuple[Point, Point]] = []
        self._labels: list[tuple[Point, str, str, Point | None]] = []

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
        if r < 20:  # a marker, not an area
            self.taken.append((x - r, y - r, x + r, y + r))

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
        left, right = (bx - uy * w, by + ux * w), (bx + uy * w, by - ux * w)
        self.segments += [((x1, y1), (x2, y2)), (left, (x2, y2)), (right, (x2, y2)), (left, right)]
        self.add(f'<g class="{cls}"><line x1="{_f(x1)}" y1="{_f(y1)}" x2="{_f(bx)}" y2="{_f(by)}"/>'
                 f'<polygon class="wb-fig-head" points="{_f(x2)},{_f(y2)} {_f(bx - uy * w)},{_f(by + ux * w)} '
                 f'{_f(bx + uy * w)},{_f(by - ux * w)}"/></g>')

    def text(self, p: Point, content: str, cls: str = "wb-fig-label", dx: float = 0, dy: float = 0,
             anchor: str = "middle") -> None:
        x, y = self.xy(*p)
        self._text_at(x + dx, y + dy, content, cls, anchor)

    def _text_at(self, x: float, y: float, content: str, cls: str, anchor: str) -> None:
        self.add(f'<text x="{_f(x)}" y="{_f(y)}" text-anchor="{anchor}" class="{cls}">{escape(content)}</text>')
        self.taken.append(text_box(float(_f(x)), float(_f(y)), content, font_size(cls), anchor))

    # labels that keep clear of each other and of the drawing ---------------------
    def keep_clear(self, points: Iterable[Point]) -> None:
        """Have placed labels keep off this polyline (world points), as they do off arrows."""
        pts = [self.xy(*p) for p in points]
        self.segments += list(zip(pts, pts[1:]))

    def label(self, p: Point, content: str, cls: str = "wb-fig-label", toward: Point | None = None) -> None:
        """A label for the point ``p``, placed when the picture is finished (svg()).

        It goes beside ``p``, preferably in the world direction ``toward`` (say,
        along the vector that ends at ``p``): the nearest spot, trying other
        directions and then larger distances, where it overlaps no other text,
        dot or placed label, crosses no arrow or keep_clear() line, and stays
        inside the picture. Labels are placed in the order they were asked for.
        """
        self._labels.append((p, content, cls, toward))

    def _clash(self, box: Box) -> float:
        """How bad a spot is: 0 when free; leaving the picture is worst, then text on text."""
        x0, y0 = self.left, self.top
        outside = max(0.0, x0 + 2 - box[0]) + max(0.0, box[2] - (x0 + self.width - 2)) \
            + max(0.0, y0 + 2 - box[1]) + max(0.0, box[3] - (y0 + self.height - 2))
        cost = 1e6 * outside
        roomy = _grow(box, AIR)
        cost += 1e4 * sum(boxes_overlap(roomy, other) for other in self.taken)
        if cost == 0:
            grown = _grow(box, CLEARANCE)
            cost += sum(segment_hits_box(p, q, grown) for p, q in self.segments)
        return cost

    def _place_labels(self) -> None:
        for p, content, cls, toward in self._labels:
            size = font_size(cls)
            w, h = (len(content) * CHAR_EM + PAD_EM) * size, (ASCENT_EM + DESCENT_EM) * size
            x, y = self.xy(*p)
            # a point beyond the picture's edge is labelled where it leaves the picture
            x = min(max(x, self.left + 4), self.left + self.width - 4)
            y = min(max(y, self.top + 4), self.top + self.height - 4)
            tx, ty = toward if toward and math.hypot(*toward) > 1e-9 else (1.0, 1.0)
            base = math.atan2(-ty, tx)  # the viewBox's y points down
            best: tuple[float, Box] | None = None
            for gap in LABEL_GAPS:
                for turn in LABEL_TURNS:
                    ux, uy = math.cos(base + turn * math.pi / 12), math.sin(base + turn * math.pi / 12)
                    reach = gap + abs(ux) * w / 2 + abs(uy) * h / 2
                    cx, cy = x + ux * reach, y + uy * reach
                    box = (cx - w / 2, cy - h / 2, cx + w / 2, cy + h / 2)
                    cost = self._clash(box)
                    if best is None or cost < best[0]:
                        best = (cost, box)
                    if cost == 0:
                        break
                if best is not None and best[0] == 0:
                    break
            assert best is not None  # (LABEL_GAPS and LABEL_TURNS are not empty)
            box = best[1]
            # the baseline sits DESCENT_EM above the box's bottom
            self._text_at((box[0] + box[2]) / 2, box[3] - DESCENT_EM * size, content, cls, "middle")
        self._labels = []

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
        self._place_labels()
        return render_svg(self.width, self.height + extra_height, title, self.parts, css)


def render_svg(width: float, height: float, title: str, parts: Iterable[str], css: str = "") -> str:
    cls = "wb-fig-svg" + (f" {css}" if css else "")
    return (f'<svg class="{cls}" viewBox="0 0 {_f(width)} {_f(height)}" width="100%" role="img" '
            f'xmlns="http://www.w3.org/2000/svg"><title>{escape(title)}</title>{"".join(parts)}</svg>')
