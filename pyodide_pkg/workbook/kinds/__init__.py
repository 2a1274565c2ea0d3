"""The exercise kinds: one module each, named after the kind.

A kind's module holds everything about it: its data (a frozen dataclass that
subclasses :class:`~workbook.kinds.base.Exercise`), its check, and the markup of
its widget. The kinds are registered in one place, the ``kinds`` list of
``contract.json``; the page's widget for kind ``K`` is ``docs/assets/js/kinds/K.js``.
Adding a kind means adding ``kinds/K.py`` and ``kinds/K.js`` and its name there.

>>> [cls.__name__ for cls in classes().values()]
['Derive', 'Trace', 'Build', 'Debug', 'Design']
"""

from __future__ import annotations

import importlib
from functools import cache

from ..contract import KINDS
from .base import Exercise


@cache
def classes() -> dict[str, type[Exercise]]:
    """Each registered kind's exercise class, by kind name."""
    out = {}
    for name in KINDS:
        module = importlib.import_module(f"{__name__}.{name}")
        cls = module.EXERCISE
        if cls.kind != name:
            raise TypeError(f"kinds/{name}.py defines an exercise of kind {cls.kind!r}")
        out[name] = cls
    return out
