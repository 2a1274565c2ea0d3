"""Chapter 8 · Code the robot: PID with a clamped output and anti-windup."""

from ..kinds.build import Build
from ..reference.pid import pid_step_clamped

_SOLUTION = '''def pid_step_clamped(e, e_prev, integral, Kp, Ki, Kd, dt, u_min, u_max):
    """One PID step, output held in [u_min, u_max], with anti-windup; return (u, new_integral)."""
    d = Kd * (e - e_prev) / dt if dt > 0 else 0.0  # dt = 0: no time passed
    new_integral = integral + e * dt
    u = Kp * e + Ki * new_integral + d
    if (u > u_max and e > 0) or (u < u_min and e < 0):
        new_integral = integral  # integrating would only wind further past the limit
        u = Kp * e + Ki * integral + d
    return (min(u_max, max(u_min, u)), new_integral)
'''

EXERCISES = (
    Build(
        id="8.8",
        title="Code the robot: pid_step_clamped",
        function="pid_step_clamped",
        params=("e", "e_prev", "integral", "Kp", "Ki", "Kd", "dt", "u_min", "u_max"),
        starter=(
            "def pid_step_clamped(e, e_prev, integral, Kp, Ki, Kd, dt, u_min, u_max):\n"
            '    """One PID step, output held in [u_min, u_max], with anti-windup; return (u, new_integral)."""\n'
            "    # Your code here: the three terms, the anti-windup rule, then the clamp.\n"
            "    return (Kp * e, integral)\n"
        ),
        solution=_SOLUTION,
        reference=pid_step_clamped,
        run_figure="pid-clamp",
        examples=(
            (3, 3, 0, 2, 0, 0, 1, -10, 10),
            (1, 3, 8, 1, 0.1, 0.5, 1, -10, 10),
            (1, 3, 8, 1, 0.1, 0.5, 1, -0.5, 0.5),
            (5, 0, 0, 1, 0.1, 0.5, 1, -2, 2),
        ),
        edge_cases=(
            (2, 1, 0.5, 1, 1, 1, 0, -10, 10),  # dt = 0: no integration, no derivative
            (-4, -1, -3, 2, 1, 0.5, 0.1, -5, 5),  # saturated low with the error pushing lower
            (-1, -1, 20, 1, 1, 0, 0.5, -5, 5),  # saturated high, but the error pulls back: integrate
            (0, 0, 2, 1, 1, 1, 0.2, -1, 1),  # no error, the old integral alone saturates
            (1, 1, 4, 0, 1, 0, 2, -5, 5),  # the old integral inside the limits, the new one past u_max: hold it
            (-1, -1, -4, 0, 1, 0, 2, -5, 5),  # and past u_min
            (1, 1, 0, 1, 1, 0, 0.5, -1.5, 1.5),  # u exactly at u_max is not above it: integrate (exact in binary)
        ),
        random_args=lambda rng: (rng.uniform(-10, 10), rng.uniform(-10, 10), rng.uniform(-20, 20),
                                 rng.uniform(0, 5), rng.uniform(0, 2), rng.uniform(0, 2), rng.uniform(0.01, 1),
                                 -rng.uniform(0.5, 10), rng.uniform(0.5, 10)),
    ),
)
