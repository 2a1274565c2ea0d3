"""The discrete PID controller: u = Kp·e + Ki·Σe·dt + Kd·Δe/dt."""

from __future__ import annotations

from typing import Sequence


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
    """
    return Kd * (e - e_prev) / dt


def pid_step(e: float, e_prev: float, integral: float, Kp: float, Ki: float, Kd: float,
             dt: float) -> tuple[float, float]:
    """One PID step; returns ``(u, new_integral)`` with new_integral = integral + e·dt.

    Exercise 8.2, third step: the integral so far is (5 + 3)·1 = 8.

    >>> u, s = pid_step(1, 3, 8, 1, 0.1, 0.5, 1)
    >>> round(u, 12), s
    (0.9, 9)
    """
    new_integral = integral + e * dt
    u = Kp * e + Ki * new_integral + Kd * (e - e_prev) / dt
    return u, new_integral


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
