"""Vector and matrix answers: read a pasted matrix, parse its entries, name whole-matrix slips.

A matrix is a list of rows. Entries are read by the scalar parser, so each may
be an expression (``sqrt(2)/2``, ``cos(30°)``).

>>> parse_pasted("[[0, -1], [1, 0]]")
[['0', '-1'], ['1', '0']]
>>> parse_entries(parse_pasted("cos(60°) -sin(60°); sin(60°) cos(60°)"), (2, 2))[0]
[0.5000000000000001, -0.8660254037844386]
"""

from __future__ import annotations

import math
import re
from typing import Callable

from .answers import InvalidAnswer, normalise, parse_quantity
from .reference.linalg import inverse
from .tolerance import agrees

Grid = list[list[str]]
Matrix = list[list[float]]


class InvalidEntries(InvalidAnswer):
    """Some entries could not be read; ``positions`` lists them as 1-based (row, col)."""

    def __init__(self, message: str, positions: list[tuple[int, int]]):
        super().__init__(message)
        self.positions = positions


# --------------------------------------------------------------------------- pasted text -> entry texts

_WRAPPER = re.compile(r"^\s*(?:np\.|numpy\.|sympy\.)?(?:array|matrix|Matrix|mat)\s*\((.*)\)\s*$", re.S)
_DTYPE = re.compile(r",\s*dtype\s*=\s*[\w.]+\s*$")
_OPERATORS = "+-*/^,("


def _split_top(s: str, seps: str) -> list[str]:
    """Split ``s`` at the characters of ``seps`` outside parentheses."""
    out, depth, start = [], 0, 0
    for i, ch in enumerate(s):
        if ch == "(":
            depth += 1
        elif ch == ")":
            depth = max(0, depth - 1)
        elif ch in seps and depth == 0:
            out.append(s[start:i])
            start = i + 1
    out.append(s[start:])
    return out


def _split_row(row: str) -> list[str]:
    """Entries of one row: at commas if it has any, else at spaces the way MATLAB reads them.

    >>> _split_row("0 -1"), _split_row("1 - 2  3"), _split_row("sqrt(2) / 2, cos(30°)")
    (['0', '-1'], ['1 - 2', '3'], ['sqrt(2) / 2', 'cos(30°)'])
    """
    parts = _split_top(row, ",")
    if len(parts) > 1:
        parts = [p.strip() for p in parts]
        if parts[-1] == "" and len(parts) > 1 and any(parts[:-1]):  # a trailing comma: [1, 2, ]
            parts = parts[:-1]
        return parts
    words = [w for w in _split_top(row.strip(), " \t") if w != ""]
    entries: list[str] = []
    for k, word in enumerate(words):
        prev = entries[-1] if entries else ""
        nxt_is_binary = word in ("+", "-") and k + 1 < len(words)
        joins = entries and (prev[-1] in _OPERATORS or word[0] in "*/^)" or nxt_is_binary
                             or (prev in ("+", "-")))
        if joins:
            entries[-1] = f"{prev} {word}"
        else:
            entries.append(word)
    return entries


def parse_pasted(text: object, shape: tuple[int, int] | None = None) -> Grid:
    """Split a pasted matrix or vector into entry texts, one list per row.

    Reads ``[[0,-1],[1,0]]``, ``0 -1; 1 0``, ``[0, -1; 1, 0]``, rows on separate
    lines, a NumPy repr, ``{{0,-1},{1,0}}``. With ``shape=(r, c)`` a flat list of
    r·c entries (one row, or one column) is reshaped row by row, so ``[1, 2, 3]``
    fills a 3×1 column; any other count is InvalidAnswer saying what is needed.

    >>> parse_pasted("array([[ 0., -1.],\\n       [ 1.,  0.]])")
    [['0.', '-1.'], ['1.', '0.']]
    >>> parse_pasted("[1, 2, 3]", shape=(3, 1))
    [['1'], ['2'], ['3']]
    >>> parse_pasted("1 2; 3 4", shape=(3, 1))
    Traceback (most recent call last):
    ...
    workbook.answers.InvalidAnswer: This answer is a 3×1 column vector (3 entries); what you pasted is 2×2 (4 entries).
    """
    if not isinstance(text, str) or not text.strip():
        raise InvalidAnswer("Paste or type the matrix first, for example [[0, -1], [1, 0]] or 0 -1; 1 0.")
    if len(text) > 4000:
        raise InvalidAnswer("That is too long for a matrix answer.")
    s = normalise(text).replace("{", "[").replace("}", "]")
    m = _WRAPPER.match(s)
    if m:
        s = _DTYPE.sub("", m.group(1))
    if s.count("[") != s.count("]"):
        raise InvalidAnswer("The brackets do not match: check every “[” has its “]”.")
    if "[" in s:
        groups = re.findall(r"\[([^\[\]]*)\]", s)
        outside = re.sub(r"\[[^\[\]]*\]", "", s)
        if re.sub(r"[\s,;\[\]]", "", outside):
            raise InvalidAnswer("Only the matrix is expected: something is outside its brackets.")
        rows = [r for g in groups for r in _split_top(g, ";\n")] if len(groups) == 1 else groups
    else:
        if s.startswith("(") and s.endswith(")") and len(_split_top(s[1:-1], ",")) > 1:
            s = s[1:-1]  # a pasted tuple: (1, 2, 3)
        rows = _split_top(s, ";\n")
    grid = [_split_row(r) for r in rows if r.strip()]
    if not grid:
        raise InvalidAnswer("Paste or type the matrix first, for example [[0, -1], [1, 0]] or 0 -1; 1 0.")
    return _fit(grid, shape) if shape else grid


def _describe(shape: tuple[int, int]) -> str:
    r, c = shape
    if c == 1:
        return f"a {r}×1 column vector ({r} entries)"
    if r == 1:
        return f"a 1×{c} row vector ({c} entries)"
    return f"a {r}×{c} matrix ({r} rows of {c})"


def _fit(grid: Grid, shape: tuple[int, int]) -> Grid:
    r, c = shape
    counts = [len(row) for row in grid]
    if len(grid) == r and all(n == c for n in counts):
        return grid
    total = sum(counts)
    if (len(grid) == 1 or all(n == 1 for n in counts)) and total == r * c:
        flat = [e for row in grid for e in row]
        return [flat[i * c:(i + 1) * c] for i in range(r)]
    if len(set(counts)) > 1:
        k = next(i for i, n in enumerate(counts) if n != counts[0])
        raise InvalidAnswer(
            f"Row {k + 1} has {counts[k]} entries and row 1 has {counts[0]}: this answer is {_describe(shape)}.")
    raise InvalidAnswer(
        f"This answer is {_describe(shape)}; what you pasted is {len(grid)}×{counts[0]} ({total} entries).")


# --------------------------------------------------------------------------- entry texts -> numbers

def parse_entries(grid: Grid, shape: tuple[int, int], expect: str | None = None) -> Matrix:
    """Parse every entry with the scalar parser; report ALL entries that fail at once.

    ``expect`` is the unit asked for (see :func:`workbook.answers.parse_quantity`).

    >>> parse_entries([["1", ""], ["x", "0"]], (2, 2))
    Traceback (most recent call last):
    ...
    workbook.shaped.InvalidEntries: Entry (1,2) is empty. Entry (2,1): Unknown name “x”. Use numbers, pi, e and functions such as sqrt, sin, cos, atan2.
    """
    r, c = shape
    if len(grid) != r or any(len(row) != c for row in grid):
        raise InvalidAnswer(f"This answer is {_describe(shape)}.")
    values: Matrix = []
    empty: list[tuple[int, int]] = []
    problems: list[tuple[tuple[int, int], str]] = []
    for i, row in enumerate(grid, 1):
        out = []
        for j, text in enumerate(row, 1):
            if not isinstance(text, str) or not text.strip():
                empty.append((i, j))
                out.append(math.nan)
                continue
            try:
                out.append(parse_quantity(text, expect))
            except InvalidAnswer as err:
                problems.append(((i, j), str(err)))
                out.append(math.nan)
        values.append(out)
    if not empty and not problems:
        return values
    parts = []
    if empty:
        where = ", ".join(f"({i},{j})" for i, j in empty)
        parts.append(f"Entry {where} is empty." if len(empty) == 1 else f"Entries {where} are empty.")
    for (i, j), message in problems[:3]:
        parts.append(f"Entry ({i},{j}): {message}")
    if len(problems) > 3:
        parts.append(f"{len(problems) - 3} more entries could not be read either.")
    positions = sorted(empty + [p for p, _ in problems])
    raise InvalidEntries(" ".join(parts), positions)


# --------------------------------------------------------------------------- whole-matrix slips

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


def wrong_entries(got: Matrix, key: Matrix) -> list[tuple[int, int]]:
    """1-based (row, col) of every entry outside the tolerance.

    >>> wrong_entries([[0.5, -0.866], [0.866, 0.5]], [[0.5, -0.866], [-0.866, 0.5]])
    [(2, 1)]
    """
    return [(i, j) for i, (rg, rk) in enumerate(zip(got, key), 1)
            for j, (g, k) in enumerate(zip(rg, rk), 1) if not agrees(g, k)]


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


def whole_matrix_slips(got: Matrix, key: Matrix, *, rotation_angle: float | None = None) -> list[tuple[str, str]]:
    """Known whole-matrix slips that ``got`` matches, most specific first: ``(tag, message)``.

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
    for a in range(n_rows):
        for b in range(a + 1, n_rows):
            candidates.append(("rows-swapped", f"Rows {a + 1} and {b + 1} are swapped.",
                               lambda a=a, b=b: _swap_rows(key, a, b)))
    for a in range(n_cols):
        for b in range(a + 1, n_cols):
            candidates.append(("columns-swapped", f"Columns {a + 1} and {b + 1} are swapped.",
                               lambda a=a, b=b: _swap_columns(key, a, b)))
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
