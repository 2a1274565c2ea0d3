"""Chapter 7 · Code the robot: the two-link Jacobian and a singularity test."""

import math

from ..kinds.build import Build
from ..reference.arm import jacobian_singular

_SOLUTION = '''import math


def jacobian_2link(L1, L2, theta1, theta2):
    """The 2x2 Jacobian of the tip (x, y), and whether |det J| < 1e-9 (a singularity)."""
    s1, c1 = math.sin(theta1), math.cos(theta1)
    s12, c12 = math.sin(theta1 + theta2), math.cos(theta1 + theta2)
    J = [[-L1 * s1 - L2 * s12, -L2 * s12],
         [L1 * c1 + L2 * c12, L2 * c12]]
    det = J[0][0] * J[1][1] - J[0][1] * J[1][0]
    return (J, abs(det) < 1e-9)
'''

EXERCISES = (
    Build(
        id="7.8",
        title="Code the robot: jacobian_2link",
        function="jacobian_2link",
        params=("L1", "L2", "theta1", "theta2"),
        starter=(
            "import math\n\n\n"
            "def jacobian_2link(L1, L2, theta1, theta2):\n"
            '    """The 2x2 Jacobian of the tip (x, y), and whether |det J| < 1e-9 (a singularity)."""\n'
            "    # Your code here: differentiate x and y by each joint angle, then test det J.\n"
            "    J = [[0.0, 0.0], [0.0, 0.0]]\n"
            "    return (J, False)\n"
        ),
        solution=_SOLUTION,
        reference=jacobian_singular,
        run_figure="jacobian",
        examples=(
            (1, 1, 0, math.pi / 2),
            (1, 1, math.pi / 6, math.pi / 4),
            (1, 1, math.pi / 4, 0),
            (2, 1, 0.3, -1.2),
        ),
        edge_cases=(
            (1, 1, 0, math.pi),  # folded back: det J is about 1e-16 in floats, still singular
            (1.5, 0.5, 1.0, -math.pi),
            (1, 2, -2.0, 2 * math.pi),  # a whole turn of the elbow: stretched out again
            (1, 1, 3.0, 1e-12),  # all but stretched
            (1, 1, 0.5, 1e-7),  # near a singularity, |det J| = 1e-7: not singular by the 1e-9 test
        ),
        random_args=lambda rng: (rng.uniform(0.1, 3), rng.uniform(0.1, 3),
                                 rng.uniform(-math.pi, math.pi), rng.uniform(-math.pi, math.pi)),
    ),
)
