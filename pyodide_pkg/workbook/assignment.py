"""Assignments: each learner's own numbers.

An assignment link (the site's ``teach/`` page) sets exercises for a class code; a
learner who opens it gives a name or student number once, and every Derive
exercise of the assignment then shows the variant :func:`assigned_variant` of
(class code, student id, exercise id). The same function, in the page's
``docs/assets/js/assignment-hash.js``, chooses it in the browser, and the class
page (``class/``) recomputes it from a hand-in file to re-grade the answers; a
test checks the two agree over many inputs.

The text is tidied first, the same way in both (:func:`tidy`): Unicode NFC,
whitespace runs as one space, trimmed. A student id is also folded (:func:`fold`):
Unicode NFKC and full case folding (``str.casefold``), so that "Ada Lovelace",
"ada  lovelace", "Émile" and "ÉMILE" each name one student whatever the keyboard
typed. The page folds with a table written from this Python's own case folding
(``scripts/casefold_table.py``), so the two agree on every code point.

>>> assigned_variant("ROB101", "s1234567", "0.1")
300744
>>> assigned_variant("ROB101", " S1234567 ", "0.1") == assigned_variant("ROB101", "s1234567", "0.1")
True
>>> fold(" ÉMILE  Straße "), fold("ﬁ")
('émile strasse', 'fi')
>>> 1 <= assigned_variant("x", "y", "9.7") <= MAX_SEED
True
"""

from __future__ import annotations

import hashlib
import re
import unicodedata

from .variants import MAX_SEED

SALT = "robotics-math-workbook/assignment/1"
_SPACE = re.compile(r"\s+")


def tidy(text: str) -> str:
    """``text`` as the hash reads it: NFC, runs of whitespace as one space, trimmed."""
    return _SPACE.sub(" ", unicodedata.normalize("NFC", text)).strip(" ")


def fold(text: str) -> str:
    """A student id as the hash reads it: NFKC, full case folding, NFKC again (folding can undo
    it), then tidied. For ASCII, capitals as small letters and the spaces tidied."""
    return tidy(unicodedata.normalize("NFKC", unicodedata.normalize("NFKC", text).casefold()))


def assigned_variant(class_code: str, student: str, exercise_id: str) -> int:
    """The variant (1 to MAX_SEED) a student's assignment shows for an exercise: SHA-256 of the
    salt, the tidied class code, student id and exercise id, one per line; its first 8 bytes
    as a whole number, modulo MAX_SEED, plus 1."""
    text = "\n".join((SALT, tidy(class_code), fold(student), exercise_id))
    digest = hashlib.sha256(text.encode("utf-8")).digest()
    return 1 + int.from_bytes(digest[:8], "big") % MAX_SEED
