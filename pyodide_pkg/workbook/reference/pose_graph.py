"""Pose-graph SLAM in the plane: variables, edge errors, information, cost.

A pose is ``(x, y, theta)``; an odometry edge from pose i to pose j carries the
measured motion ``z`` expressed in the frame of pose i.
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Sequence

from .linalg import Matrix, Vector, inverse, matmul, matvec, transpose

Pose = Sequence[float]


def pose_graph_variables(n_poses: int, pose_dof: int = 3) -> int:
    """How many unknowns a graph of ``n_poses`` poses has: one per degree of freedom.

    Exercise 5.1: 100 planar poses of 3 DOF each.

    >>> pose_graph_variables(100)
    300
    >>> pose_graph_variables(100, pose_dof=6)
    600
    """
    return n_poses * pose_dof


def gauss_newton_size(n_poses: int, pose_dof: int, n_landmarks: int = 0, landmark_dof: int = 0) -> int:
    """The side of the square matrix H in the Gauss–Newton step H Δx = −b.

    H has one row (and one column) per unknown, poses and landmarks alike.

    Exercise 5.5: 1000 poses of 6 DOF and 500 landmarks of 3 DOF.

    >>> gauss_newton_size(1000, 6, 500, 3)
    7500
    """
    return pose_graph_variables(n_poses, pose_dof) + n_landmarks * landmark_dof


def wrap_angle(a: float) -> float:
    """Bring an angle into (−π, π].

    >>> round(wrap_angle(3 * math.pi / 2), 4)
    -1.5708
    >>> wrap_angle(math.pi) == math.pi
    True
    """
    w = math.atan2(math.sin(a), math.cos(a))
    return math.pi if w == -math.pi else w


def compose_pose(a: Pose, b: Pose) -> tuple[float, float, float]:
    """a ⊕ b: pose ``b``, given in the frame of ``a``, expressed in the world.

    >>> [round(v, 4) + 0.0 for v in compose_pose((1, 0, math.pi / 2), (1, 0, 0))]
    [1.0, 1.0, 1.5708]
    """
    x, y, t = a
    c, s = math.cos(t), math.sin(t)
    return (x + c * b[0] - s * b[1], y + s * b[0] + c * b[1], wrap_angle(t + b[2]))


def invert_pose(a: Pose) -> tuple[float, float, float]:
    """a⁻¹, the pose with a ⊕ a⁻¹ = (0, 0, 0).

    >>> [round(v, 4) + 0.0 for v in invert_pose((1, 0, math.pi / 2))]
    [0.0, 1.0, -1.5708]
    """
    x, y, t = a
    c, s = math.cos(t), math.sin(t)
    return (-c * x - s * y, s * x - c * y, wrap_angle(-t))


def relative_pose(xi: Pose, xj: Pose) -> tuple[float, float, float]:
    """xi⁻¹ ⊕ xj: where pose j sits as seen from pose i (what odometry should read).

    >>> [round(v, 4) + 0.0 for v in relative_pose((0, 0, 0), (1.1, 0.05, 0.02))]
    [1.1, 0.05, 0.02]
    >>> [round(v, 4) + 0.0 for v in relative_pose((1, 1, math.pi / 2), (1, 2, math.pi / 2))]
    [1.0, 0.0, 0.0]
    """
    return compose_pose(invert_pose(xi), xj)


def edge_error_simple(xi: Pose, xj: Pose, z: Pose) -> list[float]:
    """The workbook's simple edge error e = z − (xj − xi), component by component.

    It is exact when pose i sits at the origin facing east, and a fair
    approximation while headings stay small.

    Exercise 5.2: odometry said (1, 0, 0); the poses differ by (1.1, 0.05, 0.02).

    >>> [round(v, 4) + 0.0 for v in edge_error_simple((0, 0, 0), (1.1, 0.05, 0.02), (1, 0, 0))]
    [-0.1, -0.05, -0.02]
    """
    return [zk - (bj - ai) for zk, ai, bj in zip(z, xi, xj)]


def edge_error_relative(xi: Pose, xj: Pose, z: Pose) -> list[float]:
    """e = z − (xi⁻¹ ⊕ xj): the measured motion minus the motion the poses
    imply, both in the frame of pose i, angle wrapped.

    The subtraction form of :func:`edge_error` for a pose i anywhere in the
    plane: x and y are first turned into pose i's frame (exercise 5.6). With
    pose i at the origin facing east it is :func:`edge_error_simple`.

    Exercise 5.6: pose 1 at (2, 1) facing north; pose 2 is 1.1 m ahead of it
    and 0.05 m to its left (at (1.95, 2.1) in the world), turned 0.02 rad more;
    odometry said (1, 0, 0).

    >>> [round(v, 4) + 0.0
    ...  for v in edge_error_relative((2, 1, math.pi / 2), (1.95, 2.1, math.pi / 2 + 0.02), (1, 0, 0))]
    [-0.1, -0.05, -0.02]
    >>> a, b = (0, 0, 0), (1.1, 0.05, 0.02)
    >>> edge_error_relative(a, b, (1, 0, 0)) == edge_error_simple(a, b, (1, 0, 0))
    True
    """
    h = relative_pose(xi, xj)
    return [z[0] - h[0], z[1] - h[1], wrap_angle(z[2] - h[2])]


def edge_error(xi: Pose, xj: Pose, z: Pose) -> list[float]:
    """The relative-pose edge error e = z ⊖ (xi⁻¹ ⊕ xj), angle wrapped.

    Here a ⊖ b = b⁻¹ ⊕ a, the pose of ``a`` seen from ``b``: the measured
    motion z seen from the predicted motion h = xi⁻¹ ⊕ xj. It is zero exactly
    when h = z, and it does not change if the whole graph is moved or turned.
    To first order it matches :func:`edge_error_simple` when pose i is the
    origin (exercise 5.2: −0.101 against −0.1 in x).

    >>> [round(v, 3) + 0.0 for v in edge_error((0, 0, 0), (1.1, 0.05, 0.02), (1, 0, 0))]
    [-0.101, -0.048, -0.02]
    >>> e = edge_error((2, 3, 1.0), compose_pose((2, 3, 1.0), (1, 0, 0)), (1, 0, 0))
    >>> [round(v, 12) + 0.0 for v in e]
    [0.0, 0.0, 0.0]
    """
    h = relative_pose(xi, xj)
    return list(relative_pose(h, z))


def information_matrix(sigma: Matrix) -> Matrix:
    """Ω = Σ⁻¹: small variance, large information.

    Exercise 5.3: Σ = diag(0.01, 0.01, 0.001) gives Ω = diag(100, 100, 1000).

    >>> [[round(w, 6) + 0.0 for w in row] for row in information_matrix(
    ...     [[0.01, 0, 0], [0, 0.01, 0], [0, 0, 0.001]])]
    [[100.0, 0.0, 0.0], [0.0, 100.0, 0.0], [0.0, 0.0, 1000.0]]
    """
    return inverse(sigma)


def edge_cost(e: Vector, omega: Matrix) -> float:
    """eᵀ Ω e, the squared error of one edge weighted by its information.

    Exercise 5.2's error weighted by exercise 5.3's Ω:
    100·0.01 + 100·0.0025 + 1000·0.0004 = 1.65.

    >>> round(edge_cost([-0.1, -0.05, -0.02], [[100, 0, 0], [0, 100, 0], [0, 0, 1000]]), 6)
    1.65
    """
    return sum(ek * wk for ek, wk in zip(e, matvec(omega, e)))


def total_cost(edges: Iterable[tuple[Vector, Matrix]]) -> float:
    """F(x) = Σ eᵀ Ω e over all edges, each given as a pair (e, Ω).

    >>> W = [[100, 0, 0], [0, 100, 0], [0, 0, 1000]]
    >>> round(total_cost([([-0.1, -0.05, -0.02], W), ([0.1, 0, 0], W)]), 6)
    2.65
    """
    return sum(edge_cost(e, omega) for e, omega in edges)


Edge = tuple[int, int, Pose, Matrix]  # (i, j, z_ij, Ω_ij)


def graph_cost(poses: Sequence[Pose], edges: Iterable[Edge]) -> float:
    """F(x) = Σ e_ijᵀ Ω_ij e_ij with :func:`edge_error`, for edges given as (i, j, z, Ω).

    Two poses one metre apart, and an odometry edge that says so: no cost.

    >>> W = [[100, 0, 0], [0, 100, 0], [0, 0, 1000]]
    >>> graph_cost([(0, 0, 0), (1, 0, 0)], [(0, 1, (1, 0, 0), W)])
    0.0
    >>> round(graph_cost([(0, 0, 0), (1.1, 0, 0)], [(0, 1, (1, 0, 0), W)]), 6)
    1.0
    """
    return total_cost((edge_error(poses[i], poses[j], z), omega) for i, j, z, omega in edges)


def _edge_jacobians(xi: Pose, xj: Pose, z: Pose, h: float = 1e-6) -> tuple[Matrix, Matrix]:
    """∂e/∂xi and ∂e/∂xj (3×3 each) by central differences."""
    def column(k: int, which: int) -> list[float]:
        plus, minus = [list(xi), list(xj)], [list(xi), list(xj)]
        plus[which][k] += h
        minus[which][k] -= h
        ep, em = edge_error(plus[0], plus[1], z), edge_error(minus[0], minus[1], z)
        return [(p - m) / (2 * h) for p, m in zip(ep, em)]
    A = transpose([column(k, 0) for k in range(3)])
    B = transpose([column(k, 1) for k in range(3)])
    return A, B


def gauss_newton(poses: Sequence[Pose], edges: Sequence[Edge], fixed: int = 0,
                 max_iterations: int = 10, tol: float = 1e-9) -> tuple[list[tuple[float, ...]], list[float]]:
    """Minimise F(x) over every pose but ``fixed`` (which anchors the graph).

    Each iteration linearises every edge error, e ≈ e0 + A Δxi + B Δxj, adds
    AᵀΩA, AᵀΩB, … into H and AᵀΩe0, BᵀΩe0 into b, solves H Δx = −b and moves all
    poses at once. A step that would raise the cost is halved until it does not
    (a simple line search). Stops when the cost falls by less than ``tol``
    (relative). Returns ``(poses, costs)``, ``costs[0]`` being the cost before
    the first step. The Jacobians A and B are taken by central differences.

    A square driven with a heading error of 0.05 rad per corner, then a loop
    closure saying the fourth pose is back at the start:

    >>> W = [[100, 0, 0], [0, 100, 0], [0, 0, 1000]]
    >>> z = (1, 0, math.pi / 2 + 0.05)
    >>> drifted = [(0.0, 0.0, 0.0)]
    >>> for _ in range(4):
    ...     drifted.append(compose_pose(drifted[-1], z))
    >>> edges = [(k, k + 1, z, W) for k in range(4)] + [(4, 0, (0, 0, 0), W)]
    >>> solved, costs = gauss_newton(drifted, edges)
    >>> round(costs[0], 2), round(costs[-1], 2)
    (41.9, 8.02)
    >>> all(a >= b for a, b in zip(costs, costs[1:]))
    True

    The cost cannot reach zero, as the measurements disagree: the 0.2 rad of
    extra heading ends up shared by the five edges, 0.04 rad each, and
    5 · 1000 · 0.04² = 8.
    """
    x = [tuple(float(v) for v in p) for p in poses]
    free = [k for k in range(len(x)) if k != fixed]
    slot = {k: 3 * n for n, k in enumerate(free)}
    size = 3 * len(free)
    costs = [graph_cost(x, edges)]
    for _ in range(max_iterations):
        H = [[0.0] * size for _ in range(size)]
        b = [0.0] * size
        for i, j, z, omega in edges:
            e = edge_error(x[i], x[j], z)
            A, B = _edge_jacobians(x[i], x[j], z)
            blocks = {i: A, j: B}
            for p, Jp in blocks.items():
                if p not in slot:
                    continue
                JtW = matmul(transpose(Jp), omega)
                g = matvec(JtW, e)
                for r in range(3):
                    b[slot[p] + r] += g[r]
                for q, Jq in blocks.items():
                    if q not in slot:
                        continue
                    block = matmul(JtW, Jq)
                    for r in range(3):
                        for c in range(3):
                            H[slot[p] + r][slot[q] + c] += block[r][c]
        step = matvec(inverse(H), [-v for v in b])
        scale = 1.0
        while True:
            trial = list(x)
            for k in free:
                s = slot[k]
                px, py, pt = x[k]
                trial[k] = (px + scale * step[s], py + scale * step[s + 1], wrap_angle(pt + scale * step[s + 2]))
            cost = graph_cost(trial, edges)
            if cost <= costs[-1] or scale < 1e-3:
                break
            scale /= 2
        if cost > costs[-1]:
            break
        x = trial
        costs.append(cost)
        if costs[-2] - cost <= tol * max(costs[-2], 1e-12):
            break
    return x, costs


def gauss_newton_step_1d(x: Sequence[float], edges: Sequence[tuple[int, int, float, float]]):
    """Exercise 5.8: one Gauss–Newton step on three poses along a line, pose 0 held fixed.

    ``edges`` are ``(i, j, z, w)``: pose j measured ``z`` ahead of pose i, with weight (information) w.
    Each edge's error is e = z − (x_j − x_i); the step solves H Δx = −b over poses 1 and 2, with
    H = Σ w JᵀJ and b = Σ w Jᵀe (J = ∂e/∂x: +1 at i, −1 at j). Returns ``(errors before the step,
    poses after it)``, or None when H is singular (a pose no edge ties to the anchor).

    Odometry says 1 and 1, the loop closure says 2.2: the mismatch of 0.2 is shared out.

    >>> errors, after = gauss_newton_step_1d([0, 1, 2], [(0, 1, 1, 1), (1, 2, 1, 1), (0, 2, 2.2, 1)])
    >>> [round(e, 4) + 0.0 for e in errors], [round(p, 4) + 0.0 for p in after]
    ([0.0, 0.0, 0.2], [0.0, 1.0667, 2.1333])
    >>> gauss_newton_step_1d([0, 1, 2], [(0, 1, 1, 1)]) is None
    True
    """
    errors = [z - (x[j] - x[i]) for i, j, z, w in edges]
    H = [[0.0] * 3 for _ in range(3)]
    b = [0.0] * 3
    for (i, j, _, w), e in zip(edges, errors):
        for a, ja in ((i, 1.0), (j, -1.0)):
            b[a] += w * ja * e
            for c, jc in ((i, 1.0), (j, -1.0)):
                H[a][c] += w * ja * jc
    free = [row[1:] for row in H[1:]]
    if free[0][0] * free[1][1] - free[0][1] * free[1][0] == 0:
        return None
    step = matvec(inverse(free), [-b[1], -b[2]])
    return errors, [x[0], x[1] + step[0], x[2] + step[1]]
