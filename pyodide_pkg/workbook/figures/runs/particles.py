"""12.8 particle_step: the cloud before (the particles moved, each sized by the reference's weight) and
after (the resampled particles, yours over the reference's, with how many copies of each were kept)."""

from __future__ import annotations

import math
from collections import Counter

from ...number_format import compact
from ..svg import Canvas
from . import Drawn, RunFigure
from .marks import INPUT, REFERENCE, YOURS, finite, inside, key, message, off_picture, with_message


def _points(got) -> list[tuple[float, float]] | None:
    """Your resampled particles as points, or None when they are not a sequence of finite pairs."""
    try:
        out = [(float(p[0]), float(p[1])) for p in got[0]]
    except (TypeError, ValueError, IndexError, KeyError):
        return None
    return out if all(finite(*p) for p in out) else None


def _copies(points) -> Counter:
    return Counter((round(x, 9), round(y, 9)) for x, y in points)


def frame(d: Drawn) -> tuple[str, str]:
    particles, u, _z, landmarks = d.args[:4]
    moved = [(float(x) + u[0], float(y) + u[1]) for x, y in particles]
    ref_points = [(float(p[0]), float(p[1])) for p in d.want[0]]
    weights = [float(w) for w in d.want[1]]
    xs = [x for x, _ in (*moved, *landmarks)]
    ys = [y for _, y in (*moved, *landmarks)]
    cx, cy = (min(xs) + max(xs)) / 2, (min(ys) + max(ys)) / 2
    half = max(1.0, max(xs) - min(xs), max(ys) - min(ys)) * 0.7
    c = Canvas(360, 320, (cx - half, cx + half), (cy - half, cy + half), pad=(12, 12, 12, 24))
    c.grid(10 ** math.floor(math.log10(half)), labels=False)
    key(c)
    for m in landmarks:
        c.dot((float(m[0]), float(m[1])), 5, "wb-fig-b wb-fig-solid")
    for pt, w in zip(moved, weights):
        c.dot(pt, 2 + 8 * math.sqrt(max(w, 0.0)), f"{INPUT} wb-fig-thin")
    for pt, n in _copies(ref_points).items():
        c.dot(pt, 4 + 2 * n, REFERENCE)
    said = d.message
    mine = _points(d.got) if d.got is not None else None
    if mine is not None:
        if any(off_picture(c, p) for p in mine):
            said = said or "some of your particles lie beyond the picture's edge"
        for pt in mine:
            c.dot(inside(c, pt), 3, f"{YOURS} wb-fig-solid")
        same = _copies(mine) == _copies(ref_points)
        yours = (f"you kept {len(mine)} particles at {len(_copies(mine))} places"
                 + (", the same as the reference" if same else ", not the reference's"))
    else:
        yours = "your function gave no particles to draw"
    below = message(c, said)
    kept = _copies(ref_points)
    heaviest = max(weights) if weights else 0.0
    description = with_message(
        f"{d.label}: {len(moved)} particles moved by ({compact(u[0])}, {compact(u[1])}) (hollow, sized by weight; "
        f"the heaviest weighs {compact(heaviest)}), {len(landmarks)} landmarks (filled); the reference keeps "
        f"{len(ref_points)} particles at {len(kept)} places (dashed rings, larger for more copies); {yours}.", said)
    return c.svg(f"particle_step, {d.label}: the cloud before and after resampling",
                 extra_height=below), description


RUN = RunFigure(name="particles", title="Your resampled cloud, drawn over the reference's", unit="m", frame=frame)
