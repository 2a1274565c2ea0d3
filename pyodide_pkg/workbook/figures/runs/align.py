"""13.9 align_2d: the target set Q, and P moved by your R and t over P moved by the reference's."""

from __future__ import annotations

import math

from ...number_format import compact
from ..svg import Canvas
from . import Drawn, RunFigure
from .marks import INPUT, REFERENCE, YOURS, finite, inside, key, message, off_picture, with_message


def _moved(R, t, P):
    return [(R[0][0] * x + R[0][1] * y + t[0], R[1][0] * x + R[1][1] * y + t[1]) for x, y in P]


def _readable(got):
    """Your (R, t) as numbers, or None when it is not a 2 × 2 matrix and a pair of finite numbers."""
    try:
        R, t = got
        if len(R) != 2 or any(len(row) != 2 for row in R) or len(t) != 2:
            return None
        if not finite(*R[0], *R[1], *t):
            return None
        return R, t
    except (TypeError, ValueError):
        return None


def frame(d: Drawn) -> tuple[str, str]:
    P, Q = d.args
    R_ref, t_ref = d.want
    ref = _moved(R_ref, t_ref, P)
    mine = _readable(d.got) if d.got is not None else None
    xs = [x for x, _ in (*P, *Q, *ref)]
    ys = [y for _, y in (*P, *Q, *ref)]
    cx, cy = (min(xs) + max(xs)) / 2, (min(ys) + max(ys)) / 2
    half = max(1.0, max(xs) - min(xs), max(ys) - min(ys)) * 0.75
    c = Canvas(360, 320, (cx - half, cx + half), (cy - half, cy + half), pad=(12, 12, 12, 24))
    c.grid(10 ** math.floor(math.log10(half)), labels=False)
    key(c)
    for x, y in P:
        c.dot((x, y), 3, f"{INPUT} wb-fig-thin")
    for x, y in Q:
        c.dot((x, y), 4, f"{INPUT} wb-fig-solid")
    c.polygon(ref, f"{REFERENCE} wb-fig-thin")
    for pt in ref:
        c.dot(pt, 6, "wb-fig-c")
    said = d.message
    if mine is not None:
        got = _moved(mine[0], mine[1], P)
        if any(off_picture(c, g) for g in got):
            said = said or "some of your moved points lie beyond the picture's edge"
        shown = [inside(c, g) for g in got]
        c.polygon(shown, f"{YOURS} wb-fig-thick")
        for pt in shown:
            c.dot(pt, 3, f"{YOURS} wb-fig-solid")
        (a, b), (e, f) = mine[0]
        det = a * f - b * e
        worst = max(math.dist(g, r) for g, r in zip(got, ref))
        yours = (f"your R and t put P's points at most {compact(worst)} from where the reference's put them; "
                 f"your R has determinant {compact(det)}" + (" (a mirror)" if det < 0 else ""))
    else:
        yours = "your function gave no R and t to draw"
    below = message(c, said)
    angle = math.degrees(math.atan2(R_ref[1][0], R_ref[0][0]))
    description = with_message(
        f"{d.label}: {len(P)} points of P (hollow) to map onto Q (filled); the reference turns them by "
        f"{compact(angle)}° and shifts them by ({compact(t_ref[0])}, {compact(t_ref[1])}); {yours}.", said)
    return c.svg(f"align_2d, {d.label}: P moved by yours and by the reference, over Q", extra_height=below), description


RUN = RunFigure(name="align", title="Your alignment, drawn over the reference's", unit="m", frame=frame)
