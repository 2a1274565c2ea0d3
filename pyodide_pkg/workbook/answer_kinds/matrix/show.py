"""Showing a matrix answer: the worked grid, the Answer line's TeX, the label and the grid of inputs."""

from __future__ import annotations

from html import escape
from typing import TYPE_CHECKING

from ...contract import ATTR, ROLE, role_attr
from ...markup import check_button, form, keypad
from ...number_format import fmt
from ...tolerance import clean

if TYPE_CHECKING:
    from . import MatrixAnswer, Rows


def attributes(ans: MatrixAnswer) -> dict[str, str]:
    r, c = ans.shape
    return {ATTR.answerShape: f"{r}x{c}"}


def worked_text(ans: MatrixAnswer) -> str:
    return "[" + "; ".join(" ".join(fmt(v) for v in row) for row in ans.cleaned) + "]"


def worked_tex(ans: MatrixAnswer) -> str:
    rows = r" \\ ".join(" & ".join(fmt(v) for v in row) for row in ans.cleaned)
    return rf"\begin{{bmatrix}} {rows} \end{{bmatrix}}"


def typed(ans: MatrixAnswer, value: Rows) -> list[list[str]]:
    return [[fmt(clean(v), significant=7) for v in row] for row in value]


def worked_html(ans: MatrixAnswer) -> str:
    r, c = ans.shape
    cells = "".join(
        f'<span {role_attr(ROLE.worked_entry)} {ATTR.row}="{i}" {ATTR.col}="{j}">{fmt(v)}</span>'
        for i, row in enumerate(ans.cleaned, 1) for j, v in enumerate(row, 1)
    )
    return (f'<p class="wb-worked">Type it as:</p><div class="wb-worked-grid" {role_attr(ROLE.worked_answer)} '
            f'style="grid-template-columns: repeat({c}, auto)" aria-label="{r} by {c}">{cells}</div>')


def _names(ans: MatrixAnswer) -> list[str]:
    return [name.split("|")[0] for name in ans.names]


def label_html(ans: MatrixAnswer) -> str:
    r, c = ans.shape
    what = "column vector" if c == 1 else ("row vector" if r == 1 else "matrix")
    named = f": {', '.join(escape(n) for n in _names(ans))}" if ans.names else ""
    return f"{escape(ans.label)} ({r}×{c} {what}{named}; paste a whole {what} into any entry)"


def _cell_name(ans: MatrixAnswer, i: int, j: int) -> str:
    """An entry's accessible name: the answer's label and the entry (its component's name, or row and column)."""
    if ans.names:
        return f"{ans.label}, {_names(ans)[(i - 1) * ans.shape[1] + (j - 1)]}"
    return f"{ans.label}, row {i}, column {j}"


def widget(ans: MatrixAnswer, base: str) -> str:
    r, c = ans.shape
    keys = keypad(units=tuple(ans.units) or (ans.unit,))
    cells = "".join(
        f'<input {role_attr(ROLE.entry)} {ATTR.row}="{i}" {ATTR.col}="{j}" type="text" inputmode="text" '
        f'enterkeyhint="{"go" if (i, j) == (r, c) else "next"}" {keys} '
        f'autocomplete="off" autocapitalize="off" spellcheck="false" aria-label="{escape(_cell_name(ans, i, j))}"'
        f'{f" id={chr(34)}{base}-answer{chr(34)}" if (i, j) == (1, 1) else ""}>'
        for i in range(1, r + 1) for j in range(1, c + 1)
    )
    return form("derive", (
        f'<label class="wb-label" id="{base}-label" for="{base}-answer">{label_html(ans)}</label>'
        f'<span class="wb-grid-row"><span class="wb-grid" role="group" aria-labelledby="{base}-label" '
        f'aria-describedby="{base}-feedback" style="grid-template-columns: repeat({c}, auto)">{cells}</span>'
        f"{check_button()}</span>"
    ))
