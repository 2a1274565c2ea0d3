"""How a vector or matrix is laid out in text: rows, entries, names, and the notations learners paste.

Reads the notations of NumPy (``[[0, -1], [1, 0]]``, ``array(...)``), MATLAB
(``[0 -1; 1 0]``), Mathematica (``{{0,-1},{1,0}}``), rows on separate lines, a
tuple (``(1, 2, 3)``), a transposed row (``(1, 2, 3)ᵀ``, ``[1 2 3]^T``,
``[1 2 3]'``), the page's own LaTeX (``\\begin{bmatrix} 1 & 2 \\\\ 3 & 4
\\end{bmatrix}``, also ``pmatrix``, ``vmatrix``, ``array``), and components
written with their names (``x = 1, y = 2``), which are placed by name, never by
position. Each entry stays text here; the entries are read as numbers by
:mod:`.quantity`, one at a time.

>>> split_matrix("[[0, -1], [1, 0]]")
[['0', '-1'], ['1', '0']]
>>> split_matrix(r"\\begin{pmatrix} \\frac{1}{2} & 0 \\\\ 0 & 1 \\end{pmatrix}")
[['\\\\frac{1}{2}', '0'], ['0', '1']]
>>> split_matrix("(1, 2, 3)ᵀ", shape=(3, 1))
[['1'], ['2'], ['3']]
>>> split_matrix("y = 2, x = 1", shape=(2, 1), names=("x", "y"))
[['1'], ['2']]
"""

from __future__ import annotations

import re

from .. import units as U
from .grammar import ALIASES, FUNCTIONS, MAX_LENGTH, InvalidAnswer
from .tokens import canonical_name, normalise

Grid = list[list[str]]

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


_FUNCTION_END = re.compile(r"(?:^|[^A-Za-z])(?:%s)$" % "|".join(sorted(
    (*FUNCTIONS, *ALIASES, "√"), key=len, reverse=True)))


def _split_row(row: str) -> list[str]:
    """Entries of one row: at commas if it has any, else at spaces the way MATLAB reads them;
    a function keeps the argument after its space (``-sin 120°`` is one entry), a number its unit.

    >>> _split_row("0 -1"), _split_row("1 - 2  3"), _split_row("sqrt(2) / 2, cos(30°)")
    (['0', '-1'], ['1 - 2', '3'], ['sqrt(2) / 2', 'cos(30°)'])
    >>> _split_row("cos 30° -sin 30°"), _split_row("1 m 2 m")
    (['cos 30°', '-sin 30°'], ['1 m', '2 m'])
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
                             or (prev in ("+", "-")) or _FUNCTION_END.search(prev) is not None
                             or (U.lookup(word) is not None and prev[-1] in "0123456789.)°"))
        if joins:
            entries[-1] = f"{prev} {word}"
        else:
            entries.append(word)
    return entries


def split_matrix(text: object, shape: tuple[int, int] | None = None, names: tuple[str, ...] = ()) -> Grid:
    """Split a pasted matrix or vector into entry texts, one list per row.

    With ``shape=(r, c)`` a flat list of r·c entries (one row, or one column) is
    reshaped row by row, so ``[1, 2, 3]`` fills a 3×1 column; any other count is
    InvalidAnswer saying what is needed. ``names`` are the components' names of
    a vector answer (``"theta|th"`` gives a name its other spellings).

    >>> split_matrix("array([[ 0., -1.],\\n       [ 1.,  0.]])")
    [['0.', '-1.'], ['1.', '0.']]
    >>> split_matrix("[1, 2, 3]", shape=(3, 1))
    [['1'], ['2'], ['3']]
    >>> split_matrix("1 2; 3 4", shape=(3, 1))
    Traceback (most recent call last):
    ...
    workbook.expr.InvalidAnswer: This answer is a 3×1 column vector (3 entries); what you pasted is 2×2 (4 entries).
    """
    if not isinstance(text, str) or not text.strip():
        raise InvalidAnswer("Paste or type the matrix first, for example [[0, -1], [1, 0]] or 0 -1; 1 0.")
    if len(text) > 4000:
        raise InvalidAnswer("That is too long for a matrix answer.")
    text, transposed = _transpose_mark(text)
    if "\\begin" in text:
        grid = _latex_matrix(text)
    else:
        named = _named(text, shape, names)
        if named is not None:
            return named
        grid = _bracketed(text)
    if transposed:
        grid = [list(col) for col in zip(*grid)] if all(len(row) == len(grid[0]) for row in grid) else grid
    return _fit(grid, shape) if shape else grid


def _bracketed(text: str) -> Grid:
    """Rows and entries of a matrix written with brackets, semicolons or lines."""
    s = _strip_name(normalise(text)).replace("{", "[").replace("}", "]")
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
    return grid


_MARKS = re.compile(r"(?:ᵀ|\^\s*\{?\s*(?:T|\\top|\\intercal)\s*\}?|\\top|')\s*$")
_CLOSED = re.compile(r"[)\]}]\s*$|\\end\{\w+\}\s*(?:\\right[)\]])?\s*$")


def _transpose_mark(text: str) -> tuple[str, bool]:
    """The text without a transpose mark after its closing bracket (``(1, 2)ᵀ``, ``[1 2]'``), and whether it had one."""
    m = _MARKS.search(text)
    if m and _CLOSED.search(text[:m.start()]):
        return text[:m.start()], True
    return text, False


_ENV = re.compile(r"\\begin\{(\w+\*?)\}(?:\{[^{}]*\})?(.*?)\\end\{\1\}", re.S)


def _latex_matrix(text: str) -> Grid:
    """The entries of the last LaTeX matrix environment in ``text``: rows at ``\\\\``, entries at ``&``."""
    found = _ENV.findall(text)
    if not found:
        raise InvalidAnswer("That LaTeX matrix is not closed: end it with \\end{bmatrix}.")
    rows = [row.strip() for row in found[-1][1].split("\\\\")]
    grid = [[entry.strip() for entry in row.split("&")] for row in rows if row]
    if not grid:
        raise InvalidAnswer("That LaTeX matrix is empty.")
    return grid


_NAME = re.compile(r"^\s*(\\?[^\W\d][\w'′⁻⁺^{}\-+\\]*?)\s*[=≈]\s*(?![=])")


def _strip_name(s: str) -> str:
    """``R = [[...]]`` without ``R =``: a name in front of a whole matrix."""
    m = re.match(r"^\s*[^\W\d][\w'⁻⁺]*\s*=\s*(?=[\[({])", s)
    return s[m.end():] if m else s


def component_key(name: str) -> str:
    """How a component's name is compared: Greek spelled out, no primes, signs, braces or underscores.

    >>> component_key("θ′"), component_key("x^-"), component_key("e_θ"), component_key(r"\\theta'")
    ('theta', 'x', 'etheta', 'theta')
    """
    s = normalise(name) if "\\" in name else name
    s = canonical_name(re.sub(r"[\s'′⁻⁺^{}()\-+_]", "", s))
    return s


def named_entry(text: str) -> tuple[str, str] | None:
    """``("x", "1.5")`` for ``"x = 1.5"`` (a component written with its name), else None.

    >>> named_entry("θ' = 0.62 rad"), named_entry("0.5"), named_entry("x == 2")
    (("θ'", '0.62 rad'), None, None)
    """
    m = _NAME.match(text)
    if not m or not text[m.end():].strip():
        return None
    return m.group(1), text[m.end():].strip()


def _named(text: str, shape: tuple[int, int] | None, names: tuple[str, ...]) -> Grid | None:
    """A vector written as ``name = value`` entries, placed by name; None when no entry has a name."""
    s = text.strip()
    s = s[1:-1] if s[:1] + s[-1:] in ("()", "[]", "{}") else s
    if any(ch in s for ch in "[]{}"):
        return None
    parts = [p.strip() for p in _split_top(s, ",;\n") if p.strip()]
    pairs = [named_entry(p) for p in parts]
    if not any(pairs):
        return None
    if not all(pairs):
        raise InvalidAnswer("Give every entry its name, or none: x = 1, y = 2 (or just 1, 2 in order).")
    return place_by_name([p for p in pairs if p], shape, names)


def place_by_name(pairs: list[tuple[str, str]], shape: tuple[int, int] | None,
                  names: tuple[str, ...], partial: bool = False) -> Grid:
    """Entries written with their names, put where those names belong (a column, or a row);
    with ``partial``, a name not given leaves its entry empty instead of being an error."""
    if not names or shape is None or min(shape) != 1:
        raise InvalidAnswer("This answer's entries have no names: type the values in order, without “name =”.")
    spellings = {component_key(alias): k for k, name in enumerate(names) for alias in name.split("|")}
    shown = ", ".join(name.split("|")[0] for name in names)
    slots: list[str | None] = [None] * len(names)
    for name, value in pairs:
        k = spellings.get(component_key(name))
        if k is None:
            k = _caseless(name, spellings)
        if k is None:
            raise InvalidAnswer(f"This answer has no entry named “{name[:20]}”: its entries are {shown}.")
        if slots[k] is not None:
            raise InvalidAnswer(f"“{name[:20]}” is given twice.")
        slots[k] = value
    missing = [names[k].split("|")[0] for k, v in enumerate(slots) if v is None]
    if missing and not partial:
        raise InvalidAnswer(f"{', '.join(missing)} {'is' if len(missing) == 1 else 'are'} missing: "
                            f"this answer's entries are {shown}.")
    values = [v or "" for v in slots]
    return [[v] for v in values] if shape[1] == 1 else [values]


def _caseless(name: str, spellings: dict[str, int]) -> int | None:
    low = [k for key, k in spellings.items() if key.lower() == component_key(name).lower()]
    return low[0] if len(set(low)) == 1 else None


def is_one_value(text: object) -> bool:
    """Whether pasted text is one entry (``cos(30°) - sin(30°)``) rather than a whole matrix.

    >>> is_one_value("cos(30°) - sin(30°)"), is_one_value("0.5 -0.866"), is_one_value("[1, 2]")
    (True, False, False)
    """
    if not isinstance(text, str) or len(text) > 3 * MAX_LENGTH or "\\begin" in text or "\n" in text.strip():
        return False
    try:
        s = normalise(text)
    except InvalidAnswer:
        return False
    if any(ch in s for ch in ",;[]{}&") or named_entry(s):
        return False
    return len(_split_row(s)) == 1


def describe_shape(shape: tuple[int, int]) -> str:
    """A shape in words: ``a 3×1 column vector (3 entries)``."""
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
            f"Row {k + 1} has {counts[k]} entries and row 1 has {counts[0]}: this answer is {describe_shape(shape)}.")
    raise InvalidAnswer(
        f"This answer is {describe_shape(shape)}; what you pasted is {len(grid)}×{counts[0]} ({total} entries).")
