"""5.8 gauss_newton_step: three poses on a line before the step, with the edges that tie them, and
after it: yours over the reference's (pose 0, the anchor, never moves)."""

from __future__ import annotations

from ...number_format import compact
from ..svg import Canvas
from . import Drawn, RunFigure
from .marks import INPUT, REFERENCE, YOURS, finite, key, message, with_message

ROWS = {"before": 3.0, "reference": 1.8, "yours": 0.8}


def _poses(c: Canvas, xs, row: str, cls: str, name: str) -> None:
    y = ROWS[row]
    c.text((c.xrange[0], y), name, f"wb-fig-label wb-fig-small {cls.split()[0]}", dx=-8, dy=4, anchor="end")
    lo, hi = c.xrange
    shown = [min(max(x, lo), hi) for x in xs]
    c.polyline([(x, y) for x in shown], f"{cls} wb-fig-thin")
    for k, x in enumerate(shown):
        c.dot((x, y), 6, f"{cls.split()[0]} wb-fig-solid")
        c.text((x, y), str(k), f"wb-fig-label wb-fig-small {cls.split()[0]}", dy=-10)


def _edges(c: Canvas, xs, edges) -> None:
    """Each edge as an arc over the 'before' row, from pose i to pose j."""
    y = ROWS["before"]
    for n, (i, j, z, _w) in enumerate(edges):
        a, b = xs[int(i)], xs[int(j)]
        rise = 0.35 + 0.22 * n
        mid = (a + b) / 2
        pts = [(a + (b - a) * t / 16, y + rise * 4 * (t / 16) * (1 - t / 16)) for t in range(17)]
        c.polyline(pts, f"{INPUT} wb-fig-thin wb-fig-dash")
        c.text((mid, y + rise), f"z = {compact(z)}", "wb-fig-label wb-fig-small wb-fig-muted", dy=-3)


def frame(d: Drawn) -> tuple[str, str]:
    xs, edges = d.args
    xs = [float(x) for x in xs]
    after = d.want[1] if d.want is not None else None
    got = d.got[1] if d.got is not None and finite(*d.got[1]) and finite(*d.got[0]) else None
    spread = xs + (after or []) + (got or [])
    lo, hi = min(spread), max(spread)
    pad = max(0.5, 0.2 * (hi - lo))
    c = Canvas(480, 260, (lo - pad, hi + pad), (0.2, 4.6), pad=(128, 12, 12, 20), aspect=False)
    key(c)
    _edges(c, xs, edges)
    _poses(c, xs, "before", INPUT, "before")
    if after is not None:
        _poses(c, after, "reference", REFERENCE, "after (reference)")
        truth = "the reference moves them to " + ", ".join(compact(x) for x in after)
    else:
        truth = "a pose is tied to nothing, so the reference returns None"
    if got is not None:
        _poses(c, got, "yours", YOURS, "after (yours)")
        yours = "yours moves them to " + ", ".join(compact(x) for x in got)
    elif d.got is None and d.want is None and not d.message:
        yours = "yours returns None too"
    else:
        yours = "your function gave no poses to draw"
    below = message(c, d.message)
    ties = "; ".join(f"{int(i)} to {int(j)}: {compact(z)} (weight {compact(w)})" for i, j, z, w in edges)
    description = with_message(f"{d.label}: poses at {', '.join(compact(x) for x in xs)}, edges {ties}; {truth}; "
                               f"{yours}.", d.message)
    return c.svg(f"gauss_newton_step, {d.label}: the poses before and after one step", extra_height=below), description


RUN = RunFigure(name="pose-graph", title="Your Gauss–Newton step, drawn", unit="", frame=frame)
