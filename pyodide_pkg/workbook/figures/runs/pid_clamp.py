"""8.8 pid_step_clamped: your clamped controller with anti-windup closes the loop around chapter 8's
plant, over the reference's; the output limit is tight enough that a wound-up integral overshoots."""

from __future__ import annotations

from . import RunFigure, Trace
from .pid import DT, STEPS, frame

RUNS = ((10, 8, 1, -2.0, 2.0), (6, 6, 0.5, -1.5, 1.5))

RUN = RunFigure(name="pid-clamp", title="Your clamped PID controller in a closed loop", unit="", frame=frame,
                trace=Trace("pid_loop", tuple((Kp, Ki, Kd, DT, STEPS, lo, hi) for Kp, Ki, Kd, lo, hi in RUNS)))
