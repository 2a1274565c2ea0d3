"""Chains: every declared link, over 200 variants, carries a wrong earlier value forward.

For each link (an exercise's ``uses``) and each of 200 draws: a wrong answer to the
earlier exercise plus a later answer that follows from it is ``carried``; the right
later answer is still ``correct``; a later answer that follows from neither is plain
``incorrect``. The key for the learner's value is the generator's own (``make(p,
given=...)``). A draw that carries none of the earlier exercise's numbers, or an
earlier answer given for another variant, carries nothing.
"""

import random

import pytest

from moved import moved
from workbook import bank, chains
from workbook.api import handle

DRAWS = 200
CHAINED = [(ex.id, link) for ex in bank.all_exercises() for link in getattr(ex, "uses", ())]


def test_the_chains_the_issue_names_are_declared():
    assert {(i, link.source) for i, link in CHAINED} >= {("9.3", "9.2"), ("9.4", "9.2"), ("9.6", "9.4"),
                                                          ("7.2", "7.1"), ("3.8", "3.7")}


def _wrong(source, rng):
    """A wrong answer to ``source`` as a learner types it: the key, or one entry of it, moved."""
    return source.answer.typed(moved(source.answer.key, rng))


def _off(later, theirs):
    """A later answer that follows from neither value: the learner's key scaled and shifted."""
    for scale, shift in ((1.37, 0.61), (0.71, -0.53), (1.9, 1.3)):
        if isinstance(theirs.key, tuple):
            typed = later.answer.typed(tuple(tuple(v * scale + shift for v in row) for row in theirs.key))
        else:
            typed = later.answer.typed(theirs.key * scale + shift)
        if "correct" not in (later.answer.check(typed).status, theirs.check(typed).status):
            return typed
    raise AssertionError("no answer that follows from neither value")


def _nothing_carried_into(later, link, rng):
    """A draw that carries none of the source's numbers ignores a wrong answer to it, for any of its variants."""
    for at in (0, 1):
        source = bank.variant(link.source, at)
        typed = _wrong(source, rng)
        value = chains.value_of(source.answer.reader.read(source.answer, typed))
        theirs = later.carried_answer({link.name: value})
        verdict = later.grade(theirs.typed(theirs.key), given={link.source: {"answer": typed, "variant": at}},
                              lookup=bank.variant)
        assert verdict.tag != "carried", (later.id, later.seed, at)


@pytest.mark.parametrize("exercise_id,link", CHAINED, ids=[f"{i}<-{u.source}" for i, u in CHAINED])
def test_a_wrong_earlier_value_is_carried_forward(exercise_id, link):
    rng = random.Random(f"chain {exercise_id}")
    carried = 0
    for n in range(DRAWS):
        later = bank.variant(exercise_id, n)
        if link.variant(later.params) is None:  # this draw prints none of the source's numbers: nothing to carry
            _nothing_carried_into(later, link, rng)
            later = bank.variant(exercise_id, 0)
        at = link.variant(later.params)
        source = bank.variant(link.source, at)
        typed = _wrong(source, rng)
        assert source.answer.check(typed).status == "incorrect", (n, typed)
        given = {link.source: {"answer": typed, "variant": at}}
        value = chains.value_of(source.answer.reader.read(source.answer, typed))
        theirs = later.carried_answer({link.name: value})
        follows = theirs.typed(theirs.key)
        right = later.answer.typed(later.answer.key)

        assert later.grade(right, given=given, lookup=bank.variant).status == "correct", (n, right)
        off = later.grade(_off(later, theirs), given=given, lookup=bank.variant)
        assert off.status == "incorrect" and off.tag != "carried", (n, off)
        if later.answer.check(follows).status == "correct":
            continue  # this wrong value happens to change nothing downstream
        verdict = later.grade(follows, given=given, lookup=bank.variant)
        assert (verdict.status, verdict.tag) == ("incorrect", "carried"), (n, typed, follows, verdict)
        assert verdict.data["carried"]["from"] == link.source and verdict.data["carried"]["variant"] == at
        assert link.source in verdict.message
        # the same value given for another variant of the source is not this draw's chain
        elsewhere = {link.source: {"answer": typed, "variant": at + 1}}
        assert later.grade(follows, given=elsewhere, lookup=bank.variant).tag != "carried"
        carried += 1
    assert carried >= DRAWS * 0.95


def test_a_right_earlier_answer_carries_nothing():
    later = bank.get("9.6")
    right = bank.get("9.4").answer
    given = {"9.4": {"answer": right.typed(right.key), "variant": 0}}
    mine = later.carried_answer({"xu": 6.0})
    assert later.grade(mine.typed(mine.key), given=given, lookup=bank.variant).tag != "carried"


def test_the_grade_request_carries_the_earlier_answers():
    import json

    later = bank.get("9.3")
    mine = later.carried_answer({"x": 6.5})
    request = {"op": "grade", "exercise": "9.3", "answer": mine.typed(mine.key),
               "given": {"9.2": {"answer": "6.5", "variant": 0}}}
    value = json.loads(handle(json.dumps(request)))["value"]
    assert value["tag"] == "carried" and value["data"]["carried"]["link"] == "Back to exercise 9.2"
    for bad in ({"9.2": "6.5"}, {"9.2": {"answer": "6.5", "variant": -1}}, {"9.2": {"answer": "6.5", "who": 1}},
                {str(i): {"answer": "1"} for i in range(20)}):
        reply = json.loads(handle(json.dumps({**request, "given": bad})))
        assert reply["error"]["kind"] == "bad-request"
