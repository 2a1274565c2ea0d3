"""Chapter 7 · The Jacobian and velocity."""

import math

from ..answer_kinds.expression import FormulaDerive
from ..answer_kinds.matrix import MatrixDerive
from ..kinds.debug import Debug
from ..kinds.derive import Derive, Slip
from ..reference.arm import (
    end_effector_velocity,
    jacobian_2link,
    jacobian_det,
    most_manipulable_theta2,
)
from . import grid

_J = jacobian_2link(1, 1, 0, math.pi / 2)

_BUGGY = """\
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

EXERCISES = (
    Derive(
        id="7.1",
        title="Jacobian at θ = (0, 90°)",
        key=_J[0][0],
        label="J(1,1)",
        slips=(
            Slip(-_J[0][0], "Check the sign, and the entry: J(1,1) = ∂x/∂θ1 = −L1 sin θ1 − L2 sin(θ1+θ2), "
                 "negative here (the derivative of cos is −sin). +1 is J(2,1), the derivative of y."),
        ),
    ),
    Derive(
        id="7.2",
        title="End-effector velocity",
        key=end_effector_velocity(_J, [1, 0])[0],
        label="ẋ",
        unit="m/s",
        slips=(
            Slip(end_effector_velocity(_J, [1, 0])[1], "That is ẏ, from the second row of J. ẋ comes from the first row."),
            Slip(end_effector_velocity(_J, [1, 1])[0], "θ̇2 is 0, so the second column of J contributes nothing."),
        ),
    ),
    Derive(
        id="7.3",
        title="Spot the singularity",
        key=jacobian_det(1, 1, 0, 0),
        label="det J at θ2 = 0",
        slips=(
            Slip(jacobian_det(1, 1, 0, math.pi / 2),
                 "That is det J at θ2 = 90°. det J = L1 L2 sin θ2, and sin 0 = 0."),
            Slip(2.0, "det J = L1 L2 sin θ2, a product with sin θ2, not a sum of lengths."),
        ),
    ),
    Derive(
        id="7.4",
        title="Best elbow angle",
        key=math.degrees(most_manipulable_theta2(1, 1)),
        label="θ2 that maximises w = |det J|",
        unit="°",
        angle="deg",
        slips=(
            Slip(0.0, "At θ2 = 0 the arm is straight and w = 0: that is the worst angle, a singularity."),
            Slip(180.0, "At θ2 = 180° the arm is folded back and w = 0: another singularity."),
            Slip(jacobian_det(1, 1, 0, math.pi / 2), "That is the largest value of w. The question asks for the angle where it happens."),
        ),
    ),
    Debug(
        id="7.5",
        title="Find the bug in the Jacobian",
        code=_BUGGY,
        bug_line=8,
        fixed_line="    J22 = L2 * c12",
        bug=("J(2,2) = ∂y/∂θ2. Only the second link depends on θ2, through y ∋ L2·sin(θ1 + θ2), whose "
             "derivative is L2·cos(θ1 + θ2) = L2·c12. The line uses s12, so ẏ is wrong whenever joint 2 moves."),
        notes={
            1: "imports math for sin and cos",
            2: "takes both link lengths and both joint angles",
            3: "link 1 points at θ1, so its sine and cosine use t1",
            4: "link 2 points at θ1 + θ2, so its terms use the sum",
            5: "correct: ∂x/∂θ1 = −L1 sin θ1 − L2 sin(θ1+θ2)",
            6: "correct: ∂x/∂θ2 = −L2 sin(θ1+θ2), only link 2 depends on θ2",
            7: "correct: ∂y/∂θ1 = L1 cos θ1 + L2 cos(θ1+θ2)",
            9: "returns the rows [∂x/∂θ, ∂y/∂θ] in the right places",
        },
        function="jacobian_2link",
        reference=jacobian_2link,
        cases=((1, 1, 0.0, math.pi / 2), (2, 1, 0.3, 0.4), (1, 1, 0.5, -1.2)),
    ),
    MatrixDerive(
        id="7.6",
        title="The whole Jacobian at θ = (0, 90°)",
        key=grid(_J),
        label="J",
        slips=(
            Slip(grid([_J[0], [_J[1][0], 1 * math.sin(0 + math.pi / 2)]]),
                 "J(2,2) uses sin(θ1 + θ2): that is the bug of exercise 7.5. ∂/∂θ2 of L2 sin(θ1 + θ2) is "
                 "L2 cos(θ1 + θ2) = cos 90° = 0."),
            Slip(grid(jacobian_2link(1, 1, math.pi / 2, 0)),
                 "That is J at θ = (90°, 0): the two joint angles are swapped. Here θ1 = 0 and θ2 = 90°."),
            Slip(grid(jacobian_2link(1, 1, 0, 0)),
                 "That is J of the straight arm, θ2 = 0. Put θ2 = 90° into sin(θ1 + θ2) and cos(θ1 + θ2)."),
        ),
    ),
    FormulaDerive(
        id="7.7",
        title="J(1,1) as a formula",
        key=lambda theta1, theta2, L1, L2: jacobian_2link(L1, L2, theta1, theta2)[0][0],
        variables=("theta1", "theta2", "L1", "L2"),
        domain={"theta1": (-3.0, 3.0), "theta2": (-3.0, 3.0), "L1": (0.2, 2.0), "L2": (0.2, 2.0)},
        answer_text="-L1*sin(theta1) - L2*sin(theta1 + theta2)",
        label="J(1,1) = ∂x/∂θ1",
        slips=(
            Slip(lambda theta1, theta2, L1, L2: -jacobian_2link(L1, L2, theta1, theta2)[0][0],
                 "The sign is flipped: the derivative of cos is −sin."),
            Slip(lambda theta1, theta2, L1, L2: -L1 * math.sin(theta1),
                 "Link 2 moves with θ1 too: its term L2 cos(θ1 + θ2) also depends on θ1, and contributes "
                 "−L2 sin(θ1 + θ2)."),
            Slip(lambda theta1, theta2, L1, L2: jacobian_2link(L1, L2, theta1, theta2)[0][1],
                 "That is J(1,2) = ∂x/∂θ2: only link 2 depends on θ2. J(1,1) differentiates by θ1, which "
                 "moves both links."),
            Slip(lambda theta1, theta2, L1, L2: jacobian_2link(L1, L2, theta1, theta2)[1][0],
                 "That is J(2,1) = ∂y/∂θ1, from the sines of y. J(1,1) differentiates x, the cosines."),
        ),
    ),
)
