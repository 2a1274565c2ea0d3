"""Chapter 4 · EKF update step."""

import math

from ..answer_kinds.expression import FormulaDerive
from ..answer_kinds.matrix import MatrixDerive
from ..kinds.build import Build
from ..kinds.derive import Derive, Slip
from ..kinds.trace import Option, Trace
from ..reference.ekf import ekf_update, measurement_jacobian, range_bearing
from . import grid

_POSE = (0, 0, 0)
_LANDMARK = (3, 4)
_H_PRED = range_bearing(_POSE, _LANDMARK)
_Z = (4.8, 0.95)
_H = measurement_jacobian(_POSE, _LANDMARK)
_DX, _DY = _LANDMARK[0] - _POSE[0], _LANDMARK[1] - _POSE[1]
_SQ = _DX * _DX + _DY * _DY

EXERCISES = (
    Derive(
        id="4.1",
        title="Predicted range",
        key=_H_PRED[0],
        label="r (m)",
        unit="m",
        slips=(Slip(25.0, "That is q = dx² + dy², the squared range. Take its square root."),),
    ),
    Derive(
        id="4.2",
        title="Predicted bearing",
        key=math.degrees(_H_PRED[1]),
        label="φ (degrees)",
        unit="°",
        angle="deg",
        periodic=True,  # a bearing: 413.13° points the same way
        slips=(
            Slip(math.degrees(math.atan2(3, 4)),
                 "The arguments are swapped. atan2 takes (dy, dx): atan2(4, 3), measured from the x-axis."),
        ),
    ),
    Derive(
        id="4.3",
        title="An entry of H",
        key=measurement_jacobian(_POSE, _LANDMARK)[0][0],
        label="H(1,1)",
        slips=(
            Slip(measurement_jacobian(_POSE, _LANDMARK)[0][1],
                 "That is H(1,2) = −dy/√q, the derivative with respect to y. H(1,1) uses dx."),
            Slip(-3 / 25, "You divided by q. The range row divides by √q = 5; it is the bearing row that divides by q."),
        ),
    ),
    Derive(
        id="4.4",
        title="The innovation",
        key=_Z[0] - _H_PRED[0],
        label="range innovation (m)",
        unit="m",
        slips=(
            Slip(_H_PRED[0] - _Z[0],
                 "The sign is flipped. The innovation is z − h(x): measured minus predicted."),
            Slip(_Z[1] - _H_PRED[1],
                 "That is the bearing innovation, the second component. The range is the first."),
        ),
    ),
    Build(
        id="4.5",
        title="Implement ekf_update",
        function="ekf_update",
        params=("x", "P", "z", "R"),
        starter=(
            "def ekf_update(x, P, z, R):\n"
            '    """Scalar Kalman update with h(x) = x; return (x_new, P_new)."""\n'
            "    # Your code here: the gain K, then the new state and covariance.\n"
            "    return (x, P)\n"
        ),
        solution=(
            "def ekf_update(x, P, z, R):\n"
            '    """Scalar Kalman update with h(x) = x; return (x_new, P_new)."""\n'
            "    K = P / (P + R)\n"
            "    return (x + K * (z - x), (1 - K) * P)\n"
        ),
        reference=ekf_update,
        examples=((5.866, 0.5, 5.7, 0.2), (0.0, 1.0, 1.0, 1.0), (2.0, 1.0, 3.0, 0.0), (10.0, 0.1, 12.0, 2.0)),
        random_args=lambda rng: (rng.uniform(-10, 10), rng.uniform(0.01, 5), rng.uniform(-10, 10), rng.uniform(0.01, 5)),
    ),
    Trace(
        id="4.6",
        title="The gain at the extremes",
        answer="a",
        options=(
            Option("a", "$K \\to 1$: the update returns the measurement, $x^+ = z$",
                   "Right. $K = P/(P+R) \\to P/P = 1$, so $x^+ = x^- + (z - x^-) = z$: a perfect sensor overrides "
                   "the prediction. At the other end, $R \\to \\infty$ gives $K \\to 0$."),
            Option("b", "$K \\to 0$: the measurement is ignored",
                   "That is the opposite extreme, $R \\to \\infty$: a useless sensor. With $R \\to 0$ the "
                   "denominator shrinks to $P$."),
            Option("c", "$K \\to 0.5$: prediction and measurement are averaged",
                   "An even split happens when $P = R$, when both are equally trusted, not when the sensor "
                   "is perfect."),
            Option("d", "$K$ grows without bound",
                   "$K = P/(P+R)$ never exceeds 1 while $P, R \\ge 0$; at $R = 0$ it is exactly 1."),
        ),
    ),
    MatrixDerive(
        id="4.7",
        title="The whole measurement Jacobian H",
        key=grid(_H),
        label="H",
        slips=(
            Slip(grid([[h / _SQ ** 0.5 for h in _H[0]], _H[1]]),
                 "The range row divides by q. Differentiating √q gives 1/(2√q) times the derivative of q, so "
                 "the range row divides by √q = 5 (only the bearing row divides by q)."),
            Slip(grid([_H[0], [_DY / _SQ ** 0.5, -_DX / _SQ ** 0.5, -1.0]]),
                 "The bearing row divides by √q. The derivative of atan2(dy, dx) divides by q = dx² + dy² = 25."),
            Slip(grid([_H[0], [_H[1][0], _H[1][1], 0.0]]),
                 "H(2,3) is not 0: the bearing is φ = atan2(dy, dx) − θ, so turning the robot by δθ changes "
                 "it by −δθ."),
            Slip(grid([[-h for h in _H[0]], [-_H[1][0], -_H[1][1], _H[1][2]]]),
                 "The x and y columns have the wrong sign: you differentiated by the landmark's position. "
                 "dx = lx − x, so moving the robot by +δx shrinks dx."),
        ),
    ),
    FormulaDerive(
        id="4.8",
        title="H(2,1) as a formula",
        key=lambda dx, dy: measurement_jacobian((0.0, 0.0, 0.0), (dx, dy))[1][0],
        variables=("dx", "dy"),
        domain={"dx": (0.5, 5.0), "dy": (0.5, 5.0)},
        answer_text="dy/(dx^2 + dy^2)",
        label="H(2,1) = ∂φ/∂x",
        slips=(
            Slip(lambda dx, dy: -dy / (dx * dx + dy * dy),
                 "The sign is flipped. dx = lx − x, so ∂dx/∂x = −1, and that minus cancels the one in "
                 "∂atan2(dy, dx)/∂dx = −dy/q."),
            Slip(lambda dx, dy: dy / (dx * dx + dy * dy) ** 0.5,
                 "That divides by √q, as the range row does. The derivative of atan2 divides by q = dx² + dy²."),
            Slip(lambda dx, dy: -dx / (dx * dx + dy * dy),
                 "That is H(2,2) = ∂φ/∂y. The x-derivative has dy on top."),
            Slip(lambda dx, dy: -dx / (dx * dx + dy * dy) ** 0.5,
                 "That is H(1,1) = ∂r/∂x, from the range row. The bearing row is the second one."),
        ),
    ),
)
