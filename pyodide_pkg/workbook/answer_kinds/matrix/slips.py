"""Slips a whole matrix can make, named from the key alone: transpose, inverse, R(−θ), degrees, swaps, negation.

>>> c, s = math.cos(math.radians(30)), math.sin(math.radians(30))
>>> key = [[c, -s], [s, c]]
>>> [tag for tag, _ in whole_matrix_slips([[c, s], [-s, c]], key, rotation_angle=math.radians(30))]
['transpose', 'inverse', 'sine-sign']
"""

from __future__ import annotations

import math
from collections.abc import Callable
from functools import partial

from ...reference.linalg import inverse
from ...tolerance import agrees

Matrix = list[list[float]]


def _agree(a: Matrix, b: Matrix) -> bool:
    if len(a) != len(b):
        return False
    for ra, rb in zip(a, b):
        if len(ra) != len(rb):
            return False
        for x, y in zip(ra, rb):
            if not agrees(x, y):
                return False
    return True


def _sine_flipped(key: Matrix, theta: float) -> Matrix | None:
    s = abs(math.sin(theta))
    if s < 1e-9:
        return None
    out = [row[:] for row in key]
    flipped = False
    for i, row in enumerate(key):
        for j, v in enumerate(row):
            if i != j and v != 0 and agrees(abs(v), s):
                out[i][j] = -v
                flipped = True
    return out if flipped else None


def _degrees_as_radians(key: Matrix, theta: float) -> Matrix | None:
    c, s = math.cos(theta), math.sin(theta)
    wrong = math.degrees(theta)  # the number of degrees, typed into a calculator in radian mode
    wc, ws = math.cos(wrong), math.sin(wrong)
    out = [row[:] for row in key]
    changed = False
    for i, row in enumerate(key):
        for j, v in enumerate(row):
            table = ((c, wc), (-c, -wc), (s, ws), (-s, -ws)) if i == j else ((s, ws), (-s, -ws), (c, wc), (-c, -wc))
            for right, misread in table:
                if abs(right) > 1e-9 and agrees(v, right):
                    out[i][j] = misread
                    changed = True
                    break
    return out if changed else None


def whole_matrix_slips(got: Matrix, key: Matrix, *, rotation_angle: float | None = None,
                       names: tuple[str, ...] = ()) -> list[tuple[str, str]]:
    """Known whole-matrix slips that ``got`` matches, most specific first: ``(tag, message)``.

    ``names`` are a vector's components' names, in reading order (the swap then names them).
    Tags: transpose, inverse, sine-sign, degrees, rows-swapped, columns-swapped,
    negated. Each is tried only where it differs from the key by more than the
    tolerance. ``rotation_angle`` (radians) is the angle the key was built from;
    the sine-sign and degrees slips need it.

    R(30°) answered with R(−30°): for a rotation that is the transpose, the
    inverse and the flipped sine terms at once.

    >>> c, s = math.cos(math.radians(30)), math.sin(math.radians(30))
    >>> key = [[c, -s], [s, c]]
    >>> [tag for tag, _ in whole_matrix_slips([[c, s], [-s, c]], key, rotation_angle=math.radians(30))]
    ['transpose', 'inverse', 'sine-sign']
    >>> deg = math.radians(30)
    >>> [tag for tag, _ in whole_matrix_slips([[math.cos(30), -math.sin(30)], [math.sin(30), math.cos(30)]], key,
    ...                                         rotation_angle=deg)]
    ['degrees']
    >>> [tag for tag, _ in whole_matrix_slips([[-c, s], [-s, -c]], key)]
    ['negated']
    >>> whole_matrix_slips(key, key), whole_matrix_slips([[1, 0], [0, 1]], key)
    ([], [])
    """
    n_rows = len(key)
    n_cols = len(key[0]) if key else 0
    if len(got) != n_rows or any(len(row) != n_cols for row in got):
        return []
    candidates: list[tuple[str, str, Callable[[], Matrix | None]]] = []  # built only when tried
    if n_rows == n_cols:
        candidates.append(("transpose", "That is the transpose of the answer: its rows are the answer's columns.",
                           lambda: [list(col) for col in zip(*key)]))
        candidates.append(("inverse", "That is the inverse of the answer: the transformation that undoes it.",
                           lambda: _inverse_or_none(key)))
    if rotation_angle is not None:
        theta = rotation_angle
        candidates.append(("sine-sign", "The sine terms have the wrong sign: that is R(−θ), a turn the other way. "
                           "In R(θ), −sin θ sits in the first row.", lambda: _sine_flipped(key, theta)))
        candidates.append(("degrees", "Those values come from the angle in degrees read as radians: set the "
                           "calculator to degrees, or multiply by π/180 first.",
                           lambda: _degrees_as_radians(key, theta)))
    def swapped(what: str, a: int, b: int) -> str:  # a vector's components by their names
        return (f"The values of {names[a]} and {names[b]} are swapped." if names
                else f"{what} {a + 1} and {b + 1} are swapped.")

    for a in range(n_rows):
        for b in range(a + 1, n_rows):
            candidates.append(("rows-swapped", swapped("Rows", a, b), partial(_swap_rows, key, a, b)))
    for a in range(n_cols):
        for b in range(a + 1, n_cols):
            candidates.append(("columns-swapped", swapped("Columns", a, b),
                               partial(_swap_columns, key, a, b)))
    candidates.append(("negated", "Every sign is flipped: the whole matrix is negated.",
                       lambda: [[-v for v in row] for row in key]))
    out: list[tuple[str, str]] = []
    for tag, message, build in candidates:
        if any(t == tag for t, _ in out):
            continue
        candidate = build()
        # got must match the slip, and the slip must differ from the key (R(180°) is its own transpose)
        if candidate is not None and _agree(got, candidate) and not _agree(candidate, key):
            out.append((tag, message))
    return out


def _inverse_or_none(key: Matrix) -> Matrix | None:
    try:
        return inverse(key)
    except (ValueError, ZeroDivisionError):
        return None


def _swap_rows(key: Matrix, a: int, b: int) -> Matrix:
    out = [row[:] for row in key]
    out[a], out[b] = out[b], out[a]
    return out


def _swap_columns(key: Matrix, a: int, b: int) -> Matrix:
    out = [row[:] for row in key]
    for row in out:
        row[a], row[b] = row[b], row[a]
    return out
