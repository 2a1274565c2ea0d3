"""Chapter 11's bug hunt: an arm's forward kinematics that multiplies each new exponential on the
left, so the product comes out in reverse order (e^[Sₙ]θₙ ⋯ e^[S₁]θ₁ M)."""

from __future__ import annotations

import math

from ..kinds.debug import Debug
from ..number_format import fmt
from ..reference.screw import arm_home, arm_screws, fk_poe
from ..reference.se3 import translation_of

_TOOL_POSE = """\
import math
def mat_mul(A, B):
    return [[sum(A[i][k] * B[k][j] for k in range(4)) for j in range(4)] for i in range(4)]
def twist_exp(S, th):
    (wx, wy, wz), v = S[:3], S[3:]
    W = [[0, -wz, wy], [wz, 0, -wx], [-wy, wx, 0]]
    W2 = [[sum(W[i][k] * W[k][j] for k in range(3)) for j in range(3)] for i in range(3)]
    s, c = math.sin(th), math.cos(th)
    R = [[(i == j) + s * W[i][j] + (1 - c) * W2[i][j] for j in range(3)] for i in range(3)]
    G = [[th * (i == j) + (1 - c) * W[i][j] + (th - s) * W2[i][j] for j in range(3)] for i in range(3)]
    p = [sum(G[i][k] * v[k] for k in range(3)) for i in range(3)]
    return [R[0] + [p[0]], R[1] + [p[1]], R[2] + [p[2]], [0, 0, 0, 1]]
def tool_pose(M, screws, joints):
    # screws: (w, v) in the base frame, base joint first
    T = [[float(i == j) for j in range(4)] for i in range(4)]
    for S, th in zip(screws, joints):
        T = mat_mul(twist_exp(S, th), T)
    return mat_mul(T, M)
"""


def _arm(*theta):
    return ([list(r) for r in arm_home(1.0, 2.0, 1.0)], arm_screws(1.0, 2.0), list(theta))


_CASES = (
    _arm(math.pi / 2, math.pi / 2, -math.pi / 2),
    _arm(math.pi / 4, math.pi / 6, 0.0),
    _arm(-1.0, 0.5, 1.2),
)


def tool_facts() -> dict:
    """The first case (11.3's arm and angles): where the tool is, and where the bug puts it."""
    program: dict = {}
    exec(_TOOL_POSE, program)  # the bug's own code says where it puts the tool: nothing here copies it
    return {"right": translation_of(fk_poe(*_CASES[0])), "wrong": translation_of(program["tool_pose"](*_CASES[0]))}


def _point(p) -> str:
    return "(" + ", ".join(fmt(round(c, 12) + 0.0) for c in p) + ")"


def _bug() -> str:
    f = tool_facts()
    return ("Line 17 multiplies each new exponential on the left of the product so far, so after the loop T is "
            "e^[S₃]θ₃ e^[S₂]θ₂ e^[S₁]θ₁, the order reversed. In the space form the base's exponential must be "
            "the leftmost: T = e^[S₁]θ₁ e^[S₂]θ₂ e^[S₃]θ₃ M, because every S is written at home in the base frame "
            "and the later joints' motions must be carried by the earlier ones. With one joint moving the two "
            "orders agree, which is why the arm looked right in tests of one joint at a time. At exercise 11.3's "
            f"angles (90°, 90°, −90°) the tool is at {_point(f['right'])} and the code reports "
            f"{_point(f['wrong'])}. Fix: T = mat_mul(T, twist_exp(S, th)).")


EXERCISES = (
    Debug(
        id="11.9",
        title="Find the bug in the arm's forward kinematics",
        code=_TOOL_POSE,
        bug_line=17,
        fixed_line="        T = mat_mul(T, twist_exp(S, th))",
        bug=_bug(),
        notes={
            1: "imports math for sin and cos",
            2: "correct: the product of two 4 × 4 matrices",
            3: "correct: entry (i, j) is row i of A times column j of B",
            4: "correct: the exponential of one joint's twist",
            5: "correct: ω and v, the two halves of S",
            6: "correct: [ω], the cross-product matrix",
            7: "correct: [ω]²",
            8: "correct: sin θ and cos θ",
            9: "correct: Rodrigues' formula, I + sin θ [ω] + (1 − cos θ)[ω]²",
            10: "correct: G(θ) = I θ + (1 − cos θ)[ω] + (θ − sin θ)[ω]²",
            11: "correct: the shift G(θ) v",
            12: "correct: the 4 × 4 transform [R p; 0 1]",
            13: "correct: the arm's pose from its home pose, screws and joint values",
            14: "correct: a comment that says which frame the screws are in",
            15: "correct: the product starts as the identity",
            16: "correct: each joint in turn, base first",
            18: "correct: the home pose M goes last, on the right",
        },
        function="tool_pose",
        reference=fk_poe,
        cases=_CASES,
    ),
)
