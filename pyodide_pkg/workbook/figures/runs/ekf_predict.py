"""3.10 ekf_predict: your prediction fed its own output for a short drive along an arc, without any
measurement: the estimated path and its 1σ ellipses growing, yours over the reference's."""

from __future__ import annotations

import math

from ...number_format import compact
from ...reference.ekf import covariance_ellipse
from ..svg import Canvas
from . import Drawn, RunFigure, Trace
from .marks import REFERENCE, YOURS, key, message, with_message

P0 = ((0.01, 0.0, 0.0), (0.0, 0.01, 0.0), (0.0, 0.0, 0.001))
Q = ((0.004, 0.0, 0.0), (0.0, 0.004, 0.0), (0.0, 0.0, 0.002))
DT = 0.5
RUNS = (((0.0, 0.0, 0.0), tuple((1.0, 0.35) for _ in range(14))),
        ((0.0, 0.0, math.pi / 2), tuple((0.8, -0.5 if k < 7 else 0.5) for k in range(14))))
EVERY = 3  # an ellipse every few steps


def _ellipses(c: Canvas, rows, cls: str) -> None:
    for k, row in enumerate(rows):
        if k % EVERY and k != len(rows) - 1:
            continue
        x, y, _, pxx, pxy, pyy = row
        try:
            a, b, angle = covariance_ellipse([[pxx, pxy, 0.0], [pxy, pyy, 0.0], [0.0, 0.0, 0.0]])
        except (ValueError, ZeroDivisionError, OverflowError):  # not a covariance: no ellipse to draw
            continue
        if all(math.isfinite(v) for v in (a, b, angle)) and a < 50:
            c.ellipse((x, y), a, b, angle, cls)


def frame(d: Drawn) -> tuple[str, str]:
    start, controls = d.args[0], d.args[2]
    want, got = d.want, list(d.got or [])
    pts = [(r[0], r[1]) for r in want] + [(r[0], r[1]) for r in got if abs(r[0]) < 100 and abs(r[1]) < 100]
    xs, ys = [p[0] for p in pts], [p[1] for p in pts]
    span = max(max(xs) - min(xs), max(ys) - min(ys), 1.0) * 0.6 + 0.5
    cx, cy = (max(xs) + min(xs)) / 2, (max(ys) + min(ys)) / 2
    c = Canvas(400, 340, (cx - span, cx + span), (cy - span, cy + span), pad=(12, 12, 12, 20))
    c.grid(1.0, labels=False)
    key(c)
    _ellipses(c, want, "wb-fig-c wb-fig-dash wb-fig-thin")
    c.polyline([(r[0], r[1]) for r in want], f"{REFERENCE} wb-fig-thick")
    if len(got) > 1:
        _ellipses(c, got, "wb-fig-a wb-fig-area wb-fig-thin")
        c.polyline([(r[0], r[1]) for r in got], f"{YOURS} wb-fig-thick")
    if got and (d.message or len(got) < len(want)):
        c.dot((got[-1][0], got[-1][1]), 5, "wb-fig-bad wb-fig-solid")
    c.dot((start[0], start[1]), 5, "wb-fig-muted wb-fig-solid")
    c.label((start[0], start[1]), "start", "wb-fig-label wb-fig-small wb-fig-muted", toward=(-1, -1))
    below = message(c, d.message)
    end = want[-1]
    if len(got) > 1:
        last = got[-1]
        yours = (f"yours ends at ({compact(last[0])}, {compact(last[1])}) with variances {compact(last[3])} and "
                 f"{compact(last[5])} after {len(got) - 1} steps")
    else:
        yours = "your function gave no path to draw"
    description = with_message(
        f"{d.label}: {len(controls)} predictions of {compact(DT)} s from ({compact(start[0])}, {compact(start[1])}) "
        f"with no measurement; the reference ends at ({compact(end[0])}, {compact(end[1])}) with x and y variances "
        f"{compact(end[3])} and {compact(end[5])}; {yours}.", d.message)
    return c.svg(f"ekf_predict, {d.label}: the predicted path and its ellipses", extra_height=below), description


RUN = RunFigure(name="ekf-predict", title="Your EKF prediction over a short drive", unit="", frame=frame, width=6,
                trace=Trace("ekf_track", tuple((start, P0, controls, DT, Q) for start, controls in RUNS)))
