"""Chapter 6 · Two-link arm: forward and inverse kinematics."""

import math

from ..answer_kinds.expression import FormulaDerive
from ..kinds.build import Build
from ..kinds.derive import Derive, Slip
from ..kinds.trace import Option, Trace
from ..reference.arm import (
    cos_elbow,
    forward_kinematics_2link,
    inverse_kinematics_2link,
    is_reachable,
)

_T1, _T2 = math.radians(30), math.radians(45)

# Exercise 6.4: the arm L1 = 2, L2 = 1 reaches the annulus 1 ≤ r ≤ 3.
_ARM = (2, 1)
_TARGETS = {"a": (3, 0), "b": (1, 0), "c": (2, 1), "d": (3, 1)}
_UNREACHABLE = [k for k, (x, y) in _TARGETS.items() if not is_reachable(*_ARM, x, y)]
assert _UNREACHABLE == ["d"], _UNREACHABLE

EXERCISES = (
    Derive(
        id="6.1",
        title="FK of the straight arm",
        key=forward_kinematics_2link(1, 1, 0, 0)[0],
        label="x-coordinate of the end effector",
        unit="m",
        slips=(Slip(1.0, "That is the elbow, the end of link 1. Add link 2, which also points along x."),),
    ),
    Derive(
        id="6.2",
        title="FK of a bent arm",
        key=forward_kinematics_2link(1, 1, _T1, _T2)[0],
        label="x-coordinate of the end effector",
        unit="m",
        slips=(
            Slip(math.cos(_T1) + math.cos(_T2),
                 "You used cos 45° for link 2. Its direction is θ1 + θ2 = 75°: joint angles add up along the chain."),
            Slip(forward_kinematics_2link(1, 1, _T1, _T2)[1], "That is the y-coordinate. For x use the cosines."),
            Slip(math.cos(_T1 + _T2), "That is link 2's share alone. Add link 1's L1·cos θ1 = 0.8660."),
        ),
    ),
    Derive(
        id="6.3",
        title="IK: the elbow angle",
        key=math.degrees(inverse_kinematics_2link(1, 1, 1, 1).elbow_down[1]),
        label="θ2 (elbow-down, θ2 ≥ 0)",
        unit="°",
        angle="deg",
        slips=(
            Slip(cos_elbow(1, 1, 1, 1), "That is cos θ2. The angle whose cosine is 0 is what is asked."),
            Slip(math.degrees(inverse_kinematics_2link(1, 1, 1, 1).elbow_up[1]),
                 "−90° is a valid pose too: the elbow-up solution. This exercise asks for the elbow-down one, θ2 ≥ 0."),
            Slip(45.0, "45° is the direction of the target, atan2(1, 1); it goes into θ1, not θ2."),
        ),
    ),
    Trace(
        id="6.4",
        title="Workspace boundary",
        answer=_UNREACHABLE[0],
        options=(
            Option("a", "$(3, 0)$",
                   "Reachable, just: it is exactly $L_1 + L_2 = 3$ away, so the arm reaches it fully stretched. "
                   "The boundary belongs to the workspace, with a single IK solution."),
            Option("b", "$(1, 0)$",
                   "Reachable, just: it is exactly $|L_1 - L_2| = 1$ away, the inner edge, reached with the elbow folded back "
                   "($\\theta_2 = 180°$)."),
            Option("c", "$(2, 1)$",
                   "Reachable: $\\sqrt{4 + 1} \\approx 2.24$ lies between 1 and 3, inside the annulus, so there are two "
                   "elbow solutions."),
            Option("d", "$(3, 1)$",
                   "Right. $\\sqrt{9 + 1} = \\sqrt{10} \\approx 3.16 > L_1 + L_2 = 3$: beyond full stretch. "
                   "$\\cos\\theta_2$ would come out above 1, which no angle has."),
        ),
    ),
    Build(
        id="6.5",
        title="Implement forward_kinematics_2link",
        function="forward_kinematics_2link",
        params=("L1", "L2", "theta1", "theta2"),
        starter=(
            "import math\n\n\n"
            "def forward_kinematics_2link(L1, L2, theta1, theta2):\n"
            '    """Tip position (x, y) of a two-link planar arm; angles in radians."""\n'
            "    # Your code here: add up the two links, each at its own angle.\n"
            "    return (L1 + L2, 0.0)\n"
        ),
        solution=(
            "import math\n\n\n"
            "def forward_kinematics_2link(L1, L2, theta1, theta2):\n"
            '    """Tip position (x, y) of a two-link planar arm; angles in radians."""\n'
            "    phi = theta1 + theta2  # direction of link 2\n"
            "    x = L1 * math.cos(theta1) + L2 * math.cos(phi)\n"
            "    y = L1 * math.sin(theta1) + L2 * math.sin(phi)\n"
            "    return (x, y)\n"
        ),
        reference=forward_kinematics_2link,
        examples=((1, 1, 0.0, 0.0), (1, 1, _T1, _T2), (1, 1, 0.0, math.pi / 2), (2, 1, math.pi / 2, math.pi)),
        random_args=lambda rng: (rng.uniform(0.1, 3), rng.uniform(0.1, 3),
                                 rng.uniform(-math.pi, math.pi), rng.uniform(-math.pi, math.pi)),
    ),
    FormulaDerive(
        id="6.6",
        title="FK as a formula",
        key=lambda theta1, theta2, L1, L2: forward_kinematics_2link(L1, L2, theta1, theta2)[0],
        variables=("theta1", "theta2", "L1", "L2"),
        domain={"theta1": (-3.0, 3.0), "theta2": (-3.0, 3.0), "L1": (0.2, 2.0), "L2": (0.2, 2.0)},
        answer_text="L1*cos(theta1) + L2*cos(theta1 + theta2)",
        label="x(θ1, θ2)",
        slips=(
            Slip(lambda theta1, theta2, L1, L2: L1 * math.cos(theta1) + L2 * math.cos(theta2),
                 "Link 2 points at θ1 + θ2, not θ2: θ2 is measured from link 1, so the angles add up along "
                 "the chain."),
            Slip(lambda theta1, theta2, L1, L2: forward_kinematics_2link(L1, L2, theta1, theta2)[1],
                 "That is y(θ1, θ2), with sines. The x-coordinate uses cosines."),
            Slip(lambda theta1, theta2, L1, L2: (L1 + L2) * math.cos(theta1 + theta2),
                 "That puts both links at θ1 + θ2. Link 1 points at θ1 alone."),
        ),
    ),
)
