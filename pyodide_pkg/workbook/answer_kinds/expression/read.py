"""Reading a formula answer: the learner's text over the exercise's variables."""

from __future__ import annotations

from typing import TYPE_CHECKING

from ...expr import Formula, InvalidAnswer, parse_formula
from ...verdict import Verdict

if TYPE_CHECKING:
    from . import FormulaAnswer


def reply(formula: Formula) -> dict:
    """The ``read`` op's reply: the formula as read, typeset."""
    return {"latex": formula.latex}


def read(ans: FormulaAnswer, answer: object) -> Formula | Verdict:
    """The formula read, or an ``invalid`` verdict saying why it could not be read."""
    try:
        return parse_formula(answer, ans.variables)
    except InvalidAnswer as err:
        return Verdict("invalid", str(err))
