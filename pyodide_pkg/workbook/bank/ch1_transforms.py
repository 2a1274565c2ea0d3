"""Chapter 1 · Homogeneous transforms."""

import math

from ..answer_kinds.matrix import MatrixDerive
from ..kinds.derive import Derive, Slip
from ..kinds.design import Design, Step
from ..kinds.trace import Option, Trace
from ..reference.linalg import matvec, transpose
from ..reference.transform2d import apply, chain, inverse_transform, transform2d
from . import grid

_T_WORLD_BASE = transform2d(0, 1, 0)
_T_BASE_TOOL = transform2d(2, 0, math.pi / 2)
_T12 = transform2d(2, 1, math.pi / 2)  # exercise 1.2's robot pose
_RT = transpose([row[:2] for row in _T12[:2]])
_RT_t = matvec(_RT, [_T12[0][2], _T12[1][2]])


def _with(rot, t):
    """[[rot, t], [0, 1]] as a 3×3 key."""
    return grid([[*rot[0], t[0]], [*rot[1], t[1]], [0.0, 0.0, 1.0]])

EXERCISES = (
    Derive(
        id="1.1",
        title="Pure translation",
        key=apply(transform2d(3, 4, 0), 1, 0)[0],
        label="x-coordinate in the world frame",
        slips=(
            Slip(1.0, "That is the point in the robot frame. The robot sits at (3, 4), so add its position."),
            Slip(3.0, "That is the robot's own x. The point is 1 m ahead of it: add the point too."),
        ),
    ),
    Derive(
        id="1.2",
        title="Rotation plus translation",
        key=apply(transform2d(2, 1, math.pi / 2), 1, 0)[1],
        label="y-coordinate in the world frame",
        slips=(
            Slip(1.0, "You left something out: turning (1, 0) by 90° alone gives y = 1, and shifting it by (2, 1) "
                      "without turning also gives y = 1. T rotates first, then adds t."),
            Slip(apply(transform2d(2, 1, -math.pi / 2), 1, 0)[1],
                 "That is a clockwise turn. A heading of +90° turns the robot's x-axis onto the world's +y."),
        ),
    ),
    Derive(
        id="1.3",
        title="Chain two transforms",
        key=apply(chain(_T_WORLD_BASE, _T_BASE_TOOL), 1, 0)[0],
        label="x-coordinate in the world frame",
        slips=(
            Slip(apply(chain(_T_BASE_TOOL, _T_WORLD_BASE), 1, 0)[0],
                 "The order is reversed. Apply the tool-to-base transform to the point first, then base-to-world."),
            Slip(3.0, "You added the offsets but skipped the tool frame's 90° turn: (1, 0) in the tool frame "
                      "points along the base's y-axis."),
        ),
    ),
    Trace(
        id="1.4",
        title="Invert a transform",
        answer="c",
        options=(
            Option("a", "Multiply the world point by $T^\\top$",
                   "The transpose undoes a pure rotation only. $T^\\top$ moves the translation into the bottom row, "
                   "so it is not even a valid transform."),
            Option("b", "Subtract the robot's position $t$ from the point",
                   "That undoes the shift but not the turn: the difference is still expressed along the world "
                   "axes, not the robot's."),
            Option("c", "Multiply by $T^{-1} = \\begin{bmatrix} R^\\top & -R^\\top t \\\\ 0 & 1 \\end{bmatrix}$",
                   "Right. Undo the shift, then the turn: $R^\\top(p - t) = R^\\top p - R^\\top t$. It costs a "
                   "transpose and one matrix–vector product, no general inversion."),
            Option("d", "Multiply by $T$ a second time",
                   "That moves the point one more robot pose further away from the robot frame, rather than back."),
        ),
    ),
    Design(
        id="1.5",
        title="A LiDAR-to-world pipeline",
        steps=(
            Step("lidar", "The pedestrian in the LiDAR frame, ${}^{\\text{lidar}}p$"),
            Step("car", "Apply ${}^{\\text{car}}T_{\\text{lidar}}$ (LiDAR to car)"),
            Step("world", "Apply ${}^{\\text{world}}T_{\\text{car}}$ (car to world)"),
            Step("out", "The pedestrian in the world (GPS) frame, ${}^{\\text{world}}p$"),
        ),
        shown=("world", "out", "lidar", "car"),
    ),
    MatrixDerive(
        id="1.6",
        title="The inverse transform, whole",
        key=grid(inverse_transform(_T12)),
        label="T⁻¹",
        slips=(
            Slip(_with(_RT, [-_T12[0][2], -_T12[1][2]]),
                 "The rotation block is right, but the translation is −t, the robot's position negated in world "
                 "axes. T⁻¹ needs it in the robot's own axes: −Rᵀt."),
            Slip(_with(_RT, _RT_t),
                 "The translation has the wrong sign: it is −Rᵀt. Check with the robot's own position: "
                 "T⁻¹ must send (2, 1) to the origin."),
            Slip(_with([row[:2] for row in _T12[:2]], [-_T12[0][2], -_T12[1][2]]),
                 "Negating the translation is not enough: the turn must be undone too, so the rotation block is "
                 "Rᵀ, and the translation becomes −Rᵀt."),
            Slip(grid(_T12), "That is T itself, the robot's pose. The question asks for the transform that undoes it."),
        ),
    ),
)
