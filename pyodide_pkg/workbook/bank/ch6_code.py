"""Chapter 6 · Code the robot: two-link inverse kinematics with an elbow choice, refusing the unreachable."""

import math

from ..kinds.build import Build
from ..reference.arm import forward_kinematics_2link, ik_2link

_SOLUTION = '''import math


def ik_2link(L1, L2, x, y, elbow_up):
    """Joint angles (theta1, theta2) putting the tip at (x, y); None when out of reach."""
    r = math.hypot(x, y)
    if r > L1 + L2 + 1e-9 or r < abs(L1 - L2) - 1e-9:
        return None  # farther than L1 + L2, or nearer than |L1 - L2|
    c2 = (x * x + y * y - L1 * L1 - L2 * L2) / (2 * L1 * L2)
    c2 = max(-1.0, min(1.0, c2))  # round-off at the edge can put c2 a hair past 1 or -1
    theta2 = math.acos(c2)
    if elbow_up:
        theta2 = -theta2
    theta1 = math.atan2(y, x) - math.atan2(L2 * math.sin(theta2), L1 + L2 * math.cos(theta2))
    theta1 = math.atan2(math.sin(theta1), math.cos(theta1))  # into [-pi, pi]
    return (theta1, theta2)
'''


def _target(rng):
    L1, L2 = rng.uniform(0.3, 2), rng.uniform(0.3, 2)
    up = rng.random() < 0.5
    if rng.random() < 0.7:
        t2 = rng.uniform(0.2, 2.9) * rng.choice((-1, 1))
        x, y = forward_kinematics_2link(L1, L2, rng.uniform(-math.pi, math.pi), t2)
    else:
        far = abs(L1 - L2) < 0.1 or rng.random() < 0.6
        r = L1 + L2 + rng.uniform(0.05, 1) if far else abs(L1 - L2) * rng.uniform(0, 0.9)
        a = rng.uniform(-math.pi, math.pi)
        x, y = r * math.cos(a), r * math.sin(a)
    return (L1, L2, x, y, up)


EXERCISES = (
    Build(
        id="6.7",
        title="Code the robot: ik_2link",
        function="ik_2link",
        params=("L1", "L2", "x", "y", "elbow_up"),
        starter=(
            "import math\n\n\n"
            "def ik_2link(L1, L2, x, y, elbow_up):\n"
            '    """Joint angles (theta1, theta2) putting the tip at (x, y); None when out of reach."""\n'
            "    # Your code here: the elbow from the law of cosines, then the shoulder.\n"
            "    return (math.atan2(y, x), 0.0)\n"
        ),
        solution=_SOLUTION,
        reference=ik_2link,
        run_figure="ik",
        examples=(
            (1, 1, 1, 1, True),
            (1, 1, 1, 1, False),
            (2, 1, 2, 1, False),
            (2, 1, 3, 1, True),
        ),
        edge_cases=(
            (1, 1, 2, 0, True),  # full stretch: both elbows give (0, 0)
            (2, 1, -1, 0, False),  # folded back at the inner edge: theta2 = π
            (1, 1, -1.5, -0.3, False),  # theta1 past −π before it is wrapped
            (2, 1, 0.5, 0, True),  # inside the hole of the workspace: None
            (1, 1, 0, 2.5, False),  # too far: None
            (0.3, 0.7, 0.6, 0.8, False),  # on the outer edge, where c2 comes out 1 + 2e-16 in floats: reachable
            (1.3, 0.3, -1, 0, True),  # on the inner edge behind the base: c2 = -1 - 2e-16, theta1 a half-turn
            (1, 1, -2, -0.0, True),  # stretched straight back: theta1 a half-turn, π or −π
        ),
        angles=("[0]", "[1]"),
        random_args=_target,
    ),
)
