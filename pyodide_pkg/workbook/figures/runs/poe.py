"""11.8 fk_poe: the arm in 3-D (chapter 10's orthographic view), its joints where the joints before
them carried them and the tool frame the reference's T gives (dashed), with the tool frame your T
gives and the last link drawn to it (solid) over it."""

from __future__ import annotations

import math

from ...number_format import compact
from ...reference.screw import cross, fk_poe
from ..poses_3d import COLOURS, view
from ..svg import Canvas
from . import Drawn, RunFigure
from .marks import REFERENCE, YOURS, finite, inside, key, message, off_picture, with_message

AZIMUTH = -55  # the view: from the front right, a little above


def joints(M, S_list, theta) -> list[list[float]]:
    """The base, then a point of each revolute joint's axis (ω × v, the one nearest the origin at home)
    carried by the joints before it; a prismatic joint adds none.

    >>> joints([[1, 0, 0, 1], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]], [(0, 0, 1, 0, -1, 0)], [1.0])
    [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0]]
    """
    out: list[list[float]] = [[0.0, 0.0, 0.0]]
    before: list[tuple] = []
    for S, th in zip(S_list, theta):
        w = [float(c) for c in S[:3]]
        if any(w):
            q = cross(w, S[3:])
            carried = fk_poe([[1.0, 0.0, 0.0, q[0]], [0.0, 1.0, 0.0, q[1]], [0.0, 0.0, 1.0, q[2]], [0, 0, 0, 1]],
                             [b[0] for b in before], [b[1] for b in before])
            out.append([row[3] + 0.0 for row in carried[:3]])
        before.append((S, th))
    return out


def _readable(got):
    """Your T as 4 rows of 4 finite numbers, or None."""
    try:
        T = [[float(v) for v in row] for row in got]
        if len(T) != 4 or any(len(row) != 4 for row in T) or not finite(*(v for row in T for v in row)):
            return None
        return T
    except (TypeError, ValueError):
        return None


def _tool(c: Canvas, at, T, cls: str, length: float) -> None:
    o = [T[i][3] for i in range(3)]
    for k in range(3):
        tip = [o[i] + length * T[i][k] for i in range(3)]
        c.arrow(inside(c, at(o)), inside(c, at(tip)), f"{COLOURS[k]} {cls}")


def frame(d: Drawn) -> tuple[str, str]:
    M, S_list, theta = d.args
    want = d.want
    right, up = view(AZIMUTH)

    def at(point) -> tuple[float, float]:
        return (sum(a * b for a, b in zip(point, right)), sum(a * b for a, b in zip(point, up)))

    chain = joints(M, S_list, theta)
    ref_tool = [want[i][3] for i in range(3)]
    mine = _readable(d.got) if d.got is not None else None
    seen = [at(q) for q in (*chain, ref_tool)]
    xs, ys = [x for x, _ in seen], [y for _, y in seen]
    cx, cy = (min(xs) + max(xs)) / 2, (min(ys) + max(ys)) / 2
    half = max(0.5, max(xs) - min(xs), max(ys) - min(ys)) * 0.75
    c = Canvas(360, 320, (cx - half, cx + half), (cy - half, cy + half), pad=(12, 12, 12, 24))
    key(c)
    length = half * 0.25
    c.polyline([at(q) for q in (*chain, ref_tool)], f"{REFERENCE} wb-fig-thin")
    for q in chain:
        c.dot(at(q), 3, "wb-fig-muted wb-fig-solid")
    _tool(c, at, want, "wb-fig-thin wb-fig-dash", length)
    said = d.message
    if mine is not None:
        tool = [mine[i][3] for i in range(3)]
        if off_picture(c, at(tool)):
            said = said or "your tool frame lies beyond the picture's edge"
        c.line(inside(c, at(chain[-1])), inside(c, at(tool)), f"{YOURS} wb-fig-thick")
        _tool(c, at, mine, "wb-fig-thick", length)
        gap = math.dist(tool, ref_tool)
        turn = max(abs(mine[i][k] - want[i][k]) for i in range(3) for k in range(3))
        yours = (f"your tool frame is {compact(gap)} m from the reference's, and its axes differ by up to "
                 f"{compact(turn)} in any entry")
    else:
        yours = "your function gave no 4 × 4 transform to draw"
    below = message(c, said)
    description = with_message(
        f"{d.label}: an arm of {len(S_list)} joints; the reference puts the tool at "
        f"({', '.join(compact(v) for v in ref_tool)}); {yours}.", said)
    return c.svg(f"fk_poe, {d.label}: your tool frame over the reference's", extra_height=below), description


RUN = RunFigure(name="poe", title="Your arm's tool frame, drawn over the reference's", unit="", frame=frame)
