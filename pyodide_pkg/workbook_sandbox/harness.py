"""Drivers: how a Build exercise's function is exercised on one case.

A driver takes the function under test and one case's arguments (as decoded from
JSON: numbers, lists, dicts) and returns what the grader compares. The grader
runs its reference implementation through the same driver, natively, so a
learner's output and the expected one always come from the same procedure.
A Build exercise names its driver in ``Build.harness`` (``nav_loop``: exercise 9.9
closed loop); a run figure may name another closed-loop one (``pid_loop``,
``ekf_track``) that calls the function step by step and returns the whole trajectory.

>>> call(lambda x, y: (y, x), 1, 2)
(2, 1)
>>> driver("call") is call
True
>>> sorted(DRIVERS)
['call', 'ekf_track', 'nav_loop', 'pid_loop']
>>> driver("nope")
Traceback (most recent call last):
...
KeyError: "no harness driver 'nope'"

When the function fails part-way through a trajectory, the driver raises
:class:`Partial` with what it had so far; its ``__cause__`` is the function's
own error (the runner reports both):

>>> def bad(e, e_prev, integral, Kp, Ki, Kd, dt):
...     return (Kp * e, integral) if e > 0.5 else 1 / 0
>>> try:
...     pid_loop(bad, 8, 0, 0, 0.1, 20)
... except Partial as stop:
...     print(len(stop.so_far), type(stop.__cause__).__name__)
5 ZeroDivisionError
"""

from __future__ import annotations

import math
import random
from collections.abc import Callable
from typing import Any

# The plant of the PID loop: a mass on a spring and damper, m·ÿ + c·ẏ + k·y = u
# (the plant of chapter 8's figure), started at rest, asked to reach TARGET.
MASS, DAMPING, STIFFNESS, TARGET = 1.0, 2.0, 1.0, 1.0
RUNAWAY = 1000.0
# The world of the closed loop (exercise 9.9): how far the true robot's turn rate drifts from the
# command, the sensor's reach and noise (standard deviations), and when a waypoint counts as reached.
TURN_BIAS, SENSOR_RANGE, RANGE_NOISE, BEARING_NOISE, REACHED = 0.06, 2.5, 0.05, 0.02, 0.3


class Partial(Exception):
    """The function failed during a closed-loop run: ``so_far`` is the trajectory until then."""

    def __init__(self, so_far: Any) -> None:
        super().__init__("the run stopped part-way")
        self.so_far = so_far


def call(fn: Callable[..., Any], *args: Any) -> Any:
    """One call: the function's own return value."""
    return fn(*args)


def _step(so_far: Any, read: Callable[[Any, str], Any], what: str, fn: Callable[..., Any], *args: Any) -> Any:
    """One step of a closed loop: ``fn(*args)`` read by ``read``; Partial(so_far) from any failure of
    the function (an interrupt or running out of memory goes through: the run stops there)."""
    try:
        return read(fn(*args), what)
    except (KeyboardInterrupt, MemoryError):
        raise
    except BaseException as err:
        raise Partial(so_far) from err


def _pair(got: Any, what: str) -> tuple[float, float]:
    """Two numbers from what a step returned, or TypeError saying what came back."""
    try:
        a, b = got
        return float(a), float(b)
    except (TypeError, ValueError) as err:
        shown = type(got).__name__
        raise TypeError(f"{what}: expected a pair of numbers, got {shown} ({err})") from None


def pid_loop(fn: Callable[..., Any], Kp: float, Ki: float, Kd: float, dt: float, steps: int,
             *limits: float) -> list[float]:
    """Closed loop: ``fn`` (a ``pid_step``) drives the plant for ``steps`` samples of ``dt`` seconds.
    With ``limits`` (u_min, u_max), ``fn`` is a clamped controller and is passed them too.

    Each sample reads e = TARGET − y, asks ``fn`` for (u, integral), then moves the
    plant (semi-implicit Euler). Returns the outputs y, starting with y = 0; it stops
    early when the output runs away (|y| > 1000) or stops being a number.

    >>> ys = pid_loop(lambda e, ep, i, Kp, Ki, Kd, dt: (Kp * e, i), 9, 0, 0, 0.1, 60)
    >>> len(ys), round(ys[-1], 2)
    (61, 0.9)
    """
    y = velocity = integral = 0.0
    e_prev = TARGET - y
    ys = [y]
    for k in range(int(steps)):
        e = TARGET - y
        u, integral = _step(ys, _pair, f"step {k + 1}", fn, e, e_prev, integral, Kp, Ki, Kd, dt, *limits)
        e_prev = e
        velocity += (u - DAMPING * velocity - STIFFNESS * y) / MASS * dt
        y += velocity * dt
        ys.append(y)
        if not math.isfinite(y) or abs(y) > RUNAWAY:
            break
    return ys


def _state(got: Any, what: str) -> tuple[list[float], list[list[float]]]:
    """A pose (x, y, θ) and its 3×3 covariance from what a step returned, or TypeError saying what came back."""
    try:
        x, P = got
        x, P = [float(a) for a in x], [[float(a) for a in row] for row in P]
        if len(x) != 3 or len(P) != 3 or any(len(row) != 3 for row in P):
            raise ValueError("wrong sizes")
    except (TypeError, ValueError) as err:
        raise TypeError(f"{what}: expected (x, P), a pose of 3 numbers and a 3×3 covariance, got "
                        f"{type(got).__name__} ({err})") from None
    return x, P


def ekf_track(fn: Callable[..., Any], x: list, P: list, controls: list, dt: float, Q: list) -> list[list[float]]:
    """Closed loop: ``fn`` (an ``ekf_predict(x, P, v, omega, dt, Q)``) is fed its own output, once per
    command (v, ω) in ``controls``. Returns, from the start, each step's x, y, θ and the x–y block of P
    (pxx, pxy, pyy): one row of six numbers per step.

    >>> still = lambda x, P, v, omega, dt, Q: (x, P)
    >>> ekf_track(still, [1, 2, 0], [[1, 0, 0], [0, 2, 0], [0, 0, 3]], [(0, 0)], 1, None)
    [[1.0, 2.0, 0.0, 1.0, 0.0, 2.0], [1.0, 2.0, 0.0, 1.0, 0.0, 2.0]]
    """
    def row(x: list[float], P: list[list[float]]) -> list[float]:
        return [*x, P[0][0], P[0][1], P[1][1]]

    x, P = _state((x, P), "the start")
    rows = [row(x, P)]
    for k, (v, omega) in enumerate(controls):
        x, P = _step(rows, _state, f"step {k + 1}", fn, list(x), [list(r) for r in P], v, omega, dt, Q)
        rows.append(row(x, P))
        if not all(math.isfinite(a) for a in rows[-1]):
            break
    return rows


def _step_out(out: Any, what: str) -> tuple[list[float], list[list[float]], list[float]]:
    """What a navigation step returned, as plain floats: (pose, 3×3 covariance, command); a clear error else."""
    try:
        x, P, u = out
        x, P, u = [float(a) for a in x], [[float(a) for a in row] for row in P], [float(a) for a in u]
        if len(x) != 3 or len(P) != 3 or any(len(row) != 3 for row in P) or len(u) != 2:
            raise ValueError
    except (TypeError, ValueError):
        raise TypeError(f"{what} returned {str(out)[:80]}; expected (x, P, u): a pose of 3 numbers, "
                        "a 3×3 covariance and a command (v, omega)") from None
    return x, P, u


def nav_loop(fn: Callable[..., Any], start: list, P: list, landmark: list, waypoints: list, dt: float,
             Q: list, R: list, steps: int, seed: int) -> list[list[float]]:
    """A closed-loop run: ``fn(x, P, u, z, landmark, waypoint, dt, Q, R)`` returns ``(x, P, u)`` each step.

    A true robot (unseen by ``fn``) drives with the last command, its turn rate off by TURN_BIAS; ``z`` is
    its noisy (range, bearing) to the landmark, or None beyond SENSOR_RANGE; the waypoint moves on to the
    next one once the estimate is within REACHED of it. Returns the estimated pose after every step
    (Partial with the path so far when ``fn`` fails).

    >>> stay = lambda x, P, u, z, lm, wp, dt, Q, R: (x, P, (0.0, 0.0))
    >>> nav_loop(stay, [0, 0, 0], [[0] * 3] * 3, [1, 0], [[2, 0]], 0.5, [[0] * 3] * 3, [[0] * 2] * 2, 2, 1)
    [[0.0, 0.0, 0.0], [0.0, 0.0, 0.0]]
    """
    rng = random.Random(seed)
    true = [float(a) for a in start]
    x, u, goal, path = list(true), [0.0, 0.0], 0, list[list[float]]()
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
        x, P, u = _step(path, _step_out, f"step {k + 1}", fn, x, P, u, z, list(landmark), waypoint, dt, Q, R)
        if goal < len(waypoints) - 1 and math.hypot(waypoint[0] - x[0], waypoint[1] - x[1]) < REACHED:
            goal += 1
        path.append(x)
    return path


DRIVERS: dict[str, Callable[..., Any]] = {"call": call, "pid_loop": pid_loop, "ekf_track": ekf_track,
                                          "nav_loop": nav_loop}


def driver(name: str) -> Callable[..., Any]:
    """The driver called ``name`` (KeyError when there is none)."""
    try:
        return DRIVERS[name]
    except (KeyError, TypeError):
        raise KeyError(f"no harness driver {name!r}") from None
