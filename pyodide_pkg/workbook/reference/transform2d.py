"""2D homogeneous transforms: one 3×3 matrix for a turn and a shift together."""

from __future__ import annotations

import math

from .linalg import Matrix, matmul, matvec


def transform2d(x: float, y: float, theta: float) -> Matrix:
    """T = [[R(θ), t], [0, 1]]: the pose of a frame at (x, y) with heading θ.

    >>> [[round(v, 4) + 0.0 for v in row] for row in transform2d(2, 1, math.pi / 2)]
    [[0.0, -1.0, 2.0], [1.0, 0.0, 1.0], [0.0, 0.0, 1.0]]
    """
    c, s = math.cos(theta), math.sin(theta)
    return [[c, -s, float(x)], [s, c, float(y)], [0.0, 0.0, 1.0]]


def apply(T: Matrix, px: float, py: float) -> tuple[float, float]:
    """Map the point (px, py) through T (append 1, multiply, drop the 1).

    Exercise 1.1: robot at (3, 4), θ = 0; the point (1, 0) lands on (4, 4).

    >>> apply(transform2d(3, 4, 0), 1, 0)
    (4.0, 4.0)

    Exercise 1.2: robot at (2, 1) facing 90°; (1, 0) lands on (2, 2).

    >>> [round(v, 4) for v in apply(transform2d(2, 1, math.pi / 2), 1, 0)]
    [2.0, 2.0]
    """
    x, y, _ = matvec(T, [px, py, 1.0])
    return (x, y)


def chain(*transforms: Matrix) -> Matrix:
    """The product T1·T2·…·Tn (apply the rightmost first).

    Exercise 1.3: T_world_base · T_base_tool sends the tool point (1, 0)
    to (2, 2) in the world.

    >>> T = chain(transform2d(0, 1, 0), transform2d(2, 0, math.pi / 2))
    >>> [round(v, 4) for v in apply(T, 1, 0)]
    [2.0, 2.0]
    """
    out = transforms[0]
    for T in transforms[1:]:
        out = matmul(out, T)
    return out


def inverse_transform(T: Matrix) -> Matrix:
    """T⁻¹ = [[Rᵀ, −Rᵀt], [0, 1]], with no general matrix inversion.

    Exercise 1.4: taking a world point back into the robot frame.

    >>> T = transform2d(2, 1, math.pi / 2)
    >>> [round(v, 4) + 0.0 for v in apply(inverse_transform(T), 2, 2)]
    [1.0, 0.0]
    >>> [[round(v, 4) + 0.0 for v in row] for row in chain(T, inverse_transform(T))]
    [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]
    """
    (r00, r01, tx), (r10, r11, ty), _ = T
    return [[r00, r10, -(r00 * tx + r10 * ty)],
            [r01, r11, -(r01 * tx + r11 * ty)],
            [0.0, 0.0, 1.0]]
