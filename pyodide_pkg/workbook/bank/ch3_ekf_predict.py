"""Chapter 3 · EKF prediction step."""

import math

from ..answer_kinds.expression import FormulaDerive
from ..answer_kinds.matrix import MatrixDerive
from ..kinds.debug import Debug
from ..kinds.derive import Derive, Slip
from ..kinds.trace import Option, Trace
from ..reference.ekf import ekf_predict, motion_jacobian, motion_model
from ..reference.linalg import add, matmul, sub, identity, transpose
from . import grid

_P = [[1, 0, 0], [0, 1, 0], [0, 0, 0.1]]
_Q = [[0.01, 0, 0], [0, 0.01, 0], [0, 0, 0.001]]
_P_PRED = ekf_predict((0, 0, 0), _P, 1, 0, 1, _Q)[1]
_F0 = motion_jacobian((0, 0, 0), 1, 0, 1)  # exercise 3.4's F
_ZERO = [[0.0] * 3 for _ in range(3)]
_F_NORTH = motion_jacobian((0, 0, math.pi / 2), 2, 0, 0.5)  # exercise 3.7


def _predict_pose(x, y, theta, v, omega, dt):
    """The correct answer to exercise 3.5, as a flat tuple."""
    return motion_model((x, y, theta), v, omega, dt)


EXERCISES = (
    Derive(
        id="3.1",
        title="Predict the new position",
        key=motion_model((0, 0, 0), 1, 0, 1)[0],
        label="x (m)",
        unit="m",
        slips=(Slip(0.0, "That is y (or you used sin for x). Facing east, all the motion goes into x: cos 0 = 1."),),
    ),
    Derive(
        id="3.2",
        title="Predict at a heading",
        key=motion_model((0, 0, math.pi / 4), 2, 0, 0.5)[1],
        label="y (m)",
        unit="m",
        slips=(Slip(2 * math.sin(math.pi / 4),
                    "You left out dt. The robot drives for 0.5 s, so it covers v·dt = 1 m, not 2 m."),),
    ),
    Derive(
        id="3.3",
        title="An entry of the Jacobian F",
        key=motion_jacobian((0, 0, math.pi / 2), 1, 0, 0.5)[0][2],
        label="F(1,3)",
        slips=(
            Slip(-1.0, "You left out dt: F(1,3) = −v·sinθ·dt, and dt = 0.5."),
            Slip(0.0, "That uses cos θ. Differentiating v·cosθ·dt with respect to θ gives −v·sinθ·dt."),
        ),
    ),
    Derive(
        id="3.4",
        title="Predict the covariance",
        key=_P_PRED[0][0],
        label="P⁻(1,1)",
        slips=(
            Slip(_P_PRED[1][1], "That is P⁻(2,2), the y variance. The question asks for the top-left entry."),
            Slip(1.0, "That is F P Fᵀ alone. Add the process noise Q: its (1,1) entry is 0.01."),
        ),
    ),
    Debug(
        id="3.5",
        title="Find the bug",
        code=(
            "import math\n"
            "def ekf_predict_pose(x, y, theta, v, omega, dt):\n"
            "    x_new = x + v * math.cos(theta) * dt\n"
            "    y_new = y + v * math.cos(theta) * dt\n"
            "    theta_new = theta + omega * dt\n"
            "    return (x_new, y_new, theta_new)\n"
        ),
        bug_line=4,
        fixed_line="    y_new = y + v * math.sin(theta) * dt",
        bug=("The y update uses cos θ where it needs sin θ. Facing north (θ = π/2) both cos terms vanish, "
             "so the robot never moves; facing east it climbs in y as fast as it moves in x. "
             "Fix: y_new = y + v * math.sin(theta) * dt."),
        notes={
            1: "imports math for cos and sin",
            2: "takes the pose and the controls",
            3: "correct: x moves by v·cosθ·dt",
            5: "correct: the heading turns by ω·dt",
            6: "returns the new pose",
        },
        function="ekf_predict_pose",
        reference=_predict_pose,
        cases=(
            (0.0, 0.0, math.pi / 2, 1.0, 0.0, 1.0),
            (0.0, 0.0, 0.0, 1.0, 0.0, 1.0),
            (5.0, 3.0, math.pi / 6, 1.0, 0.1, 1.0),
            (1.0, -2.0, -math.pi / 3, 2.0, 0.5, 0.5),
        ),
    ),
    Trace(
        id="3.6",
        title="The diagonal of F",
        answer="b",
        options=(
            Option("a", "Because the robot moves with constant speed",
                   "Constant speed is not needed: even with v changing from step to step, ∂x'/∂x stays 1. "
                   "The diagonal comes from the form of the model, not from v."),
            Option("b", "Because each new coordinate is the old one plus a change, e.g. $x' = x + \\Delta x$",
                   "Right. The velocity model adds a displacement to each coordinate, and the displacement does "
                   "not depend on x, y (only on θ), so ∂x'/∂x = ∂y'/∂y = ∂θ'/∂θ = 1 and F = I plus off-diagonal terms."),
            Option("c", "Because F is a rotation matrix, and those have ones on the diagonal",
                   "F is not a rotation, and rotations have cos θ on their diagonal, not 1."),
            Option("d", "Because dt is small, so the nonlinear terms round to zero",
                   "Nothing is rounded: the ones are exact for any dt. The dt-dependent terms sit off the diagonal, "
                   "in the θ column."),
        ),
    ),
    MatrixDerive(
        id="3.7",
        title="The whole Jacobian F facing north",
        key=grid(_F_NORTH),
        label="F",
        slips=(
            Slip(grid(motion_jacobian((0, 0, 0), 2, 0, 0.5)),
                 "That is F at θ = 0 (or sin and cos swapped). Facing north, sin θ = 1 and cos θ = 0: the "
                 "heading column is (−v·dt, 0, 1)."),
            Slip(grid(motion_jacobian((0, 0, math.pi / 2), 2, 0, 1)),
                 "You left out dt: F(1,3) = −v·sin θ·dt = −2 · 1 · 0.5."),
            Slip(grid(sub(_F_NORTH, identity(3))),
                 "That is the derivative of the displacement alone. x′ = x + v cos θ dt also contains x itself, "
                 "so F carries the identity on its diagonal."),
            Slip(grid(motion_jacobian((0, 0, -math.pi / 2), 2, 0, 0.5)),
                 "The sign of F(1,3) is flipped: the derivative of cos θ is −sin θ, so F(1,3) = −v sin θ dt."),
        ),
    ),
    MatrixDerive(
        id="3.8",
        title="The whole predicted covariance",
        key=grid(_P_PRED),
        label="P⁻ = F P Fᵀ + Q",
        slips=(
            Slip(grid(ekf_predict((0, 0, 0), _P, 1, 0, 1, _ZERO)[1]),
                 "That is F P Fᵀ without the process noise. Add Q: the motion itself is uncertain."),
            Slip(grid(add(_P, _Q)),
                 "That is P + Q: you left F out. F passes the heading uncertainty into y, which is where the "
                 "off-diagonal terms come from."),
            Slip(grid(add(matmul(matmul(transpose(_F0), _P), _F0), _Q)),
                 "That is Fᵀ P F + Q, the product in the wrong order. The covariance is pushed forward as "
                 "F P Fᵀ."),
        ),
    ),
    FormulaDerive(
        id="3.9",
        title="F(1,3) as a formula",
        key=lambda v, theta, dt: motion_jacobian((0.0, 0.0, theta), v, 0.0, dt)[0][2],
        variables=("v", "theta", "dt"),
        domain={"v": (0.2, 3.0), "theta": (-3.0, 3.0), "dt": (0.05, 1.0)},
        answer_text="-v*sin(theta)*dt",
        label="F(1,3)",
        slips=(
            Slip(lambda v, theta, dt: v * math.sin(theta) * dt,
                 "The sign is flipped: the derivative of cos θ is −sin θ."),
            Slip(lambda v, theta, dt: -v * math.cos(theta) * dt,
                 "That differentiates to cos θ. x′ contains v cos θ dt, whose derivative by θ is −v sin θ dt."),
            Slip(lambda v, theta, dt: -v * math.sin(theta),
                 "You left out dt: the robot drives for dt seconds, so every displacement carries a factor dt."),
            Slip(lambda v, theta, dt: v * math.cos(theta) * dt,
                 "That is F(2,3), the derivative of y′. F(1,3) is the derivative of x′ = x + v cos θ dt."),
        ),
    ),
)
