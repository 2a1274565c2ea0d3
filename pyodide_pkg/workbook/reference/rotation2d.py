"""2D rotations: the matrix R(θ), rotating a point, composing rotations."""

from __future__ import annotations

import math

from .linalg import Matrix, matmul


def rot2(theta: float) -> Matrix:
    """R(θ), the counter-clockwise rotation by θ radians.

    >>> [[round(x, 4) + 0.0 for x in row] for row in rot2(math.pi / 2)]
    [[0.0, -1.0], [1.0, 0.0]]
    """
    c, s = math.cos(theta), math.sin(theta)
    return [[c, -s], [s, c]]


def rotate_2d(x: float, y: float, theta: float) -> tuple[float, float]:
    """Rotate the point (x, y) counter-clockwise by θ radians about the origin.

    Exercise 0.1: (3, 0) by 90° lands on (0, 3).

    >>> [round(v, 4) + 0.0 for v in rotate_2d(3, 0, math.pi / 2)]
    [0.0, 3.0]

    Exercise 0.4: (1, 1) by 45° lands on (0, √2).

    >>> [round(v, 4) + 0.0 for v in rotate_2d(1, 1, math.pi / 4)]
    [0.0, 1.4142]
    """
    c, s = math.cos(theta), math.sin(theta)
    return (c * x - s * y, s * x + c * y)


def compose(alpha: float, beta: float) -> Matrix:
    """R(α)·R(β), which equals R(α + β).

    Exercise 0.2: the (1,1) entry of R(30°)·R(60°) is cos 90° = 0.

    >>> round(compose(math.radians(30), math.radians(60))[0][0], 12) + 0.0
    0.0
    """
    return matmul(rot2(alpha), rot2(beta))


def det_rot2(theta: float) -> float:
    """det R(θ) = cos²θ + sin²θ, which is 1 for every θ.

    >>> round(det_rot2(math.radians(37)), 12)
    1.0
    """
    (a, b), (c, d) = rot2(theta)
    return a * d - b * c
