"""Vector and matrix answers: a grid of entries, graded together.

The key is a tuple of rows computed by the reference code. Each entry takes a
number or an expression; a whole matrix pasted into any entry is split by the
worker (the ``split`` op) and fills the grid. A wrong answer marks the entries
that differ and, where it can, names the slip across the whole matrix: the
exercise's own slips first, then the transpose, the inverse, R(−θ), degrees
read as radians, swapped rows or columns, and the negated matrix.

>>> from workbook.kinds.derive import Slip
>>> ex = MatrixDerive(id="x.1", title="", key=((0.0, -1.0), (1.0, 0.0)), label="R(90°)")
>>> ex.check([["0", "-1"], ["1", "0"]]).status
'correct'
>>> v = ex.check([["0", "1"], ["-1", "0"]]); v.tag, v.data["wrong"]
('transpose', [[1, 2], [2, 1]])
>>> ex.check([["0", ""], ["1", "0"]]).data["invalid"]
[[1, 2]]
>>> ex.split("[[0, -1], [1, 0]]")
{'entries': [['0', '-1'], ['1', '0']]}
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar

from ..answers import InvalidAnswer
from ..contract import ATTR, ROLE, TAG
from ..kinds.base import Page, check_button, escape, form, role_attr
from ..kinds.derive import Derive, fmt
from ..shaped import InvalidEntries, parse_entries, parse_pasted, whole_matrix_slips, wrong_entries
from ..tolerance import clean
from ..verdict import Verdict

Rows = tuple[tuple[float, ...], ...]


@dataclass(frozen=True)
class MatrixDerive(Derive):
    """``key`` holds the rows; a column vector is a key of one-entry rows.

    ``rotation_angle`` (radians) is the angle a rotation key was built from, so
    that R(−θ) and degrees-for-radians can be named.
    """

    key: Rows = ()
    rotation_angle: float | None = None
    answer_kind: ClassVar[str] = "matrix"

    @property
    def shape(self) -> tuple[int, int]:
        return len(self.key), len(self.key[0])

    @property
    def cleaned(self) -> list[list[float]]:
        return [[clean(v) for v in row] for row in self.key]

    def attributes(self) -> dict[str, str]:
        r, c = self.shape
        return {**super().attributes(), ATTR.answerShape: f"{r}x{c}"}

    def _grid(self, answer: object) -> list[list[str]]:
        if isinstance(answer, str):
            return parse_pasted(answer, self.shape)
        if not isinstance(answer, (list, tuple)) or not all(isinstance(row, (list, tuple)) for row in answer):
            raise InvalidAnswer("Fill in every entry of the answer, then check.")
        return [[str(v) for v in row] for row in answer]

    def check(self, answer: object) -> Verdict:
        try:
            got = parse_entries(self._grid(answer), self.shape, self.expect)
        except InvalidEntries as err:
            return Verdict("invalid", str(err), data={"invalid": [list(p) for p in err.positions]})
        except InvalidAnswer as err:
            return Verdict("invalid", str(err))
        key = self.cleaned
        wrong = [list(p) for p in wrong_entries(got, key)]
        if not wrong:
            return Verdict("correct", "Correct: every entry agrees.")
        if self.either_sign and not wrong_entries(got, [[-v for v in row] for row in key]):
            return Verdict("correct", f"Correct: {self.either_sign}")
        data = {"wrong": wrong}
        for slip in self.slips:
            if not wrong_entries(got, [[clean(v) for v in row] for row in slip.value]):
                return Verdict("incorrect", slip.message, tag=TAG.slip, data=data)
        for tag, message in whole_matrix_slips(got, key, rotation_angle=self.rotation_angle):
            return Verdict("incorrect", message, tag=tag, data=data)
        n = self.shape[0] * self.shape[1]
        return Verdict("incorrect", f"{n - len(wrong)} of {n} entries are right; the marked ones are not.", data=data)

    def split(self, text: object) -> dict:
        try:
            return {"entries": parse_pasted(text, self.shape)}
        except InvalidAnswer as err:
            return {"message": str(err)}

    def read(self, answer: object) -> dict:
        try:
            return {"value": parse_entries(self._grid(answer), self.shape, self.expect)}
        except InvalidAnswer as err:
            return {"message": str(err)}

    def worked_text(self) -> str:
        return "[" + "; ".join(" ".join(fmt(v, digits=4) for v in row) for row in self.cleaned) + "]"

    def worked_html(self) -> str:
        r, c = self.shape
        cells = "".join(
            f'<span {role_attr(ROLE.worked_entry)} {ATTR.row}="{i}" {ATTR.col}="{j}">{fmt(v, digits=4)}</span>'
            for i, row in enumerate(self.cleaned, 1) for j, v in enumerate(row, 1)
        )
        return (f'<p class="wb-worked">Type it as:</p><div class="wb-worked-grid" {role_attr(ROLE.worked_answer)} '
                f'style="grid-template-columns: repeat({c}, auto)" aria-label="{r} by {c}">{cells}</div>')

    def typed(self, value: Rows) -> list[list[str]]:
        return [[fmt(clean(v), digits=6) for v in row] for row in value]

    def label_html(self) -> str:
        r, c = self.shape
        what = "column vector" if c == 1 else "matrix"
        return f"{escape(self.label)} ({r}×{c} {what}; paste a whole {what} into any entry)"

    def widget(self, base: str, page: Page) -> str:
        r, c = self.shape
        cells = "".join(
            f'<input {role_attr(ROLE.entry)} {ATTR.row}="{i}" {ATTR.col}="{j}" type="text" inputmode="text" '
            f'autocomplete="off" autocapitalize="off" spellcheck="false" aria-label="row {i}, column {j}"'
            f'{f" id={chr(34)}{base}-answer{chr(34)}" if (i, j) == (1, 1) else ""}>'
            for i in range(1, r + 1) for j in range(1, c + 1)
        )
        return form(self.kind, (
            f'<label class="wb-label" for="{base}-answer">{self.label_html()}</label>'
            f'<span class="wb-grid-row"><span class="wb-grid" role="group" aria-describedby="{base}-feedback" '
            f'style="grid-template-columns: repeat({c}, auto)">{cells}</span>{check_button()}</span>'
        ))


ANSWER = MatrixDerive
