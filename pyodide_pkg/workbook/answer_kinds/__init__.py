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

import importlib
from functools import cache

from ..contract import ANSWER_KINDS


def module_name(answer_kind: str) -> str:
    return f"{__name__}.{answer_kind}"


@cache
def classes() -> dict[str, type]:
    """Each registered answer kind's class, by name."""
    out = {}
    for name in ANSWER_KINDS:
        cls = importlib.import_module(module_name(name)).ANSWER
        if cls.kind != name:
            raise TypeError(f"{module_name(name)} defines answers of kind {cls.kind!r}, not {name!r}")
        out[name] = cls
    return out
