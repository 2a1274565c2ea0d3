"""Drivers: how a Build exercise's function is exercised on one case.

A driver takes the function under test and one case's arguments (as decoded from
JSON: numbers, lists, dicts) and returns what the grader compares. The grader
runs its reference implementation through the same driver, natively, so a
learner's output and the expected one always come from the same procedure.
A Build exercise names its driver in ``Build.harness``.

>>> call(lambda x, y: (y, x), 1, 2)
(2, 1)
>>> driver("call") is call
True
>>> sorted(DRIVERS)
['call', 'nav_loop']
>>> driver("nope")
Traceback (most recent call last):
...
KeyError: "no harness driver 'nope'"
"""

from __future__ import annotations

import math
import random
from typing import Any, Callable

# The world of the closed loop (exercise 9.9): how far the true robot's turn rate drifts from the
# command, the sensor's reach and noise (standard deviations), and when a waypoint counts as reached.
TURN_BIAS, SENSOR_RANGE, RANGE_NOISE, BEARING_NOISE, REACHED = 0.06, 2.5, 0.05, 0.02, 0.3


def call(fn: Callable[..., Any], *args: Any) -> Any:
    """One call: the function's own return value."""
    return fn(*args)


def _step_out(out: Any, k: int) -> tuple[list[float], list[list[float]], list[float]]:
    """What a navigation step returned, as plain floats: (pose, 3×3 covariance, command); a clear error else."""
    try:
        x, P, u = out
        x, P, u = [float(a) for a in x], [[float(a) for a in row] for row in P], [float(a) for a in u]
        if len(x) != 3 or len(P) != 3 or any(len(row) != 3 for row in P) or len(u) != 2:
            raise ValueError
    except (TypeError, ValueError):
        raise TypeError(f"step {k + 1} returned {str(out)[:80]}; expected (x, P, u): a pose of 3 numbers, "
                        "a 3×3 covariance and a command (v, omega)") from None
    return x, P, u


def nav_loop(fn: Callable[..., Any], start: list, P: list, landmark: list, waypoints: list, dt: float,
             Q: list, R: list, steps: int, seed: int) -> list[list[float]]:
    """A closed-loop run: ``fn(x, P, u, z, landmark, waypoint, dt, Q, R)`` returns ``(x, P, u)`` each step.

    A true robot (unseen by ``fn``) drives with the last command, its turn rate off by TURN_BIAS; ``z`` is
    its noisy (range, bearing) to the landmark, or None beyond SENSOR_RANGE; the waypoint moves on to the
    next one once the estimate is within REACHED of it. Returns the estimated pose after every step.

    >>> stay = lambda x, P, u, z, lm, wp, dt, Q, R: (x, P, (0.0, 0.0))
    >>> nav_loop(stay, [0, 0, 0], [[0] * 3] * 3, [1, 0], [[2, 0]], 0.5, [[0] * 3] * 3, [[0] * 2] * 2, 2, 1)
    [[0.0, 0.0, 0.0], [0.0, 0.0, 0.0]]
    """
    rng = random.Random(seed)
    true = [float(a) for a in start]
    x, u, goal, path = list(true), [0.0, 0.0], 0, []
    for k in range(int(steps)):
        v, omega = u
        turn = omega + TURN_BIAS if v else omega
        true = [true[0] + v * math.cos(true[2]) * dt, true[1] + v * math.sin(true[2]) * dt, true[2] + turn * dt]
        dx, dy = landmark[0] - true[0], landmark[1] - true[1]
        noise = (rng.gauss(0, RANGE_NOISE), rng.gauss(0, BEARING_NOISE))
        z = None
        if math.hypot(dx, dy) <= SENSOR_RANGE:
            bearing = math.atan2(dy, dx) - true[2] + noise[1]
            z = [math.hypot(dx, dy) + noise[0], math.atan2(math.sin(bearing), math.cos(bearing))]
        waypoint = list(waypoints[min(goal, len(waypoints) - 1)])
        x, P, u = _step_out(fn(x, P, u, z, list(landmark), waypoint, dt, Q, R), k)
        if goal < len(waypoints) - 1 and math.hypot(waypoint[0] - x[0], waypoint[1] - x[1]) < REACHED:
            goal += 1
        path.append(x)
    return path


DRIVERS: dict[str, Callable[..., Any]] = {"call": call, "nav_loop": nav_loop}


def driver(name: str) -> Callable[..., Any]:
    """The driver called ``name`` (KeyError when there is none)."""
    try:
        return DRIVERS[name]
    except (KeyError, TypeError):
        raise KeyError(f"no harness driver {name!r}") from None
