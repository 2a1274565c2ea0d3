"""Chapter 8's bug hunt: integral windup."""

from __future__ import annotations

from ..figures.symptoms import windup_facts
from ..kinds.debug import Debug
from ..number_format import fixed, fmt
from ..reference.pid import pid_step_saturated

_PID = """\
def pid_step_limited(e, e_prev, integral, Kp, Ki, Kd, dt, u_max):
    derivative = (e - e_prev) / dt
    candidate = integral + e * dt
    u = Kp * e + Ki * candidate + Kd * derivative
    winding = (u > u_max and e > 0) or (u < -u_max and e < 0)
    integral = candidate
    u = Kp * e + Ki * integral + Kd * derivative
    return (max(-u_max, min(u_max, u)), integral)
"""


def _bug() -> str:
    f = windup_facts()
    o = f["overshoot"]
    return (f"The integral keeps growing while the actuator is already at its limit and the error pushes it "
            "further (winding is computed and never used). The motor cannot push harder, so the extra integral does "
            "nothing until the error "
            f"changes sign, and then it has to be unwound by pushing past the target. With Kp, Ki, Kd = "
            f"{', '.join(fmt(g) for g in f['gains'])} and the push limited to {fmt(f['u_max'])}, the step response "
            f"overshoots by {fixed(o['bug'], 1)} % instead of {fixed(o['fixed'], 1)} %. "
            f"Fix: integral = integral if winding else candidate, the conditional integration of exercise 8.8.")


def _reference(e, e_prev, integral, Kp, Ki, Kd, dt, u_max):
    return pid_step_saturated(e, e_prev, integral, Kp, Ki, Kd, dt, u_max)


EXERCISES = (
    Debug(
        id="8.9",
        title="Find the windup",
        code=_PID,
        bug_line=6,
        fixed_line="    integral = integral if winding else candidate",
        bug=_bug(),
        notes={
            1: "takes the error, the last error, the integral so far, the gains, the step and the actuator's limit",
            2: "correct: the derivative of the error",
            3: "correct: what the integral would be after this step",
            4: "correct: the PID law with that integral",
            5: "correct: whether integrating would wind the output further past a limit (exercise 8.8's rule)",
            7: "correct: the PID law with the integral kept",
            8: "returns the command, clipped to ±u_max, and the integral to carry to the next step",
        },
        function="pid_step_limited",
        reference=_reference,
        cases=((1.0, 1.0, 0.0, 6.0, 4.0, 1.0, 0.01, 2.5), (0.8, 0.82, 0.5, 6.0, 4.0, 1.0, 0.01, 2.5),
               (0.1, 0.12, 0.4, 2.0, 1.0, 0.5, 0.1, 5.0), (-2.0, -1.9, -0.3, 3.0, 2.0, 0.2, 0.05, 1.0),
               # saturated high while the error pulls back: integrate; then winding, the output from the kept integral
               (-0.5, -0.5, 2.0, 1.0, 4.0, 0.0, 0.01, 2.5), (1.0, 1.0, 0.0, 2.0, 10.0, 0.0, 0.1, 2.5)),
        symptom="windup",
    ),
)
