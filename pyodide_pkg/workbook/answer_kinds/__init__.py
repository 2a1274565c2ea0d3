"""The kinds of answer a Derive exercise takes: one package each.

An answer kind ``A`` is the package ``answer_kinds/A/`` (``__init__.py`` its
options, ``read.py``, ``mark.py``, ``show.py``) exporting ``ANSWER`` (a subclass
of :class:`~.base.AnswerKind`) and a factory the bank writes
(``number(...)``, ``matrix(...)``, ``formula(...)``); its widget's behaviour is
``docs/assets/js/answer-kinds/A.js``. The ``answerKinds`` list of
``contract.json`` registers them.

>>> sorted(classes())
['expression', 'matrix', 'number']
"""

from __future__ import annotations

from functools import cache

from ..registry import ANSWERS


@cache
def classes() -> dict[str, type]:
    """Each registered answer kind's class, by name (:data:`workbook.registry.ANSWERS`)."""
    return ANSWERS.check()
