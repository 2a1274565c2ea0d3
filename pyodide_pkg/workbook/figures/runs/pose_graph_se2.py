"""5.10 gauss_newton_se2: the three poses before the iteration (grey triangles pointing along their
headings) with the edges that tie them (thin lines, the loop closure dashed), then the poses after it,
yours over the reference's; pose 0, the anchor, stays where it was."""

from __future__ import annotations

import math

from ...number_format import compact
from ..svg import Canvas
from . import Drawn, RunFigure
from .marks import INPUT, REFERENCE, YOURS, finite, inside, key, message, off_picture, with_message

FAR = 50.0  # a learner's pose further out than this is not used to size the picture


def _poses(value) -> list[tuple[float, float, float]] | None:
    """The poses in ``value`` when it has the shape of three (x, y, θ) rows, every number finite; else None."""
    try:
        out = [(float(p[0]), float(p[1]), float(p[2])) for p in value]
    except (TypeError, ValueError, IndexError, KeyError):
        return None
    if not out or any(len(p) != 3 for p in value) or not finite(*(v for p in out for v in p)):
        return None
    return out


def _triangle(c: Canvas, pose, size: float, cls: str) -> None:
    """A pose as a triangle pointing along its heading, its centre on the position."""
    x, y, t = pose
    tip = (x + size * math.cos(t), y + size * math.sin(t))
    back = [(x + 0.6 * size * math.cos(t + a), y + 0.6 * size * math.sin(t + a)) for a in (2.5, -2.5)]
    c.polygon([tip, back[0], back[1]], cls)
    c.keep_clear([tip, back[0], back[1], tip])  # the pose numbers keep off it


def _graph(c: Canvas, poses, edges, size: float, cls: str, name: str, numbered: bool) -> str:
    """Every edge as a line between its poses (a loop closure, i to j not next to each other, dashed),
    then each pose; returns what is odd about the poses ("" when nothing)."""
    at = [inside(c, p[:2]) for p in poses]
    for i, j, *_ in edges:
        i, j = int(i), int(j)
        closure = abs(i - j) != 1
        c.line(at[i], at[j], f"{cls.split()[0]} wb-fig-thin" + (" wb-fig-dash" if closure else ""))
        c.keep_clear([at[i], at[j]])
    for k, p in enumerate(poses):
        _triangle(c, (*at[k], p[2]), size, cls + (" wb-fig-face" if numbered else ""))
        if numbered:
            c.label(at[k], f"{name}{k}", f"wb-fig-label wb-fig-small {cls.split()[0]}",
                    toward=(-math.cos(p[2]), -math.sin(p[2])))
    return "beyond the picture's edge" if any(off_picture(c, p[:2]) for p in poses) else ""


def _listed(poses) -> str:
    return "; ".join(f"pose {k} at ({compact(x)}, {compact(y)}) facing {compact(math.degrees(t))}°"
                     for k, (x, y, t) in enumerate(poses))


def frame(d: Drawn) -> tuple[str, str]:
    poses, edges = d.args
    before = [(float(x), float(y), float(t)) for x, y, t in poses]
    want = _poses(d.want) if d.want is not None else None
    got = _poses(d.got) if d.got is not None else None
    pts = [p[:2] for p in before]
    for est in (want, got):
        if est is not None:
            pts += [p[:2] for p in est if max(map(abs, p[:2])) < FAR]
    xs, ys = [p[0] for p in pts], [p[1] for p in pts]
    span = max(max(xs) - min(xs), max(ys) - min(ys), 1.0) * 0.6 + 0.8
    cx, cy = (max(xs) + min(xs)) / 2, (max(ys) + min(ys)) / 2
    c = Canvas(400, 360, (cx - span, cx + span), (cy - span, cy + span), pad=(12, 12, 12, 20))
    c.grid(1.0 if span < 8 else 5.0, labels=False)
    key(c)
    size = span / 9
    _graph(c, before, edges, size, INPUT, "", numbered=True)
    said = d.message
    if want is not None:
        _graph(c, want, edges, size, REFERENCE, "", numbered=False)
        truth = f"the reference moves them to: {_listed(want)}"
    else:
        truth = "the reference gives no poses"
    if got is not None:
        odd = _graph(c, got, edges, size, YOURS, "", numbered=False)
        moved = math.dist(got[0][:2], before[0][:2]) > 1e-9 or abs(math.remainder(got[0][2] - before[0][2],
                                                                                    2 * math.pi)) > 1e-9
        said = said or (f"your poses lie {odd}" if odd else "") or ("your pose 0 moved: it is the anchor"
                                                                      if moved else "")
        yours = f"yours moves them to: {_listed(got)}"
    else:
        yours = "your function gave no poses to draw"
    below = message(c, said)
    ties = ", ".join(f"{int(i)} to {int(j)}" for i, j, *_ in edges)
    description = with_message(f"{d.label}: before the iteration, {_listed(before)}; edges {ties}; {truth}; "
                               f"{yours}.", said)
    return c.svg(f"gauss_newton_se2, {d.label}: the pose graph before and after one iteration, yours and the "
                 "reference", extra_height=below), description


RUN = RunFigure(name="pose-graph-se2", title="Your Gauss–Newton iteration, drawn", unit="", frame=frame)
