"""The kinds of answer a Derive exercise takes: one module each.

``number`` is the Derive kind's own default (``workbook/kinds/derive.py``); every
other answer kind ``A`` is ``answer_kinds/A.py``, whose ``ANSWER`` class
subclasses :class:`~workbook.kinds.derive.Derive`, with its widget's behaviour in
``docs/assets/js/answer-kinds/A.js``. The ``answerKinds`` list of
``contract.json`` registers them.

>>> classes()["number"].__name__
'Derive'
"""

from __future__ import annotations

import importlib
from functools import cache

from ..contract import ANSWER_KINDS


def module_name(answer_kind: str) -> str:
    return "workbook.kinds.derive" if answer_kind == "number" else f"{__name__}.{answer_kind}"


@cache
def classes() -> dict[str, type]:
    """Each registered answer kind's exercise class, by name."""
    out = {}
    for name in ANSWER_KINDS:
        cls = getattr(importlib.import_module(module_name(name)), "ANSWER")
        if cls.answer_kind != name:
            raise TypeError(f"{module_name(name)} defines answers of kind {cls.answer_kind!r}, not {name!r}")
        out[name] = cls
    return out
