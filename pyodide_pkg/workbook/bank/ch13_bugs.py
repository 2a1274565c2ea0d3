"""Chapter 13's bug hunt: a LiDAR odometry step whose cross-covariance is built transposed, so the
robot's turn comes out with its sign flipped."""

from __future__ import annotations

import math

from ..kinds.debug import Debug
from ..number_format import fmt
from ..reference.alignment import align_2d

_SCAN_MATCH = """\
import math
def scan_turn(P, Q):
    # P: the last scan's points, Q: the same points seen now, paired in order
    n = len(P)
    px, py = sum(p[0] for p in P) / n, sum(p[1] for p in P) / n
    qx, qy = sum(q[0] for q in Q) / n, sum(q[1] for q in Q) / n
    h = [[0.0, 0.0], [0.0, 0.0]]
    for (ax, ay), (bx, by) in zip(P, Q):
        a, b = (ax - px, ay - py), (bx - qx, by - qy)
        for i in range(2):
            for j in range(2):
                h[i][j] += b[i] * a[j]
    theta = math.atan2(h[0][1] - h[1][0], h[0][0] + h[1][1])
    c, s = math.cos(theta), math.sin(theta)
    return (theta, qx - (c * px - s * py), qy - (s * px + c * py))
"""


def _turn(P, Q):
    """The turn and shift that map P onto Q: (θ, tx, ty)."""
    R, t = align_2d(P, Q)
    return (math.atan2(R[1][0], R[0][0]), t[0], t[1])


def _turned(P, deg, t):
    c, s = math.cos(math.radians(deg)), math.sin(math.radians(deg))
    return tuple((c * x - s * y + t[0], s * x + c * y + t[1]) for x, y in P)


_WALLS = ((2.0, 0.0), (2.0, 1.0), (1.0, 2.0), (0.0, 2.0), (-1.0, 1.5))
_CASES = (
    (_WALLS, _turned(_WALLS, 10, (0.0, 0.0))),
    (_WALLS, _turned(_WALLS, -25, (0.3, -0.1))),
    (((0.0, 0.0), (4.0, 0.0), (4.0, 2.0)), _turned(((0.0, 0.0), (4.0, 0.0), (4.0, 2.0)), 90, (1.0, 1.0))),
)


def scan_facts() -> dict:
    """The first case: the scan turned by 10°; what the bug reports."""
    P, Q = _CASES[0]
    program: dict = {}
    exec(_SCAN_MATCH, program)  # the bug's own code says what it reports: nothing here copies it
    wrong = math.degrees(program["scan_turn"](P, Q)[0])
    return {"right": math.degrees(_turn(P, Q)[0]), "wrong": wrong}


def _bug() -> str:
    f = scan_facts()
    return ("Line 12 adds b[i] · a[j], a point of Q times a point of P: that builds Σ q′ p′ᵀ, H transposed. "
            "Line 13's formula atan2(H₁₂ − H₂₁, H₁₁ + H₂₂) expects H = Σ p′ q′ᵀ (row from P, column from Q), "
            "and the transpose swaps H₁₂ and H₂₁, so the turn's sign flips: a scan turned by "
            f"{fmt(f['right'])}° is reported as {fmt(f['wrong'])}°, and the shift built on it is wrong too. "
            "Nothing fails; the odometry just turns the wrong way. Fix: h[i][j] += a[i] * b[j].")


EXERCISES = (
    Debug(
        id="13.10",
        title="Find the bug in the scan matcher",
        code=_SCAN_MATCH,
        bug_line=12,
        fixed_line="                h[i][j] += a[i] * b[j]",
        bug=_bug(),
        notes={
            1: "imports math for atan2, cos and sin",
            2: "takes the two scans, paired point by point",
            3: "correct: a comment that says how the scans are paired",
            4: "correct: the number of pairs",
            5: "correct: the centroid of P",
            6: "correct: the centroid of Q",
            7: "correct: H starts at zero",
            8: "correct: each pair of points",
            9: "correct: the centred points p′ = p − p̄ and q′ = q − q̄",
            10: "correct: each row of H",
            11: "correct: each column of H",
            13: "correct: θ = atan2(H₁₂ − H₂₁, H₁₁ + H₂₂) for H = Σ p′ q′ᵀ",
            14: "correct: cos θ and sin θ",
            15: "correct: t = q̄ − R p̄",
        },
        function="scan_turn",
        reference=_turn,
        cases=_CASES,
    ),
)
