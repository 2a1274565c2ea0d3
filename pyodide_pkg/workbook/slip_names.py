"""The names of the slips a class makes: what the class page counts a wrong answer under.

A wrong answer that matches a named slip says which in its verdict's
``data.slip`` (:func:`slip_name`): the tag for the slips every answer can make
(``sign``, ``degrees``, ``transpose``...), and for an exercise's own slips
``slip: `` and its message with every number written as ``#``, so the same
mistake has the same name in every variant:

>>> slip_name("slip", "That is the y-coordinate, 2.5 m, not x = −1.25.")
'slip: That is the y-coordinate, # m, not x = #.'
>>> slip_name("sign", "The size is right but the sign is wrong.")
'sign'
>>> slip_name("", "Not quite.") is None
True

Since issue 46 a named slip of the bank also has a stable id (``data.slipId``, ``6.3/took-away-l1-l2``),
which the class page counts by; this name (``data.slip``) is kept for the counts older records hold.
"""

from __future__ import annotations

import re

from .contract import LIMIT

# The tags that name a mistake (contract.json "tags"): the exercise's own slips, and those every answer kind knows.
NAMED = ("slip", "close", "radians", "degrees", "sign", "transpose", "inverse", "sine-sign", "rows-swapped",
         "columns-swapped", "negated")
NAME_CAP = LIMIT.slipName  # characters of a slip's name (contract.json, the page's limit too)
# A number the variant chose; not a digit that is part of a name (θ1, atan2, e[k−1]) or an
# entry's place (J(1,2), "the (2,2) entry"), which every variant shares.
_NUMBER = re.compile(r"(?<![\w\[−\-])[−\-+]?\d+(?:[.,]\d+)*(?:e[−\-+]?\d+)?(?!\w)")
_PLACE = re.compile(r"\((\d(?:,\d)*)\)")
_SPACE = re.compile(r"\s+")


def slip_name(tag: str, message: str) -> str | None:
    """The stable name of the named slip a wrong answer hit (its verdict's tag and message), or None."""
    if tag not in NAMED:
        return None
    if tag != "slip":
        return tag
    places = _PLACE.findall(message)
    text = _NUMBER.sub("#", _PLACE.sub("(@)", message))
    for place in places:
        text = text.replace("(@)", f"({place})", 1)
    text = _SPACE.sub(" ", text).strip()
    if len(text) > NAME_CAP - 6:
        text = text[: NAME_CAP - 7].rsplit(" ", 1)[0] + "…"
    return f"slip: {text}"
