"""9.9 nav_step: the path your navigation loop drives (the estimate after every step of the closed
loop, ``workbook_sandbox.harness.nav_loop``) over the reference's, with the waypoints and the landmark."""

from __future__ import annotations

from ...number_format import compact
from ..svg import Canvas
from . import Drawn, RunFigure
from .marks import REFERENCE, YOURS, inside, key, message, with_message


def frame(d: Drawn) -> tuple[str, str]:
    start, _, landmark, waypoints, dt, _, _, steps, _ = d.args
    want, got = list(d.want or []), list(d.got or [])
    pts = [tuple(start[:2]), tuple(landmark)] + [tuple(w) for w in waypoints] + [(r[0], r[1]) for r in want]
    xs, ys = [p[0] for p in pts], [p[1] for p in pts]
    span = max(max(xs) - min(xs), max(ys) - min(ys), 1.0) * 0.6 + 0.5
    cx, cy = (max(xs) + min(xs)) / 2, (max(ys) + min(ys)) / 2
    c = Canvas(400, 360, (cx - span, cx + span), (cy - span, cy + span), pad=(12, 12, 12, 20))
    c.grid(1.0, labels=False)
    key(c)
    for k, w in enumerate(waypoints):
        c.dot(tuple(w), 7, "wb-fig-b")
        c.label(tuple(w), f"waypoint {k + 1}", "wb-fig-label wb-fig-small wb-fig-b", toward=(1, 1))
    lx, ly = landmark
    c.polygon([(lx, ly + 0.18), (lx + 0.13, ly), (lx, ly - 0.18), (lx - 0.13, ly)], "wb-fig-c wb-fig-solid")
    c.label(tuple(landmark), "landmark", "wb-fig-label wb-fig-small wb-fig-c", toward=(1, -1))
    c.polyline([tuple(start[:2])] + [(r[0], r[1]) for r in want], f"{REFERENCE} wb-fig-thick")
    if got:
        path = [inside(c, (r[0], r[1])) for r in got]
        c.polyline([tuple(start[:2])] + path, f"{YOURS} wb-fig-thick")
        if d.message or len(got) < len(want):
            c.dot(path[-1], 5, "wb-fig-bad wb-fig-solid")
    c.dot(tuple(start[:2]), 5, "wb-fig-muted wb-fig-solid")
    c.label(tuple(start[:2]), "start", "wb-fig-label wb-fig-small wb-fig-muted", toward=(-1, -1))
    below = message(c, d.message)
    end = want[-1] if want else start
    yours = (f"yours ends at ({compact(got[-1][0])}, {compact(got[-1][1])}) after {len(got)} steps" if got
             else "your loop gave no path to draw")
    description = with_message(
        f"{d.label}: {steps} steps of {compact(dt)} s from ({compact(start[0])}, {compact(start[1])}) through "
        f"{len(waypoints)} waypoints, a landmark at ({compact(lx)}, {compact(ly)}); the reference's estimate ends at "
        f"({compact(end[0])}, {compact(end[1])}); {yours}.", d.message)
    return c.svg(f"nav_step, {d.label}: the path driven, yours over the reference's", extra_height=below), description


RUN = RunFigure(name="capstone", title="The path your navigation loop drives", unit="", frame=frame, width=3,
                with_start=False)
