"""Error carried forward says only true things: over 200 draws of every stepped exercise and
chain, no verdict names the wrong place, none ignores a step the learner typed, and a value
that leaves the quantity undefined never earns "carried" (the probes: ``carried_probe.py``).
Then the cases the probes cannot draw: the issue's own examples, a recomputed key that
cancels to 0, undefined values in words, a named slip that still wins."""

from __future__ import annotations

import random

import pytest

import carried_probe
from carried_probe import grade, read, variants
from workbook import bank
from workbook.tolerance import REL


@pytest.fixture(scope="module")
def counts():
    return carried_probe.run(draws=40)  # `python tests/unit/carried_probe.py` runs 200 of each


@pytest.mark.parametrize("what", ["wrong place", "ignores a typed step", "undefined earns carried",
                                  "undefined as a plain Not quite"])
def test_no_verdict_is_untrue(counts, what):
    assert counts[what] == 0, dict(counts)


def test_the_probes_check_enough(counts):
    assert counts["checked: two wrong steps"] >= 300
    assert counts["checked: a step that follows a wrong one"] >= 300
    assert counts["checked: right step after a wrong one"] >= 100
    assert counts["checked: carried from an earlier exercise"] >= 100
    assert counts["checked: a step carried from an earlier exercise"] >= 50
    assert counts["checked: a chain of chains"] >= 30
    assert counts["checked: undefined values"] >= 30


def test_the_learners_own_step_is_the_learners():
    ex = bank.get("4.1")
    d = ex.step_answers["d"].typed(((300.0,), (400.0,)))
    assert grade(ex, "500", mine={"d": d, "q": "25"})["tag"] != "carried"  # √25 = 5, not 500
    said = grade(ex, "500", mine={"d": d})  # q not typed: recomputed from the learner's d
    assert said["tag"] == "carried" and said["data"]["carried"]["step"] == "d"
    said = grade(ex, "500", mine={"d": d, "q": "250000"})
    assert said["tag"] == "carried" and said["data"]["carried"]["step"] == "d"
    assert "in step 2, which follows from your (dx, dy) in step 1" in said["message"]
    said = grade(ex, "10", mine={"d": d, "q": "100"})  # two wrong steps: the answer follows from step 2
    assert said["tag"] == "carried" and said["data"]["carried"]["step"] == "q" and "slip is in step 2" in said["message"]


def _root(f, lo, hi):
    """A zero of f between lo and hi (f changes sign there), by bisection."""
    flo = f(lo)
    for _ in range(200):
        mid = (lo + hi) / 2
        fm = f(mid)
        if (fm < 0) == (flo < 0):
            lo, flo = mid, fm
        else:
            hi = mid
    return (lo + hi) / 2


@pytest.mark.parametrize("ex_id", ["7.1", "7.6", "6.2"])
def test_a_carried_key_that_cancels_accepts_zero(ex_id):
    """A learner's wrong θ1 + θ2 that makes the answer cancel: 0 follows from it."""
    checked = 0
    for v in variants(ex_id, 40):
        name = v.steps[0].name
        kind = v.step_answers[name]
        def f(t, v=v, name=name):
            key = v.carried_answer({name: t}).key
            return key[0][0] if isinstance(key, tuple) else key

        grid = [kind.key + d for d in range(-180, 181, 7)]
        pairs = [(a, b) for a, b in zip(grid, grid[1:]) if (f(a) < 0) != (f(b) < 0)]
        if not pairs:
            continue
        t = _root(f, *pairs[0])
        key = v.carried_answer({name: t}).key
        if isinstance(key, tuple):
            answer = v.answer.typed(key)
            answer[0][0] = "0"
        else:
            answer = "0"
        if v.answer.check(answer).status == "correct":
            continue
        said = grade(v, answer, mine={name: f"{t!r}°" if kind.angle == "deg" else repr(t)})
        assert said["tag"] == "carried", (v.seed, t, said)
        checked += 1
    assert checked >= 10


def test_an_offset_of_zero_has_no_bearing_in_words():
    ex = bank.get("4.2")
    zero = ex.step_answers["d"].typed(((0.0,), (0.0,)))
    said = grade(ex, "0", mine={"d": zero})
    assert said["tag"] == "undefined" and "no bearing is defined" in said["message"], said
    assert said["data"]["carried"] == {"step": "d", "link": "Back to step 1"}
    said = grade(ex, "0", step="phi", mine={"d": zero})
    assert said["tag"] == "undefined" and "step 1" in said["message"]


def test_a_named_slip_still_wins_over_an_undefined_value():
    ex = bank.get("4.2")
    zero = ex.step_answers["d"].typed(((0.0,), (0.0,)))
    slip = ex.answer.slips[0]
    said = grade(ex, ex.answer.typed(slip.value), mine={"d": zero})
    assert said["tag"] == "slip" and said["message"] == slip.message


@pytest.mark.parametrize("ex_id", ["4.3", "4.7"])
def test_a_division_by_zero_is_said_not_hidden(ex_id):
    ex = bank.get(ex_id)
    key = ex.answer.key
    answer = [["7"] * len(row) for row in key] if isinstance(key, tuple) else "7"
    said = grade(ex, answer, mine={"d": ex.step_answers["d"].typed(((0.0,), (0.0,)))})
    assert said["tag"] == "undefined" and "divides by zero" in said["message"], said


def test_a_folded_elbow_leaves_theta1_undefined():
    for v in variants("6.3", 40):
        if v.params["asked"] != "θ1":
            continue
        said = grade(v, "12", mine={"t2": "180°"})
        assert said["tag"] == "undefined" and "folds back" in said["message"], said
        return
    pytest.fail("no draw of 6.3 asks for θ1")


def after_a_wrong_3_7(seed: int):
    """Draws of 3.8 that carry 3.7's result, each with a wrong F(1,3) typed in 3.7:
    (the draw, 3.7's answer kind, the wrong F as typed, the request's ``given``)."""
    rng = random.Random(seed)
    for v in variants("3.8", 30):
        (link,) = v.uses
        at = link.variant(v.params)
        if at is None:
            continue
        source = bank.variant("3.7", at)
        rows = [list(r) for r in source.answer.key]
        rows[0][2] += 0.5 + rng.random()
        typed = source.answer.typed(tuple(map(tuple, rows)))
        yield v, source.answer, typed, {"3.7": {"answer": typed, "variant": at}}


def test_after_a_wrong_3_7_the_steps_of_3_8_point_to_3_7():
    for v, source, typed, given in after_a_wrong_3_7(38):
        fp = v.carried_steps({"F": read(source, typed)})["FP"]
        t1 = v.step_answers["FP"].typed(fp.key)
        one = grade(v, t1, step="FP", given=given)
        fpf = v.carried_steps({"F": read(source, typed), "FP": read(v.step_answers["FP"], t1)})["FPF"]
        two = grade(v, v.step_answers["FPF"].typed(fpf.key), step="FPF", mine={"FP": t1}, given=given)
        for said in (one, two):
            assert said["tag"] == "carried" and said["data"]["carried"].get("from") == "3.7", said


def test_only_an_entry_that_cancels_is_judged_on_the_questions_scale():
    """3.8 after a wrong 3.7: the answer as the learner's F gives it is carried; with one entry
    that does not cancel off by 0.9 of the floor the question's scale sets (beyond that entry's
    own figures, which a direct answer's check holds it to), it is not."""
    checked = 0
    for v, source, typed, given in after_a_wrong_3_7(39):
        key = v.carried_answer({"F": read(source, typed)}).key
        floor = REL * max(abs(x) for row in (*key, *v.answer.key) for x in row)  # the question's scale
        small = [(abs(x), i, j) for i, row in enumerate(key) for j, x in enumerate(row) if abs(x) > 3 * floor]
        _, i, j = min(small)
        answer = v.answer.typed(key)
        assert grade(v, answer, given=given)["tag"] == "carried"
        answer[i][j] = f"{key[i][j] + 0.9 * floor:.8g}"
        said = grade(v, answer, given=given)
        assert said["tag"] != "carried" and said["status"] != "correct", (v.seed, key[i][j], answer[i][j], said)
        checked += 1
    assert checked >= 10
