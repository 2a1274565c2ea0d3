"""Chapter 1 · Code the robot: the pose of one frame seen from another (inverse, then compose)."""

import math

from ..kinds.build import Build
from ..reference.pose_graph import relative_pose

_SOLUTION = '''import math


def relative_pose(a, b):
    """Pose (x, y, theta) of frame B in frame A's coordinates; a and b are world poses."""
    xa, ya, ta = a
    xb, yb, tb = b
    c, s = math.cos(ta), math.sin(ta)
    dx, dy = xb - xa, yb - ya
    # T_A^-1 T_B: undo A's translation, then A's rotation (R transposed).
    x = c * dx + s * dy
    y = -s * dx + c * dy
    theta = math.atan2(math.sin(tb - ta), math.cos(tb - ta))  # into [-pi, pi]
    return (x, y, theta)
'''


def _pose(rng):
    return (rng.uniform(-5, 5), rng.uniform(-5, 5), rng.uniform(-math.pi, math.pi))


EXERCISES = (
    Build(
        id="1.7",
        title="Code the robot: relative_pose",
        function="relative_pose",
        params=("a", "b"),
        starter=(
            "import math\n\n\n"
            "def relative_pose(a, b):\n"
            '    """Pose (x, y, theta) of frame B in frame A\'s coordinates; a and b are world poses."""\n'
            "    # Your code here: invert A's transform, then compose it with B's.\n"
            "    return (b[0] - a[0], b[1] - a[1], b[2] - a[2])\n"
        ),
        solution=_SOLUTION,
        reference=relative_pose,
        run_figure="frames",
        examples=(
            ((0, 0, 0), (2, 1, 0.5)),
            ((1, 2, math.pi / 2), (1, 3, math.pi / 2)),
            ((2, 1, math.pi / 2), (0, 0, 0)),
            ((1, 0, 3.0), (0, 1, -3.0)),
        ),
        edge_cases=(
            ((1.5, -2, 0.7), (1.5, -2, 0.7)),  # the same pose: the identity
            ((0, 0, -3.0), (1, 1, 3.0)),  # the heading difference is past π
            ((3, 4, 2.5), (-1, 0, -2.5)),  # and past −π the other way
            ((1, 2, math.pi), (3, 1, 0.0)),  # exactly a half-turn apart: π or −π
            ((-2, 1, -math.pi / 2), (0, -1, math.pi / 2)),  # and the other way round
        ),
        angles=("[2]",),
        random_args=lambda rng: (_pose(rng), _pose(rng)),
    ),
)
