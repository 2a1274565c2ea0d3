"""Probes of error carried forward, through the grader's entry point (``api.handle``) only.

Each probe draws a learner's work over many variants (a wrong step, two wrong steps, a
right step after a wrong one, a wrong earlier exercise, a chain of chains, a value that
leaves the quantity undefined) and counts the verdicts that are not true: ones that
name the wrong place, carried ones that ignore a step the learner typed, and undefined
values that earn "carried". ``tests/unit/test_carried.py`` asserts every count is 0;
``python tests/unit/carried_probe.py`` prints them (against any checkout on the path).
"""

from __future__ import annotations

import json
import random
from collections import Counter

from moved import moved
from workbook import bank
from workbook.api import handle

DRAWS = 200


def grade(ex, answer, step=None, mine=None, given=None) -> dict:
    request = {"op": "grade", "exercise": ex.id, "variant": ex.seed, "answer": answer}
    if step is not None:
        request["step"] = step
    if mine:
        request["steps"] = mine
    if given:
        request["given"] = given
    reply = json.loads(handle(json.dumps(request)))
    assert reply["ok"], reply
    return reply["value"]


def read(kind, typed):
    reading = kind.reader.read(kind, typed)
    if isinstance(reading, list):
        return tuple(tuple(r.value for r in row) for row in reading)
    return reading.value


def variants(ex_id: str, draws: int | None = None):
    draws = draws or DRAWS
    seen = set()
    for seed in range(draws * 3):
        v = bank.variant(ex_id, seed)
        key = tuple(sorted(v.values.items()))
        if key not in seen:
            seen.add(key)
            yield v
        if len(seen) == draws:
            return


def _right(kind, typed) -> bool:
    return kind.check(typed).status == "correct"


def _flat(key) -> list[float]:
    return [float(x) for row in key for x in row] if isinstance(key, tuple) else [float(key)]


def _near(key, right) -> bool:
    """Two keys no answer can tell apart: within 10⁻³ of the question's scale (the grader's floor)."""
    a, b = _flat(key), _flat(right)
    scale = max(abs(x) for x in a + b)
    return all(abs(x - y) <= 1e-3 * scale for x, y in zip(a, b))


def _carried_to(verdict) -> str:
    c = verdict.get("data", {}).get("carried") or {}
    return c.get("step") or c.get("from") or ""


STEPPED = [ex.id for ex in bank.all_exercises() if ex.kind == "derive" and len(getattr(ex, "steps", ())) >= 2]


def probe_steps(counts: Counter, ex_id: str, rng: random.Random) -> None:
    """A wrong step 1, then: step 2 right / wrong on its own / following step 1; the final answer
    computed from the learner's typed steps (and, for the old bug, from a step 2 recomputed)."""
    for v in variants(ex_id):
        s1, s2 = v.steps[0].name, v.steps[1].name
        k1, k2 = v.step_answers[s1], v.step_answers[s2]
        try:
            w1 = moved(k1.key, rng)
            w2 = moved(k2.key, rng)
            follows2 = v.carried_steps({s1: w1})[s2]
            old_bug = v.carried_answer({s1: w1})
            both = v.carried_answer({s1: w1, s2: w2})
            chained = v.carried_answer({s1: w1, s2: follows2.key})
            right2 = v.carried_answer({s1: w1, s2: k2.key})
        except (ValueError, ArithmeticError):
            continue
        t1, t2 = k1.typed(w1), k2.typed(w2)
        if _right(k1, t1) or _right(follows2, k2.typed(k2.key)):
            continue  # this wrong step 1 changes nothing downstream
        counts["draws"] += 1
        # a right step 2 typed after a wrong step 1: the final answer recomputed from step 1 alone is not carried
        answer = v.answer.typed(old_bug.key)
        if not _right(v.answer, answer) and not _right(right2, answer):
            said = grade(v, answer, mine={s1: t1, s2: k2.typed(k2.key)})
            counts["ignores a typed step"] += said["tag"] == "carried"
            counts["checked: right step after a wrong one"] += 1
        # two wrong steps, step 2 wrong on its own: the final answer follows from step 2, where the slip is
        answer = v.answer.typed(both.key)
        if not _right(follows2, t2) and not _right(v.answer, answer) and not _near(both.key, v.answer.key):
            said = grade(v, answer, mine={s1: t1, s2: t2})
            want = s2 if not _right(v.carried_answer({s1: w1, s2: k2.key}), answer) else s1
            counts["wrong place"] += said["tag"] != "carried" or _carried_to(said) != want
            counts["checked: two wrong steps"] += 1
        # step 2 follows from the wrong step 1: both the step and the final answer point to step 1
        t2f = k2.typed(follows2.key)
        if not _right(k2, t2f) and not _near(follows2.key, k2.key):
            said = grade(v, t2f, step=s2, mine={s1: t1})
            counts["wrong place"] += said["tag"] != "carried" or _carried_to(said) != s1
            answer = v.answer.typed(chained.key)
            if not _right(v.answer, answer) and not _near(chained.key, v.answer.key):
                said = grade(v, answer, mine={s1: t1, s2: t2f})
                counts["wrong place"] += said["tag"] != "carried" or _carried_to(said) != s1
            counts["checked: a step that follows a wrong one"] += 1


def probe_chain(counts: Counter, ex_id: str, rng: random.Random) -> None:
    """A wrong answer to the earlier exercise; the steps and the final answer follow from it: each
    verdict points to the earlier exercise, never to a step."""
    for v in variants(ex_id):
        for link in v.uses:
            at = link.variant(v.params)
            if at is None:
                continue
            source = bank.variant(link.source, at)
            typed = source.answer.typed(moved(source.answer.key, rng))
            if _right(source.answer, typed):
                continue
            given = {link.source: {"answer": typed, "variant": at}}
            mine: dict = {}
            values = {link.name: read(source.answer, typed)}
            try:
                for s in v.steps:
                    kind = v.carried_steps(values)[s.name]
                    t = v.step_answers[s.name].typed(kind.key)
                    if not _right(v.step_answers[s.name], t):
                        said = grade(v, t, step=s.name, mine=mine, given=given)
                        counts["wrong place"] += said["tag"] != "carried" or _carried_to(said) != link.source
                        counts["checked: a step carried from an earlier exercise"] += 1
                    mine[s.name] = t
                    values[s.name] = read(v.step_answers[s.name], t)
                final = v.carried_answer(values)
            except (ValueError, ArithmeticError):
                continue
            answer = v.answer.typed(final.key)
            if not _right(v.answer, answer):
                said = grade(v, answer, mine=mine, given=given)
                counts["wrong place"] += said["tag"] != "carried" or _carried_to(said) != link.source
                counts["checked: carried from an earlier exercise"] += 1


def probe_chain_of_chains(counts: Counter, rng: random.Random) -> None:
    """9.6 ← 9.4 ← 9.2: a wrong 9.2, a 9.4 that follows from it, a 9.6 that follows from that 9.4."""
    first, middle, last = bank.get("9.2"), bank.get("9.4"), bank.get("9.6")
    for _ in range(DRAWS):
        t92 = first.answer.typed(moved(first.answer.key, rng))
        if _right(first.answer, t92):
            continue
        try:
            m = middle.carried_answer({"x": read(first.answer, t92)})
            t94 = middle.answer.typed(m.key)
            end = last.carried_answer({"xu": read(middle.answer, t94)})
        except (ValueError, ArithmeticError):
            continue
        answer = last.answer.typed(end.key)
        if _right(middle.answer, t94) or _right(last.answer, answer):
            continue
        given = {"9.4": {"answer": t94, "variant": 0}, "9.2": {"answer": t92, "variant": 0}}
        said = grade(last, answer, given=given)
        counts["wrong place"] += said["tag"] != "carried" or _carried_to(said) != "9.2"
        counts["checked: a chain of chains"] += 1


def probe_undefined(counts: Counter) -> None:
    """Values that leave the next quantity undefined never earn "carried"."""
    zero = ((0.0,), (0.0,))
    cases = [("4.2", "d", zero, None), ("4.3", "d", zero, None), ("4.7", "d", zero, None),
             ("6.3", "t2", 180.0, "θ1"), ("6.3", "t2", -180.0, "θ1")]
    for ex_id, name, value, asked in cases:
        for v in variants(ex_id, max(DRAWS // 3, 20)):
            if asked and v.params.get("asked") != asked:
                continue
            kind = v.step_answers[name]
            mine = {name: kind.typed(value)}
            for answer in ("0", "1", "-1"):
                if _right(v.answer, answer) or v.answer.typed(v.answer.key) == answer:
                    continue
                said = grade(v, answer, mine=mine)
                counts["undefined earns carried"] += said["tag"] == "carried"
                counts["undefined as a plain Not quite"] += said["tag"] == "" and said["message"].startswith("Not quite")
                counts["checked: undefined values"] += 1


def run(draws: int = 200) -> Counter:
    """The counts over ``draws`` draws of each exercise (200 for the closing note; fewer in the suite)."""
    global DRAWS
    DRAWS = draws
    counts: Counter = Counter()
    for ex_id in STEPPED:
        probe_steps(counts, ex_id, random.Random(f"steps {ex_id}"))
    for ex_id in sorted({ex.id for ex in bank.all_exercises() if getattr(ex, "uses", ())}):
        probe_chain(counts, ex_id, random.Random(f"chain {ex_id}"))
    probe_chain_of_chains(counts, random.Random("9.6"))
    probe_undefined(counts)
    return counts


if __name__ == "__main__":
    for name, n in sorted(run().items()):
        print(f"{name}: {n}")
