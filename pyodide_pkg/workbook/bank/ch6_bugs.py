"""Chapter 6's bug hunt: inverse kinematics with atan where atan2 is needed."""

from __future__ import annotations

import math

from ..figures.symptoms import ik_facts
from ..kinds.debug import Debug
from ..number_format import fmt, prose
from ..reference.arm import inverse_kinematics_2link

_IK = """\
import math
def ik_2link(L1, L2, x, y):
    c2 = (x * x + y * y - L1 * L1 - L2 * L2) / (2 * L1 * L2)
    t2 = math.acos(max(-1.0, min(1.0, c2)))
    k1 = L1 + L2 * math.cos(t2)
    k2 = L2 * math.sin(t2)
    t1 = math.atan(y / x) - math.atan2(k2, k1)
    return (t1, t2)
"""


def _elbow_down(L1: float, L2: float, x: float, y: float) -> tuple[float, float]:
    return inverse_kinematics_2link(L1, L2, x, y).elbow_down


def _bug() -> str:
    f = ik_facts()
    (x, y), tip = f["target"], f["tip_bug"]
    return (f"atan(y/x) only knows the ratio y/x, so it answers between −90° and 90°: a target behind the base "
            f"(x < 0) is taken for the one straight opposite. For unit links and the target ({prose(x)}, "
            f"{prose(y)}), the base should turn to {prose(math.degrees(f['t1']))}° but turns to "
            f"{prose(math.degrees(f['t1_bug']))}°, half a turn away: the tip lands at ({prose(tip[0])}, "
            f"{prose(tip[1])}), {fmt(f['miss'])} m from the target, and a target on the y axis (x = 0) stops "
            f"the arm with a ZeroDivisionError. Fix: t1 = math.atan2(y, x) - math.atan2(k2, k1).")


EXERCISES = (
    Debug(
        id="6.8",
        title="Find the bug in the inverse kinematics",
        code=_IK,
        bug_line=7,
        fixed_line="    t1 = math.atan2(y, x) - math.atan2(k2, k1)",
        bug=_bug(),
        notes={
            1: "imports math for acos, atan2, sin and cos",
            2: "takes both link lengths and the target",
            3: "correct: the law of cosines gives cos θ2 from the target's distance",
            4: "clamps cos θ2 into [−1, 1] against rounding, then takes the elbow-down angle θ2 ≥ 0",
            5: "correct: the reach of the bent arm along its first link, L1 + L2 cos θ2",
            6: "correct: how far the elbow bends the tip off that line, L2 sin θ2",
            8: "returns both joint angles in radians",
        },
        function="ik_2link",
        reference=_elbow_down,
        # the last: L2 > L1 puts the elbow term's k1 below 0, where atan(k2/k1) is off by a half turn
        cases=((1, 1, 1, 1), (1, 1, -1.2, 0.8), (2, 1, -1.5, -2), (1.5, 1, 2, 0.5), (1, 2, 1.2, 0)),
        symptom="ik-quadrant",
    ),
)
