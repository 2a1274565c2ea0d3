"""The exercise kinds: one module each, named after the kind.

A kind's module holds everything about it: its data (a frozen dataclass that
subclasses :class:`~workbook.kinds.base.Exercise`), its check, and the markup of
its widget. The kinds are registered in one place, the ``kinds`` list of
``contract.json`` (read by :mod:`workbook.registry`); the page's widget for kind ``K`` is ``docs/assets/js/kinds/K.js``.
Adding a kind means adding ``kinds/K.py`` and ``kinds/K.js`` and its name there.

>>> [cls.__name__ for cls in classes().values()]
['Derive', 'Trace', 'Build', 'Debug', 'Design']
"""

from __future__ import annotations

from functools import cache

from ..registry import KINDS
from .base import Exercise


@cache
def classes() -> dict[str, type[Exercise]]:
    """Each registered kind's exercise class, by kind name (:data:`workbook.registry.KINDS`)."""
    return KINDS.check()
