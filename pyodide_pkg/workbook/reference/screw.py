"""Arm kinematics in 3-D: screw axes S = (ω, v), the exponential of a twist (Rodrigues' formula for
the turn, G(θ) for the shift), forward kinematics as a product of exponentials in the space frame,
Denavit–Hartenberg link transforms (standard and Craig's modified), the adjoint and the space
Jacobian. The 4 × 4 transforms are chapter 10's (``se3.pose``, ``se3.compose``).

The formulas are written for a unit ω (a revolute joint, or a screw with pitch) or ω = 0 (a
prismatic joint, where they give R = I and p = v θ); given any other ω they apply the same
formulas literally, which is what a learner's own S carried from an earlier exercise needs.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

from .linalg import Matrix, identity, matmul, matvec
from .rotation3d import rx, rz
from .se3 import compose, pose, rotation_of, translation_of

Vec3 = tuple[float, float, float]


def cross(a, b) -> Vec3:
    """a × b.

    >>> cross((1, 0, 0), (0, 1, 0))
    (0, 0, 1)
    """
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def skew(w) -> Matrix:
    """[ω], the matrix with [ω] x = ω × x.

    >>> skew((1, 2, 3))
    [[0.0, -3.0, 2.0], [3.0, 0.0, -1.0], [-2.0, 1.0, 0.0]]
    """
    x, y, z = (float(c) for c in w)
    return [[0.0, -z, y], [z, 0.0, -x], [-y, x, 0.0]]


def terms(theta_term: float, a: float, b: float, w) -> Matrix:
    """theta_term·I + a·[ω] + b·[ω]²: Rodrigues' formula and G(θ) are both of this form.

    >>> terms(2.0, 1.0, 0.0, (0, 0, 1))
    [[2.0, -1.0, 0.0], [1.0, 2.0, 0.0], [0.0, 0.0, 2.0]]
    """
    W = skew(w)
    W2 = matmul(W, W)
    return [[theta_term * (i == j) + a * W[i][j] + b * W2[i][j] for j in range(3)] for i in range(3)]


def rotation_exp(w, theta: float) -> Matrix:
    """Rodrigues' formula e^{[ω]θ} = I + sin θ [ω] + (1 − cos θ)[ω]² for a unit axis ω (θ in radians).

    A quarter turn about z is chapter 2's Rz(90°):

    >>> R = rotation_exp((0, 0, 1), math.pi / 2)
    >>> max(abs(a - b) for r, s in zip(R, rz(math.pi / 2)) for a, b in zip(r, s)) < 1e-12
    True
    """
    return terms(1.0, math.sin(theta), 1 - math.cos(theta), w)


def g_matrix(w, theta: float) -> Matrix:
    """G(θ) = I θ + (1 − cos θ)[ω] + (θ − sin θ)[ω]², which turns v into the shift of e^{[S]θ}.

    With ω = 0 (a prismatic joint) it is I θ:

    >>> g_matrix((0, 0, 0), 2.0)
    [[2.0, 0.0, 0.0], [0.0, 2.0, 0.0], [0.0, 0.0, 2.0]]
    """
    return terms(float(theta), 1 - math.cos(theta), theta - math.sin(theta), w)


def revolute_screw(w, q, pitch: float = 0.0) -> tuple[float, ...]:
    """The screw axis (ω, v) of a joint turning about the unit axis ω through the point q:
    v = −ω × q (+ h ω for a screw of pitch h).

    >>> revolute_screw((0, 0, 1), (2, 0, 0))
    (0.0, 0.0, 1.0, 0.0, -2.0, 0.0)
    """
    v = cross(w, q)
    return tuple(float(c) for c in w) + tuple(-v[i] + pitch * w[i] + 0.0 for i in range(3))


def twist_exp(S, theta: float) -> Matrix:
    """e^{[S]θ} = [e^{[ω]θ}  G(θ) v; 0 1] for S = (ω, v).

    A prismatic joint (ω = 0) slides by v θ; a turn of 90° about the z-axis through (1, 0, 0) takes
    the origin to (1, −1, 0):

    >>> translation_of(twist_exp((0, 0, 0, 0, 0, 1), 0.5))
    [0.0, 0.0, 0.5]
    >>> [round(c, 12) + 0.0 for c in translation_of(twist_exp(revolute_screw((0, 0, 1), (1, 0, 0)), math.pi / 2))]
    [1.0, -1.0, 0.0]
    """
    w, v = S[:3], S[3:]
    return pose(rotation_exp(w, theta), matvec(g_matrix(w, theta), v))


def fk_poe(M: Matrix, S_list: Sequence, theta: Sequence[float]) -> Matrix:
    """T(θ) = e^{[S₁]θ₁} e^{[S₂]θ₂} ⋯ e^{[Sₙ]θₙ} M, the screws in the space frame, M the home pose.

    With every θ at zero, T = M:

    >>> M = pose(identity(3), (2, 0, 1))
    >>> fk_poe(M, [(0, 0, 1, 0, 0, 0)], [0.0]) == M
    True
    """
    return compose(*(twist_exp(S, th) for S, th in zip(S_list, theta)), [list(map(float, r)) for r in M])


def adjoint(T: Matrix) -> Matrix:
    """Ad_T = [R 0; [p]R R] (6 × 6), which takes a twist (ω, v) from one frame to another.

    >>> Ad = adjoint(pose(identity(3), (0, 0, 1)))
    >>> Ad[3][:3], Ad[3][3:]
    ([0.0, -1.0, 0.0], [1.0, 0.0, 0.0])
    """
    R, p = rotation_of(T), translation_of(T)
    pR = matmul(skew(p), R)
    top = [list(map(float, R[i])) + [0.0, 0.0, 0.0] for i in range(3)]
    return top + [list(pR[i]) + list(map(float, R[i])) for i in range(3)]


def twist_moved(T: Matrix, S) -> tuple[float, ...]:
    """Ad_T S: the screw S carried by the motion T.

    >>> twist_moved(pose(rz(math.pi / 2), (0, 0, 0)), (0, 0, 0, 1, 0, 0))[3:]
    (0.0, 1.0, 0.0)
    """
    return tuple(round(c, 15) + 0.0 for c in matvec(adjoint(T), [float(c) for c in S]))


def jacobian_space(S_list: Sequence, theta: Sequence[float]) -> list[tuple[float, ...]]:
    """The columns of the space Jacobian: J_s1 = S₁, J_si = Ad(e^{[S₁]θ₁} ⋯ e^{[S_{i−1}]θ_{i−1}}) S_i.

    >>> jacobian_space([(0, 0, 1, 0, 0, 0), (0, 0, 1, 0, -1, 0)], [math.pi / 2, 0.0])[1][3:]
    (1.0, 0.0, 0.0)
    """
    columns, T = [], identity(4)
    for S, th in zip(S_list, theta):
        columns.append(twist_moved(T, S))
        T = matmul(T, twist_exp(S, th))
    return columns


def dh_standard(a: float, alpha: float, d: float, theta: float) -> Matrix:
    """One link of standard DH: Rot_z(θ) Trans_z(d) Trans_x(a) Rot_x(α) (angles in radians).

    >>> [round(v, 12) + 0.0 for v in translation_of(dh_standard(2, 0, 1, math.pi / 2))]
    [0.0, 2.0, 1.0]
    """
    return compose(pose(rz(theta), (0, 0, d)), pose(rx(alpha), (a, 0, 0)))


def dh_modified(a: float, alpha: float, d: float, theta: float) -> Matrix:
    """One link of Craig's modified DH, its row (α_{i−1}, a_{i−1}, θ_i, d_i):
    Rot_x(α) Trans_x(a) Rot_z(θ) Trans_z(d).

    >>> [round(v, 12) + 0.0 for v in translation_of(dh_modified(2, math.pi / 2, 1, 0))]
    [2.0, -1.0, 0.0]
    """
    return compose(pose(rx(alpha), (a, 0, 0)), pose(rz(theta), (0, 0, d)))


def fk_dh(rows: Sequence[Sequence[float]], modified: bool = False) -> Matrix:
    """The product of the link transforms of a DH table, rows (a, α, d, θ).

    >>> T = fk_dh([(1, 0, 0, 0), (1, 0, 0, math.pi / 2)])
    >>> [round(v, 12) + 0.0 for v in translation_of(T)]
    [1.0, 1.0, 0.0]
    """
    link = dh_modified if modified else dh_standard
    return compose(identity(4), *(link(*row) for row in rows))


# ---- The chapter's arm: a base turning about z, a shoulder and an elbow about −y -----------------

def arm_screws(L0: float, L1: float) -> list[tuple[float, ...]]:
    """The screw axes of the chapter's 3R arm at home (stretched along x): the base about z through the
    origin, the shoulder about −y at height L0, the elbow about −y at (L1, 0, L0).

    >>> arm_screws(1, 2)[2]
    (0.0, -1.0, 0.0, 1.0, 0.0, -2.0)
    """
    return [revolute_screw((0, 0, 1), (0, 0, 0)), revolute_screw((0, -1, 0), (0, 0, L0)),
            revolute_screw((0, -1, 0), (L1, 0, L0))]


def arm_home(L0: float, L1: float, L2: float) -> Matrix:
    """The tool frame at home, M: at (L1 + L2, 0, L0), with the DH convention's axes (x along the arm,
    z along the elbow's axis −y, so y is the world's z).

    >>> arm_home(1, 2, 3)[0][3], arm_home(1, 2, 3)[2]
    (5.0, [0.0, 1.0, 0.0, 1.0])
    """
    return pose([[1.0, 0.0, 0.0], [0.0, 0.0, -1.0], [0.0, 1.0, 0.0]], (L1 + L2, 0, L0))


def arm_dh(L0: float, L1: float, L2: float, theta: Sequence[float]) -> list[tuple[float, float, float, float]]:
    """The same arm's standard DH table, rows (a, α, d, θ).

    >>> arm_dh(1, 2, 3, (0, 0, 0))[0]
    (0.0, 1.5707963267948966, 1.0, 0.0)
    """
    t1, t2, t3 = (float(t) for t in theta)
    return [(0.0, math.pi / 2, float(L0), t1), (float(L1), 0.0, 0.0, t2), (float(L2), 0.0, 0.0, t3)]


def arm_points(L0: float, L1: float, L2: float, theta: Sequence[float]) -> list[list[float]]:
    """Base, shoulder, elbow and tool positions of the arm, in the world.

    >>> [[round(c, 12) + 0.0 for c in p] for p in arm_points(1, 2, 3, (0, math.pi / 2, 0))][3]
    [0.0, 0.0, 6.0]
    """
    S = arm_screws(L0, L1)
    e1 = twist_exp(S[0], theta[0])
    e12 = compose(e1, twist_exp(S[1], theta[1]))
    elbow = compose(e12, pose(identity(3), (L1, 0, L0)))
    tool = fk_poe(arm_home(L0, L1, L2), S, theta)
    return [[0.0, 0.0, 0.0], translation_of(compose(e1, pose(identity(3), (0, 0, L0)))),
            translation_of(elbow), translation_of(tool)]
