"""Chapter 5 · Pose-graph SLAM."""

from ..kinds.derive import Derive, Slip
from ..kinds.trace import Option, Trace
from ..reference.pose_graph import (
    edge_error_simple,
    gauss_newton_size,
    information_matrix,
    pose_graph_variables,
)

_X1 = (0.0, 0.0, 0.0)
_X2 = (1.1, 0.05, 0.02)
_Z12 = (1.0, 0.0, 0.0)
_SIGMA = [[0.01, 0, 0], [0, 0.01, 0], [0, 0, 0.001]]

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
)
