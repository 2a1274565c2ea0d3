"""Marking a formula answer: the same function as the key at random points of its domain.

In order: equivalent to the key; undefined at most points; one of the
exercise's own slips; degrees typed inside sin, cos or tan (``sin(θ1 + 90)``,
where formulas work in radians); otherwise a point where the two differ.
"""

from __future__ import annotations

import math
import random
from collections.abc import Callable, Mapping
from typing import TYPE_CHECKING, cast

from ...contract import TAG
from ...expr import Formula, parse_formula
from ...number_format import compact, prose
from ...tolerance import agrees, clean
from ...verdict import Verdict
from ..base import slip_data

if TYPE_CHECKING:
    from . import FormulaAnswer

DEGREES = ("Inside sin, cos and tan a formula works in radians, so a number such as 90 there is 90 radians. "
           "Write pi/2, or the degree sign: 90°.")


def _same(value: float, key: float) -> bool:
    return agrees(value, clean(key)) or abs(value - key) <= 1e-9 * (1 + abs(key))


def equivalent(formula: Formula, reference: Callable[..., float], domain: Mapping[str, tuple[float, float]],
               points: int = 12, seed: int = 0) -> bool | None:
    """Do ``formula`` and ``reference`` agree at ``points`` random points of ``domain``?

    ``reference`` is called with the variables as keyword arguments. Points
    where either side is undefined (an exception, or not finite) are skipped;
    agreement uses the grading tolerance of :mod:`workbook.tolerance`. Returns
    None when fewer than half the points (at least 3) could be evaluated.

    >>> dom = {"x": (-3.0, 3.0)}
    >>> equivalent(parse_formula("1 - 2sin(x)^2", ["x"]), lambda x: math.cos(2 * x), dom)
    True
    >>> equivalent(parse_formula("2x", ["x"]), lambda x: x * x, dom)   # agrees at x = 0 and 2 only
    False
    >>> print(equivalent(parse_formula("sqrt(x)", ["x"]), lambda x: x ** 0.5, {"x": (-9.0, -1.0)}))
    None
    """
    missing = sorted(formula.names - set(domain))
    if missing:
        raise ValueError(f"the domain gives no range for {', '.join(missing)}")
    rng = random.Random(seed)
    bounds = list(domain.items())
    defined = 0
    for _ in range(points * 4):
        if defined >= points:
            break
        env = {name: rng.uniform(lo, hi) for name, (lo, hi) in bounds}
        try:
            key = float(reference(**env))
            value = formula.evaluate(env)
        except (ValueError, ArithmeticError, TypeError):
            continue
        if not (math.isfinite(key) and math.isfinite(value)):
            continue
        defined += 1
        if not _same(value, key):
            return False
    return True if defined >= max(3, points // 2) else None


def counterexample(ans: FormulaAnswer, formula: Formula) -> str:
    """Where the formula and the key differ, in words."""
    rng = random.Random(1)
    for _ in range(40):
        # a point with two decimals, which the workbook's printer shows as it is: the message names the
        # point the two values were computed at, not a rounding of it
        env = {name: round(rng.uniform(lo, hi), 2) for name, (lo, hi) in ans.domain.items()}
        if any(not lo <= env[name] <= hi for name, (lo, hi) in ans.domain.items()):
            continue
        try:
            want, got = float(cast("Callable[..., float]", ans.key)(**env)), formula.evaluate(env)
        except (ValueError, ArithmeticError, TypeError):
            continue
        if math.isfinite(want) and math.isfinite(got) and not agrees(got, clean(want)):
            where = ", ".join(f"{n} = {prose(env[n])}" for n in ans.variables)
            return f"Not the same formula: at {where} yours gives {compact(got)}, the answer {compact(want)}."
    return "Not the same formula. Check each term against the derivation."


def mark(ans: FormulaAnswer, formula: Formula) -> Verdict:
    data = {"latex": formula.latex}
    same = equivalent(formula, cast("Callable[..., float]", ans.key), ans.domain)
    if same is None:
        return Verdict("invalid", "Your formula cannot be evaluated at most points of the question's range "
                       "(a square root or logarithm of a negative number?).", data=data)
    if same:
        return Verdict("correct", "Correct: your formula agrees with the answer everywhere it was tried.", data=data)
    for slip in ans.slips:
        if equivalent(formula, slip.value, ans.domain):
            return Verdict("incorrect", slip.message, tag=TAG.slip, data={**data, **slip_data(slip)})
    in_degrees = formula.with_degree_arguments()
    if in_degrees is not None and equivalent(in_degrees, cast("Callable[..., float]", ans.key), ans.domain):
        return Verdict("incorrect", DEGREES, tag=TAG.degrees, data=data)
    return Verdict("incorrect", counterexample(ans, formula), data=data)


def degenerate(ans: FormulaAnswer) -> str | None:
    """The worked formula must be accepted, and no slip may agree with the key."""
    verdict = ans.check(ans.answer_text)
    if verdict.status != "correct":
        return f"its worked answer {ans.answer_text!r} is graded {verdict.status}"
    formula = parse_formula(ans.answer_text, ans.variables)
    for slip in ans.slips:
        if equivalent(formula, slip.value, ans.domain) is not False:
            return f"the slip {slip.message[:40]!r} agrees with the key"
    return None
