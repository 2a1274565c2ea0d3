"""The steps at the hard part (issue 26): 1.6's Rᵀ and −Rᵀt, 3.7's move and θ column, 4.3's
∂r/∂dx (in place of q = dx² + dy²), 4.7's bearing row (in place of q); and the chain 3.8 ← 3.7 over 3.8's whole grid.

Over 200 draws of each exercise, every step's key is checked against a computation written
here from the formulas the derivation states (not the bank's), so a generator that carries a
learner's value into the wrong place fails:

- each step's key typed is correct, and each of its slips typed gets its own message;
- a wrong value at any step (moved as a learner might, ``moved``) gives every later step, and the
  final answer, the key this file recomputes from that value; the grader calls that later step
  (and that final answer) carried, naming the wrong step, and still calls the right one correct.

And for 3.8, over 200 variants: the variant of 3.7 it names (its ``Uses.variant``) prints the
v, dt and F that 3.8 uses, and 3.8's key is what 3.7's printed F, read back, gives.
"""

from __future__ import annotations

import math
import random

import pytest

import many_draws
from moved import moved
from through_api import grade
from workbook import bank, chains, steps
from workbook.bank import ch3_whole_matrices
from workbook.number_format import bmatrix

DRAWS = many_draws.count(200)


def _inverse(v, given):
    """1.6: Rᵀ, then −Rᵀt from the learner's Rᵀ, then T⁻¹ = [[Rᵀ, −Rᵀt], [0, 0, 1]] from both."""
    th = math.radians(v.params["theta"])
    t = (v.params["tx"], v.params["ty"])
    RT = ((math.cos(th), math.sin(th)), (-math.sin(th), math.cos(th)))
    A = given.get("RT", RT)
    tinv = tuple((-(row[0] * t[0] + row[1] * t[1]),) for row in A)
    b = given.get("tinv", tinv)
    final = ((A[0][0], A[0][1], b[0][0]), (A[1][0], A[1][1], b[1][0]), (0.0, 0.0, 1.0))
    return {"RT": RT, "tinv": tinv}, final


def _north(v, given):
    """3.7: the move (v cos θ dt, v sin θ dt) at θ = π/2, then the θ column (−Δy, Δx, 1) from the
    learner's move, then F: the identity with that column."""
    speed, dt = v.params["v"], v.params["dt"]
    move = ((0.0,), (speed * dt,))
    (a,), (b,) = given.get("move", move)
    col = ((-b,), (a,), (1.0,))
    c = given.get("col", col)
    final = ((1.0, 0.0, c[0][0]), (0.0, 1.0, c[1][0]), (0.0, 0.0, c[2][0]))
    return {"move": move, "col": col}, final


def _jacobian(v, given):
    """4.7: d = (lx − x, ly − y), then the bearing row (dy/q, −dx/q, −1) from the learner's d, then
    H: the range row (−dx/√q, −dy/√q, 0) from d and the learner's bearing row."""
    p = v.params
    d = ((p["lx"] - p["x"],), (p["ly"] - p["y"],))
    (dx,), (dy,) = given.get("d", d)
    q = dx * dx + dy * dy
    bearing = ((dy / q, -dx / q, -1.0),)
    row = given.get("bearing", bearing)
    final = ((-dx / math.sqrt(q), -dy / math.sqrt(q), 0.0), row[0])
    return {"d": d, "bearing": bearing}, final


def _slope(v, given):
    """4.3: d = (lx − x, ly − y), then ∂r/∂dx = dx/√q from the learner's d, then H(1,1) = −∂r/∂dx."""
    p = v.params
    d = ((p["lx"] - p["x"],), (p["ly"] - p["y"],))
    (dx,), (dy,) = given.get("d", d)
    drdx = dx / math.sqrt(dx * dx + dy * dy)
    return {"d": d, "drdx": drdx}, -given.get("drdx", drdx)


EXPECTED = {"1.6": _inverse, "3.7": _north, "4.3": _slope, "4.7": _jacobian}
STEPS = {"1.6": ["RT", "tinv"], "3.7": ["move", "col"], "4.3": ["d", "drdx"], "4.7": ["d", "bearing"]}


def _agrees(kind, value) -> bool:
    return kind.check(kind.typed(value)).status == "correct"


def test_the_hard_steps_are_declared():
    for ex_id, names in STEPS.items():
        assert [s.name for s in bank.get(ex_id).steps] == names


@pytest.mark.parametrize("ex_id", sorted(EXPECTED))
def test_each_step_key_and_slip(ex_id):
    ex = bank.get(ex_id)
    for seed in range(DRAWS):
        v = ex.variant(seed)
        keys, final = EXPECTED[ex_id](v, {})
        assert _agrees(v.answer, final), (seed, "final key")
        for name, key in keys.items():
            kind = v.step_answers[name]
            assert _agrees(kind, key), (seed, name, kind.key, key)
            assert kind.check(kind.typed(kind.key)).status == "correct", (seed, name)
            for slip in kind.slips:
                said = kind.check(kind.typed(slip.value))
                assert (said.status, said.message) == ("incorrect", slip.message), (seed, name, slip, said)


@pytest.mark.parametrize("ex_id", sorted(EXPECTED))
def test_a_wrong_step_is_carried_into_every_later_step_and_the_answer(ex_id):
    ex = bank.get(ex_id)
    rng = random.Random(f"hard steps {ex_id}")
    names = STEPS[ex_id]
    carried = dict.fromkeys(names, 0)
    for seed in range(DRAWS):
        v = ex.variant(seed)
        _printed, _ = EXPECTED[ex_id](v, {})
        for i, name in enumerate(names):
            kind = v.step_answers[name]
            wrong = chains.value_of(kind.reader.read(kind, kind.typed(moved(kind.key, rng))))  # as typed, and read back
            if _agrees(kind, wrong):
                continue
            given = {name: wrong}
            keys, final = EXPECTED[ex_id](v, given)
            later = v.carried_steps(given)
            for after in names[i + 1:]:
                assert _agrees(later[after], keys[after]), (seed, name, after, later[after].key, keys[after])
            mine = v.carried_answer(given)
            assert _agrees(mine, final), (seed, name, mine.key, final)
            # through the grader: the earlier steps right, this one wrong
            sent = {n: v.step_answers[n].typed(v.step_answers[n].key) for n in names[:i]}
            sent[name] = kind.typed(wrong)
            for after in names[i + 1:]:
                right = v.step_answers[after]
                if _agrees(right, keys[after]):
                    continue
                said = grade(v, right.typed(keys[after]), after, sent)
                assert (said["status"], said["tag"], said["data"]["carried"]["step"]) == ("incorrect", "carried", name), \
                    (seed, name, after, said)
                assert grade(v, right.typed(right.key), after, sent)["status"] == "correct", (seed, after)
            if not _agrees(v.answer, final):
                said = grade(v, v.answer.typed(final), sent=sent)
                assert (said["status"], said["tag"], said["data"]["carried"]["step"]) == ("incorrect", "carried", name), \
                    (seed, name, said)
                carried[name] += 1
    for name, n in carried.items():
        assert n >= DRAWS * 0.9, f"{ex_id}: only {n} of {DRAWS} wrong values at step {name} changed the answer"


def test_the_derivations_print_the_new_steps():
    from pathlib import Path

    from exercise_text import load_all  # docs/hooks/exercise_text.py

    texts = load_all(Path(__file__).resolve().parents[2])
    for ex_id, names in STEPS.items():
        for name in names:
            assert "{{" + steps.placeholder(name) + "}}" in texts[ex_id].solution, (ex_id, name)


# ---- the chain 3.8 ← 3.7 over 3.8's grid ---------------------------------------------------------
def test_every_set_of_3_7_that_3_8_draws_is_the_one_3_7_shows():
    """3.8 reads 3.7's numbers from 3.7's generator: for every set it may draw, they are the variant's own."""
    for n in ch3_whole_matrices._SETS_37:
        shown = bank.variant("3.7", n).params
        assert ch3_whole_matrices._numbers_of_37(n) == (shown["v"], shown["dt"]), n


def test_the_3_7_variant_3_8_names_prints_the_F_it_uses():
    ex = bank.get("3.8")
    (link,) = ex.uses
    named = set()
    for seed in range(DRAWS + 50):
        v = ex.variant(seed)
        at = link.variant(v.params)
        assert at is not None, seed  # every draw carries 3.7's F
        named.add(at)
        source = bank.variant("3.7", at)
        assert (source.values["v"], source.values["dt"]) == (v.values["v"], v.values["dt"]), (seed, at)
        assert v.values["F"] == bmatrix(source.answer.key), (seed, at)
        # 3.7's printed answer, as a learner types it from the page, gives 3.8's own key
        typed = source.answer.worked_text()
        read = source.answer.reader.read(source.answer, typed)
        F = tuple(tuple(e.value for e in row) for row in read)
        assert _agrees(v.carried_answer({"F": F}), v.answer.key), (seed, at)
        # the statement names the set (the workbook's numbers at 0)
        if at:
            assert f"variant=3.7-{at}" in v.values["set37"], (seed, v.values["set37"])
        else:
            assert "workbook's numbers" in v.values["set37"]
    assert len(named) >= 0.6 * (DRAWS + 50)  # 3.8's draws reach many of 3.7's sets, not one (150 of 250 in the full suite)


def test_a_wrong_3_7_is_carried_into_3_8_only_at_the_set_3_8_names():
    from workbook import chains

    rng = random.Random("3.8 sets")
    ex = bank.get("3.8")
    (link,) = ex.uses
    carried = 0
    for seed in range(DRAWS):
        v = ex.variant(seed)
        at = link.variant(v.params)
        source = bank.variant("3.7", at)
        wrong = moved(source.answer.key, rng)
        if _agrees(source.answer, wrong):
            continue
        typed = source.answer.typed(wrong)
        theirs = v.carried_answer({"F": chains.value_of(source.answer.reader.read(source.answer, typed))})
        follows = v.answer.typed(theirs.key)
        if _agrees(v.answer, theirs.key):
            continue
        here = v.grade(follows, given={"3.7": {"answer": typed, "variant": at}}, lookup=bank.variant)
        assert (here.status, here.tag, here.data["carried"]["variant"]) == ("incorrect", "carried", at), (seed, here)
        other = v.grade(follows, given={"3.7": {"answer": typed, "variant": at + 1}}, lookup=bank.variant)
        assert other.tag != "carried", (seed, other)
        carried += 1
    assert carried >= DRAWS * 0.9
