"""An angle typed in the other unit is named with the learner's own number, converted.

"That looks like radians" once gave the same example (0.9273 rad) in every exercise;
it now says what the learner's value is in the unit asked, and both ways it offers to
type it (the converted number, or the number with its unit) are accepted.
"""

from __future__ import annotations

import math
import re
import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "pyodide_pkg"))

from workbook import bank
from workbook.kinds.derive import Derive
from workbook.number_format import fmt

VARIANTS = range(0, 40, 3)


def angle_answers():
    """(where, answer kind) for every angle answer, final or step, over several variants."""
    out = []
    for ex in bank.all_exercises():
        if not isinstance(ex, Derive):
            continue
        for seed in VARIANTS if ex.vary is not None else (0,):
            shown = ex.variant(seed)
            kinds = {"answer": shown.answer, **{f"step {n}": k for n, k in shown.step_answers.items()}}
            for name, kind in kinds.items():
                if getattr(kind, "angle", None) and not kind.exact:  # an exact key takes no other unit
                    out.append((f"{ex.id} v{seed} {name}", kind))
    return out


ANSWERS = angle_answers()


def test_there_are_angle_answers_in_both_units():
    units = {kind.angle for _, kind in ANSWERS}
    assert units == {"deg", "rad"}, units
    assert {where.split()[0] for where, _ in ANSWERS} >= {"4.2", "6.3", "7.4"}


def typed_in_the_other_unit(kind) -> list[float]:
    """Values a learner might type in the wrong unit: the key converted, rounded to 4 and 6
    places, and nudged inside the tolerance."""
    key = kind.key
    other = math.radians(key) if kind.angle == "deg" else math.degrees(key)
    return [round(other, 6), float(fmt(other)), other * (1 + 3e-4), other * (1 - 2e-4)]


@pytest.mark.parametrize("where,kind", ANSWERS, ids=[w for w, _ in ANSWERS])
def test_the_message_converts_the_learners_own_value(where, kind):
    if kind.key == 0:
        pytest.skip("0 is the same angle in both units")
    messages = set()
    for value in typed_in_the_other_unit(kind):
        verdict = kind.check(repr(value))
        if kind.angle == "deg":
            assert verdict.tag == "radians", (where, value, verdict)
            said, converted = f"{fmt(value)} rad", fmt(math.degrees(value))
            assert re.search(rf"{re.escape(said)} is (about )?{re.escape(converted)}°", verdict.message), verdict.message
        else:
            assert verdict.tag == "degrees", (where, value, verdict)
            said, converted = f"{fmt(value)}°", fmt(math.radians(value))
            assert re.search(rf"{re.escape(said)} is (about )?{re.escape(converted)} rad", verdict.message), verdict.message
        # both ways the message offers are right answers in this exercise
        assert said in verdict.message.split("type the unit, ")[1], verdict.message
        assert kind.check(said).status == "correct", (where, said)
        assert kind.check(converted).status == "correct", (where, converted)
        messages.add(verdict.message)
    assert len(messages) > 1, "the same words whatever the learner typed"


def test_the_example_is_not_one_fixed_number():
    """4.2's variants name their own values, never 0.9273 when the learner typed something else."""
    seen = set()
    for seed in VARIANTS:
        kind = bank.get("4.2").variant(seed).answer
        typed = fmt(math.radians(kind.key))
        message = kind.check(typed).message
        assert f"{fmt(float(typed))} rad" in message
        if abs(float(typed) - 0.9273) > 1e-3:
            assert "0.9273" not in message, message
        seen.add(message)
    assert len(seen) > 1


def test_is_only_for_numbers_that_print_exactly():
    """A rounded number is "about": 1.5708 rad is about 90.0002°, and π/2 typed in full about 90°."""
    kind = bank.get("6.3").answer  # 90°
    assert "1.5708 rad is about 90.0002°" in kind.check("1.5708").message
    assert "1.5708 rad is about 90°" in kind.check(repr(math.pi / 2)).message
