"""Chapter 4's bug hunt: a bearing innovation that is never wrapped."""

from __future__ import annotations

import math

from ..kinds.debug import Debug
from ..number_format import fmt, prose
from ..reference.ekf import innovation, innovation_wrapped, range_bearing

_INNOVATION = """\
import math
def innovation(x, y, theta, lx, ly, z_range, z_bearing):
    dx, dy = lx - x, ly - y
    r_hat = math.hypot(dx, dy)
    b_hat = math.atan2(dy, dx) - theta
    nu_r = z_range - r_hat
    nu_b = z_bearing - b_hat
    return (nu_r, nu_b)
"""


def _innovation(x, y, theta, lx, ly, z_range, z_bearing) -> list[float]:
    return innovation_wrapped((z_range, z_bearing), range_bearing((x, y, theta), (lx, ly)))


# The robot faces east; the landmark is behind it, a little to the left; the sensor reads
# it a little to the right, on the other side of ±180°.
_SEEN = (0.0, 0.0, 0.0, -4.0, 0.2, 4.0, -3.1)


def _bug() -> str:
    x, y, theta, lx, ly, z_range, z_bearing = _SEEN
    h = range_bearing((x, y, theta), (lx, ly))
    plain = innovation((z_range, z_bearing), h)[1]
    wrapped = _innovation(*_SEEN)[1]
    return (f"Bearings are angles: two either side of ±180° point almost the same way, yet their plain difference is "
            f"nearly a full turn. A landmark right behind the robot is predicted at {prose(h[1])} rad and seen at "
            f"{prose(z_bearing)} rad, "
            f"{fmt(abs(math.degrees(wrapped)))}° apart, but the innovation comes out as {prose(plain)} rad "
            f"({prose(math.degrees(plain))}°) instead of {prose(wrapped)} rad. The update then turns the robot's "
            f"heading hard the wrong way, and the filter can lose the robot whenever a landmark sits behind it. "
            f"Fix: wrap the difference into (−π, π], e.g. "
            f"nu_b = math.atan2(math.sin(z_bearing - b_hat), math.cos(z_bearing - b_hat)).")


EXERCISES = (
    Debug(
        id="4.9",
        title="Find the bug in the innovation",
        code=_INNOVATION,
        bug_line=7,
        fixed_line="    nu_b = math.atan2(math.sin(z_bearing - b_hat), math.cos(z_bearing - b_hat))",
        bug=_bug(),
        notes={
            1: "imports math for hypot and atan2",
            2: "takes the predicted pose, the landmark and the measured range and bearing",
            3: "correct: the landmark's offset from the robot",
            4: "correct: the predicted range is the length of that offset",
            5: "correct: the predicted bearing, measured from the robot's heading (it need not be wrapped "
               "itself, if the difference is)",
            6: "correct: measured minus predicted range",
            8: "returns the innovation (range, bearing)",
        },
        function="innovation",
        reference=_innovation,
        cases=(_SEEN, (0.0, 0.0, 0.0, 3.0, 4.0, 4.8, 0.95), (1.0, 2.0, 2.8, -3.0, 3.0, 4.2, -2.9),
               (2.0, -1.0, -2.5, -1.0, -2.0, 3.0, 2.9)),
    ),
)
