"""Chapter 10 · Code the robot: SLERP between two unit quaternions, the short way, safe when they
are nearly equal."""

from __future__ import annotations

import math

from ..kinds.build import Build
from ..reference.rotation3d import quat_from_axis_angle, quat_multiply
from ..reference.se3 import slerp

_SOLUTION = '''import math


def slerp(q0, q1, t):
    """Unit quaternion (w, x, y, z) a fraction t of the way from q0 to q1, the short way."""
    d = sum(a * b for a, b in zip(q0, q1))
    if d < 0:  # -q1 is the same rotation: take the short way round
        q1, d = [-c for c in q1], -d
    omega = math.acos(min(d, 1.0))
    s = math.sin(omega)
    if s < 1e-6:  # nearly equal: the straight line, made unit, is the same path
        q = [(1 - t) * a + t * b for a, b in zip(q0, q1)]
        n = math.sqrt(sum(c * c for c in q))
        return [c / n for c in q]
    a, b = math.sin((1 - t) * omega) / s, math.sin(t * omega) / s
    return [a * c0 + b * c1 for c0, c1 in zip(q0, q1)]
'''

_STARTER = (
    "import math\n\n\n"
    "def slerp(q0, q1, t):\n"
    '    """Unit quaternion (w, x, y, z) a fraction t of the way from q0 to q1, the short way."""\n'
    "    # Your code here: this straight line is neither unit length nor the short way.\n"
    "    return [(1 - t) * a + t * b for a, b in zip(q0, q1)]\n"
)


def _unit(rng):
    q = [rng.gauss(0, 1) for _ in range(4)]
    n = math.sqrt(sum(c * c for c in q))
    return tuple(c / n for c in q)


def _pair(rng):
    """Two random unit quaternions, not within 3° of a half turn apart (there both ways are as long)."""
    while True:
        q0, q1 = _unit(rng), _unit(rng)
        if abs(sum(a * b for a, b in zip(q0, q1))) > 0.03:
            return q0, q1, rng.uniform(0, 1)


_H = math.sqrt(0.5)
_Q0 = (0.5, 0.5, 0.5, 0.5)  # 120° about (1, 1, 1)
_Z90 = (_H, 0.0, 0.0, _H)
_TINY = quat_multiply(_Q0, quat_from_axis_angle((0, 1, 0), 1e-9))  # 1e-9 rad from _Q0
_ROUNDS_UP = tuple(c / math.sqrt(12) for c in (1.0, 1.0, 1.0, 3.0))  # its dot with itself rounds above 1
_ARC_4DEG = quat_multiply(_Z90, quat_from_axis_angle((1, 0, 0), 0.16))  # Ω = 0.08 rad from _Z90
_MINUS_Z60 = tuple(-c for c in quat_from_axis_angle((0, 0, 1), math.pi / 3))  # 60° about z, written past 360°

EXERCISES = (
    Build(
        id="10.8",
        title="Code the robot: slerp",
        function="slerp",
        params=("q0", "q1", "t"),
        starter=_STARTER,
        solution=_SOLUTION,
        reference=slerp,
        run_figure="slerp",
        examples=(
            ((1.0, 0.0, 0.0, 0.0), _Z90, 0.5),
            ((1.0, 0.0, 0.0, 0.0), _MINUS_Z60, 0.5),
            (_Z90, _Q0, 0.25),
        ),
        edge_cases=(
            ((1.0, 0.0, 0.0, 0.0), _Z90, 0.0),  # t = 0: q0 itself
            ((1.0, 0.0, 0.0, 0.0), _Z90, 1.0),  # t = 1: q1 itself
            ((1.0, 0.0, 0.0, 0.0), _MINUS_Z60, 1.0),  # t = 1 after the flip: −q1, the same rotation
            (_Q0, tuple(-c for c in _Q0), 0.3),  # q1 = −q0: no turn at all
            (_Q0, _Q0, 0.5),  # equal: sin Ω = 0
            (_Q0, _TINY, 0.25),  # nearly equal: sin Ω rounds to 0
            (_Q0, tuple(-c for c in _TINY), 0.75),  # nearly equal, across the double cover
            (_ROUNDS_UP, _ROUNDS_UP, 0.5),  # equal, and the dot rounds to 1.0000000000000002: clamp before acos
            (_Z90, _ARC_4DEG, 0.3),  # a 4.6° arc: sin Ω = 0.08 is far from 0, so the arc, not the straight line
        ),
        random_args=_pair,
    ),
)
