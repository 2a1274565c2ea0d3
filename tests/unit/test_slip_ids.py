"""Every named slip in the bank has a stable id, ``EXERCISE/NAME`` (``6.3/cos-theta2-angle-whose``), and a grade
reply that hits it carries it as ``data.slipId``, next to ``data.slip`` (issue 46: the class page once named
a slip by a regular expression over its English message, so that a change of wording renamed it).

The name is written next to the slip in the bank; it is checked here over many draws of every Derive
exercise: every slip has one, in the stable format; within a draw an id names one slip (one message); and an
exercise's ids are a fixed set, the same whatever the numbers drawn.
"""

from __future__ import annotations

import json
import re

import pytest

import many_draws
from workbook import bank
from workbook.answer_kinds.base import SLIP_NAME
from workbook.api import handle
from workbook.contract import OPS

DERIVE = [ex for ex in bank.all_exercises() if ex.kind == "derive"]
SEEDS = range(many_draws.count(60))
ID = re.compile(r"(\d+\.\d+)/([a-z0-9]+(?:-[a-z0-9]+)*)")


def slips_of(v):
    """(where, slip) for the answer's slips and every step's, of one draw."""
    yield from (("answer", s) for s in v.answer.slips)
    for name, kind in v.step_answers.items():
        yield from ((f"step {name}", s) for s in kind.slips)


@pytest.mark.parametrize("ex", DERIVE, ids=[ex.id for ex in DERIVE])
def test_every_slip_has_a_stable_unique_id(ex):
    ids: set[str] = set()
    for seed in SEEDS:
        v = ex.variant(seed)
        said: dict[str, set[str]] = {}
        for where, slip in slips_of(v):
            assert slip.name and SLIP_NAME.fullmatch(slip.name), (ex.id, seed, where, slip.message)
            m = ID.fullmatch(slip.id)
            assert m and m[1] == ex.id and m[2] == slip.name, (ex.id, slip.id)
            said.setdefault(slip.id, set()).add(slip.message)
        repeated = {i: m for i, m in said.items() if len(m) > 1}
        assert not repeated, f"{ex.id} variant {seed}: one id names different slips: {repeated}"
        ids |= set(said)
    sites = sum(1 for _ in slips_of(ex)) if ex.vary is None else None
    assert sites is None or len(ids) == sites


def test_the_reply_carries_the_slip_id_beside_the_slip_name():
    assert "slipId" in OPS["grade"]["data"] and "slip" in OPS["grade"]["data"]
    hit = 0
    for ex in DERIVE:
        v = ex.variant(0)
        for where, slip in slips_of(v):
            if callable(slip.value):
                continue  # a formula's slip is a function: typed as text below only where the kind can
            request = {"op": "grade", "exercise": ex.id, "variant": 0}
            kind = v.answer if where == "answer" else v.step_kind(where.removeprefix("step "))
            request["answer"] = kind.typed(slip.value)
            if where != "answer":
                request["step"] = where.removeprefix("step ")
            reply = json.loads(handle(json.dumps(request)))["value"]
            if reply["tag"] != "slip" or reply["message"] != slip.message:
                continue  # another slip of the same value said first, or a step's own rule
            assert reply["data"]["slipId"] == slip.id, (ex.id, where, reply)
            if where == "answer":
                assert reply["data"]["slip"].startswith("slip: "), reply  # the older name stays beside it
            hit += 1
    assert hit >= 150


def test_a_slip_id_survives_a_change_of_its_words():
    """The id is the bank's name, not the message: a draw whose messages carry other numbers has the same ids."""
    ex = bank.get("6.3")
    first = {s.id: s.message for _, s in slips_of(ex.variant(0))}
    same = [v for v in (ex.variant(seed) for seed in range(1, 40))
            if {s.id for _, s in slips_of(v)} == set(first) and {s.message for _, s in slips_of(v)} != set(first.values())]
    assert first and same
    assert all(s.message not in s.id for _, s in slips_of(ex.variant(0)))
