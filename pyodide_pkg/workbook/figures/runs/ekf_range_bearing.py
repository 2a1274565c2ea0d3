"""4.10 ekf_update_rb: the robot before the update with its 1σ position ellipse, the landmark and the
sighting drawn from the robot (range along the measured bearing), then the pose and ellipse after
the update, yours beside the reference."""

from __future__ import annotations

import math

from ...number_format import compact
from ...reference.ekf import covariance_ellipse
from ..svg import Canvas
from . import Drawn, RunFigure
from .marks import INPUT, REFERENCE, YOURS, finite, inside, key, message, off_picture, with_message

AXIS = 0.7  # length of a pose's heading arrow, in metres
FAR = 50.0  # a learner's pose further out than this is not used to size the picture


def _estimate(value) -> tuple[list[float], list[list[float]]] | None:
    """(pose, covariance) when ``value`` has the shape of one, every number finite; else None."""
    try:
        pose, P = value
        pose = [float(v) for v in pose]
        P = [[float(v) for v in row] for row in P]
    except (TypeError, ValueError):
        return None
    if len(pose) != 3 or len(P) != 3 or any(len(row) != 3 for row in P):
        return None
    if not finite(*pose, *(v for row in P for v in row)):
        return None
    return pose, P


def _pose(c: Canvas, pose, P, cls: str, name: str) -> str:
    """A pose as a dot, its heading arrow and its 1σ x–y ellipse; returns what is odd about it ("" when nothing)."""
    x, y, t = pose
    at = inside(c, (x, y))
    odd = ""
    if P[0][0] >= 0 and P[1][1] >= 0 and P[0][0] * P[1][1] - P[0][1] * P[1][0] >= 0:
        a, b, angle = covariance_ellipse(P)
        c.ellipse(at, a, b, angle, f"{cls} wb-fig-thin")
    else:
        odd = "a covariance that is not positive: no ellipse to draw"
    c.arrow(at, (at[0] + AXIS * math.cos(t), at[1] + AXIS * math.sin(t)), f"{cls} wb-fig-thick")
    c.dot(at, 4, f"{cls.split()[0]} wb-fig-solid")
    c.label(at, name, f"wb-fig-label wb-fig-small {cls.split()[0]}", toward=(-math.cos(t), -math.sin(t)))
    if off_picture(c, (x, y)):
        odd = odd or "beyond the picture's edge"
    return odd


def frame(d: Drawn) -> tuple[str, str]:
    x, P, z, landmark, _R = d.args
    seen = (x[0] + z[0] * math.cos(x[2] + z[1]), x[1] + z[0] * math.sin(x[2] + z[1]))
    want = _estimate(d.want) if d.want is not None else None
    got = _estimate(d.got) if d.got is not None else None
    pts = [tuple(x[:2]), tuple(landmark), seen]
    for est in (want, got):
        if est is not None and max(map(abs, est[0][:2])) < FAR:
            pts.append(tuple(est[0][:2]))
    xs, ys = [p[0] for p in pts], [p[1] for p in pts]
    span = max(max(xs) - min(xs), max(ys) - min(ys), 1.0) * 0.6 + 1.2
    cx, cy = (max(xs) + min(xs)) / 2, (max(ys) + min(ys)) / 2
    c = Canvas(400, 360, (cx - span, cx + span), (cy - span, cy + span), pad=(12, 12, 12, 20))
    c.grid(1.0 if span < 8 else 5.0, labels=False)
    key(c)
    c.line(tuple(x[:2]), seen, "wb-fig-b wb-fig-dash")
    c.dot(tuple(landmark), 5, "wb-fig-b wb-fig-solid")
    c.label(tuple(landmark), "landmark", "wb-fig-label wb-fig-small wb-fig-b")
    _pose(c, x, P, INPUT, "before")
    said = d.message
    if want is not None:
        _pose(c, want[0], want[1], REFERENCE, "after")
        truth = (f"the reference moves it to ({compact(want[0][0])}, {compact(want[0][1])}) facing "
                 f"{compact(math.degrees(want[0][2]))}°")
    else:
        truth = "the landmark is where the robot is, and the reference returns None"
    if got is not None:
        odd = _pose(c, got[0], got[1], YOURS, "yours")
        said = said or (f"your estimate has {odd}" if odd else "")
        yours = (f"yours moves it to ({compact(got[0][0])}, {compact(got[0][1])}) facing "
                 f"{compact(math.degrees(got[0][2]))}°")
    elif d.got is None and d.want is None and not said:
        yours = "your function returns None too"
    else:
        yours = "your function gave no estimate to draw"
    below = message(c, said)
    description = with_message(
        f"{d.label}: the robot at ({compact(x[0])}, {compact(x[1])}) facing {compact(math.degrees(x[2]))}° sees the "
        f"landmark at ({compact(landmark[0])}, {compact(landmark[1])}) {compact(z[0])} m away at a bearing of "
        f"{compact(math.degrees(z[1]))}°; {truth}; {yours}.", said)
    return c.svg(f"ekf_update_rb, {d.label}: the pose before and after the update, yours and the reference",
                 extra_height=below), description


RUN = RunFigure(name="ekf-range-bearing", title="Your range–bearing update, drawn", unit="", frame=frame)
