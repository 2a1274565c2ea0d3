"""Chains: a Derive exercise that builds on an earlier one's result, and error carried forward.

An exercise declares, in the bank next to its generator, the earlier results it
uses: ``uses=(Uses("9.2", "x", "x′"),)`` says that its ``make(p, given=...)``
takes ``given["x"]`` in place of exercise 9.2's printed x′. ``variant(p)`` says
which variant of 9.2 printed the value this draw carries (``None``: this draw
carries none, so nothing is carried forward from it).

When a learner's last answer to that variant of 9.2 was wrong, the page sends it
with the grade request (``given``). The grader reads it with 9.2's own answer
kind, recomputes this exercise's key with the learner's value substituted, by the
exercise's own generator, and when the answer agrees with that key (and not with
the right one) says so: the verdict is ``incorrect`` with tag ``carried`` and
``data.carried = {"from": "9.2", "variant": 0, "link": "Back to exercise 9.2"}``;
the page links back to 9.2 with that text.

>>> from workbook import bank
>>> ex = bank.get("9.3")
>>> [u.source for u in ex.uses]
['9.2']
>>> given = {"9.2": {"answer": "6", "variant": 0}}
>>> carried = ex.carried_answer({"x": 6.0})
>>> v = grade(ex, carried.typed(carried.key), given, bank.variant)
>>> v.status, v.tag, v.data["carried"]["from"], v.data["carried"]["variant"]
('incorrect', 'carried', '9.2', 0)
>>> grade(ex, ex.answer.typed(ex.answer.key), given, bank.variant).status
'correct'
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from dataclasses import dataclass
from typing import Any

from .contract import TAG
from .number_format import prose
from .tolerance import clean
from .verdict import Verdict

Derive = Any  # a workbook.kinds.derive.Derive (which imports this module, so not imported here)

MAX_GIVEN = 8  # earlier answers a request may carry


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


def _shown(value: Any) -> str:
    return prose(clean(value)) if isinstance(value, float) and math.isfinite(value) else ""


def wrong_values(ex: Derive, sent: Mapping[str, Any], find: Callable[[str, int], Any]) -> tuple[dict, dict]:
    """The learner's earlier values that are wrong, by the name ``make()`` takes, and the link each came from."""
    values, links = {}, {}
    for link in ex.uses:
        earlier = sent.get(link.source)
        variant = link.variant(ex.params)
        if not isinstance(earlier, Mapping) or variant is None or earlier.get("variant", 0) != variant:
            continue
        source = find(link.source, variant)
        reading = source.answer.reader.read(source.answer, earlier.get("answer"))
        if isinstance(reading, Verdict) or source.answer.marker.mark(source.answer, reading).status == "correct":
            continue
        values[link.name], links[link.name] = value_of(reading), (link, variant)
    return values, links


def grade(ex: Derive, answer: object, sent: Mapping[str, Any] | None, find: Callable[[str, int], Any]) -> Verdict:
    """The verdict on ``answer``, carried forward from the learner's wrong earlier values where it follows from them."""
    verdict = ex.answer.check(answer)
    if verdict.status != "incorrect" or not sent or not ex.uses:
        return verdict
    return follow(ex, answer, verdict, wrong_values(ex, sent, find))


def follow(ex: Derive, answer: object, verdict: Verdict, chain: tuple[dict, dict]) -> Verdict:
    """``verdict`` on ``answer``, or carried when it is wrong but follows from the learner's wrong
    earlier values (``chain``: what :func:`wrong_values` found)."""
    values, links = chain
    if verdict.status != "incorrect" or not values:
        return verdict
    try:
        carried = ex.carried_answer(values)
        follows = carried.check(answer).status == "correct"
    except (ValueError, ArithmeticError, TypeError):  # the learner's value leaves the model (a root of a negative, ...)
        return verdict
    if not follows:
        return verdict
    return carried_verdict(values, links)


def carried_verdict(values: Mapping[str, Any], links: Mapping[str, Any]) -> Verdict:
    """The verdict on an answer that follows from the learner's wrong earlier values (``links``: from wrong_values)."""
    (name, (link, variant)), *_ = links.items()
    shown = _shown(values[name])
    mine = f"your {link.what}" + (f" = {shown}" if shown else "")
    return Verdict("incorrect", f"This follows correctly from {mine} from exercise {link.source}, but that value is "
                   f"wrong: the slip is in exercise {link.source}. Fix it there, and carry the right value here.",
                   tag=TAG.carried, data={"carried": {"from": link.source, "variant": variant,
                                                        "link": f"Back to exercise {link.source}"}})
