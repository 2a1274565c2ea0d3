"""Tiny dense linear algebra on lists of lists (no NumPy needed)."""

from __future__ import annotations

Matrix = list[list[float]]
Vector = list[float]


def identity(n: int) -> Matrix:
    """The n×n identity.

    >>> identity(2)
    [[1.0, 0.0], [0.0, 1.0]]
    """
    return [[1.0 if i == j else 0.0 for j in range(n)] for i in range(n)]


def transpose(a: Matrix) -> Matrix:
    """Example.

    >>> transpose([[1, 2], [3, 4]])
    [[1, 3], [2, 4]]
    """
    return [list(col) for col in zip(*a)]


def matmul(a: Matrix, b: Matrix) -> Matrix:
    """Matrix product.

    >>> matmul([[0, -1], [1, 0]], [[3], [0]])
    [[0], [3]]
    """
    bt = transpose(b)
    return [[sum(x * y for x, y in zip(row, col)) for col in bt] for row in a]


def matvec(a: Matrix, v: Vector) -> Vector:
    """Matrix times vector.

    >>> matvec([[0, -1], [1, 0]], [3, 0])
    [0, 3]
    """
    return [sum(x * y for x, y in zip(row, v)) for row in a]


def add(a: Matrix, b: Matrix) -> Matrix:
    """Example.

    >>> add([[1, 0]], [[0.5, 2]])
    [[1.5, 2]]
    """
    return [[x + y for x, y in zip(ra, rb)] for ra, rb in zip(a, b)]


def sub(a: Matrix, b: Matrix) -> Matrix:
    """Example.

    >>> sub([[1, 0]], [[0.5, 2]])
    [[0.5, -2]]
    """
    return [[x - y for x, y in zip(ra, rb)] for ra, rb in zip(a, b)]


def scale(a: Matrix, k: float) -> Matrix:
    """Example.

    >>> scale([[1, 2]], 0.5)
    [[0.5, 1.0]]
    """
    return [[k * x for x in row] for row in a]


def det2(a: Matrix) -> float:
    """Determinant of a 2×2 matrix.

    >>> det2([[-1, -1], [1, 0]])
    1
    """
    return a[0][0] * a[1][1] - a[0][1] * a[1][0]


PIVOT_RTOL = 1e-12


def inverse(a: Matrix) -> Matrix:
    """Inverse by Gauss–Jordan elimination with partial pivoting.

    >>> inverse([[0.01, 0, 0], [0, 0.01, 0], [0, 0, 0.001]])[0][0]
    100.0
    >>> inverse([[1, 2], [2, 4]])
    Traceback (most recent call last):
    ...
    ValueError: matrix is singular (a pivot is 0 times its largest entry 4)

    The singularity test is relative to the matrix's size (its largest entry),
    not an absolute 1e-12: a tiny but well-conditioned matrix inverts, and a
    singular one stays singular at any scale.

    >>> inverse([[1e-13, 0], [0, 1e-13]])[0][0]
    10000000000000.0
    >>> inverse([[1e9, 2e9], [2e9, 4e9]])
    Traceback (most recent call last):
    ...
    ValueError: matrix is singular (a pivot is 0 times its largest entry 4e+09)
    >>> inverse([[0.0, 0.0], [0.0, 0.0]])
    Traceback (most recent call last):
    ...
    ValueError: matrix is singular (all its entries are 0)
    """
    n = len(a)
    m = [[float(x) for x in row] + identity(n)[i] for i, row in enumerate(a)]
    size = max((abs(x) for row in m for x in row[:n]), default=0.0)
    if n and size == 0.0:
        raise ValueError("matrix is singular (all its entries are 0)")
    for c in range(n):
        p = max(range(c, n), key=lambda r: abs(m[r][c]))
        if abs(m[p][c]) <= PIVOT_RTOL * size:
            raise ValueError(f"matrix is singular (a pivot is {abs(m[p][c]) / size:.3g} times its largest entry "
                             f"{size:g})")
        m[c], m[p] = m[p], m[c]
        piv = m[c][c]
        m[c] = [x / piv for x in m[c]]
        for r in range(n):
            if r != c and m[r][c] != 0.0:
                f = m[r][c]
                m[r] = [x - f * y for x, y in zip(m[r], m[c])]
    return [row[n:] for row in m]
