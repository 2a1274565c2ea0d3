"""Chains: a Derive exercise that builds on an earlier one's result, and error carried forward.

An exercise declares, in the bank next to its generator, the earlier results it
uses: ``uses=(Uses("9.2", "x", "x′"),)`` says that its ``make(p, given=...)``
takes ``given["x"]`` in place of exercise 9.2's printed x′. ``variant(p)`` says
which variant of 9.2 printed the value this draw carries (``None``: this draw
carries none, so nothing is carried forward from it).

When a learner's last answer to that variant of 9.2 was wrong, the page sends it
with the grade request (``given``), with the answers 9.2 itself builds on, and the
exercise grades with it (``Derive.grade``, :mod:`workbook.carried`): the verdict
is ``incorrect`` with tag ``carried`` and
``data.carried = {"from": "9.2", "variant": 0, "link": "Back to exercise 9.2"}``;
the page links back to 9.2 with that text.

>>> from workbook import bank
>>> ex = bank.get("9.3")
>>> [u.source for u in ex.uses]
['9.2']
>>> carried = ex.carried_answer({"x": 6.0})
>>> v = ex.grade(carried.typed(carried.key), given={"9.2": {"answer": "6", "variant": 0}}, lookup=bank.variant)
>>> v.status, v.tag, v.data["carried"]["from"], v.data["carried"]["variant"]
('incorrect', 'carried', '9.2', 0)
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass
from typing import Any

from .contract import LIMIT

MAX_GIVEN = LIMIT.given  # earlier answers a request may carry


def _first(p: Mapping[str, Any]) -> int:
    return 0


@dataclass(frozen=True)
class Uses:
    """One link of a chain: ``source``'s answer feeds ``make(p, given={name: value})``.

    ``what`` names the value in the learner's words (``x′``, ``the Jacobian F``);
    ``variant(p)`` is the source's variant whose printed answer this draw carries,
    or None when the draw carries none of the source's numbers.
    """

    source: str
    name: str
    what: str
    variant: Callable[[Mapping[str, Any]], int | None] = _first


def given(values: Mapping[str, Any] | None, name: str, default: Any) -> Any:
    """What ``make()`` uses for ``name``: the learner's value when one is given, else the printed one."""
    return default if not values or name not in values else values[name]


def value_of(reading: Any) -> Any:
    """A reading (a number's, or a matrix's rows of them) as plain values: a float, or a tuple of rows."""
    if isinstance(reading, list):
        return tuple(tuple(r.value for r in row) for row in reading)
    return reading.value

