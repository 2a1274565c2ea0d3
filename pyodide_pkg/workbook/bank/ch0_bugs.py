"""Chapter 0's bug hunt: degrees handed to math.cos and math.sin."""

from __future__ import annotations

import math

from ..kinds.debug import Debug
from ..number_format import fmt, prose
from ..reference.rotation2d import rotate_2d
from ..reference.transform2d import apply, transform2d

_LIDAR = """\
import math
def lidar_point(x, y, heading, r, beam_deg):
    angle = heading + beam_deg
    px = x + r * math.cos(angle)
    py = y + r * math.sin(angle)
    return (px, py)
"""


def _lidar_point(x: float, y: float, heading: float, r: float, beam_deg: float) -> tuple[float, float]:
    """The return at range r on the beam beam_deg (degrees) left of the nose, in the world frame."""
    return apply(transform2d(x, y, heading), *rotate_2d(r, 0.0, math.radians(beam_deg)))


_SEEN = (0.0, 0.0, 0.0, 2.0, 90.0)  # a wall 2 m to the left of a robot at the origin facing east


def _bug() -> str:
    x, y, heading, r, beam = _SEEN
    right = _lidar_point(*_SEEN)
    wrong = (x + r * math.cos(heading + beam), y + r * math.sin(heading + beam))
    return (f"The beam's angle arrives in degrees and is added to a heading in radians, and math.cos and math.sin "
            f"read the sum as radians: {fmt(beam)} radians is {fmt(beam / (2 * math.pi))} full turns, not a quarter "
            "turn. "
            f"A wall {fmt(r)} m to the left of a robot at the origin facing east is seen at ({prose(right[0])}, "
            f"{prose(right[1])}), but drawn at ({prose(wrong[0])}, {prose(wrong[1])}), "
            f"{fmt(math.dist(right, wrong))} m away; every beam lands somewhere else, so the map is a scatter. "
            f"Fix: angle = heading + math.radians(beam_deg).")


EXERCISES = (
    Debug(
        id="0.8",
        title="Find the bug in the LiDAR point",
        code=_LIDAR,
        bug_line=3,
        fixed_line="    angle = heading + math.radians(beam_deg)",
        bug=_bug(),
        notes={
            1: "imports math for cos and sin",
            2: "takes the robot's pose (heading in radians), the range and the beam's angle in degrees",
            4: "correct once the angle is in radians: the return lies r along the beam, x by r·cos",
            5: "correct once the angle is in radians: y by r·sin",
            6: "returns the point in the world frame",
        },
        function="lidar_point",
        reference=_lidar_point,
        cases=((0.0, 0.0, 0.0, 2.0, 90.0), (1.0, 2.0, math.pi / 4, 3.0, -30.0), (-2.0, 0.5, math.pi, 1.5, 45.0)),
    ),
)
