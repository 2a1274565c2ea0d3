"""Hand-in files for the class page's tests and bench: a class of generated students, each
answer made from the bank's own keys and slips at the student's assigned numbers (never
hand-typed), so the class page's re-grade can be predicted here."""

from __future__ import annotations

import json
import random

from workbook import bank
from workbook.assignment import assigned_variant
from workbook.kinds.derive import Derive

FORMAT = "robotics-math-workbook-hand-in"


def derive_ids(n: int, chapters=range(11)) -> list[str]:
    """The first ``n`` Derive exercises without checked steps, in the bank's order."""
    out = [ex.id for ch in chapters for ex in bank.chapter(ch) if ex.kind == "derive" and not ex.steps]
    assert len(out) >= n
    return out[:n]


def answer(ex_id: str, code: str, student: str, right: bool, slip: int = 0):
    """A typed answer to ``ex_id`` at the student's numbers: the key, or a named slip (a far-off
    number when the exercise has none)."""
    ex = bank.variant(ex_id, assigned_variant(code, student, ex_id))
    assert isinstance(ex, Derive)
    a = ex.answer
    if right:
        return a.typed(a.key)
    if a.slips:
        return a.typed(a.slips[slip % len(a.slips)].value)
    return "123456"


def record(ex_id: str, code: str, student: str, attempts: list[tuple[object, str]], at: int, **extra) -> dict:
    """A progress record of ``ex_id`` whose assignment attempts are ``attempts`` [(answer, recorded status)]."""
    v = assigned_variant(code, student, ex_id)
    tried = [{"answer": ans, "status": st, "at": at + i} for i, (ans, st) in enumerate(attempts)]
    out = {"attempts": len(tried), "updated": at + len(tried), "variant": v, "assigned": {code: {"variant": v, "attempts": tried}}, **extra}
    if any(st == "correct" for _, st in attempts):
        out.update(solved=True, done=[v], clean=[v])
    return out


def hand_in(code: str, student: str, ids: list[str], records: dict, handed_in: str = "2026-11-27T10:00:00Z",
            due: str | None = None) -> bytes:
    data = {"format": FORMAT, "version": 1, "handedIn": handed_in, "student": student,
            "assignment": {"class": code, "exercises": ids, "due": due}, "records": records}
    return json.dumps(data).encode()


def build_record(ex_id: str, code: str, at: int, passes: bool = True) -> dict:
    """A claimed Build solve whose code is the bank's solution (or its starter)."""
    ex = bank.get(ex_id)
    return {"attempts": 1, "updated": at, "code": ex.solution if passes else ex.starter, "solved": True, "done": [0], "clean": [0]}


def a_class(code: str, n: int, ids: list[str], at: int, seed: int = 1, build: str | None = None,
            due: str | None = None) -> list[tuple[str, bytes]]:
    """``n`` students ``s01`` … of ``code``: student i solves each exercise with a chance that grows
    with i (a spread of scores), after 0-2 slips; some leave an exercise unanswered; every tenth
    had a link without the last exercise (not set). With ``build``, every file also carries a
    passing Build solve of that exercise."""
    rng = random.Random(seed)
    files = []
    for i in range(n):
        student = f"s{i + 1:02d}"
        strength = (i + 1) / (n + 1)
        records = {}
        mine = ids[:-1] if i % 10 == 9 else ids
        for k, ex_id in enumerate(mine):
            roll = rng.random()
            if roll < 0.08:
                continue  # not tried: set, not solved
            wrong = [(answer(ex_id, code, student, False, s), "incorrect") for s in range(rng.randrange(3))]
            solved = rng.random() < strength
            tries = wrong + ([(answer(ex_id, code, student, True), "correct")] if solved else [])
            if not tries:
                tries = [(answer(ex_id, code, student, False), "incorrect")]
            records[ex_id] = record(ex_id, code, student, tries, at + 1000 * k, hinted=rng.random() < 0.3)
        every = list(mine)
        if build:
            every.append(build)
            records[build] = build_record(build, code, at)
        files.append((f"hand-in-{code}-{student}.json", hand_in(code, student, every, records, due=due)))
    return files
