"""Chapter 7's bug hunt: a Jacobian entry with the wrong sign."""

from __future__ import annotations

import math

from ..kinds.debug import Debug
from ..number_format import fmt
from ..reference.arm import end_effector_velocity, jacobian_2link

# 7.5 (in ch7_jacobians.py): J22 written with s12 where it needs c12.
JACOBIAN_SIGN_BUG = """\
import math
def jacobian_2link(L1, L2, t1, t2):
    s1, c1 = math.sin(t1), math.cos(t1)
    s12, c12 = math.sin(t1 + t2), math.cos(t1 + t2)
    J11 = -L1 * s1 - L2 * s12
    J12 = -L2 * s12
    J21 = L1 * c1 + L2 * c12
    J22 = L2 * s12
    return [[J11, J12], [J21, J22]]
"""


_VELOCITY = """\
import math
def tip_velocity(L1, L2, t1, t2, w1, w2):
    s1, c1 = math.sin(t1), math.cos(t1)
    s12, c12 = math.sin(t1 + t2), math.cos(t1 + t2)
    J11 = -L1 * s1 - L2 * s12
    J12 = -L2 * s12
    J21 = L1 * c1 - L2 * c12
    J22 = L2 * c12
    vx = J11 * w1 + J12 * w2
    vy = J21 * w1 + J22 * w2
    return (vx, vy)
"""


def _tip_velocity(L1, L2, t1, t2, w1, w2):
    return end_effector_velocity(jacobian_2link(L1, L2, t1, t2), (w1, w2))


_STRAIGHT = (1.0, 1.0, 0.0, 0.0, 1.0, 0.0)  # the straight arm along x, joint 1 turning at 1 rad/s


def _bug() -> str:
    L1, L2, t1, t2, w1, w2 = _STRAIGHT
    right = _tip_velocity(*_STRAIGHT)
    wrong = (L1 * math.cos(t1) - L2 * math.cos(t1 + t2)) * w1 + L2 * math.cos(t1 + t2) * w2
    return (f"J(2,1) = ∂y/∂θ1, and y = L1 sin θ1 + L2 sin(θ1 + θ2): both terms grow with θ1, so both derivatives "
            f"come with a plus, L1 cos θ1 + L2 cos(θ1 + θ2). With the minus, the second link moves the tip the "
            f"wrong way. Stretched out along x with joint 1 turning at {fmt(w1)} rad/s, the tip really sweeps up at "
            f"{fmt(right[1])} m/s, but this Jacobian says {fmt(wrong)} m/s: it calls the arm still, and a "
            f"controller that inverts it asks the joints for speeds that send the tip elsewhere. "
            f"Fix: J21 = L1 * c1 + L2 * c12.")


EXERCISES = (
    Debug(
        id="7.9",
        title="Find the sign error in the tip velocity",
        code=_VELOCITY,
        bug_line=7,
        fixed_line="    J21 = L1 * c1 + L2 * c12",
        bug=_bug(),
        notes={
            1: "imports math for sin and cos",
            2: "takes the links, the joint angles and the joint rates",
            3: "link 1 points at θ1",
            4: "link 2 points at θ1 + θ2",
            5: "correct: ∂x/∂θ1 = −L1 sin θ1 − L2 sin(θ1 + θ2)",
            6: "correct: ∂x/∂θ2 = −L2 sin(θ1 + θ2)",
            8: "correct: ∂y/∂θ2 = L2 cos(θ1 + θ2)",
            9: "correct: ẋ is row 1 of J times the joint rates",
            10: "correct: ẏ is row 2 of J times the joint rates",
            11: "returns the tip velocity (ẋ, ẏ)",
        },
        function="tip_velocity",
        reference=_tip_velocity,
        cases=(_STRAIGHT, (1.0, 1.0, 0.3, 0.8, 0.5, -0.4), (2.0, 1.0, -0.6, 1.2, 0.1, 0.7)),
    ),
)
