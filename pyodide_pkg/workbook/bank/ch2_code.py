"""Chapter 2 · Code the robot: axis-angle to a unit quaternion, and a vector turned by it."""

import math

from ..kinds.build import Build
from ..reference.rotation3d import rotate_axis_angle

_SOLUTION = '''import math


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def rotate_axis_angle(axis, angle, v):
    """Unit quaternion (w, x, y, z) for angle radians about axis, and v turned by it."""
    n = math.sqrt(axis[0] ** 2 + axis[1] ** 2 + axis[2] ** 2)
    s = math.sin(angle / 2) / n  # half the angle; the axis made unit
    q = (math.cos(angle / 2), s * axis[0], s * axis[1], s * axis[2])
    w, u = q[0], q[1:]
    t = cross(u, v)  # q v q* written with two cross products
    tt = cross(u, t)
    turned = tuple(v[i] + 2 * w * t[i] + 2 * tt[i] for i in range(3))
    return (q, turned)
'''


def _axis(rng):
    while True:
        a = tuple(rng.uniform(-1, 1) for _ in range(3))
        if math.sqrt(sum(c * c for c in a)) > 0.2:
            return tuple(rng.uniform(0.3, 3) * c for c in a)


EXERCISES = (
    Build(
        id="2.8",
        title="Code the robot: rotate_axis_angle",
        function="rotate_axis_angle",
        params=("axis", "angle", "v"),
        starter=(
            "import math\n\n\n"
            "def rotate_axis_angle(axis, angle, v):\n"
            '    """Unit quaternion (w, x, y, z) for angle radians about axis, and v turned by it."""\n'
            "    # Your code here: the quaternion first, then turn v with it.\n"
            "    q = (1.0, 0.0, 0.0, 0.0)\n"
            "    return (q, tuple(v))\n"
        ),
        solution=_SOLUTION,
        reference=rotate_axis_angle,
        run_figure="axis-angle",
        examples=(
            ((0, 0, 1), math.pi / 2, (1, 0, 0)),
            ((1, 0, 0), math.pi, (0, 1, 0)),
            ((0, 0, 2), math.pi / 2, (1, 2, 3)),
            ((1, 1, 1), 2 * math.pi / 3, (1, 0, 0)),
        ),
        edge_cases=(
            ((0, 1, 0), 0.0, (1, 2, 3)),  # no turn: the identity quaternion
            ((0, 3, 0), 3 * math.pi / 2, (1, 0, 0)),  # past π, and an axis of length 3
            ((1, 0, 0), 2 * math.pi, (0, 1, 1)),  # a full turn: w = −1, the vector unchanged
            ((0, 0, 1), -math.pi / 2, (1, 0, 0)),  # a negative angle turns the other way
        ),
        random_args=lambda rng: (_axis(rng), rng.uniform(-2 * math.pi, 2 * math.pi),
                                 tuple(rng.uniform(-3, 3) for _ in range(3))),
    ),
)
