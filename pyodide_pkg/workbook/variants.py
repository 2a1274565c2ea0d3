"""Variants: a Derive exercise as a generator of fresh numbers.

An exercise with ``vary=Vary(make, Param(...), ...)`` draws its parameters from
grids chosen to stay teachable (angles in steps of 5°, lengths in steps of
0.1 m, ...). ``make(p)`` turns one draw into the exercise's fields (``key``,
``slips``, and optionally ``title``, ``label``, ...) computed with the reference
code, plus ``values``: the strings that fill the ``{{name}}`` placeholders of the
exercise's statement, hint and derivation in the chapter's Markdown.

Variant 0 is the workbook's own numbers (every parameter at its ``default``);
variant ``n > 0`` is a deterministic draw seeded by the exercise id and ``n``,
so a link with ``n`` in it opens the same numbers in any browser.

>>> p = Param("x", 3, lo=-5, hi=5, step=1)
>>> p.grid()[:3], p.describe()
([-5, -4, -3], 'x from -5 to 5 in steps of 1')
>>> fill("<p>({{x}}, 0)</p> {{m}}", {"x": "-2", "m": "a & b"})
'<p>(-2, 0)</p> a &amp; b'
"""

from __future__ import annotations

import math
import random
import re
from collections.abc import Callable, Iterator, Mapping
from dataclasses import dataclass
from functools import cached_property
from html import escape
from typing import Any

from .contract import LIMIT

PLACEHOLDER = re.compile(r"\{\{\s*([A-Za-z_][A-Za-z0-9_]*)\s*\}\}")
MAX_SEED = LIMIT.variant  # the largest variant number (contract.json, limits)
TRIES = 400
JUDGED_KEPT = 16384  # draws whose validity a generator remembers; a full memory starts again


class VariantError(Exception):
    """A template names a value the generator does not give, or no draw is well posed."""


def placeholders(template: str) -> list[str]:
    """The names a template asks for, in order of first use."""
    return list(dict.fromkeys(PLACEHOLDER.findall(template)))


def fill(template: str, values: Mapping[str, str], *, html: bool = True) -> str:
    """Put each value into the template: HTML (values escaped: they are text or
    TeX) or, with ``html=False``, the chapter's Markdown as written."""

    def one(match: re.Match) -> str:
        name = match.group(1)
        if name not in values:
            raise VariantError(f"the template asks for {{{{{name}}}}}, which the generator does not give")
        return escape(str(values[name]), quote=False) if html else str(values[name])

    return PLACEHOLDER.sub(one, template)


def _trim(x: float) -> float | int:
    """A grid value without float noise (0.30000000000000004 -> 0.3, 3.0 -> 3)."""
    x = round(x, 10)
    return int(x) if x == int(x) else x


@dataclass(frozen=True)
class Param:
    """A number drawn from ``lo, lo+step, ..., hi``; ``default`` is variant 0's.

    ``unit`` only serves the description (e.g. ``"°"``, ``" m"``); ``avoid``
    lists values never drawn (e.g. 0 where it would make the question trivial).
    """

    name: str
    default: float
    lo: float
    hi: float
    step: float
    unit: str = ""
    avoid: tuple[float, ...] = ()

    def grid(self) -> list[float]:
        return list(self._grid)

    @cached_property
    def _grid(self) -> tuple[float, ...]:
        """The values, worked out once (every draw picks from them)."""
        n = round((self.hi - self.lo) / self.step)
        values = [_trim(self.lo + k * self.step) for k in range(n + 1)]
        return tuple(v for v in values if not any(math.isclose(v, a, abs_tol=1e-9) for a in self.avoid))

    def pick(self, rng: random.Random) -> float:
        return rng.choice(self._grid)

    def describe(self) -> str:
        u = self.unit
        return f"{self.name} from {_trim(self.lo)}{u} to {_trim(self.hi)}{u} in steps of {_trim(self.step)}{u}" + (
            f" (never {', '.join(f'{_trim(a)}{u}' for a in self.avoid)})" if self.avoid else "")


@dataclass(frozen=True)
class Choice:
    """One of a few named cases (e.g. which entry is asked); ``default`` is variant 0's."""

    name: str
    default: Any
    options: tuple[Any, ...]

    def grid(self) -> list[Any]:
        return list(self.options)

    def pick(self, rng: random.Random) -> Any:
        return rng.choice(self.options)

    def describe(self) -> str:
        return f"{self.name} one of {', '.join(map(str, self.options))}"


class Vary:
    """How an exercise varies: ``make(p) -> {field: value, ..., "values": {...}}``.

    ``valid(p)`` rejects draws that are not well posed (an unreachable target,
    an accidental singularity, a question that became trivial). Draws equal to
    variant 0's parameters are never used for ``n > 0``.
    """

    def __init__(self, make: Callable[..., dict[str, Any]], *params: Param | Choice,
                 valid: Callable[[dict[str, Any]], bool] | None = None) -> None:
        self.make, self.params = make, tuple(params)
        self.valid = valid or (lambda p: True)
        self._judged: dict[tuple, bool] = {}  # valid(p) of the draws seen so far (a function of the numbers)

    @property
    def defaults(self) -> dict[str, Any]:
        return {q.name: q.default for q in self.params}

    def candidates(self, exercise_id: str, seed: int) -> Iterator[dict[str, Any]]:
        """Variant 0's parameters; or, for ``seed > 0``, valid draws in a fixed order."""
        if seed == 0:
            yield self.defaults
            return
        rng = random.Random(f"{exercise_id}/{seed}")
        defaults = self.defaults
        for _ in range(TRIES):
            p = {q.name: q.pick(rng) for q in self.params}
            if p != defaults and self._well_posed(p):
                yield p

    def _well_posed(self, p: dict[str, Any]) -> bool:
        """``valid(p)``, judged once per draw: many seeds draw the same numbers on a small grid."""
        try:
            key = tuple(sorted(p.items()))
            hash(key)
        except TypeError:
            return bool(self.valid(p))
        if key not in self._judged:
            if len(self._judged) >= JUDGED_KEPT:
                self._judged.clear()
            self._judged[key] = bool(self.valid(p))
        return self._judged[key]

    def describe(self) -> str:
        return "; ".join(q.describe() for q in self.params)


def check_seed(seed: object) -> int:
    """A variant number from a request or a link: a whole number 0..MAX_SEED."""
    if isinstance(seed, bool) or not isinstance(seed, (int, str)):
        raise ValueError("a variant is a whole number")
    n = int(seed) if isinstance(seed, int) or str(seed).isdigit() else -1
    if not 0 <= n <= MAX_SEED:
        raise ValueError(f"a variant is a whole number from 0 to {MAX_SEED}")
    return n
