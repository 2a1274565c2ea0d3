"""Reading a page's printed math back: its relations, evaluated from the printed numbers only.

The rule the workbook prints by (``workbook/number_format.py``): a number with
fewer than 4 significant figures, or without a decimal point, is exact; one
with 4 or more may be rounded, by at most half a unit of its last digit. A
line ``A = B`` holds when B, evaluated from its printed numbers, is A evaluated
from its printed numbers, within what B's own rounding allows. A line
``A ≈ B`` holds when they agree within the rounding of both sides.

The math is read by the grader's own reader (:mod:`workbook.expr`, which takes
LaTeX): a side it cannot read as a number (a symbol such as ``x'``, a set of
numbers) is left out, and so is a pair whose sides have different units.
"""

from __future__ import annotations

import html
import math
import re
from dataclasses import dataclass
from functools import lru_cache

from workbook.expr import InvalidAnswer, parse_answer, split_matrix

MATH = re.compile(r"\\\((.*?)\\\)|\\\[(.*?)\\\]", re.S)
_LITERAL = re.compile(r"(?<![\w.])(\d+\.\d+|\d+)(?![\w.])")
_RELATION = re.compile(r"\\approx|≈|\\neq?\b|\\[lg]eq?\b|\\[lg]t\b|[<>]|(?<![<>!\\])=")
_ENVIRONMENT = re.compile(r"\\begin\{([bpvBV]?matrix|array)\}.*?\\end\{\1\}", re.S)


def math_of(html_text: str) -> list[str]:
    """Every inline and display formula of a page fragment, as TeX."""
    return [html.unescape(a or b) for a, b in MATH.findall(html_text)]


_BRACKETS = re.compile(r"[{\[(}\])]")


def _top_split(s: str, separators: re.Pattern) -> list[tuple[str, str]]:
    """``s`` cut at the separators outside braces, brackets and parentheses: ``[(piece, separator before it)]``.
    (No separator starts with a bracket; a closing bracket with none open is ignored.)"""
    out, depth, start, before = [], 0, 0, ""
    i, scanned = 0, 0  # the next place a separator may start; how far the depth is counted
    while (m := separators.search(s, i)) is not None:
        for b in _BRACKETS.finditer(s, scanned, m.start()):
            depth = depth + 1 if b.group(0) in "{[(" else max(0, depth - 1)
        scanned = m.start()
        if depth == 0 and m.end() > m.start():
            out.append((s[start:m.start()], before))
            before, start = m.group(0), m.end()
            i = scanned = m.end()  # (brackets inside a separator, as in \text{...}, are not counted)
        else:
            i = m.start() + 1
    out.append((s[start:], before))
    return out


_LINES = re.compile(r"\\\\|,|;|\\qquad|\\quad|\\text\{[^}]*\b(?:and|so|if|with|for|then|since)\b[^}]*\}")


@lru_cache(maxsize=1 << 16)  # pure, and many draws print the same formulas: each is read once
def relations(tex: str) -> list[list[tuple[str, str]]]:
    """Each chain of relations in a formula: ``[(side, relation before it), ...]`` (the first has ``""``)."""
    tex = re.sub(r"\\(?:begin|end)\{(?:aligned|align\*?|gathered|split|cases)\}", r" \\\\ ", tex)
    matrices: list[str] = []

    def hide(m: re.Match) -> str:
        matrices.append(m.group(0))
        return f"\x00{len(matrices) - 1}\x00"

    tex = _ENVIRONMENT.sub(hide, tex).replace("&", " ")
    show = lambda side: re.sub("\x00(\\d+)\x00", lambda m: matrices[int(m.group(1))], side)  # noqa: E731
    chains = []
    for line, _ in _top_split(tex, _LINES):
        sides = [(show(side).strip(), rel) for side, rel in _top_split(line, _RELATION)]
        if len(sides) > 1:
            chains.append(sides)
    return chains


@dataclass
class Value:
    """A side read as a number (or the entries of a matrix), with how far its printed rounding lets it move."""

    values: list[float]
    slack: list[float]
    dimension: str | None
    single: bool = False  # one printed number (perhaps with a unit): it may stand for its rounding


_SINGLE = re.compile(r"-?\s*\d+(?:\.\d+)?\s*(?:°|\^\{?\\circ\}?|\\text\{\s*\w+\s*\}|\\,?\s*\w+)?")


def _literals(tex: str) -> list[tuple[int, int, float]]:
    """The printed numbers that may be rounded (4 or more significant figures, with a decimal point): where, and half a unit."""
    out = []
    for m in _LITERAL.finditer(tex):
        text = m.group(1)
        if "." not in text:
            continue
        figures = len(text.replace(".", "").lstrip("0"))
        if figures >= 4:
            out.append((m.start(1), m.end(1), 0.5 * 10.0 ** -len(text.split(".")[1])))
    return out


def _scalar(tex: str) -> tuple[float, str | None]:
    answer = parse_answer(tex)
    return answer.si, answer.dimension


def _one(tex: str) -> tuple[float, float, str | None]:
    """A side's value, its slack (the first-order effect of rounding each printed number), its dimension."""
    value, dim = _scalar(tex)
    slack = 0.0
    for start, end, half in _literals(tex):
        shifted = tex[:start] + repr(float(tex[start:end]) + half) + tex[end:]
        try:
            slack += abs(_scalar(shifted)[0] - value)
        except InvalidAnswer:
            slack += half
    return value, slack, dim


@lru_cache(maxsize=1 << 16)
def read_side(tex: str) -> Value | None:
    """A side as numbers, or None when it is not (only) numbers."""
    tex = tex.strip().rstrip(".").strip()
    if not tex or not re.search(r"\d", tex):
        return None
    tex = re.sub(r"(\\end\{\w+\}|\))\s*\\text\{\s*[\w/]+\s*\}$", r"\1", tex)  # a vector's unit after it
    try:
        if "\\begin" in tex:
            if not re.fullmatch(r"\\begin\{[bpv]?matrix\}.*\\end\{[bpv]?matrix\}", tex, re.S) or tex.count("\\begin") > 1:
                return None
            entries = [_one(e) for row in split_matrix(tex) for e in row]
            return Value([e[0] for e in entries], [e[1] for e in entries], "matrix", True)
        if tex[:1] + tex[-1:] in ("()", "[]") and len(_top_split(tex[1:-1], re.compile(","))) > 1:
            entries = [_one(e.replace("\\;", " ").replace("\\ ", " ")) for e, _ in _top_split(tex[1:-1], re.compile(","))]
            return Value([e[0] for e in entries], [e[1] for e in entries], "vector", True)
        value, slack, dim = _one(tex)
        return Value([value], [slack], dim, bool(_SINGLE.fullmatch(tex)))
    except (InvalidAnswer, ValueError, ZeroDivisionError, OverflowError):
        return None


@lru_cache(maxsize=1 << 16)
def check_formula(tex: str) -> list[str]:
    """Every relation of ``tex`` between two numeric sides that does not hold (a message each)."""
    problems = []
    for chain in relations(tex):
        read = [(read_side(side), side, rel) for side, rel in chain]
        for (a, a_tex, _), (b, b_tex, rel) in zip(read, read[1:]):
            if a is None or b is None or a.dimension != b.dimension or len(a.values) != len(b.values):
                continue
            if rel not in ("=", "\\approx", "≈"):
                continue
            approx = rel != "="
            for va, sa, vb, sb in zip(a.values, a.slack, b.values, b.slack):
                # "A = B": B follows from A's printed numbers, to B's own precision; a side that is one
                # printed number may stand for its rounding. "A ≈ B": within the rounding of both sides.
                if approx:
                    room = sa + sb
                elif a.single and not b.single:
                    room = sa
                else:
                    room = sb + (sa if a.single else 0.0)
                room += 1e-9 * max(1.0, abs(vb))
                if not (math.isfinite(va) and math.isfinite(vb)) or abs(va - vb) > room:
                    problems.append(f"{a_tex.strip()} {rel} {b_tex.strip()}: {va!r} vs {vb!r} (room {room:.2g})")
                    break
    return problems


def computed(tex: str) -> Value | None:
    """A side that is arithmetic on printed numbers (``0.8192 - 0.8660``, or a matrix with such an entry), read
    as numbers; None for a side of single printed numbers or of no numbers."""
    value = read_side(tex)
    if value is None:
        return None
    tex = tex.strip().rstrip(".").strip()
    if "\\begin" in tex:
        entries = [e for row in split_matrix(tex) for e in row]
    elif tex[:1] + tex[-1:] in ("()", "[]"):
        entries = [e for e, _ in _top_split(tex[1:-1], re.compile(","))]
    else:
        entries = [tex]
    return None if all(_SINGLE.fullmatch(e.strip()) for e in entries) else value
