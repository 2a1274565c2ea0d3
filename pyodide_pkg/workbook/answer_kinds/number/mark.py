"""Marking a number answer: the key, the exercise's slips, then the slips every number can make.

In order: right (within the tolerance, or within half a unit of the last digit
typed to at least 3 significant figures; a whole turn away for a periodic
angle; the negated key where either sign is right); one of the exercise's own
slips; degrees typed inside sin, cos or tan where they are read as radians;
radians given for degrees and the reverse; the sign; close; plain wrong.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

from ...contract import TAG
from ...expr import Reading
from ...number_format import fmt, is_exact
from ...tolerance import FIGURES, agrees, clean, is_close_miss, is_rounding, is_sign_slip
from ...verdict import Verdict
from ..base import slip_data

if TYPE_CHECKING:
    from . import NumberAnswer

TRIG_DEGREES = ("A number inside sin, cos or tan without a unit is read in radians, so {how}. "
                "Write the degree sign: cos(90°), not cos(90).")


def _half(reading: Reading) -> float | None:
    return reading.half_unit if reading.figures is not None and reading.figures >= FIGURES else None


def agrees_with(ans: NumberAnswer, value: float, target: float, half_unit: float | None = None) -> bool:
    """``value`` counts as ``target`` for this answer (its tolerance, exactness and turns)."""
    target = clean(target)
    if ans.periodic and ans.angle:
        turn = 360.0 if ans.angle == "deg" else math.tau
        value = target + math.remainder(value - target, turn)
    return agrees(value, target, rel=ans.rel_tol, exact=ans.exact, half_unit=half_unit)


def figures_word(figures: int) -> str:
    """``1 significant figure``, ``2 significant figures``."""
    return f"{figures} significant figure{'' if figures == 1 else 's'}"


def too_coarse(reading: Reading, key: float) -> bool:
    """The answer is the key rounded to its own significant figures, and those are fewer than wanted."""
    return reading.figures is not None and reading.figures < FIGURES and is_rounding(reading.value, key,
                                                                                      reading.figures)


def close_message(reading: Reading, key: float) -> str:
    """What "close" says: more figures only when the answer is the key rounded to the few it has."""
    if reading.figures is not None and too_coarse(reading, key):
        return (f"Close, but give at least {FIGURES} significant figures: you gave {figures_word(reading.figures)}. "
                "Carry more digits through the intermediate steps.")
    return (f"Close, but not within tolerance. Round correctly to at least {FIGURES} significant figures "
            "(4 is safer), and carry more digits through the intermediate steps.")


def _converted(value: float, other: float, unit: str, other_unit: str) -> str:
    """The learner's angle in the other unit, "is" only when both numbers print exactly.

    >>> _converted(0.5, 28.64788975654116, " rad", "°"), _converted(90, math.pi / 2, "°", " rad")
    ('0.5 rad is about 28.6479°', '90° is about 1.5708 rad')
    """
    verb = "is" if is_exact(value) and is_exact(other) else "is about"
    return f"{fmt(value)}{unit} {verb} {fmt(other)}{other_unit}"


def mark(ans: NumberAnswer, reading: Reading) -> Verdict:
    value, half = reading.value, _half(reading)
    key = clean(ans.key)
    if agrees_with(ans, value, key, half):
        unit = f" {ans.unit}" if ans.unit and ans.angle is None else ""
        return Verdict("correct", f"Correct: {ans.worked_text()}{unit}.")
    if ans.either_sign and agrees_with(ans, -value, key, half):
        return Verdict("correct", f"Correct: {ans.either_sign}")
    for slip in ans.slips:
        if agrees_with(ans, value, slip.value, half):
            return Verdict("incorrect", slip.message, tag=TAG.slip, data=slip_data(slip))
    as_degrees = reading.with_degree_arguments()
    if as_degrees is not None and agrees_with(ans, as_degrees, key):
        how = ("your angle was taken as radians while this exercise works in degrees" if ans.angle != "rad"
               else "your angle was taken as radians although you meant degrees")
        return Verdict("incorrect", TRIG_DEGREES.format(how=how), tag=TAG.degrees)
    if reading.bare and ans.angle == "deg" and agrees_with(ans, math.degrees(value), key):
        return Verdict("incorrect", f"That looks like radians: {_converted(value, math.degrees(value), ' rad', '°')}. "
                       f"This answer is in degrees: multiply by 180/π, or type the unit, {fmt(value)} rad.",
                       tag=TAG.radians)
    if reading.bare and ans.angle == "rad" and agrees_with(ans, math.radians(value), key):
        return Verdict("incorrect", f"That looks like degrees: {_converted(value, math.radians(value), '°', ' rad')}. "
                       f"This answer is in radians: multiply by π/180, or type the unit, {fmt(value)}°.",
                       tag=TAG.degrees)
    if is_sign_slip(value, key, rel=ans.rel_tol) or (half and key and agrees(-value, key, half_unit=half)):
        return Verdict("incorrect", "The size is right but the sign is wrong. Check which way the quantity points.",
                       tag=TAG.sign)
    if not ans.exact and is_close_miss(value, key, rel=ans.rel_tol, figures=reading.figures):
        return Verdict("incorrect", close_message(reading, key), tag=TAG.close)
    return Verdict("incorrect", "Not quite. Try the hint, or work the derivation one line at a time.")
