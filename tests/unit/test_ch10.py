"""Chapter 10's Derive exercises, over many draws: every named slip is said for exactly that slip (and
for its negation, the same rotation, where the answer is a quaternion), a right answer never hears
one, and the checked steps judge two wrong steps and a right step after a wrong one truthfully."""

from __future__ import annotations

import random

import pytest

import many_draws
from moved import moved
from through_api import grade
from workbook import bank
from workbook.reference.se3 import slerp

DERIVE = [ex for ex in bank.chapter(10) if ex.kind == "derive"]
STEPPED = [ex for ex in DERIVE if ex.steps]
QUATERNIONS = ("10.3", "10.5")
SEEDS = range(many_draws.count(150))


def _neg(value):
    return tuple(tuple(-x for x in row) for row in value)


def test_chapter_10_is_the_chapter_beyond_the_core_path():
    assert bank.chapters()[:11] == list(range(11))  # the core path 0-9, then chapter 10 first beyond it
    assert [ex.kind for ex in bank.chapter(10)] == ["derive"] * 5 + ["trace", "design", "build", "debug", "debug"]


@pytest.mark.parametrize("ex", DERIVE, ids=[ex.id for ex in DERIVE])
def test_each_slip_is_said_for_exactly_that_slip_and_never_for_the_key(ex):
    said = 0
    for seed in SEEDS:
        v = ex.variant(seed)
        right = grade(v, v.answer.typed(v.answer.key))
        assert right["status"] == "correct" and right["tag"] != "slip", (seed, right)
        if ex.id in QUATERNIONS:  # −q is the same rotation
            assert grade(v, v.answer.typed(_neg(v.answer.key)))["status"] == "correct", seed
        messages = [s.message for s in v.answer.slips]
        for slip in v.answer.slips:
            verdict = grade(v, v.answer.typed(slip.value))
            assert (verdict["status"], verdict["tag"]) == ("incorrect", "slip"), (seed, slip.message, verdict)
            assert verdict["message"] == slip.message, seed
            said += 1
        plain = grade(v, v.answer.typed(moved(v.answer.key, random.Random(seed))))
        assert plain["status"] == "incorrect" and plain["message"] not in messages, (seed, plain)
    assert said >= len(SEEDS)


@pytest.mark.parametrize("ex", STEPPED, ids=[ex.id for ex in STEPPED])
def test_each_step_slip_is_said_with_the_steps_before_it_right(ex):
    for seed in SEEDS:
        v = ex.variant(seed)
        sent = {}
        for step in v.steps:
            kind = v.step_answers[step.name]
            assert grade(v, kind.typed(kind.key), step.name, sent)["status"] == "correct", (seed, step.name)
            for slip in kind.slips:
                verdict = grade(v, kind.typed(slip.value), step.name, sent)
                assert (verdict["tag"], verdict["message"]) == ("slip", slip.message), (seed, step.name, verdict)
            sent[step.name] = kind.typed(kind.key)


@pytest.mark.parametrize("ex", STEPPED, ids=[ex.id for ex in STEPPED])
def test_two_wrong_steps_and_a_right_step_after_a_wrong_one(ex):
    """First step wrong, second step wrong in a way of its own (not following from the first): a
    final answer that follows from the learner's second step is carried from that step, the last
    wrong value it follows from. And the right second step after a wrong first one is correct."""
    checked = 0
    for seed in SEEDS:
        v = ex.variant(seed)
        rng = random.Random(seed)
        first, second = v.steps[0].name, v.steps[1].name
        k1, k2 = v.step_answers[first], v.step_answers[second]
        wrong1 = moved(k1.key, rng)
        try:
            carried2 = v.carried_steps({first: wrong1})[second]
        except ArithmeticError:
            continue
        right_second = grade(v, k2.typed(k2.key), second, {first: k1.typed(wrong1)})
        assert right_second["status"] == "correct", (seed, right_second)
        wrong2 = moved(carried2.key, rng)
        if carried2.check(carried2.typed(wrong2)).status == "correct" or k2.check(k2.typed(wrong2)).status == "correct":
            continue
        sent = {first: k1.typed(wrong1), second: k2.typed(wrong2)}
        try:
            final = v.carried_answer({first: wrong1, second: wrong2})
        except ArithmeticError:
            continue
        if v.answer.check(v.answer.typed(final.key)).status == "correct":
            continue
        verdict = grade(v, v.answer.typed(final.key), sent=sent)
        assert verdict["tag"] == "carried" and verdict["data"]["carried"]["step"] == second, (seed, verdict)
        checked += 1
    assert checked >= len(SEEDS) // 2


def test_the_slerp_midpoint_key_is_the_reference_slerp():
    """10.5's generator writes SLERP at t = ½ out by hand (the flip, then 1/(2 cos(Ω/2))); it must be the
    reference's slerp, the short way, in every draw."""
    ex = bank.get("10.5")
    for seed in SEEDS:
        v = ex.variant(seed)
        q0 = tuple(float(x) for x in v.values["q0"].split(",\\ "))
        q1 = tuple(float(x) for x in v.values["q1"].split(",\\ "))
        want = slerp(q0, q1, 0.5)
        got = [row[0] for row in v.answer.key]
        assert all(abs(a - b) < 2e-4 for a, b in zip(got, want)), (seed, got, want)


def test_the_angle_step_names_the_long_way_round():
    """10.4: forgetting the absolute value gives 360° − θ, and the slip says so in those numbers."""
    ex = bank.get("10.4")
    for seed in SEEDS:
        v = ex.variant(seed)
        long_way = 360 - v.answer.key
        verdict = grade(v, v.answer.typed(long_way))
        assert verdict["tag"] == "slip" and "long way round" in verdict["message"], (seed, verdict)


def test_the_words_that_depend_on_the_numbers_stay_true():
    """10.4's statement says q₁ has a negative w and its derivation that q₀ · q₁ is negative; 10.5's that
    q₀ · q₁ is negative: in every draw, as printed."""
    for seed in SEEDS:
        v = bank.get("10.4").variant(seed)
        assert float(v.values["q1"].split(",\\ ")[0]) < 0, seed
        assert float(v.values["step_dot"]) < 0, seed
        assert float(bank.get("10.5").variant(seed).values["step_dot"]) < 0, seed
