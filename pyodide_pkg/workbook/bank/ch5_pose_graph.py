"""Chapter 5 · Pose-graph SLAM."""

import math

from ..answer_kinds.matrix import MatrixDerive
from ..kinds.derive import Derive, Slip
from ..kinds.trace import Option, Trace
from ..reference.linalg import det2
from ..reference.pose_graph import (
    edge_error_relative,
    edge_error_simple,
    gauss_newton_size,
    information_matrix,
    pose_graph_variables,
    relative_pose,
)
from . import column, grid

_X1 = (0.0, 0.0, 0.0)
_X2 = (1.1, 0.05, 0.02)
_Z12 = (1.0, 0.0, 0.0)
_SIGMA = [[0.01, 0, 0], [0, 0.01, 0], [0, 0, 0.001]]
# Exercise 5.6: the same motion as 5.2, seen from a pose at (2, 1) facing north.
_XI = (2.0, 1.0, math.pi / 2)
_XJ = (1.95, 2.1, math.pi / 2 + 0.02)
# Exercise 5.7: a scan match whose x and y errors are correlated.
_SIGMA_C = [[0.02, 0.01, 0], [0.01, 0.02, 0], [0, 0, 0.001]]
_DET_XY = det2([row[:2] for row in _SIGMA_C[:2]])

EXERCISES = (
    Derive(
        id="5.1",
        title="Count the unknowns",
        key=pose_graph_variables(100, pose_dof=3),
        label="number of optimisation variables",
        unit="variables",
        slips=(
            Slip(100, "That counts poses, not numbers. Each planar pose carries three unknowns: x, y and θ."),
            Slip(pose_graph_variables(100, pose_dof=6),
                 "Six per pose is the 3D case. A planar pose has only x, y and θ."),
        ),
    ),
    Derive(
        id="5.2",
        title="Odometry edge error",
        key=edge_error_simple(_X1, _X2, _Z12)[0],
        label="x-component of e = z₁₂ − (x₂ − x₁)",
        unit="m",
        slips=(
            Slip(-edge_error_simple(_X1, _X2, _Z12)[0],
                 "The sign is flipped: you computed (x₂ − x₁) − z₁₂. The error is measurement minus prediction."),
            Slip(_X2[0] - _X1[0], "That is the pose difference x₂ − x₁ alone. Subtract it from the odometry reading z₁₂."),
        ),
    ),
    Derive(
        id="5.3",
        title="Information matrix",
        key=information_matrix(_SIGMA)[0][0],
        label="Ω(1,1), the (1,1) entry of Σ⁻¹",
        slips=(
            Slip(_SIGMA[0][0], "That is Σ(1,1), the covariance itself. The information matrix is its inverse, Ω = Σ⁻¹."),
            Slip(information_matrix(_SIGMA)[2][2],
                 "That is Ω(3,3), the heading entry. The (1,1) entry belongs to x."),
        ),
    ),
    Trace(
        id="5.4",
        title="What a loop closure does",
        answer="c",
        options=(
            Option("a", "Pose $x_{50}$ jumps onto $x_1$; every other pose stays where it was",
                   "That satisfies the new edge but tears the odometry edge between $x_{49}$ and $x_{50}$ wide open. "
                   "The optimiser minimises the cost of all edges, so one large error is not what it settles on."),
            Option("b", "Only $x_1$ and $x_{50}$ move, meeting halfway",
                   "The two end poses are tied to their neighbours by odometry edges; moving them alone would load "
                   "all the error onto those two edges. The neighbours follow, and their neighbours too."),
            Option("c", "Every pose from $x_1$ to $x_{50}$ shifts a little, spreading the accumulated drift",
                   "Right. Gauss–Newton solves for all poses at once; the drift the loop closure reveals is shared "
                   "out along the chain, so each odometry edge takes a small error instead of one edge taking a huge one."),
            Option("d", "Nothing: the new edge contradicts 49 odometry edges and is outvoted",
                   "Edges are not votes. The loop-closure edge adds its own term to the cost, and the optimum balances "
                   "it against the odometry terms according to their information matrices."),
        ),
    ),
    Derive(
        id="5.5",
        title="Size of the Gauss–Newton system",
        key=gauss_newton_size(1000, 6, 500, 3),
        label="rows (= columns) of H",
        slips=(
            Slip(gauss_newton_size(1000, 6),
                 "That counts the poses only. In full SLAM the 500 landmarks are unknowns too, 3 numbers each."),
            Slip(gauss_newton_size(1000, 3, 500, 3),
                 "A 3D pose has 6 degrees of freedom (x, y, z, roll, pitch, yaw), not 3."),
            Slip(gauss_newton_size(1000, 6, 500, 3) ** 2,
                 "That is the number of entries of H. The question asks for its side: one row per unknown."),
            Slip(1500, "That counts the landmarks only. Add the 1000 poses, 6 numbers each."),
        ),
    ),
    MatrixDerive(
        id="5.6",
        title="Edge error from a turned pose",
        key=column(edge_error_relative(_XI, _XJ, _Z12)),
        label="e₁₂ = (eₓ, e_y, e_θ)ᵀ",
        slips=(
            Slip(column(edge_error_simple(_XI, _XJ, _Z12)),
                 "You subtracted the poses in world axes. Odometry measures the motion in pose 1's frame, and "
                 "pose 1 faces north: turn x₂ − x₁ into that frame first (its forward axis is the world's +y)."),
            Slip(column([-v for v in edge_error_relative(_XI, _XJ, _Z12)]),
                 "The sign is flipped: that is prediction minus measurement. The error is z₁₂ − h, measured "
                 "minus predicted."),
            Slip(column(relative_pose(_XI, _XJ)),
                 "That is h, the motion the poses imply, seen from pose 1. The error subtracts it from the "
                 "odometry reading z₁₂."),
        ),
    ),
    MatrixDerive(
        id="5.7",
        title="Information from a correlated covariance",
        key=grid(information_matrix(_SIGMA_C)),
        label="Ω = Σ⁻¹",
        slips=(
            Slip(grid([[1 / _SIGMA_C[i][i] if i == j else 0.0 for j in range(3)] for i in range(3)]),
                 "You inverted the diagonal alone. With the correlation 0.01 between x and y, the 2×2 block has "
                 "to be inverted as a whole: 1/det times [[d, −b], [−c, a]]."),
            Slip(grid([[1 / v if v else 0.0 for v in row] for row in _SIGMA_C]),
                 "You took the reciprocal of each entry. The inverse of a matrix is not entry by entry: invert "
                 "the x–y block as a whole, then the θ entry on its own."),
            Slip(grid([[v / _DET_XY if i < 2 and j < 2 else (1 / v if i == j else 0.0)
                        for j, v in enumerate(row)] for i, row in enumerate(_SIGMA_C)]),
                 "The off-diagonal entries have the wrong sign. The inverse of [[a, b], [c, d]] is "
                 "[[d, −b], [−c, a]] / (ad − bc): swap the diagonal and negate the off-diagonal."),
        ),
    ),
)
