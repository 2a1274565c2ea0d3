"""The exercise bank: the modules ``chN_*.py`` hold chapter N's exercises.

A chapter may span several modules (``ch6_arm_kinematics.py`` for the derivations,
``ch6_code.py`` for its Build and Debug exercises, say). Each defines ``EXERCISES``;
the chapter is their union in the order of the ids (6.2 before 6.10).
Chapters are imported lazily, so grading exercise 4.2 imports chapter 4 only.
"""

from __future__ import annotations

from functools import cache, lru_cache

from .. import run_caches
from ..kinds.base import Exercise
from ..registry import CHAPTER_MODULES


@cache
def _chapter_modules() -> dict[int, list[str]]:
    """Chapter N's modules (``chN_*``, :data:`workbook.registry.CHAPTER_MODULES`), by N."""
    found: dict[int, list[str]] = {}
    for name in CHAPTER_MODULES.names():
        head = name.partition("-")[0]
        if not head[2:].isdigit():
            raise TypeError(f"bank module {name.replace('-', '_')}.py is named like no chapter (chN_topic.py)")
        found.setdefault(int(head[2:]), []).append(name)
    return {n: sorted(names) for n, names in sorted(found.items())}


@cache
def chapter(n: int) -> tuple[Exercise, ...]:
    """The exercises of chapter ``n``, in page order."""
    names = _chapter_modules().get(n)
    if names is None:
        raise KeyError(f"no chapter {n}")
    exercises = [ex for name in names for ex in CHAPTER_MODULES.get(name)]
    for ex in exercises:
        if ex.id.split(".")[0] != str(n):
            raise ValueError(f"exercise {ex.id} sits in chapter {n}'s module")
    return tuple(sorted(exercises, key=lambda ex: int(ex.id.split(".")[1])))


def grid(matrix) -> tuple[tuple[float, ...], ...]:
    """A matrix from the reference code (a list of rows) as a MatrixDerive key or slip.

    >>> grid([[0, -1], [1, 0]])
    ((0, -1), (1, 0))
    """
    return tuple(tuple(row) for row in matrix)


def column(vector) -> tuple[tuple[float], ...]:
    """A vector as a column: one-entry rows.

    >>> column((1.0, 2.0))
    ((1.0,), (2.0,))
    """
    return tuple((v,) for v in vector)


def entries(rows) -> list[float]:
    """A column's entries as numbers: :func:`column`'s inverse (for a key, or a learner's step).

    >>> entries(((1.0,), (2,)))
    [1.0, 2.0]
    """
    return [float(r[0]) for r in rows]


def chapters() -> list[int]:
    return list(_chapter_modules())


def get(exercise_id: str) -> Exercise:
    """Look an exercise up by its id, e.g. ``get("4.2")``."""
    head, dot, tail = str(exercise_id).partition(".")
    if not (dot and head.isdigit() and tail.isdigit()):
        raise KeyError(f"not an exercise id: {exercise_id!r}")
    for ex in chapter(int(head)) if int(head) in _chapter_modules() else ():
        if ex.id == exercise_id:
            return ex
    raise KeyError(f"no exercise {exercise_id}")


@lru_cache(maxsize=512)
def variant(exercise_id: str, seed: int = 0) -> Exercise:
    """Exercise ``exercise_id`` with variant ``seed``'s numbers (kinds without variants: itself)."""
    ex = get(exercise_id)
    return ex.variant(seed) if hasattr(ex, "variant") else ex


run_caches.register(variant.cache_clear)  # a Build run in this process empties it (kinds.build)


def all_exercises() -> list[Exercise]:
    """Every exercise in the workbook, in order; ids are checked to be unique."""
    out: list[Exercise] = []
    seen: set[str] = set()
    for n in chapters():
        for ex in chapter(n):
            if ex.id in seen:
                raise ValueError(f"duplicate exercise id {ex.id}")
            seen.add(ex.id)
            out.append(ex)
    return out
