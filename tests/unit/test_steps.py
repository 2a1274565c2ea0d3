"""Checked steps: every exercise with steps, over 200 variants.

For each draw of each exercise that declares steps (``steps=(Step(...), ...)``):

- the derivation prints every step through its ``{{step_NAME}}`` placeholder, so the
  intermediate it shows is the step's worked answer, and the step's grader accepts
  that printed value (and refuses each of the step's slips with its own message);
- the steps chain to the final key: the generator fed every step's key (as a learner
  who typed each printed value) gives the same final key;
- a wrong step carries forward: the next step (and the final answer) computed by the
  generator from the learner's wrong value is ``carried`` and names the wrong step;
  the right next step is still ``correct``; a value that follows from neither is plain
  ``incorrect``.
"""

from __future__ import annotations

import json
import random
from pathlib import Path

import pytest

import many_draws
from exercise_text import load_all  # docs/hooks/exercise_text.py
from moved import moved
from through_api import grade
from workbook import bank, chains, steps
from workbook.api import handle

ROOT = Path(__file__).resolve().parents[2]
DRAWS = many_draws.count(200)
STEPPED = [ex for ex in bank.all_exercises() if ex.kind == "derive" and ex.steps]
TEXTS = load_all(ROOT)
# The exercises that must offer steps: every EKF, pose-graph, IK, Jacobian and capstone derivation
# with two intermediate quantities or more (4.4, 7.2, 9.5 and 9.6 have one: nothing to step through).
REQUIRED = {"1.6", "3.4", "3.7", "3.8", "4.1", "4.2", "4.3", "4.7", "5.2", "5.6", "5.7",
            "6.2", "6.3", "7.1", "7.6", "9.2", "9.3", "9.4", "9.8"}


def test_enough_exercises_can_be_worked_in_steps():
    missing = REQUIRED - {ex.id for ex in STEPPED}
    assert not missing, f"these exercises should offer steps: {', '.join(sorted(missing))}"
    assert len(STEPPED) >= 15
    for ex in STEPPED:
        assert len(ex.steps) >= 2, f"{ex.id}: a derivation worked in steps has at least two intermediates"


def _variants(ex):
    """Up to 200 distinct draws (a small grid may have fewer)."""
    seen = set()
    for seed in range(DRAWS * 3):
        v = ex.variant(seed)
        key = tuple(sorted(v.values.items()))
        if key in seen:
            continue
        seen.add(key)
        yield v
        if len(seen) == DRAWS:
            return


@pytest.mark.parametrize("ex", STEPPED, ids=[ex.id for ex in STEPPED])
def test_the_derivation_prints_each_step_and_the_step_accepts_it(ex):
    solution = TEXTS[ex.id].solution
    for s in ex.steps:
        assert "{{" + steps.placeholder(s.name) + "}}" in solution, f"{ex.id}: the derivation never prints step {s.name}"
    for v in _variants(ex):
        for s in v.steps:
            kind = v.step_answers[s.name]
            assert v.values[steps.placeholder(s.name)] == kind.worked_tex()
            assert kind.check(kind.worked_text()).status == "correct", (v.seed, s.name, kind.worked_text())
            for slip in kind.slips:
                said = kind.check(kind.typed(slip.value))
                assert said.status == "incorrect" and said.message == slip.message, (v.seed, s.name, slip.message)


@pytest.mark.parametrize("ex", STEPPED, ids=[ex.id for ex in STEPPED])
def test_the_steps_chain_to_the_final_key(ex):
    for v in _variants(ex):
        typed = {s.name: v.step_answers[s.name].worked_text() for s in v.steps}
        read = {s.name: chains.value_of(v.step_answers[s.name].reader.read(v.step_answers[s.name], typed[s.name]))
                for s in v.steps}
        final = v.carried_answer(read)
        assert final.check(v.answer.typed(v.answer.key)).status == "correct", (v.seed, "printed steps, final key")
        later = v.carried_steps(read)
        for s in v.steps:
            assert later[s.name].check(typed[s.name]).status == "correct", (v.seed, s.name)
        verdict = grade(v, v.answer.typed(v.answer.key), sent=typed)
        assert verdict["status"] == "correct", (v.seed, verdict)


@pytest.mark.parametrize("ex", STEPPED, ids=[ex.id for ex in STEPPED])
def test_a_wrong_step_is_carried_forward_and_named(ex):
    rng = random.Random(ex.id)
    checked = drawn = 0
    for v in _variants(ex):
        drawn += 1
        first, second = v.steps[0], v.steps[1]
        kind = v.step_answers[first.name]
        wrong = moved(kind.key, rng)
        sent = {first.name: kind.typed(wrong)}
        try:
            carried = v.carried_steps({first.name: wrong})[second.name]
            final = v.carried_answer({first.name: wrong})
        except (ValueError, ArithmeticError):
            continue  # the wrong value leaves the model (a root of a negative, ...): nothing to carry
        right = v.step_answers[second.name]
        if right.check(carried.typed(carried.key)).status == "correct":
            continue  # this wrong value happens not to change the next step
        checked += 1
        said = grade(v, carried.typed(carried.key), second.name, sent)
        assert (said["status"], said["tag"]) == ("incorrect", "carried"), (v.seed, said)
        assert said["data"]["carried"]["step"] == first.name
        assert grade(v, right.typed(right.key), second.name, sent)["status"] == "correct", v.seed
        neither = moved(right.key, rng)
        if carried.check(carried.typed(neither)).status != "correct":
            plain = grade(v, right.typed(neither), second.name, sent)
            assert plain["status"] == "incorrect" and plain["tag"] != "carried", (v.seed, plain)
        if v.answer.check(final.typed(final.key)).status != "correct":
            said = grade(v, final.typed(final.key), sent=sent)
            assert said["tag"] == "carried" and said["data"]["carried"]["step"] == first.name, (v.seed, said)
    assert checked >= drawn // 2, f"{ex.id}: only {checked} of {drawn} draws had a first step that changes the second"


@pytest.mark.parametrize("ex", STEPPED, ids=[ex.id for ex in STEPPED])
def test_a_wrong_final_answer_names_the_first_step_to_look_at(ex):
    v = ex.variant(1)
    final = v.answer
    wrong = final.typed(moved(final.key, random.Random(1)))
    said = grade(v, wrong)
    assert said["status"] == "incorrect" and said["data"]["steps"]["first"] == v.steps[0].name, said
    right_first = {v.steps[0].name: v.step_answers[v.steps[0].name].worked_text()}
    said = grade(v, wrong, sent=right_first)
    assert said["data"]["steps"] == {"first": v.steps[1].name, "number": 2, "label": v.steps[1].label}, said


def test_a_step_request_that_names_no_step_of_the_exercise_is_refused_in_words():
    ex = STEPPED[0]
    reply = json.loads(handle(json.dumps({"op": "grade", "exercise": ex.id, "step": "nope", "answer": "1"})))
    assert reply["error"]["kind"] == "bad-request" and "has no step 'nope'" in reply["error"]["message"]
    reply = json.loads(handle(json.dumps({"op": "grade", "exercise": "0.3", "step": "x", "answer": "a"})))
    assert reply["error"]["kind"] == "bad-request" and "no steps" in reply["error"]["message"]
    reply = json.loads(handle(json.dumps({"op": "grade", "exercise": ex.id, "answer": "1", "steps": [1]})))
    assert reply["error"]["kind"] == "bad-request"


def _far_off(v):
    """A final answer to ``v`` that no step leads to: a named slip's value, else the key moved by 7."""
    a = v.answer
    if a.slips:
        return a.typed(a.slips[0].value)
    key = a.key
    if isinstance(key, (int, float)):
        return a.typed(key + 7)
    return a.typed([[x + 7 for x in row] for row in key])


@pytest.mark.parametrize("ex", STEPPED, ids=[ex.id for ex in STEPPED])
def test_a_wrong_final_points_at_the_first_step_not_yet_right(ex):
    """After a wrong final, ``data.steps`` names the step to look at: the first when none was typed,
    the first untyped one after right ones, and none when every step is typed and right (the slip
    is in the last line: no step is wrong, and the class page counts none as the first wrong one)."""
    for v in list(_variants(ex))[:20]:
        typed = {s.name: v.step_answers[s.name].worked_text() for s in v.steps}
        wrong = _far_off(v)
        assert grade(v, wrong)["data"]["steps"]["first"] == v.steps[0].name, v.seed
        assert grade(v, wrong, sent={v.steps[0].name: typed[v.steps[0].name]})["data"]["steps"]["first"] == v.steps[1].name
        verdict = grade(v, wrong, sent=typed)
        assert verdict["status"] == "incorrect" and "steps" not in verdict["data"], (v.seed, verdict)
