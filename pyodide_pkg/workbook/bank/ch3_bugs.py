"""Chapter 3's bug hunts: the covariance's factors in the wrong order; milliseconds for seconds."""

from __future__ import annotations

import math

from ..kinds.debug import Debug
from ..number_format import fmt
from ..reference.ekf import motion_jacobian, motion_model
from ..reference.linalg import add, matmul, transpose

_COVARIANCE = """\
def matmul(A, B):
    return [[sum(a * b for a, b in zip(row, col)) for col in zip(*B)] for row in A]
def predict_covariance(F, P, Q):
    Ft = [list(col) for col in zip(*F)]
    FPFt = matmul(matmul(Ft, P), F)
    n = len(Q)
    return [[FPFt[i][j] + Q[i][j] for j in range(n)] for i in range(n)]
"""

_DEAD_RECKONING = """\
import math
def dead_reckon(x, y, theta, v, omega, stamps_ms):
    for k in range(1, len(stamps_ms)):
        dt = stamps_ms[k] - stamps_ms[k - 1]
        x = x + v * math.cos(theta) * dt
        y = y + v * math.sin(theta) * dt
        theta = theta + omega * dt
    return (x, y, theta)
"""


def predicted_covariance(F, P, Q):
    """P⁻ = F P Fᵀ + Q."""
    return add(matmul(matmul(F, P), transpose(F)), Q)


def _dead_reckon(x, y, theta, v, omega, stamps_ms):
    """The motion model stepped from one time stamp (ms) to the next, in seconds."""
    state = (x, y, theta)
    for earlier, later in zip(stamps_ms, stamps_ms[1:]):
        state = motion_model(state, v, omega, (later - earlier) / 1000)
    return state


# Driving east at 1 m/s for 1 s, sure of the position (σ = 0.1 m) but not of the heading.
_EAST = ((0.0, 0.0, 0.0), 1.0, 0.0, 1.0)
_P = [[0.01, 0.0, 0.0], [0.0, 0.01, 0.0], [0.0, 0.0, 0.1]]
_Q = [[0.001, 0.0, 0.0], [0.0, 0.001, 0.0], [0.0, 0.0, 0.001]]


def _covariance_bug() -> str:
    F = motion_jacobian(*_EAST)
    right = predicted_covariance(F, _P, _Q)
    wrong = add(matmul(matmul(transpose(F), _P), F), _Q)
    return (f"P⁻ = F P Fᵀ + Q: F on the left and Fᵀ on the right carry the doubt about the heading, through F's θ "
            f"column, into the doubt about where the robot went. Swapped, Fᵀ P F carries it the other way, from "
            f"the position into the heading. Driving east at {fmt(_EAST[1])} m/s for {fmt(_EAST[3])} s with a "
            f"heading variance of {fmt(_P[2][2])} rad², the sideways "
            f"variance should grow to {fmt(right[1][1])} m² (σ = {fmt(math.sqrt(right[1][1]))} m) but stays "
            f"{fmt(wrong[1][1])} m² (σ = {fmt(math.sqrt(wrong[1][1]))} m), and the heading's variance grows to "
            f"{fmt(wrong[2][2])} rad² instead of {fmt(right[2][2])}. The filter is overconfident about where it "
            f"is, and then trusts its prediction over the sensors it needs. Fix: FPFt = matmul(matmul(F, P), Ft).")


_STAMPS = tuple(50 * k for k in range(21))  # 20 samples at 20 Hz: one second


def _ms_bug() -> str:
    x, y, theta, v, omega = 0.0, 0.0, 0.0, 0.5, 0.0
    right = _dead_reckon(x, y, theta, v, omega, list(_STAMPS))
    wrong = x + v * (_STAMPS[-1] - _STAMPS[0])
    step = _STAMPS[1] - _STAMPS[0]
    return (f"The time stamps are in milliseconds, and the motion model wants seconds: dt comes out "
            f"{fmt(step)} where it should be {fmt(step / 1000)}, a thousand times too large. Driving at {fmt(v)} m/s "
            f"for {fmt((_STAMPS[-1] - _STAMPS[0]) / 1000)} s of {fmt(1000 / step)} Hz odometry, the robot "
            f"believes it moved {fmt(wrong)} m instead of {fmt(right[0])} m, and every turn is a thousand times "
            f"too sharp. Fix: dt = (stamps_ms[k] - stamps_ms[k - 1]) / 1000.")


EXERCISES = (
    Debug(
        id="3.11",
        title="Find the bug in the covariance prediction",
        code=_COVARIANCE,
        bug_line=5,
        fixed_line="    FPFt = matmul(matmul(F, P), Ft)",
        bug=_covariance_bug(),
        notes={
            1: "a matrix product for lists of rows",
            2: "correct: entry (i, j) is row i of A times column j of B",
            3: "takes the Jacobian F, the covariance P and the process noise Q",
            4: "correct: Fᵀ, the columns of F as rows",
            6: "the size of the state",
            7: "correct: adds the process noise Q entry by entry",
        },
        function="predict_covariance",
        reference=predicted_covariance,
        cases=((motion_jacobian(*_EAST), _P, _Q),
               (motion_jacobian((0.0, 0.0, math.pi / 2), 1.0, 0.0, 0.5), [[1, 0, 0], [0, 1, 0], [0, 0, 0.1]], _Q),
               (motion_jacobian((1.0, 2.0, 0.6), 2.0, 0.3, 0.2), [[0.2, 0.05, 0.01], [0.05, 0.3, 0.02],
                                                                  [0.01, 0.02, 0.05]], _Q)),
    ),
    Debug(
        id="3.12",
        title="Find the bug in the dead reckoning",
        code=_DEAD_RECKONING,
        bug_line=4,
        fixed_line="        dt = (stamps_ms[k] - stamps_ms[k - 1]) / 1000",
        bug=_ms_bug(),
        notes={
            1: "imports math for cos and sin",
            2: "takes the starting pose, the speed (m/s), the turn rate (rad/s) and the odometry's time stamps",
            3: "one step between each pair of consecutive stamps",
            5: "correct: x moves by v·cos θ·dt",
            6: "correct: y moves by v·sin θ·dt",
            7: "correct: the heading turns by ω·dt",
            8: "returns the final pose",
        },
        function="dead_reckon",
        reference=_dead_reckon,
        cases=((0.0, 0.0, 0.0, 0.5, 0.0, list(_STAMPS)), (1.0, 2.0, 0.5, 1.0, 0.2, [0, 100, 200, 350, 500]),
               (0.0, 0.0, math.pi / 2, 0.8, -0.4, [1000, 1020, 1040, 1060])),
    ),
)
