"""The SE(2) edge Jacobians of pose-graph SLAM, written out (chapter 5, exercise 5.9).

The edge error here is the subtraction form of exercise 5.6,
e = z − h with h = xi⁻¹ ⊕ xj = (R(θi)ᵀ (tj − ti), θj − θi), the angle wrapped.
Its Jacobians with respect to the two poses are

    A = ∂e/∂xi = [[ R(θi)ᵀ,  −R'(θi)ᵀ (tj − ti) ],      B = ∂e/∂xj = [[ −R(θi)ᵀ, 0 ],
                  [ 0  0,     1                 ]]                    [ 0  0,    −1 ]]

with R'(θ)ᵀ = d R(θ)ᵀ / dθ = [[−sin θ, cos θ], [−cos θ, −sin θ]]. The measurement z
enters e as a constant, so neither Jacobian depends on it.
"""

from __future__ import annotations

import math

from .linalg import Matrix
from .pose_graph import Pose


def rotation_transpose(theta: float) -> Matrix:
    """R(θ)ᵀ, which turns a world offset into the frame of a pose facing θ.

    >>> [[round(v, 4) + 0.0 for v in row] for row in rotation_transpose(math.pi / 2)]
    [[0.0, 1.0], [-1.0, 0.0]]
    """
    c, s = math.cos(theta), math.sin(theta)
    return [[c, s], [-s, c]]


def rotation_transpose_derivative(theta: float) -> Matrix:
    """R'(θ)ᵀ = d R(θ)ᵀ / dθ: each entry of R(θ)ᵀ differentiated (cos → −sin, sin → cos).

    Exercise 5.9 at θ = 60°:

    >>> [[round(v, 4) + 0.0 for v in row] for row in rotation_transpose_derivative(math.pi / 3)]
    [[-0.866, 0.5], [-0.5, -0.866]]
    """
    c, s = math.cos(theta), math.sin(theta)
    return [[-s, c], [-c, -s]]


def edge_jacobians(xi: Pose, xj: Pose) -> tuple[Matrix, Matrix]:
    """(A, B) = (∂e/∂xi, ∂e/∂xj) of e = z − (xi⁻¹ ⊕ xj), each 3×3, in closed form.

    Pose i at (1, 1) facing 60°, pose j at (4, 2): the θi column of A is (−h_y, h_x, 1),
    with h = R(θi)ᵀ (tj − ti) the offset of pose j seen from pose i.

    >>> A, B = edge_jacobians((1, 1, math.pi / 3), (4, 2, 1.4))
    >>> [round(A[r][2], 4) + 0.0 for r in range(3)], B[2]
    ([2.0981, 2.366, 1.0], [0.0, 0.0, -1.0])

    The same, by central differences of :func:`edge_error_relative`:

    >>> from workbook.reference.pose_graph import edge_error_relative
    >>> def numeric(which, k, xi=(1, 1, math.pi / 3), xj=(4, 2, 1.4), z=(3, -1, 0.3), h=1e-6):
    ...     plus, minus = [list(xi), list(xj)], [list(xi), list(xj)]
    ...     plus[which][k] += h
    ...     minus[which][k] -= h
    ...     ep, em = edge_error_relative(*plus, z), edge_error_relative(*minus, z)
    ...     return [(a - b) / (2 * h) for a, b in zip(ep, em)]
    >>> all(abs(numeric(w, k)[r] - J[r][k]) < 1e-6 for w, J in ((0, A), (1, B)) for k in range(3) for r in range(3))
    True
    """
    dx, dy = xj[0] - xi[0], xj[1] - xi[1]
    Rt, dRt = rotation_transpose(xi[2]), rotation_transpose_derivative(xi[2])
    turn = [-(dRt[r][0] * dx + dRt[r][1] * dy) for r in range(2)]
    A = [[Rt[0][0], Rt[0][1], turn[0]], [Rt[1][0], Rt[1][1], turn[1]], [0.0, 0.0, 1.0]]
    B = [[-Rt[0][0], -Rt[0][1], 0.0], [-Rt[1][0], -Rt[1][1], 0.0], [0.0, 0.0, -1.0]]
    return A, B


def heading_column_entry(xi: Pose, xj: Pose, row: int) -> float:
    """Exercise 5.9's key: ∂e_row/∂θi (row 0: e_x, row 1: e_y), the entry of A's θi column.

    It is −h_y for e_x and h_x for e_y: turning pose i by δ swings pose j about it by −δ.

    >>> round(heading_column_entry((1, 1, math.pi / 3), (4, 2, 1.4), 0), 4)
    2.0981
    """
    return edge_jacobians(xi, xj)[0][row][2]

