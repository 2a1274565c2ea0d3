"""Chapter 8: the step response of a mass on a spring and damper under PID
control, with overshoot, settling time and steady-state error."""

from __future__ import annotations

from functools import lru_cache

from ..number_format import readout
from ..reference.pid import simulate_step_response, step_metrics
from . import Control, Figure, Readout
from .svg import Canvas

DURATION = 10.0
Y_RANGE = (-0.25, 2.0)


@lru_cache(maxsize=64)
def response(Kp: float, Ki: float, Kd: float):
    """Times, outputs and metrics for the gains (cached: the sliders revisit values).

    >>> ts, ys, m = response(9.0, 0.0, 0.0)
    >>> round(m.steady_state_error, 3)
    0.1
    """
    ts, ys = simulate_step_response(Kp, Ki, Kd, duration=DURATION)
    return ts, ys, step_metrics(ts, ys)


def clipped(ts, ys, low: float, high: float, every: int = 2) -> list[tuple[float, float]]:
    """Every ``every``-th sample, its output clamped into the plot's range.

    >>> clipped([0, 1, 2], [0, 5, -5], -1, 1, every=1)
    [(0, 0), (1, 1), (2, -1)]
    """
    return [(t, min(high, max(low, y))) for t, y in list(zip(ts, ys))[::every]]


def draw(p: dict[str, float]) -> dict:
    ts, ys, m = response(p["Kp"], p["Ki"], p["Kd"])
    c = Canvas(440, 300, (0.0, DURATION), Y_RANGE, pad=(42, 14, 12, 32), aspect=False)
    for y in (0.0, 0.5, 1.0, 1.5, 2.0):
        c.line((0, y), (DURATION, y), "wb-fig-grid")
        c.text((0, y), f"{y:g}", "wb-fig-label wb-fig-small wb-fig-muted", dx=-6, dy=4, anchor="end")
    for t in range(0, int(DURATION) + 1, 2):
        c.line((t, Y_RANGE[0]), (t, Y_RANGE[1]), "wb-fig-grid")
        c.text((t, Y_RANGE[0]), f"{t} s", "wb-fig-label wb-fig-small wb-fig-muted", dy=18)
    c.line((0, 0), (DURATION, 0), "wb-fig-axis")
    final = ys[-1]
    if m.settling_time is not None:
        band = 0.02 * abs(final)
        c.polygon([(0, final - band), (DURATION, final - band), (DURATION, final + band), (0, final + band)],
                  "wb-fig-c wb-fig-area wb-fig-thin")
        c.line((m.settling_time, Y_RANGE[0]), (m.settling_time, Y_RANGE[1]), "wb-fig-c wb-fig-thin wb-fig-dash")
    c.line((0, 1), (DURATION, 1), "wb-fig-b wb-fig-dash")
    c.text((DURATION, 1), "target", "wb-fig-label wb-fig-small wb-fig-b", dx=-4, dy=-6, anchor="end")
    c.polyline(clipped(ts, ys, *Y_RANGE), "wb-fig-a wb-fig-thick")
    settled = m.settling_time is not None
    svg = c.svg(f"Step response with Kp = {p['Kp']:g}, Ki = {p['Ki']:g}, Kd = {p['Kd']:g}: overshoot "
                f"{readout(100 * m.overshoot, 0)}%, "
                "" + (f"settles in {readout(m.settling_time, 2)} s" if settled else "does not settle"))
    return {"svg": svg, "flags": [] if settled else ["unsettled"], "readouts": {
        "overshoot": f"{readout(100 * m.overshoot, 1)} %",
        "settling": f"{readout(m.settling_time, 2)} s" if settled else f"not settled within {DURATION:g} s",
        "error": readout(m.steady_state_error, 3),
    }}


FIGURE = Figure(
    name="pid-response",
    title="Tuning a PID controller",
    caption="The plant is a mass on a spring and damper (ÿ + 2ẏ + y = u), asked to move from 0 to 1 "
            "(controller sampled every 0.01 s). P alone leaves an offset and overshoots as Kp grows; "
            "Ki removes the offset; Kd damps the swing. The band is ±2 % of the final value.",
    controls=(
        Control("Kp", "Kp", 0, 30, 0.5, 8),
        Control("Ki", "Ki", 0, 20, 0.5, 0),
        Control("Kd", "Kd", 0, 5, 0.1, 0),
    ),
    readouts=(
        Readout("overshoot", "overshoot past the target"),
        Readout("settling", "settling time (±2 %)"),
        Readout("error", "steady-state error"),
    ),
    draw=draw,
)
