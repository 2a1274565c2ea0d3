"""What a Build run in this process must empty afterwards: caches a learner's code may have reached.

A run in the page happens in a sandbox of its own; one in this process (``Build.check``: tests, the
golden transcript) shares the grader's objects, and may reach a cached one through ``gc``. The layer
that owns a cache registers it here (the bank its cache of variants), so that ``kinds.build``, which
runs the code, needs to know nothing above it.

>>> seen = []
>>> register(lambda: seen.append("emptied"))
>>> empty_all(); seen
['emptied']
>>> _CACHES.pop() and None
"""

from __future__ import annotations

from collections.abc import Callable

_CACHES: list[Callable[[], object]] = []


def register(empty: Callable[[], object]) -> None:
    """Have ``empty()`` called after every Build run in this process (once, however often registered)."""
    if empty not in _CACHES:
        _CACHES.append(empty)


def empty_all() -> None:
    """Empty every registered cache (after a run in this process)."""
    for empty in _CACHES:
        empty()
