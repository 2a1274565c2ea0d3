"""Copying: how often two students of one class have the same right answer.

An assignment link gives each student a variant of every exercise
(:func:`workbook.assignment.assigned_variant`). Per-student numbers only stop
copying when they make per-student *answers*: two students share an answer when
one's worked answer, as the page prints it, is right for the other's numbers too
(the grader's own tolerance decides, in either direction). :func:`share` is the
fraction of student pairs of a class that share the right answer of an exercise.

>>> share(["1", "1", "2.5"])  # three students: one pair of three shares
0.3333333333333333
>>> share(["a", "b"], same=lambda a, b: True)
1.0

An exercise whose answer cannot differ (det R(θ) is 1 for every θ; a question with fixed
options) says why in :func:`same_answer`, and the teach page shows it.
"""

from __future__ import annotations

from collections import Counter
from collections.abc import Callable, Hashable, Sequence
from itertools import combinations
from typing import Any

from . import bank
from .assignment import assigned_variant
from .kinds.derive import Derive

CLASS_SIZE = 100
MOST = 0.01  # the largest share of pairs that may have the same right answer

# Why the kinds without numbers of their own have one right answer for everyone.
KIND_REASONS = {
    "trace": "A choice among the same options for everyone: the same one is right.",
    "design": "The same steps to put in order for everyone: the same order is right.",
    "build": "Code checked on the same tests for everyone.",
    "debug": "The same program with the same buggy line for everyone.",
}


def same_answer(ex: Any) -> str:
    """Why every student of a class has the same right answer to ``ex`` (the exercise's own
    ``same_answer``, or its kind's reason), or "" when variants tell them apart."""
    if ex.same_answer:
        return str(ex.same_answer)
    if ex.kind in KIND_REASONS:
        return KIND_REASONS[ex.kind]
    return "" if getattr(ex, "vary", None) is not None else "One set of numbers for everyone."


def students(n: int = CLASS_SIZE) -> list[str]:
    """``n`` student ids of one class, as a teacher's list would have them."""
    return [f"s{1000 + k}" for k in range(n)]


def share(keys: Sequence[Hashable], same: Callable[[Any, Any], bool] | None = None) -> float:
    """The fraction of pairs among ``keys`` (one per student) whose answers agree: equal keys do,
    and so do two different keys that ``same(a, b)`` says agree."""
    n = len(keys)
    if n < 2:
        return 0.0
    counts = Counter(keys)
    pairs = sum(c * (c - 1) // 2 for c in counts.values())
    if same is not None:
        pairs += sum(counts[a] * counts[b] for a, b in combinations(counts, 2) if same(a, b))
    return pairs / (n * (n - 1) // 2)


def _drawn(exercise_id: str, seed: int) -> Derive:
    """Variant ``seed`` of a Derive exercise (only those draw variants)."""
    ex = bank.variant(exercise_id, seed)
    if not isinstance(ex, Derive):
        raise TypeError(f"exercise {exercise_id} draws no variants")
    return ex


def _entries(answer: Any) -> list[float] | None:
    """A number's or a matrix's key as a flat list of floats; None for other kinds (a formula) and
    for an angle taken give or take whole turns, whose key alone does not say what is accepted."""
    key = getattr(answer, "key", None)
    if getattr(answer, "periodic", False) or callable(key):
        return None
    rows = key if isinstance(key, tuple) else ((key,),)
    try:
        return [float(v) for row in rows for v in row]
    except (TypeError, ValueError):
        return None


def _far(a: Any, b: Any) -> bool:
    """Keys no grader could take for each other: some entry differs in size by more than 5 %
    (and 0.01), wider than any tolerance, rounding or sign the answer kinds allow. A quick test
    that spares :func:`_accepts` most pairs; it never calls two shared answers far."""
    x, y = _entries(a), _entries(b)
    if x is None or y is None or len(x) != len(y):
        return False
    band = max(0.05, 2 * getattr(a, "rel_tol", 0.0), 2 * getattr(b, "rel_tol", 0.0))
    return any(abs(abs(u) - abs(v)) > band * max(abs(u), abs(v)) + 0.01 for u, v in zip(x, y))


def _accepts(exercise_id: str, quick: bool = True) -> Callable[[int, int], bool]:
    """Whether variant ``a``'s worked answer is right for variant ``b`` or ``b``'s for ``a``: the
    grader decides, as it would for a student who typed the other's printed answer."""

    def right(a: int, b: int) -> bool:
        return _drawn(exercise_id, b).check(_drawn(exercise_id, a).worked_text()).status == "correct"

    def either(a: int, b: int) -> bool:
        if quick and _far(_drawn(exercise_id, a).answer, _drawn(exercise_id, b).answer):
            return False
        return right(a, b) or right(b, a)

    return either


def exercise_share(exercise_id: str, class_code: str = "ROB101", ids: Sequence[str] | None = None, *,
                   quick: bool = True) -> float:
    """The share of pairs of a class (``ids``; default :func:`students`) who share exercise
    ``exercise_id``'s right answer. An exercise that draws no variants has one answer for all: 1.
    ``quick=False`` asks the grader about every pair of different answers (no :func:`_far`)."""
    ex = bank.get(exercise_id)
    if getattr(ex, "vary", None) is None:
        return 1.0
    seeds = [assigned_variant(class_code, s, exercise_id) for s in ids or students()]
    texts = {seed: _drawn(exercise_id, seed).worked_text() for seed in set(seeds)}
    by_text: dict[str, int] = {}  # a printed answer -> one seed that prints it
    for seed, text in texts.items():
        by_text.setdefault(text, seed)
    accepts = _accepts(exercise_id, quick)
    return share([texts[s] for s in seeds], same=lambda a, b: accepts(by_text[a], by_text[b]))
