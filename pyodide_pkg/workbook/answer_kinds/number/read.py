"""Reading a number answer: the learner's text in the unit asked, with its typed precision."""

from __future__ import annotations

from typing import TYPE_CHECKING

from ...expr import InvalidAnswer, Reading, read_quantity
from ...verdict import Verdict

if TYPE_CHECKING:
    from . import NumberAnswer


def read(ans: NumberAnswer, answer: object) -> Reading | Verdict:
    """The value read in the unit asked, or an ``invalid`` verdict saying why it could not be read."""
    try:
        return read_quantity(answer, ans.expect)
    except InvalidAnswer as err:
        return Verdict("invalid", str(err))


def reply(reading: Reading) -> dict:
    """The ``read`` op's reply: the value as read."""
    return {"value": reading.value}
