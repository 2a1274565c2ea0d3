"""1.7 relative_pose: frames A and B in the world, and B where your relative pose puts it when it is
laid back onto A (A ⊕ yours), beside where the reference's puts it (B itself)."""

from __future__ import annotations

import math

from ...number_format import compact
from ..svg import Canvas
from . import Drawn, RunFigure
from .marks import INPUT, REFERENCE, YOURS, finite, inside, key, message, with_message

AXIS = 0.8  # length of a frame's axes


def on_a(a, rel) -> tuple[float, float, float]:
    """The world pose of ``rel`` given in frame ``a``: a ⊕ rel.

    >>> [round(v, 6) + 0.0 for v in on_a((1, 2, math.pi / 2), (1, 0, 0))]
    [1.0, 3.0, 1.570796]
    """
    xa, ya, ta = a
    x, y, t = rel
    return (xa + math.cos(ta) * x - math.sin(ta) * y, ya + math.sin(ta) * x + math.cos(ta) * y, ta + t)


def _frame(c: Canvas, pose, cls: str, name: str) -> None:
    x, y, t = pose
    origin = inside(c, (x, y))
    c.arrow(origin, (origin[0] + AXIS * math.cos(t), origin[1] + AXIS * math.sin(t)), f"{cls} wb-fig-thick")
    c.arrow(origin, (origin[0] - 0.6 * AXIS * math.sin(t), origin[1] + 0.6 * AXIS * math.cos(t)), f"{cls} wb-fig-thin")
    c.dot(origin, 4, f"{cls.split()[0]} wb-fig-solid")
    c.label(origin, name, f"wb-fig-label wb-fig-small {cls.split()[0]}", toward=(-math.cos(t), -math.sin(t)))


def frame(d: Drawn) -> tuple[str, str]:
    a, b = d.args
    got = d.got if d.got is not None and finite(*d.got) else None
    mine = on_a(a, got) if got is not None else None
    pts = [a[:2], b[:2]] + ([mine[:2]] if mine and max(map(abs, mine[:2])) < 50 else [])
    xs, ys = [p[0] for p in pts], [p[1] for p in pts]
    span = max(max(xs) - min(xs), max(ys) - min(ys), 1.0) * 0.6 + 1.0
    cx, cy = (max(xs) + min(xs)) / 2, (max(ys) + min(ys)) / 2
    c = Canvas(380, 340, (cx - span, cx + span), (cy - span, cy + span), pad=(12, 12, 12, 20))
    c.grid(1.0, labels=False)
    key(c, reference="B")
    _frame(c, a, INPUT, "A")
    _frame(c, b, REFERENCE, "B")
    if mine is not None:
        c.line(inside(c, mine[:2]), tuple(b[:2]), "wb-fig-bad wb-fig-thin")
        _frame(c, mine, YOURS, "A ⊕ yours")
    below = message(c, d.message)
    want = d.want
    yours = (f"yours is ({compact(got[0])}, {compact(got[1])}, {compact(math.degrees(got[2]))}°), which puts B at "
             f"({compact(mine[0])}, {compact(mine[1])})" if got is not None and mine is not None
             else "your function gave no pose to draw")
    description = with_message(
        f"{d.label}: A at ({compact(a[0])}, {compact(a[1])}) facing {compact(math.degrees(a[2]))}°, B at "
        f"({compact(b[0])}, {compact(b[1])}) facing {compact(math.degrees(b[2]))}°; B seen from A is "
        f"({compact(want[0])}, {compact(want[1])}, {compact(math.degrees(want[2]))}°); {yours}.", d.message)
    return c.svg(f"relative_pose, {d.label}: frame B, and where your answer puts it", extra_height=below), description


RUN = RunFigure(name="frames", title="Your relative pose, drawn", unit="", frame=frame)
