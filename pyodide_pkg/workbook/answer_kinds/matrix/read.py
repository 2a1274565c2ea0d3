"""Reading a matrix answer: pasted text or one text per entry, to a grid of readings.

Every entry is read by :func:`workbook.expr.read_quantity` in its own unit,
and every entry that cannot be read is reported at once, by position.
Components written with their names are placed by name (``y = 2`` in the first
entry of an (x, y) vector goes to y), never graded by position. A whole matrix
typed (not pasted) into one box, the others empty, is read as if pasted.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from ...expr import InvalidAnswer, Reading, is_one_value, named_entry, place_by_name, read_quantity, split_matrix
from ...expr.layout import describe_shape
from ...verdict import Verdict

if TYPE_CHECKING:
    from . import MatrixAnswer

Grid = list[list[str]]


def split(ans: MatrixAnswer, text: object) -> dict:
    """The ``split`` op: ``{entries}`` for a whole matrix, ``{cell}`` for one value (it stays where it
    was pasted), or ``{message}``."""
    if is_one_value(text):
        return {"cell": str(text).strip()}
    try:
        return {"entries": split_matrix(text, ans.shape, ans.names)}
    except InvalidAnswer as err:
        return {"message": str(err)}


def _cells(ans: MatrixAnswer, answer: object) -> Grid:
    """The entry texts of an answer: pasted text, or the grid of inputs (names placed by name)."""
    if isinstance(answer, str):
        return split_matrix(answer, ans.shape, ans.names)
    if not isinstance(answer, (list, tuple)) or not all(isinstance(row, (list, tuple)) for row in answer):
        raise InvalidAnswer("Fill in every entry of the answer, then check.")
    grid = [["" if v is None else str(v) for v in row] for row in answer]
    r, c = ans.shape
    if len(grid) != r or any(len(row) != c for row in grid):
        given = f"{len(grid)}×{len(grid[0]) if grid else 0}"
        raise InvalidAnswer(f"This answer is {describe_shape(ans.shape)}; the boxes sent were {given}.")
    texts = [text for row in grid for text in row]
    typed = [text for text in texts if text.strip()]
    if len(texts) > 1 and len(typed) == 1 and _whole(typed[0]):
        return split_matrix(typed[0], ans.shape, ans.names)  # a whole matrix typed into one box, as if pasted
    pairs = [named_entry(text) for text in texts]
    if not any(pairs):
        return grid
    if any(text.strip() and not pair for text, pair in zip(texts, pairs)):
        raise InvalidAnswer("Give every entry its name, or none: x = 1 in each box, or just the values.")
    return place_by_name([p for p in pairs if p], ans.shape, ans.names, partial=True)


def _whole(text: str) -> bool:
    """Text in one box that is a whole vector or matrix (``[[0, -1], [1, 0]]``, ``x = 1, y = 2``), not one value."""
    return not is_one_value(text) and (named_entry(text) is None or any(ch in text for ch in ",;\n"))


def reply(readings: list[list[Reading]]) -> dict:
    """The ``read`` op's reply: every entry's value as read."""
    return {"value": [[r.value for r in row] for row in readings]}


def read(ans: MatrixAnswer, answer: object) -> list[list[Reading]] | Verdict:
    """A reading per entry, or an ``invalid`` verdict naming every entry that could not be read."""
    try:
        grid = _cells(ans, answer)
    except InvalidAnswer as err:
        return Verdict("invalid", str(err))
    out: list[list[Reading]] = []
    empty: list[tuple[int, int]] = []
    problems: list[tuple[tuple[int, int], str]] = []
    for i, row in enumerate(grid):
        out.append([])
        for j, text in enumerate(row):
            if not text.strip():
                empty.append((i + 1, j + 1))
                continue
            try:
                out[-1].append(read_quantity(text, ans.expect(i, j)))
            except InvalidAnswer as err:
                problems.append(((i + 1, j + 1), str(err)))
    if not empty and not problems:
        return out
    parts = []
    if empty:
        where = ", ".join(f"({i},{j})" for i, j in empty)
        parts.append(f"Entry {where} is empty." if len(empty) == 1 else f"Entries {where} are empty.")
    for (i, j), message in problems[:3]:
        parts.append(f"Entry ({i},{j}): {message}")
    if len(problems) > 3:
        parts.append(f"{len(problems) - 3} more entries could not be read either.")
    positions = sorted(empty + [p for p, _ in problems])
    return Verdict("invalid", " ".join(parts), data={"invalid": [list(p) for p in positions]})
