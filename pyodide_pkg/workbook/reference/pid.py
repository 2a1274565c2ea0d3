"""The discrete PID controller: u = Kp·e + Ki·Σe·dt + Kd·Δe/dt."""

from __future__ import annotations

from collections.abc import Sequence
from typing import NamedTuple


def p_term(e: float, Kp: float) -> float:
    """Proportional term Kp·e.

    Exercise 8.1: target 10, actual 7, Kp = 2.

    >>> p_term(10 - 7, 2)
    6
    """
    return Kp * e


def i_term(errors: Sequence[float], Ki: float, dt: float) -> float:
    """Integral term Ki·Σ e[j]·dt over every error so far (the current one included).

    >>> round(i_term([5, 3, 1], 0.1, 1), 12)
    0.9
    """
    return Ki * sum(e * dt for e in errors)


def d_term(e: float, e_prev: float, Kd: float, dt: float) -> float:
    """Derivative term Kd·(e − e_prev)/dt; negative while the error shrinks.

    Exercise 8.6: the error falls from 5 to 2 in 0.1 s.

    >>> round(d_term(2, 5, 1, 0.1), 9)
    -30.0
    >>> d_term(2, 5, 1, 0)
    Traceback (most recent call last):
    ...
    ValueError: dt must be positive (the time step, in seconds), got 0
    """
    _check_dt(dt)
    return Kd * (e - e_prev) / dt


def _check_dt(dt: float) -> None:
    if not dt > 0:
        raise ValueError(f"dt must be positive (the time step, in seconds), got {dt!r}")


def pid_step(e: float, e_prev: float, integral: float, Kp: float, Ki: float, Kd: float,
             dt: float) -> tuple[float, float]:
    """One PID step; returns ``(u, new_integral)`` with new_integral = integral + e·dt.

    Exercise 8.2, third step: the integral so far is (5 + 3)·1 = 8.

    >>> u, s = pid_step(1, 3, 8, 1, 0.1, 0.5, 1)
    >>> round(u, 12), s
    (0.9, 9)

    The derivative divides by dt, so dt = 0 is refused by name:

    >>> pid_step(1, 3, 8, 1, 0.1, 0.5, 0)
    Traceback (most recent call last):
    ...
    ValueError: dt must be positive (the time step, in seconds), got 0
    """
    _check_dt(dt)
    new_integral = integral + e * dt
    u = Kp * e + Ki * new_integral + Kd * (e - e_prev) / dt
    return u, new_integral


def pid_step_saturated(e: float, e_prev: float, integral: float, Kp: float, Ki: float, Kd: float,
                       dt: float, u_max: float, anti_windup: bool = True) -> tuple[float, float]:
    """One PID step whose output saturates at ±``u_max``, without integral windup.

    Returns ``(u, new_integral)``: u clipped into [−u_max, u_max]; the integral
    grows by e·dt unless the output with that growth would lie past a limit with
    the error pushing further that way (conditional integration, the rule of
    :func:`pid_step_clamped` with u_min = −u_max). A saturated actuator cannot act on
    a larger integral, so one that kept growing (``anti_windup=False``: the bug of
    exercise 8.9) would only have to be unwound later, by overshooting.

    >>> pid_step_saturated(1, 1, 0, 2, 1, 0, 0.1, 5)
    (2.1, 0.1)
    >>> pid_step_saturated(4, 4, 0.5, 2, 1, 0, 0.1, 5)
    (5, 0.5)
    >>> [round(v, 6) for v in pid_step_saturated(-4, -4, 6, 2, 1, 0, 0.1, 5)]  # the error pulls back: integrate
    [-2.4, 5.6]
    >>> pid_step_saturated(4, 4, 0.5, 2, 1, 0, 0.1, 5, anti_windup=False)
    (5, 0.9)
    """
    _check_dt(dt)
    if anti_windup:
        return pid_step_clamped(e, e_prev, integral, Kp, Ki, Kd, dt, -u_max, u_max)
    candidate = integral + e * dt
    u = Kp * e + Ki * candidate + Kd * (e - e_prev) / dt
    return max(-u_max, min(u_max, u)), candidate


def simulate_saturated(step, Kp: float, Ki: float, Kd: float, u_max: float, dt: float = 0.01,
                       duration: float = 10.0, target: float = 1.0) -> tuple[list[float], list[float]]:
    """:func:`simulate_step_response`'s plant (ÿ + 2ẏ + y = u) driven by ``step``, a function
    with :func:`pid_step_saturated`'s arguments (the controller under test, whose output saturates).

    >>> ts, ys = simulate_saturated(pid_step_saturated, 6, 4, 1, 2.5)
    >>> round(ys[-1], 3), round(max(ys), 3)
    (1.0, 1.033)
    """
    _check_dt(dt)
    y = velocity = integral = 0.0
    e_prev = target - y
    ts, ys = [0.0], [y]
    for k in range(1, round(duration / dt) + 1):
        e = target - y
        u, integral = step(e, e_prev, integral, Kp, Ki, Kd, dt, u_max)
        e_prev = e
        velocity += (u - 2.0 * velocity - y) * dt
        y += velocity * dt
        ts.append(round(k * dt, 10))
        ys.append(y)
    return ts, ys


def pid_terms(errors: Sequence[float], Kp: float, Ki: float, Kd: float, dt: float,
              e_prev: float = 0.0) -> tuple[float, float, float]:
    """The three terms (P, I, D) of the output at the last of ``errors``; they add up to u.

    ``e_prev`` is the error before the first step, e[−1].

    Exercise 8.7 (8.2's third step): errors 5, 3, 1 with Kp = 1, Ki = 0.1, Kd = 0.5, dt = 1.

    >>> [round(t, 12) for t in pid_terms([5, 3, 1], 1, 0.1, 0.5, 1)]
    [1, 0.9, -1.0]
    >>> round(sum(pid_terms([5, 3, 1], 1, 0.1, 0.5, 1)), 12) == round(pid_sequence([5, 3, 1], 1, 0.1, 0.5, 1)[-1], 12)
    True
    """
    _check_dt(dt)
    before = errors[-2] if len(errors) > 1 else e_prev
    return p_term(errors[-1], Kp), i_term(errors, Ki, dt), d_term(errors[-1], before, Kd, dt)


def pid_sequence(errors: Sequence[float], Kp: float, Ki: float, Kd: float, dt: float,
                 e_prev: float = 0.0) -> list[float]:
    """Run :func:`pid_step` over a list of errors, starting from an empty integral.

    ``e_prev`` is the error before the first step, e[−1].

    Exercise 8.2: errors 5, 3, 1 with Kp = 1, Ki = 0.1, Kd = 0.5, dt = 1.

    >>> [round(u, 12) for u in pid_sequence([5, 3, 1], 1, 0.1, 0.5, 1)]
    [8.0, 2.8, 0.9]
    """
    out, integral = [], 0.0
    for e in errors:
        u, integral = pid_step(e, e_prev, integral, Kp, Ki, Kd, dt)
        out.append(u)
        e_prev = e
    return out


class StepMetrics(NamedTuple):
    """What a step response is judged by (see :func:`step_metrics`)."""

    overshoot: float  # how far the peak goes past the target, as a fraction of it
    settling_time: float | None  # seconds; None when it has not settled
    steady_state_error: float  # target − final value


def simulate_step_response(Kp: float, Ki: float, Kd: float, dt: float = 0.01, duration: float = 10.0,
                           target: float = 1.0, mass: float = 1.0, damping: float = 2.0,
                           stiffness: float = 1.0) -> tuple[list[float], list[float]]:
    """Step a PID controller (:func:`pid_step`) against a mass on a spring and damper.

    The plant is m·ÿ + c·ẏ + k·y = u, started at rest at y = 0, with the target
    jumping to ``target`` at t = 0. Each sample the controller reads
    e = target − y and pushes with u; the plant then moves for ``dt``
    (semi-implicit Euler: velocity first, then position). The derivative
    starts from the first error, so the jump of the target itself does not kick
    the D term. Returns ``(times, outputs)``; stops early if the output runs
    away (|y| > 1000).

    P alone leaves an offset: the spring pushes back, and at rest
    Kp·e = k·y, so with Kp = 9 the output settles at 0.9.

    >>> ts, ys = simulate_step_response(9, 0, 0)
    >>> len(ts), ts[-1], round(ys[-1], 3)
    (1001, 10.0, 0.9)
    """
    _check_dt(dt)
    steps = round(duration / dt)
    y = velocity = integral = 0.0
    e_prev = target - y
    ts, ys = [0.0], [y]
    for k in range(1, steps + 1):
        e = target - y
        u, integral = pid_step(e, e_prev, integral, Kp, Ki, Kd, dt)
        e_prev = e
        velocity += (u - damping * velocity - stiffness * y) / mass * dt
        y += velocity * dt
        ts.append(round(k * dt, 10))
        ys.append(y)
        if abs(y) > 1000:
            break
    return ts, ys


def step_metrics(ts: Sequence[float], ys: Sequence[float], target: float = 1.0, band: float = 0.02) -> StepMetrics:
    """Overshoot, settling time and steady-state error of a step response.

    - overshoot: (peak − target) / target, or 0 if the output never passes the target;
    - settling time: the moment after which the output stays within ``band``
      (2 %) of its final value; ``None`` if it is still outside that band in
      the last tenth of the run (still swinging, or running away);
    - steady-state error: target − the final value.

    Kp = 9 alone: it overshoots the target by about 21 %, settles in about 3.5 s,
    and stays 0.1 short (exercise 8.3's symptom, with the P-only offset).

    >>> m = step_metrics(*simulate_step_response(9, 0, 0))
    >>> round(m.overshoot, 3), round(m.settling_time, 2), round(m.steady_state_error, 3)
    (0.214, 3.52, 0.1)

    Adding Ki removes the offset; adding Kd calms the overshoot.

    >>> round(step_metrics(*simulate_step_response(9, 4, 0)).steady_state_error, 3)
    0.0
    >>> step_metrics(*simulate_step_response(9, 0, 3)).overshoot
    0.0

    A negative target is the mirror image of a positive one: overshoot is how
    far the output goes past the target (below it), as a fraction of |target|,
    and the steady-state error keeps its sign (target − final). A target of 0
    has no size to measure overshoot against, so it is refused.

    >>> m = step_metrics(*simulate_step_response(9, 0, 0, target=-1.0), target=-1.0)
    >>> round(m.overshoot, 3), round(m.settling_time, 2), round(m.steady_state_error, 3)
    (0.214, 3.52, -0.1)
    >>> step_metrics([0.0, 1.0], [0.0, 0.0], target=0.0)
    Traceback (most recent call last):
    ...
    ValueError: target must be non-zero: overshoot is measured as a fraction of it
    """
    if target == 0:
        raise ValueError("target must be non-zero: overshoot is measured as a fraction of it")
    if target < 0:
        m = step_metrics(ts, [-y for y in ys], -target, band)
        return StepMetrics(m.overshoot, m.settling_time, -m.steady_state_error)
    final = ys[-1]
    overshoot = max(0.0, (max(ys) - target) / target)
    tolerance = band * max(abs(final), 1e-12)
    settled_from = 0
    for k, y in enumerate(ys):
        if abs(y - final) > tolerance:
            settled_from = k + 1
    settling = ts[settled_from] if settled_from < len(ts) else None
    if settling is not None and settling > ts[0] + 0.9 * (ts[-1] - ts[0]):
        settling = None
    if abs(final) > 1000:
        settling = None
    return StepMetrics(overshoot, settling, target - final)


def pid_step_clamped(e: float, e_prev: float, integral: float, Kp: float, Ki: float, Kd: float, dt: float,
                     u_min: float, u_max: float) -> tuple[float, float]:
    """Exercise 8.8: one PID step with the output held in [u_min, u_max] and anti-windup.

    The integral grows by e·dt unless the unclamped output would then lie beyond a limit with
    the error pushing further that way: then it keeps its old value (conditional integration).
    dt = 0 means no time passed: no integration and no derivative term.

    Exercise 8.2's third step with the output capped at 0.5: the integral stays at 8.

    >>> u, s = pid_step_clamped(1, 3, 8, 1, 0.1, 0.5, 1, -0.5, 0.5)
    >>> u, s
    (0.5, 8)
    >>> pid_step_clamped(2, 1, 0, 1, 1, 1, 0, -10, 10)
    (2.0, 0)
    """
    d = Kd * (e - e_prev) / dt if dt > 0 else 0.0
    new_integral = integral + e * dt
    u = Kp * e + Ki * new_integral + d
    if (u > u_max and e > 0) or (u < u_min and e < 0):
        new_integral = integral
        u = Kp * e + Ki * integral + d
    return min(u_max, max(u_min, u)), new_integral
