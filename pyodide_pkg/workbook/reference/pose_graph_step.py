"""One Gauss–Newton iteration on an SE(2) pose graph, pose 0 anchored (chapter 5, exercise 5.10).

The edge error is the chapter's subtraction form (exercise 5.6),
e = z − h with h = xi⁻¹ ⊕ xj = (R(θi)ᵀ (tj − ti), θj − θi), its angle wrapped into (−π, π],
and its Jacobians A = ∂e/∂xi and B = ∂e/∂xj are those of :mod:`.pose_graph_jacobian`. Every edge
adds AᵀΩA, AᵀΩB, BᵀΩA, BᵀΩB into four 3×3 blocks of H and AᵀΩe, BᵀΩe into two of b; pose 0's
rows and columns are dropped, H Δx = −b is solved for the others, and every angle of the result
is wrapped again.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence

from .linalg import Matrix, Vector, inverse, matmul, matvec, transpose
from .pose_graph import Edge, Pose, edge_error_relative, wrap_angle
from .pose_graph_jacobian import edge_jacobians

ErrorFn = Callable[[Pose, Pose, Pose], list[float]]


def linear_system(poses: Sequence[Pose], edges: Sequence[Edge],
                  error: ErrorFn = edge_error_relative) -> tuple[Matrix, Vector]:
    """H = Σ JᵀΩJ and b = Σ JᵀΩe over every edge (i, j, z, Ω), for all the poses (3n × 3n and 3n).

    ``error`` is the edge error e(xi, xj, z) (the chapter's, wrapped, unless a caller wants another).

    One edge that agrees with its poses adds to H but not to b:

    >>> H, b = linear_system([(0, 0, 0), (1, 0, 0)], [(0, 1, (1, 0, 0), [[1, 0, 0], [0, 1, 0], [0, 0, 1]])])
    >>> b, [H[k][k] for k in range(6)]
    ([0.0, 0.0, 0.0, 0.0, 0.0, 0.0], [1.0, 1.0, 2.0, 1.0, 1.0, 1.0])
    """
    size = 3 * len(poses)
    H = [[0.0] * size for _ in range(size)]
    b = [0.0] * size
    for i, j, z, omega in edges:
        e = error(poses[i], poses[j], z)
        A, B = edge_jacobians(poses[i], poses[j])
        blocks = ((i, A), (j, B))
        for p, Jp in blocks:
            JtW = matmul(transpose(Jp), [list(map(float, row)) for row in omega])
            g = matvec(JtW, e)
            for r in range(3):
                b[3 * p + r] += g[r]
            for q, Jq in blocks:
                block = matmul(JtW, Jq)
                for r in range(3):
                    for c in range(3):
                        H[3 * p + r][3 * q + c] += block[r][c]
    return H, b


def anchored_step(H: Matrix, b: Vector) -> list[float]:
    """Δx solving H Δx = −b with pose 0 held still: its three rows and columns dropped, its step 0.

    >>> H = [[2, 0, 0, -1, 0, 0], [0, 2, 0, 0, -1, 0], [0, 0, 2, 0, 0, -1],
    ...      [-1, 0, 0, 1, 0, 0], [0, -1, 0, 0, 1, 0], [0, 0, -1, 0, 0, 1]]
    >>> anchored_step(H, [0, 0, 0, 0.5, 0, -0.25])
    [0.0, 0.0, 0.0, -0.5, 0.0, 0.25]
    """
    free = [row[3:] for row in H[3:]]
    return [0.0, 0.0, 0.0] + [float(v) + 0.0 for v in matvec(inverse(free), [-v for v in b[3:]])]


def moved(poses: Sequence[Pose], step: Sequence[float]) -> list[list[float]]:
    """The poses after the step, each angle wrapped into (−π, π].

    >>> [round(v, 4) for v in moved([(0, 0, 3.0)], [0.5, 0.0, 0.3])[0]]
    [0.5, 0.0, -2.9832]
    """
    out = []
    for k, (x, y, t) in enumerate(poses):
        out.append([x + step[3 * k], y + step[3 * k + 1], wrap_angle(t + step[3 * k + 2])])
    return out


def gauss_newton_se2(poses: Sequence[Pose], edges: Sequence[Edge]) -> list[list[float]]:
    """Exercise 5.10: the poses after one Gauss–Newton iteration, pose 0 anchored, angles wrapped.

    ``poses`` are rows (x, y, θ); ``edges`` are (i, j, z, Ω) with z = (dx, dy, dθ) the motion from pose
    i to pose j measured in pose i's frame and Ω its 3×3 information matrix.

    Two odometry edges of 1 m, each turning 90°, and a loop closure saying pose 2 is at (1, 1.2) from
    pose 0, facing back: the step shares the 0.2 m disagreement out, a third to each edge.

    >>> import math
    >>> W = [[1, 0, 0], [0, 1, 0], [0, 0, 10]]
    >>> poses = [(0, 0, 0), (1, 0, math.pi / 2), (1, 1, math.pi)]
    >>> edges = [(0, 1, (1, 0, math.pi / 2), W), (1, 2, (1, 0, math.pi / 2), W), (0, 2, (1, 1.2, math.pi), W)]
    >>> [[round(v, 4) + 0.0 for v in p] for p in gauss_newton_se2(poses, edges)]
    [[0.0, 0.0, 0.0], [1.0, 0.0667, 1.5708], [1.0, 1.1333, 3.1416]]
    """
    poses = [tuple(float(v) for v in p) for p in poses]
    H, b = linear_system(poses, edges)
    after = moved(poses, anchored_step(H, b))
    after[0] = list(poses[0])  # the anchor, exactly as given (no round trip through the wrap)
    return after
