"""Reading a number answer: the learner's text in the unit asked, with its typed precision.

A count may be followed by the word for what it counts, as the page prints it
(``300 variables``, ``1200 rows``): the answer's own unit word, or a plural noun
of its label, in the singular or the plural.
"""

from __future__ import annotations

import re
from typing import TYPE_CHECKING

from ...expr import InvalidAnswer, Reading, read_quantity
from ...verdict import Verdict

if TYPE_CHECKING:
    from . import NumberAnswer

_TRAILING_WORD = re.compile(r"^(.*?\S)\s+([A-Za-z]+)\s*\.?\s*$", re.S)


def counted_words(ans: NumberAnswer) -> frozenset[str]:
    """The words that may follow the number: a unit that is a word (not one the reader knows, such as m),
    and, for a count, the plural nouns of the label (``rows (= columns) of H``: rows, columns)."""
    from . import UNITS
    words = set()
    if ans.unit and ans.unit not in UNITS and ans.unit.isalpha():
        words.add(ans.unit.lower())
    if ans.exact:
        words.update(w for w in re.findall(r"[a-z]+", ans.label.lower()) if len(w) >= 4 and w.endswith("s"))
    return frozenset(words)


def _without_word(ans: NumberAnswer, answer: object) -> object:
    if not isinstance(answer, str) or len(answer) > 200:
        return answer
    m = _TRAILING_WORD.match(answer)
    if not m:
        return answer
    word = m.group(2).lower()
    words = counted_words(ans)
    return m.group(1) if word in words or word + "s" in words else answer


def read(ans: NumberAnswer, answer: object) -> Reading | Verdict:
    """The value read in the unit asked, or an ``invalid`` verdict saying why it could not be read."""
    try:
        return read_quantity(_without_word(ans, answer), ans.expect)
    except InvalidAnswer as err:
        return Verdict("invalid", str(err))


def reply(reading: Reading) -> dict:
    """The ``read`` op's reply: the value as read."""
    return {"value": reading.value}
