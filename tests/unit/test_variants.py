"""Every Derive exercise is a generator: 1,000 draws each, checked natively.

For every seed: the key is finite; the statement shows the drawn parameters;
the worked answer is the key to its printed precision and the grader accepts
it; every slip is more than the tolerance away from the key and is graded as
that slip; the draw passes the exercise's own well-posedness rule and lies on
its parameter grid; every placeholder of the statement, hint and derivation
is filled. Variant 0 renders byte for byte what the workbook printed before the
templates came in (``tests/golden/variant0.json``).
"""

from __future__ import annotations

import json
import math
import sys
from pathlib import Path

import pytest

import many_draws
from exercise_text import load_all  # docs/hooks/exercise_text.py
from workbook import api, bank
from workbook.answer_kinds.number.mark import agrees_with
from workbook.expr import parse_quantity
from workbook.kinds.derive import Derive
from workbook.number_format import fmt
from workbook.tolerance import agrees, clean
from workbook.variants import Choice, Param, VariantError, Vary, check_seed, fill, placeholders

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "tests" / "golden"))
import variant0  # noqa: E402

SEEDS = range(1, 1 + many_draws.count(1000))
DERIVE = [ex for ex in bank.all_exercises() if ex.kind == "derive"]
TEXTS = load_all(ROOT)


def test_every_derive_exercise_is_a_generator():
    plain = [ex.id for ex in DERIVE if ex.vary is None]
    assert not plain, f"Derive exercises without a generator (vary=...): {', '.join(plain)}"


def test_variant_zero_prints_what_the_workbook_printed():
    golden = json.loads(variant0.FILE.read_text(encoding="utf-8"))
    now = variant0.pages()
    changed = sorted((k for k in golden if golden[k] != now.get(k)), key=lambda k: tuple(map(int, k.split("."))))
    assert not changed, (f"variant 0 of {', '.join(changed)} differs from tests/golden/variant0.json "
                         "(if the change of text is deliberate: python tests/golden/variant0.py --write)")


def test_the_draw_op_fills_the_page_templates_for_variant_zero_as_the_build_does():
    for ex in DERIVE:
        texts = TEXTS[ex.id].as_dict()
        reply = api.dispatch({"op": "draw", "exercise": ex.id, "variant": 0, "texts": texts})
        assert reply["ok"], reply
        built = TEXTS[ex.id].filled(ex.values)
        assert reply["value"]["prompt"] == built.prompt
        assert reply["value"]["solution"] == (built.solution + ex.worked_html() if built.solution else "")


def _shown(ex: Derive) -> str:
    text = TEXTS[ex.id].filled(ex.values)
    return " ".join((text.title, text.prompt, ex.label_html()))


def _key_is_finite(ex: Derive) -> bool:
    if ex.answer_kind == 'expression':
        return callable(ex.answer.key)
    if ex.answer_kind == 'matrix':
        return all(math.isfinite(v) for row in ex.answer.key for v in row)
    return math.isfinite(ex.answer.key)


def _printed_is_key(ex: Derive) -> None:
    """The worked answer, read back, is the key to the precision it is printed with."""
    if ex.answer_kind == 'expression':
        return
    if ex.answer_kind == 'matrix':
        pairs = [(float(fmt(v)), v) for row in ex.answer.cleaned for v in row]
    else:
        pairs = [(parse_quantity(ex.worked_text(), ex.answer.expect), clean(ex.answer.key))]
    for shown, key in pairs:
        assert math.isclose(shown, key, rel_tol=5e-4, abs_tol=5e-5), (ex.id, ex.seed, shown, key)


def _slips_apart(ex: Derive) -> None:
    for slip in ex.answer.slips:
        if ex.answer_kind == 'expression':
            continue  # degenerate() proves no slip formula agrees with the key
        if ex.answer_kind == 'matrix':
            assert any(not agrees(clean(a), clean(b), rel=ex.answer.rel_tol) for ra, rb in zip(slip.value, ex.answer.key)
                       for a, b in zip(ra, rb)), (ex.id, ex.seed, "a slip equals the key")
        else:
            assert not agrees_with(ex.answer, slip.value, ex.answer.key), (ex.id, ex.seed, slip.value, ex.answer.key)
        said = ex.check(ex.answer.typed(slip.value))
        assert (said.status, said.tag, said.message) == ("incorrect", "slip", slip.message), (ex.id, ex.seed, said)


@pytest.mark.parametrize("ex", DERIVE, ids=lambda ex: ex.id)
def test_a_thousand_draws_are_well_posed(ex: Derive):
    if ex.vary is None:
        pytest.skip("not a generator yet")
    template_names = set(TEXTS[ex.id].names())
    assert template_names <= set(ex.values), f"{ex.id}: the page asks for {template_names - set(ex.values)}"
    seen = set()
    for seed in SEEDS:
        v = ex.variant(seed)
        assert v.seed == seed
        for q in v.vary.params:
            assert v.params[q.name] in q.grid(), (ex.id, seed, q.name, v.params[q.name])
        draw = tuple(sorted(v.params.items()))
        if draw in seen:  # the same numbers make the same exercise (the generator is a function of them)
            continue
        seen.add(draw)
        assert v.vary.valid(v.params), (ex.id, seed)  # (a function of the numbers too: once per draw)
        assert set(v.values) >= template_names
        assert _key_is_finite(v), (ex.id, seed)
        shown = _shown(v)
        for q in v.vary.params:
            value = v.params[q.name]
            if isinstance(q, Param):
                assert v.values[q.name] == fmt(value), f"{ex.id} seed {seed}: {q.name} shown as {v.values[q.name]!r}"
                assert "{{" + q.name + "}}" in TEXTS[ex.id].prompt + TEXTS[ex.id].title or \
                    v.values[q.name] in v.label_html(), f"{ex.id}: the statement does not show {q.name}"
            assert v.values[q.name] in shown, f"{ex.id} seed {seed}: {q.name} = {value} is not in the statement"
        verdict = v.check(v.answer.typed(v.answer.key) if v.answer_kind != 'expression' else v.answer.answer_text)
        assert verdict.status == "correct", (ex.id, seed, verdict)
        assert v.check(v.worked_text() if v.answer_kind != 'matrix' else v.answer.typed(v.answer.cleaned)).status == "correct"
        _printed_is_key(v)
        _slips_apart(v)
        filled = TEXTS[ex.id].filled(v.values)
        assert not any(placeholders(part) for part in filled.parts())
    grid_size = math.prod(len(q.grid()) for q in ex.vary.params)
    assert len(seen) >= min(50, grid_size // 3, len(SEEDS) // 5), f"{ex.id}: {len(SEEDS)} seeds gave only {len(seen)} different draws"


def test_variants_are_deterministic_and_bounded():
    ex = bank.get("0.1")
    assert ex.variant(17).params == bank.get("0.1").variant(17).params
    assert ex.variant(0) is ex
    for bad in (-1, 10**7, "x", 1.5, True):
        with pytest.raises(ValueError):
            check_seed(bad)
    reply = api.dispatch({"op": "grade", "exercise": "0.1", "variant": "nope", "answer": "1"})
    assert reply["error"]["kind"] == "bad-request"


def test_grading_follows_the_variant():
    ex = bank.get("0.1").variant(42)
    reply = api.dispatch({"op": "grade", "exercise": "0.1", "variant": 42, "answer": ex.worked_text()})
    assert reply["value"]["status"] == "correct"
    if not agrees_with(ex.answer, ex.answer.key, bank.get("0.1").answer.key):
        reply = api.dispatch({"op": "grade", "exercise": "0.1", "variant": 42, "answer": bank.get("0.1").worked_text()})
        assert reply["value"]["status"] == "incorrect"


def test_a_template_that_asks_for_an_unknown_value_is_an_error():
    with pytest.raises(VariantError):
        fill("{{nope}}", {})
    reply = api.dispatch({"op": "draw", "exercise": "0.1", "variant": 3, "texts": {"prompt": "{{nope}}"}})
    assert reply["error"]["kind"] == "bad-request"


def test_choice_and_param_describe_their_ranges():
    assert Param("theta", 30, 5, 85, 5, unit="°").describe() == "theta from 5° to 85° in steps of 5°"
    assert Choice("entry", 1, (1, 2)).describe() == "entry one of 1, 2"


def test_each_draw_is_judged_once_and_the_draws_are_those_of_judging_every_time():
    """A generator remembers valid(p) per draw (many seeds draw the same numbers on a small grid),
    and the draws come out exactly as when every candidate is judged afresh."""
    judged: list[tuple] = []

    def valid(p):
        judged.append(tuple(sorted(p.items())))
        return (p["a"] + p["b"]) % 3 != 0

    params = (Param("a", 1, lo=0, hi=4, step=1), Param("b", 2, lo=0, hi=4, step=1))
    remembering = Vary(lambda p: {}, *params, valid=valid)
    afresh = Vary(lambda p: {}, *params, valid=lambda p: (p["a"] + p["b"]) % 3 != 0)
    afresh._well_posed = afresh.valid  # type: ignore[method-assign]  (no memory: judged every time)
    for seed in range(1, 300):
        assert next(remembering.candidates("x.1", seed)) == next(afresh.candidates("x.1", seed))
    assert len(judged) == len(set(judged)) <= 25  # a 5 x 5 grid: each draw judged at most once
