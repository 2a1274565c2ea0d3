"""8.4 pid_step: your controller closes the loop around chapter 8's plant (a mass on a spring and
damper) for a step to 1; its response is drawn over the reference controller's, run the same way
(``workbook_sandbox.harness.pid_loop``)."""

from __future__ import annotations

from ...number_format import compact
from ..svg import Canvas
from . import Drawn, RunFigure, Trace
from .marks import REFERENCE, YOURS, key, message, with_message

DT, STEPS = 0.1, 60
GAINS = ((10, 5, 2), (4, 2, 0.5))
Y_RANGE = (-0.5, 2.0)


def _curve(ys: list[float]) -> list[tuple[float, float]]:
    low, high = Y_RANGE
    return [(k * DT, min(high, max(low, y))) for k, y in enumerate(ys)]


def frame(d: Drawn) -> tuple[str, str]:
    Kp, Ki, Kd, dt, steps, *limits = d.args
    duration = dt * steps
    c = Canvas(440, 280, (0.0, duration), Y_RANGE, pad=(42, 14, 12, 30), aspect=False)
    for y in (0.0, 0.5, 1.0, 1.5, 2.0):
        c.line((0, y), (duration, y), "wb-fig-grid")
        c.text((0, y), f"{y:g}", "wb-fig-label wb-fig-small wb-fig-muted", dx=-6, dy=4, anchor="end")
    for t in range(int(duration) + 1):
        c.text((t, Y_RANGE[0]), f"{t} s", "wb-fig-label wb-fig-small wb-fig-muted", dy=16)
    c.line((0, 1), (duration, 1), "wb-fig-b wb-fig-dash wb-fig-thin")
    c.text((duration, 1), "target", "wb-fig-label wb-fig-small wb-fig-b", dx=-4, dy=-6, anchor="end")
    key(c)
    c.polyline(_curve(d.want), f"{REFERENCE} wb-fig-thick")
    got = list(d.got or [])
    if len(got) > 1:
        c.polyline(_curve(got), f"{YOURS} wb-fig-thick")
    if got and (d.message or len(got) < len(d.want)):
        c.dot(_curve(got)[-1], 5, "wb-fig-bad wb-fig-solid")
    below = message(c, d.message)
    gains = f"Kp = {compact(Kp)}, Ki = {compact(Ki)}, Kd = {compact(Kd)}" + (
        f", output held in [{compact(limits[0])}, {compact(limits[1])}]" if limits else "")
    ref_end = compact(d.want[-1])
    if got:
        yours = (f"with your pid_step the output is {compact(got[-1])} after {compact((len(got) - 1) * dt)} s")
    else:
        yours = "your pid_step gave no output to draw"
    description = (f"{d.label}: a step to 1 under {gains}, every {compact(dt)} s for {compact(duration)} s; "
                   f"with the reference the output ends at {ref_end}; {yours}.")
    description = with_message(description, d.message)
    return c.svg(f"pid_step, {d.label} ({gains}): step response, yours over the "
                 "reference's", extra_height=below), description


RUN = RunFigure(name="pid", title="Your PID controller in a closed loop", unit="", frame=frame,
                trace=Trace("pid_loop", tuple((*g, DT, STEPS) for g in GAINS)))
