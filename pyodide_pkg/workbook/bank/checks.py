"""Checks the chapters' generators share: is a draw a fair question?

A generator's ``valid(p)`` rejects a draw whose key and slips cannot be told
apart, or whose words would turn false. These are the common tests; each
chapter adds the ones only it needs.

>>> from workbook.answer_kinds.base import Slip
>>> apart(1.0, 1.0001), apart(1.0, 1.1, 2.0)
(False, True)
>>> slips_apart({"key": 2.0, "slips": (Slip(2.0004, "?"),)})
False
>>> slips_apart({"key": ((1.0,), (2.0,)), "slips": (Slip(((1.0,), (2.1,)), "?"),)})
True
"""

from __future__ import annotations

from typing import Any

from ..answer_kinds.base import Slip
from ..tolerance import agrees, clean

APART = 3e-3  # relatively: far enough apart that 3 significant figures tell them apart


def _cleaned(a: Any) -> Any:
    """A value (a number, or rows of numbers) with every number cleaned of float noise."""
    if isinstance(a, (tuple, list)):
        return tuple(_cleaned(x) for x in a)
    return clean(float(a))


def _same(a: Any, b: Any, rel: float, turn: float | None) -> bool:
    """``a`` and ``b`` (cleaned) are the same answer."""
    if isinstance(a, tuple):
        return all(_same(x, y, rel, turn) for x, y in zip(a, b))
    shifts = (-turn, 0.0, turn) if turn else (0.0,)
    return any(agrees(a + k, b, rel=rel) or agrees(b, a + k, rel=rel) for k in shifts)


def apart(*values: Any, rel: float = APART, turn: float | None = None) -> bool:
    """No two of the values (numbers, or rows of numbers) are the same answer within ``rel``;
    with ``turn`` (360 or 2π), angles a whole turn apart are the same."""
    cleaned = [_cleaned(v) for v in values]
    return not any(_same(cleaned[i], cleaned[j], rel, turn)
                   for i in range(len(cleaned)) for j in range(i + 1, len(cleaned)))


def slips_apart(made: dict, rel: float = APART, turn: float | None = None) -> bool:
    """A ``make()`` result's key and slips are all told apart (see :func:`apart`)."""
    return apart(made["key"], *(s.value for s in made.get("slips", ())), rel=rel, turn=turn)


_KEPT_APART = 6e-3  # relatively: beyond half a unit of the last digit of any value typed to 3 figures (≤ 0.5 %)


def kept_slips(key, candidates, turn=None) -> tuple[Slip, ...]:
    """The slips among ``candidates`` (value, message, name) that differ from ``key`` and from the ones
    kept before them (with ``turn``, angles a whole turn apart are the same): a step's slips for
    this draw, so that no draw is refused for a slip that happens to be right here. A slip such as
    1.05 is read to its 3 figures, so it must lie further from the key than half a unit of its last
    digit.

    >>> [(s.value, s.name) for s in kept_slips(1.0, ((2.0, "a", "two"), (1.0, "b", "one"), (2.0, "c", "twice"),
    ...                                                (3.0, "d", "three")))]
    [(2.0, 'two'), (3.0, 'three')]
    """
    slips: list[Slip] = []
    kept = [_cleaned(key)]  # the key and the slips kept so far, cleaned: already apart from each other,
    for value, message, name in candidates:  # so a candidate is compared with each of them (as apart() would)
        if value is None:
            continue
        here = _cleaned(value)
        if not _same(kept[0], here, _KEPT_APART, turn) and not any(_same(here, k, _KEPT_APART, turn) for k in kept[1:]):
            slips.append(Slip(value, message, name=name))
            kept.append(here)
    return tuple(slips)
