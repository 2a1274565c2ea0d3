"""Hold-out programs of exercise 10.8 (slerp), kept apart from ``holdout_programs.py`` so that
neither file grows past 400 lines; that module merges them in."""

from __future__ import annotations

WRONG: dict[str, object] = {
    "no short-way flip": [("    if d < 0:  # -q1 is the same rotation: take the short way round\n"
                           "        q1, d = [-c for c in q1], -d\n", "")],
    "no guard when nearly equal": [("    if s < 1e-6:", "    if False:")],
    "weights swapped": [("a, b = math.sin((1 - t) * omega) / s, math.sin(t * omega) / s",
                         "a, b = math.sin(t * omega) / s, math.sin((1 - t) * omega) / s")],
    "q1 flipped, its dot kept negative": [("q1, d = [-c for c in q1], -d", "q1 = [-c for c in q1]")],
    "w made non-negative": [("    return [a * c0 + b * c1 for c0, c1 in zip(q0, q1)]",
                             "    q = [a * c0 + b * c1 for c0, c1 in zip(q0, q1)]\n"
                             "    return q if q[0] >= 0 else [-c for c in q]")],
    "no clamp before acos": [("math.acos(min(d, 1.0))", "math.acos(d)")],
    "straight line for arcs up to 11.5°": [("    if s < 1e-6:", "    if s < 0.2:")],
    "plain lerp made unit everywhere": [("    if s < 1e-6:", "    if True:")],
}

RIGHT: dict[str, object] = {
    "numpy": """import numpy as np


def slerp(q0, q1, t):
    q0, q1 = np.asarray(q0, dtype=float), np.asarray(q1, dtype=float)
    d = float(np.dot(q0, q1))
    if d < 0:
        q1, d = -q1, -d
    if d > 0.9995:
        q = q0 + t * (q1 - q0)
        return q / np.linalg.norm(q)
    omega = np.arccos(d)
    return (np.sin((1 - t) * omega) * q0 + np.sin(t * omega) * q1) / np.sin(omega)
""",
    "through the relative turn": """import math


def mul(p, q):
    a, u = p[0], p[1:]
    b, v = q[0], q[1:]
    cross = (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])
    return [a * b - sum(x * y for x, y in zip(u, v))] + [a * v[i] + b * u[i] + cross[i] for i in range(3)]


def slerp(q0, q1, t):
    if sum(a * b for a, b in zip(q0, q1)) < 0:
        q1 = [-c for c in q1]
    rel = mul([q0[0], -q0[1], -q0[2], -q0[3]], q1)  # the turn from q0 to q1, w >= 0
    s = math.sqrt(rel[1] ** 2 + rel[2] ** 2 + rel[3] ** 2)
    half = math.atan2(s, rel[0])
    if s == 0:
        return list(q0)
    axis = [c / s for c in rel[1:]]
    step = [math.cos(t * half)] + [math.sin(t * half) * a for a in axis]
    return mul(q0, step)
""",
}
