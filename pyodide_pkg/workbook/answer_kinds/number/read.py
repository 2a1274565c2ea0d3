"""Reading a number answer: the learner's text in the unit asked, with its typed precision."""

from __future__ import annotations

from ...expr import InvalidAnswer, Reading, read_quantity
from ...verdict import Verdict


def reading(answer: object, expect: str | None) -> Reading | Verdict:
    """The value read, or an ``invalid`` verdict saying why it could not be read."""
    try:
        return read_quantity(answer, expect)
    except InvalidAnswer as err:
        return Verdict("invalid", str(err))
