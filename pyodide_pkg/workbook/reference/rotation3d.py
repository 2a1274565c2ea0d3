"""3D rotations: elementary matrices, ZYX Euler angles, unit quaternions,
and the gimbal lock of Euler angles at pitch ±90°."""

from __future__ import annotations

import math

from .linalg import Matrix, matmul


def rx(alpha: float) -> Matrix:
    """Rotation by α about the x-axis (roll).

    >>> [[round(v, 4) + 0.0 for v in row] for row in rx(math.pi / 2)]
    [[1.0, 0.0, 0.0], [0.0, 0.0, -1.0], [0.0, 1.0, 0.0]]
    """
    c, s = math.cos(alpha), math.sin(alpha)
    return [[1.0, 0.0, 0.0], [0.0, c, -s], [0.0, s, c]]


def ry(beta: float) -> Matrix:
    """Rotation by β about the y-axis (pitch). Note the sign of sin β: +s in row 1.

    >>> [[round(v, 4) + 0.0 for v in row] for row in ry(math.pi / 2)]
    [[0.0, 0.0, 1.0], [0.0, 1.0, 0.0], [-1.0, 0.0, 0.0]]
    """
    c, s = math.cos(beta), math.sin(beta)
    return [[c, 0.0, s], [0.0, 1.0, 0.0], [-s, 0.0, c]]


def rz(gamma: float) -> Matrix:
    """Rotation by γ about the z-axis (yaw).

    Exercise 2.1: Rz(90°) sends the x-axis (1, 0, 0) to the y-axis (0, 1, 0).

    >>> [round(row[0], 4) + 0.0 for row in rz(math.pi / 2)]
    [0.0, 1.0, 0.0]
    """
    c, s = math.cos(gamma), math.sin(gamma)
    return [[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]]


def euler_zyx(yaw: float, pitch: float, roll: float) -> Matrix:
    """R = Rz(yaw) · Ry(pitch) · Rx(roll): roll first, yaw last.

    >>> R = euler_zyx(math.pi / 2, 0, 0)
    >>> R == rz(math.pi / 2)
    True
    """
    return matmul(matmul(rz(yaw), ry(pitch)), rx(roll))


def quat_from_axis_angle(axis, angle: float) -> tuple[float, float, float, float]:
    """The unit quaternion (w, x, y, z) = (cos θ/2, sin θ/2 · n) for a unit axis n.

    The axis is normalised first. Exercise 2.3: 90° about z.

    >>> [round(v, 4) for v in quat_from_axis_angle((0, 0, 1), math.pi / 2)]
    [0.7071, 0.0, 0.0, 0.7071]

    Exercise 2.4: 180° about x is the pure quaternion (0, 1, 0, 0).

    >>> [round(v, 4) + 0.0 for v in quat_from_axis_angle((1, 0, 0), math.pi)]
    [0.0, 1.0, 0.0, 0.0]
    """
    n = math.sqrt(sum(a * a for a in axis))
    h = angle / 2
    s = math.sin(h) / n
    return (math.cos(h), s * axis[0], s * axis[1], s * axis[2])


def quat_norm(q) -> float:
    """‖q‖ = √(w² + x² + y² + z²); a rotation needs ‖q‖ = 1.

    Exercise 2.5:

    >>> quat_norm((0.5, 0.5, 0.5, 0.5))
    1.0
    """
    return math.sqrt(sum(c * c for c in q))


def quat_axis_angle(q) -> tuple[tuple[float, float, float], float]:
    """The (unit axis, angle in radians) of a unit quaternion; the inverse of
    :func:`quat_from_axis_angle` for angles in [0, 2π).

    (0.5, 0.5, 0.5, 0.5) is 120° about (1, 1, 1)/√3.

    >>> axis, angle = quat_axis_angle((0.5, 0.5, 0.5, 0.5))
    >>> [round(a, 4) for a in axis], round(math.degrees(angle), 2)
    ([0.5774, 0.5774, 0.5774], 120.0)
    """
    w, x, y, z = q
    angle = 2 * math.acos(max(-1.0, min(1.0, w)))
    s = math.sqrt(max(0.0, 1 - w * w))
    if s < 1e-12:
        return (1.0, 0.0, 0.0), 0.0
    return (x / s, y / s, z / s), angle


def gimbal_lock_angle(yaw: float, pitch_sign: int, roll: float) -> float:
    """At pitch = ±90° the ZYX matrix depends on one combined angle only.

    For pitch = +90°, R = [[0, −sin ψ, cos ψ], [0, cos ψ, sin ψ], [−1, 0, 0]]
    with ψ = yaw − roll; for pitch = −90°,
    R = [[0, −sin ψ, −cos ψ], [0, cos ψ, −sin ψ], [1, 0, 0]] with ψ = yaw + roll.
    This returns ψ. Any (yaw, roll) pair with the same ψ gives the same matrix:
    one degree of freedom is lost (exercise 2.2).

    >>> round(gimbal_lock_angle(0.7, +1, 0.2), 12), round(gimbal_lock_angle(0.9, +1, 0.4), 12)
    (0.5, 0.5)
    >>> same = lambda A, B: all(abs(a - b) < 1e-12 for ra, rb in zip(A, B) for a, b in zip(ra, rb))
    >>> same(euler_zyx(0.7, math.pi / 2, 0.2), euler_zyx(0.9, math.pi / 2, 0.4))
    True
    >>> same(euler_zyx(0.7, -math.pi / 2, 0.2), euler_zyx(0.5, -math.pi / 2, 0.4))
    True
    >>> same(euler_zyx(0.7, 0.3, 0.2), euler_zyx(0.9, 0.3, 0.4))
    False
    """
    if pitch_sign not in (1, -1):
        raise ValueError("pitch_sign must be +1 or -1")
    return yaw - roll if pitch_sign == 1 else yaw + roll


def gimbal_locked(pitch: float, tol: float = 1e-9) -> bool:
    """True when the pitch sits at ±90°, where yaw and roll turn about the same axis.

    Exercise 2.2:

    >>> gimbal_locked(math.pi / 2), gimbal_locked(-math.pi / 2), gimbal_locked(0.0)
    (True, True, False)
    """
    return abs(math.cos(pitch)) < tol


def quat_from_matrix(R: Matrix) -> tuple[float, float, float, float]:
    """The unit quaternion (w, x, y, z) of a rotation matrix, with w ≥ 0.

    Starts from the largest of w², x², y², z² (each read off the diagonal), so it
    stays accurate near 180° turns too. q and −q are the same rotation; this
    picks the one with w ≥ 0.

    Exercise 2.3 again, now from the matrix: Rz(90°).

    >>> [round(v, 4) + 0.0 for v in quat_from_matrix(rz(math.pi / 2))]
    [0.7071, 0.0, 0.0, 0.7071]

    Exercise 2.4: 180° about x.

    >>> [round(v, 4) + 0.0 for v in quat_from_matrix(rx(math.pi))]
    [0.0, 1.0, 0.0, 0.0]
    """
    (m00, m01, m02), (m10, m11, m12), (m20, m21, m22) = R
    squares = (1 + m00 + m11 + m22, 1 + m00 - m11 - m22, 1 - m00 + m11 - m22, 1 - m00 - m11 + m22)
    k = max(range(4), key=lambda i: squares[i])
    s = 2 * math.sqrt(max(squares[k], 0.0))  # 4·|component k|
    if k == 0:
        q = (s / 4, (m21 - m12) / s, (m02 - m20) / s, (m10 - m01) / s)
    elif k == 1:
        q = ((m21 - m12) / s, s / 4, (m01 + m10) / s, (m02 + m20) / s)
    elif k == 2:
        q = ((m02 - m20) / s, (m01 + m10) / s, s / 4, (m12 + m21) / s)
    else:
        q = ((m10 - m01) / s, (m02 + m20) / s, (m12 + m21) / s, s / 4)
    return q if q[0] >= 0 else tuple(-c for c in q)
