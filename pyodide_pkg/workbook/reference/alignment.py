"""Aligning point sets in the plane: centroids, the cross-covariance H, the best rotation and
translation (Arun, Huang & Blostein 1987; Umeyama 1991), and ICP's nearest-neighbour pairing
(Besl & McKay 1992).

The convention throughout: the rotation R and translation t map P onto Q, q_i ≈ R p_i + t, and
H = Σ (p_i − p̄)(q_i − q̄)ᵀ, so that with H = U S Vᵀ the best rotation is R = V Uᵀ (made proper).

>>> P = [(0.0, 0.0), (2.0, 0.0), (0.0, 1.0)]
>>> Q = [(1.0, 1.0), (1.0, 3.0), (0.0, 1.0)]  # P turned 90° and shifted by (1, 1)
>>> R, t = align_2d(P, Q)
>>> [[round(v, 9) + 0.0 for v in row] for row in R], [round(v, 9) + 0.0 for v in t]
([[0.0, -1.0], [1.0, 0.0]], [1.0, 1.0])
"""

from __future__ import annotations

import math
from collections.abc import Sequence

from .domain import Undefined
from .linalg import Matrix

Point = Sequence[float]


def centroid(points: Sequence[Point]) -> tuple[float, float]:
    """The mean of the points.

    >>> centroid([(0, 0), (2, 0), (1, 3)])
    (1.0, 1.0)
    """
    if not points:
        raise Undefined("an empty set of points has no centroid")
    n = len(points)
    return (sum(p[0] for p in points) / n, sum(p[1] for p in points) / n)


def cross_covariance(P: Sequence[Point], Q: Sequence[Point]) -> Matrix:
    """H = Σ (p_i − p̄)(q_i − q̄)ᵀ, a 2 × 2 matrix: row a of p′, column b of q′.

    >>> cross_covariance([(0, 0), (2, 0)], [(0, 0), (0, 2)])
    [[0.0, 2.0], [0.0, 0.0]]
    """
    if len(P) != len(Q):
        raise Undefined(f"{len(P)} points cannot be paired with {len(Q)}")
    pm, qm = centroid(P), centroid(Q)
    H = [[0.0, 0.0], [0.0, 0.0]]
    for p, q in zip(P, Q):
        a = (p[0] - pm[0], p[1] - pm[1])
        b = (q[0] - qm[0], q[1] - qm[1])
        for i in range(2):
            for j in range(2):
                H[i][j] += a[i] * b[j]
    return H


def angle_from_h(H: Matrix) -> float:
    """The angle θ (radians) of the best rotation R(θ) mapping P onto Q: atan2(H₁₂ − H₂₁, H₁₁ + H₂₂).

    It maximises Σ q′ᵀ R p′ = cos θ (H₁₁ + H₂₂) + sin θ (H₁₂ − H₂₁); a rotation, never a mirror.

    >>> round(math.degrees(angle_from_h([[0.0, 2.0], [0.0, 0.0]])), 9)
    90.0
    """
    s, c = H[0][1] - H[1][0], H[0][0] + H[1][1]
    if abs(s) < 1e-9 and abs(c) < 1e-9:
        raise Undefined("H₁₂ − H₂₁ and H₁₁ + H₂₂ are both 0: every rotation fits these points as well as any "
                        "other, so no angle is defined")
    return math.atan2(s, c)


def rot(theta: float) -> Matrix:
    """R(θ), the counter-clockwise turn by θ radians.

    >>> [[round(v, 9) + 0.0 for v in row] for row in rot(math.pi)]
    [[-1.0, 0.0], [0.0, -1.0]]
    """
    c, s = math.cos(theta), math.sin(theta)
    return [[c, -s], [s, c]]


def det2(M: Matrix) -> float:
    """The determinant of a 2 × 2 matrix: +1 for a rotation, −1 for a reflection.

    >>> det2([[0.6, 0.8], [0.8, -0.6]])
    -1.0
    """
    return M[0][0] * M[1][1] - M[0][1] * M[1][0]


def rotation_from_svd(U: Matrix, V: Matrix) -> Matrix:
    """R = V diag(1, d) Uᵀ with d = det(V Uᵀ): the SVD's rotation, its reflection (d = −1) undone.

    >>> rotation_from_svd([[1.0, 0.0], [0.0, 1.0]], [[1.0, 0.0], [0.0, -1.0]])
    [[1.0, 0.0], [0.0, 1.0]]
    """
    d = 1.0 if det2(V) * det2(U) > 0 else -1.0
    Vd = [[V[i][0], d * V[i][1]] for i in range(2)]
    return [[sum(Vd[i][k] * U[j][k] for k in range(2)) for j in range(2)] for i in range(2)]


def translation(R: Matrix, p_mean: Point, q_mean: Point) -> tuple[float, float]:
    """t = q̄ − R p̄: the translation that puts the turned centroid of P on that of Q.

    >>> translation([[0.0, -1.0], [1.0, 0.0]], (1.0, 0.0), (1.0, 2.0))
    (1.0, 1.0)
    """
    return (q_mean[0] - (R[0][0] * p_mean[0] + R[0][1] * p_mean[1]),
            q_mean[1] - (R[1][0] * p_mean[0] + R[1][1] * p_mean[1]))


def align_2d(P: Sequence[Point], Q: Sequence[Point]) -> tuple[Matrix, list[float]]:
    """The rotation R (det +1) and translation t minimising Σ |R p_i + t − q_i|², as ([[..], [..]], [tx, ty]).

    Collinear points are no special case in the plane: the rotation that turns P's line onto Q's
    (and not the mirror) is unique. When every rotation fits equally well (all of P at one point,
    say), R is the identity and t = q̄ − p̄.

    >>> align_2d([(1.0, 1.0), (1.0, 1.0)], [(3.0, 0.0), (5.0, 0.0)])
    ([[1.0, 0.0], [0.0, 1.0]], [3.0, -1.0])
    """
    H = cross_covariance(P, Q)
    try:
        R = rot(angle_from_h(H))
    except Undefined:
        R = [[1.0, 0.0], [0.0, 1.0]]
    return R, list(translation(R, centroid(P), centroid(Q)))


def nearest(P: Sequence[Point], Q: Sequence[Point]) -> list[int]:
    """For each point of P, the index (from 1) of the nearest point of Q; a tie goes to the lower index.

    >>> nearest([(0, 0), (3, 1)], [(3, 0), (0, 1), (5, 5)])
    [2, 1]
    """
    out = []
    for p in P:
        d = [(p[0] - q[0]) ** 2 + (p[1] - q[1]) ** 2 for q in Q]
        out.append(1 + d.index(min(d)))
    return out
