"""Drivers: how a Build exercise's function is exercised on one case.

A driver takes the function under test and one case's arguments (as decoded from
JSON: numbers, lists, dicts) and returns what the grader compares. The grader
runs its reference implementation through the same driver, natively, so a
learner's output and the expected one always come from the same procedure.
A Build exercise names its driver in ``Build.harness``; a run figure may name a
closed-loop one (``pid_loop``) that calls the function step by step and returns
the whole trajectory.

>>> call(lambda x, y: (y, x), 1, 2)
(2, 1)
>>> driver("call") is call
True
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
from typing import Any, Callable

# The plant of the PID loop: a mass on a spring and damper, m·ÿ + c·ẏ + k·y = u
# (the plant of chapter 8's figure), started at rest, asked to reach TARGET.
MASS, DAMPING, STIFFNESS, TARGET = 1.0, 2.0, 1.0, 1.0
RUNAWAY = 1000.0


class Partial(Exception):
    """The function failed during a closed-loop run: ``so_far`` is the trajectory until then."""

    def __init__(self, so_far: Any) -> None:
        super().__init__("the run stopped part-way")
        self.so_far = so_far


def call(fn: Callable[..., Any], *args: Any) -> Any:
    """One call: the function's own return value."""
    return fn(*args)


def _pair(got: Any, what: str) -> tuple[float, float]:
    """Two numbers from what a step returned, or TypeError saying what came back."""
    try:
        a, b = got
        return float(a), float(b)
    except (TypeError, ValueError) as err:
        shown = type(got).__name__
        raise TypeError(f"{what}: expected a pair of numbers, got {shown} ({err})") from None


def pid_loop(fn: Callable[..., Any], Kp: float, Ki: float, Kd: float, dt: float, steps: int) -> list[float]:
    """Closed loop: ``fn`` (a ``pid_step``) drives the plant for ``steps`` samples of ``dt`` seconds.

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
        try:
            u, integral = _pair(fn(e, e_prev, integral, Kp, Ki, Kd, dt), f"step {k + 1}")
        except (KeyboardInterrupt, MemoryError):
            raise
        except BaseException as err:
            raise Partial(ys) from err
        e_prev = e
        velocity += (u - DAMPING * velocity - STIFFNESS * y) / MASS * dt
        y += velocity * dt
        ys.append(y)
        if not math.isfinite(y) or abs(y) > RUNAWAY:
            break
    return ys


DRIVERS: dict[str, Callable[..., Any]] = {"call": call, "pid_loop": pid_loop}


def driver(name: str) -> Callable[..., Any]:
    """The driver called ``name`` (KeyError when there is none)."""
    try:
        return DRIVERS[name]
    except (KeyError, TypeError):
        raise KeyError(f"no harness driver {name!r}") from None
