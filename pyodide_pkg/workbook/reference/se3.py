"""3-D poses: SE(3) transforms [R t; 0 1], chained and inverted, and unit quaternions
(w, x, y, z), scalar first as in chapter 2: to and from matrices, the angle between
two of them, SLERP, and the scalar-last order some libraries store."""

from __future__ import annotations

import math

from .linalg import Matrix, matmul, matvec, transpose
from .rotation3d import quat_conjugate, quat_multiply

Quat = tuple[float, float, float, float]


def pose(R: Matrix, t) -> Matrix:
    """The 4×4 transform [R t; 0 1] of a rotation R and a translation t.

    >>> pose([[1, 0, 0], [0, 1, 0], [0, 0, 1]], (1, 2, 3))[3]
    [0.0, 0.0, 0.0, 1.0]
    """
    return [[float(R[i][0]), float(R[i][1]), float(R[i][2]), float(t[i])] for i in range(3)] + [[0.0, 0.0, 0.0, 1.0]]


def rotation_of(T: Matrix) -> Matrix:
    """The 3×3 rotation block of a 4×4 transform.

    >>> rotation_of(pose([[0, -1, 0], [1, 0, 0], [0, 0, 1]], (1, 2, 3)))
    [[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]]
    """
    return [list(row[:3]) for row in T[:3]]


def translation_of(T: Matrix) -> list[float]:
    """The translation column of a 4×4 transform.

    >>> translation_of(pose([[1, 0, 0], [0, 1, 0], [0, 0, 1]], (1, 2, 3)))
    [1.0, 2.0, 3.0]
    """
    return [row[3] for row in T[:3]]


def compose(*transforms: Matrix) -> Matrix:
    """The product T₁ T₂ … Tₙ: ${}^aT_b\\,{}^bT_c = {}^aT_c$ (the inner names cancel).

    >>> a = pose([[0, -1, 0], [1, 0, 0], [0, 0, 1]], (1, 0, 0))
    >>> translation_of(compose(a, pose([[1, 0, 0], [0, 1, 0], [0, 0, 1]], (2, 0, 0))))
    [1.0, 2.0, 0.0]
    """
    out = transforms[0]
    for T in transforms[1:]:
        out = matmul(out, T)
    return out


def invert(T: Matrix) -> Matrix:
    """[R t; 0 1]⁻¹ = [Rᵀ −Rᵀt; 0 1]: no general inversion needed.

    >>> T = pose([[0, -1, 0], [1, 0, 0], [0, 0, 1]], (1, 2, 3))
    >>> [round(v, 12) + 0.0 for v in translation_of(invert(T))]
    [-2.0, 1.0, -3.0]
    """
    RT = transpose(rotation_of(T))
    return pose(RT, [-v for v in matvec(RT, translation_of(T))])


def transform_point(T: Matrix, p) -> list[float]:
    """T applied to the point p: R p + t.

    >>> transform_point(pose([[0, -1, 0], [1, 0, 0], [0, 0, 1]], (1, 2, 3)), (1, 0, 0))
    [1.0, 3.0, 3.0]
    """
    return [sum(T[i][j] * p[j] for j in range(3)) + T[i][3] for i in range(3)]


def quat_to_matrix(q) -> Matrix:
    """The rotation matrix of a unit quaternion q = (w, x, y, z).

    90° about z is Rz(90°):

    >>> h = math.sqrt(0.5)
    >>> [[round(v, 12) + 0.0 for v in row] for row in quat_to_matrix((h, 0, 0, h))]
    [[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]]

    q and −q give the same matrix (every entry is a product of two components):

    >>> quat_to_matrix((0.5, 0.5, 0.5, 0.5)) == quat_to_matrix((-0.5, -0.5, -0.5, -0.5))
    True
    """
    w, x, y, z = q
    return [
        [1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
        [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
        [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)],
    ]


def quat_dot(q0, q1) -> float:
    """The 4-D dot product w₀w₁ + x₀x₁ + y₀y₁ + z₀z₁ (cos of half the angle between two unit quaternions).

    Exercise 10.4's first step: q₀ = 60° about z and q₁ written as −(120° about z).

    >>> q0 = (math.cos(math.radians(30)), 0, 0, math.sin(math.radians(30)))
    >>> q1 = (-math.cos(math.radians(60)), 0, 0, -math.sin(math.radians(60)))
    >>> round(quat_dot(q0, q1), 4)
    -0.866
    """
    return sum(a * b for a, b in zip(q0, q1))


def relative_quat(q0, q1) -> Quat:
    """q₀* ⊗ q₁: the turn that takes the orientation q₀ to q₁ (in q₀'s own axes).

    >>> relative_quat((1, 0, 0, 0), (0, 0, 0, 1))
    (0, 0, 0, 1)
    """
    return quat_multiply(quat_conjugate(q0), q1)


def angle_between(q0, q1) -> float:
    """The smallest angle (radians, in [0, π]) of the turn from orientation q₀ to q₁.

    The relative turn q₀* ⊗ q₁ has angle 2·atan2(‖v‖, w); q and −q are the same
    rotation, so the sign of w is dropped: 2·atan2(‖v‖, |w|) never exceeds π.

    >>> h = math.sqrt(0.5)
    >>> round(math.degrees(angle_between((1, 0, 0, 0), (h, 0, 0, h))), 9)
    90.0
    >>> angle_between((0.5, 0.5, 0.5, 0.5), (-0.5, -0.5, -0.5, -0.5))
    0.0

    300° one way is 60° the other:

    >>> q = (math.cos(math.radians(150)), 0, 0, math.sin(math.radians(150)))
    >>> round(math.degrees(angle_between((1, 0, 0, 0), q)), 9)
    60.0
    """
    w, x, y, z = relative_quat(q0, q1)
    return 2 * math.atan2(math.hypot(x, y, z), abs(w))


NEARLY_EQUAL = 1e-6  # below this sin(Ω), SLERP's division is replaced by the straight line


def slerp(q0, q1, t: float) -> Quat:
    """Spherical linear interpolation from unit quaternion q₀ (t = 0) to q₁ (t = 1), the short way.

    When q₀·q₁ < 0, q₁ is replaced by −q₁ (the same rotation) so the path turns by
    less than 180°. Along the arc of angle Ω = acos(q₀·q₁),
    q(t) = (sin((1−t)Ω) q₀ + sin(tΩ) q₁) / sin Ω, turning at a constant rate.
    When the two are nearly equal, sin Ω goes to 0: there the straight line,
    normalised, is the same path to within rounding.

    The midpoint of no turn and 90° about z is 45° about z:

    >>> h = math.sqrt(0.5)
    >>> [round(c, 6) + 0.0 for c in slerp((1, 0, 0, 0), (h, 0, 0, h), 0.5)]
    [0.92388, 0.0, 0.0, 0.382683]

    The ends, and q₁ = −q₀ (no turn at all):

    >>> slerp((1, 0, 0, 0), (h, 0, 0, h), 0) == (1.0, 0.0, 0.0, 0.0)
    True
    >>> slerp((0.5, 0.5, 0.5, 0.5), (-0.5, -0.5, -0.5, -0.5), 0.3)
    (0.5, 0.5, 0.5, 0.5)
    """
    d = quat_dot(q0, q1)
    if d < 0:  # the double cover: −q₁ is the same rotation, the short way round
        q1, d = tuple(-c for c in q1), -d
    d = min(d, 1.0)
    omega = math.acos(d)
    s = math.sin(omega)
    if s < NEARLY_EQUAL:
        q = tuple((1 - t) * a + t * b for a, b in zip(q0, q1))
        n = math.sqrt(sum(c * c for c in q))
        return tuple(c / n for c in q)
    a, b = math.sin((1 - t) * omega) / s, math.sin(t * omega) / s
    return tuple(a * c0 + b * c1 for c0, c1 in zip(q0, q1))


def lerp_normalised(q0, q1, t: float) -> Quat:
    """The straight line between q₀ and q₁, made unit again (no short-way flip): what SLERP is not.

    >>> h = math.sqrt(0.5)
    >>> [round(c, 6) + 0.0 for c in lerp_normalised((1, 0, 0, 0), (h, 0, 0, h), 0.5)]
    [0.92388, 0.0, 0.0, 0.382683]
    """
    q = tuple((1 - t) * a + t * b for a, b in zip(q0, q1))
    n = math.sqrt(sum(c * c for c in q))
    return tuple(c / n for c in q)


def to_xyzw(q) -> Quat:
    """(w, x, y, z) stored scalar last, (x, y, z, w), as ROS messages and SciPy's ``as_quat()`` do.

    >>> to_xyzw((1, 2, 3, 4))
    (2, 3, 4, 1)
    """
    return (q[1], q[2], q[3], q[0])


def from_xyzw(q) -> Quat:
    """(x, y, z, w), scalar last, read back into the workbook's (w, x, y, z).

    >>> from_xyzw((2, 3, 4, 1))
    (1, 2, 3, 4)
    """
    return (q[3], q[0], q[1], q[2])
