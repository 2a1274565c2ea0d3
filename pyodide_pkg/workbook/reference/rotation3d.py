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

    A zero axis has no direction:

    >>> quat_from_axis_angle((0, 0, 0), 1.0)
    Traceback (most recent call last):
    ...
    ValueError: axis must not be the zero vector: a rotation needs a direction to turn about
    """
    n = math.sqrt(sum(a * a for a in axis))
    if n == 0.0:
        raise ValueError("axis must not be the zero vector: a rotation needs a direction to turn about")
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



def quat_conjugate(q) -> tuple[float, float, float, float]:
    """q* = (w, −x, −y, −z): the same axis turned the other way; for a unit q it is q⁻¹.

    >>> quat_conjugate((0.5, 0.5, -0.5, 0.5))
    (0.5, -0.5, 0.5, -0.5)
    """
    w, x, y, z = q
    return (w, -x, -y, -z)


def quat_multiply(p, q) -> tuple[float, float, float, float]:
    """The Hamilton product p ⊗ q of two quaternions stored w-first, (w, x, y, z).

    With p = (a, u) and q = (b, v) (scalar, vector):
    p ⊗ q = (a b − u·v, a v + b u + u × v). The cross product is why the order
    matters: q ⊗ p has − u × v. For unit quaternions, p ⊗ q turns by q first,
    then by p, as the matrix product R(p) R(q) does.

    Exercise 2.10, and two quarter turns about z make a half turn:

    >>> quat_multiply((1, 2, 0, -1), (2, -1, 1, 0))
    (4, 4, 2, 0)
    >>> quat_multiply((2, -1, 1, 0), (1, 2, 0, -1))
    (4, 2, 0, -4)
    >>> h = quat_from_axis_angle((0, 0, 1), math.pi / 2)
    >>> [round(c, 12) + 0.0 for c in quat_multiply(h, h)]
    [0.0, 0.0, 0.0, 1.0]
    """
    a, ux, uy, uz = p
    b, vx, vy, vz = q
    return (a * b - ux * vx - uy * vy - uz * vz,
            a * vx + b * ux + uy * vz - uz * vy,
            a * vy + b * uy + uz * vx - ux * vz,
            a * vz + b * uz + ux * vy - uy * vx)


def quat_integrate(q, omega, dt: float, steps: int = 1, renormalise: bool = True) -> tuple[float, float, float, float]:
    """Integrate a gyroscope's body rates ω = (ωx, ωy, ωz) (rad/s) into the attitude q, ``steps`` times.

    Each step is explicit Euler on q̇ = ½ q ⊗ (0, ω), then q / ‖q‖. Euler
    lengthens q a little every step (by √(1 + (‖ω‖ dt / 2)²)), so without the
    division (``renormalise=False``, what the bug of exercise 2.9 does) the
    norm grows and the "rotation" scales every vector it turns by ‖q‖².

    Exercise 2.9: 1 s at 5 rad/s about z in 100 steps turns by about 5 rad.

    >>> q = quat_integrate((1, 0, 0, 0), (0, 0, 5), 0.01, 100)
    >>> round(quat_norm(q), 12), round(2 * math.atan2(q[3], q[0]), 2)
    (1.0, 5.0)
    >>> round(quat_norm(quat_integrate((1, 0, 0, 0), (0, 0, 5), 0.01, 100, renormalise=False)), 4)
    1.0317
    """
    w, x, y, z = q
    wx, wy, wz = omega
    for _ in range(steps):
        dw = -0.5 * (x * wx + y * wy + z * wz)
        dx = 0.5 * (w * wx + y * wz - z * wy)
        dy = 0.5 * (w * wy - x * wz + z * wx)
        dz = 0.5 * (w * wz + x * wy - y * wx)
        w, x, y, z = w + dw * dt, x + dx * dt, y + dy * dt, z + dz * dt
        if renormalise:
            n = math.sqrt(w * w + x * x + y * y + z * z)
            w, x, y, z = w / n, x / n, y / n, z / n
    return (w, x, y, z)


DEFAULT_AXIS = (1.0, 0.0, 0.0)


def quat_axis_angle(q) -> tuple[tuple[float, float, float], float]:
    """The (unit axis, angle in radians) of a unit quaternion; the inverse of
    :func:`quat_from_axis_angle` for angles in [0, 2π].

    angle = 2·atan2(‖v‖, w) with v = (x, y, z), and axis = v/‖v‖. Unlike
    2·acos(w), this keeps tiny angles (w rounds to 1 long before ‖v‖ is 0) and
    does not need q to be exactly unit length.

    (0.5, 0.5, 0.5, 0.5) is 120° about (1, 1, 1)/√3.

    >>> axis, angle = quat_axis_angle((0.5, 0.5, 0.5, 0.5))
    >>> [round(a, 4) for a in axis], round(math.degrees(angle), 2)
    ([0.5774, 0.5774, 0.5774], 120.0)

    Tiny turns: at 1e-7 rad the axis is still a unit vector, and 1e-8 rad does
    not collapse to 0 (2·acos(w) gives 0 there).

    >>> axis, angle = quat_axis_angle(quat_from_axis_angle((0, 0.6, 0.8), 1e-7))
    >>> round(math.hypot(*axis), 15), [round(a, 12) for a in axis], angle
    (1.0, [0.0, 0.6, 0.8], 1e-07)
    >>> quat_axis_angle(quat_from_axis_angle((1, 0, 0), 1e-8))[1]
    1e-08

    The identity turns by 0 about any axis; this returns the x-axis,
    ``DEFAULT_AXIS``. A zero quaternion is not a rotation.

    >>> quat_axis_angle((1.0, 0.0, 0.0, 0.0)), quat_axis_angle((-1.0, 0.0, 0.0, 0.0))
    (((1.0, 0.0, 0.0), 0.0), ((1.0, 0.0, 0.0), 6.283185307179586))
    >>> quat_axis_angle((0, 0, 0, 0))
    Traceback (most recent call last):
    ...
    ValueError: quaternion q must not be zero: it is not a rotation
    """
    w, x, y, z = (float(c) for c in q)
    s = math.hypot(x, y, z)  # no underflow of the squares for tiny turns
    if s == 0.0:
        if w == 0.0:
            raise ValueError("quaternion q must not be zero: it is not a rotation")
        return DEFAULT_AXIS, 2 * math.atan2(0.0, w)
    return (x / s, y / s, z / s), 2 * math.atan2(s, w)


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
    return q if q[0] >= 0 else (-q[0], -q[1], -q[2], -q[3])


def quat_rotate(q, v) -> tuple[float, float, float]:
    """The vector ``v`` turned by the unit quaternion ``q`` = (w, x, y, z): the vector part of q v q*.

    Written out as v' = v + 2w (u × v) + 2 u × (u × v), with u the vector part of q.
    Exercise 2.3's quaternion (90° about z) turns the x-axis into the y-axis:

    >>> [round(c, 4) + 0.0 for c in quat_rotate(quat_from_axis_angle((0, 0, 1), math.pi / 2), (1, 0, 0))]
    [0.0, 1.0, 0.0]
    """
    w, u = q[0], q[1:]

    def cross(a, b):
        return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])

    t = cross(u, v)
    tt = cross(u, t)
    return tuple(v[i] + 2 * w * t[i] + 2 * tt[i] for i in range(3))


def rotate_axis_angle(axis, angle: float, v):
    """Exercise 2.8: the unit quaternion for ``angle`` radians about ``axis`` (any length but zero), and
    ``v`` turned by it; returns ``(q, v')``.

    >>> q, w = rotate_axis_angle((0, 0, 2), math.pi / 2, (1, 0, 0))
    >>> [round(c, 4) + 0.0 for c in q], [round(c, 4) + 0.0 for c in w]
    ([0.7071, 0.0, 0.0, 0.7071], [0.0, 1.0, 0.0])
    """
    q = quat_from_axis_angle(axis, angle)
    return q, quat_rotate(q, v)
