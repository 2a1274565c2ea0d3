"""The golden walk: every exercise in the workbook, checked against its page and its key.

* Derive keys equal the numbers printed in the derivation (the ``**Answer:**``
  line) to their shown precision, and that printed answer is accepted.
* Every Build reference solution passes its tests and the starter stub fails.
* Every Debug program fails its cases and passes once its marked line is fixed.
* Every Design's solved order passes and its initial order does not.
* Every Trace has exactly one correct option, and every option says why.
* Every page places only known exercises, each exactly once.
"""

from __future__ import annotations

import math
import re
from pathlib import Path

import pytest

from workbook import bank
from workbook.contract import KINDS
from workbook.kinds.build import Build
from workbook.kinds.debug import Debug
from workbook.kinds.derive import Derive
from workbook.kinds.design import Design
from workbook.kinds.trace import Trace

from blocks import ExerciseBlock, parse  # docs/hooks/blocks.py


def check(ex, answer):
    return ex.check(answer)


run_build = check

ROOT = Path(__file__).resolve().parents[2]
PAGES = sorted((ROOT / "docs" / "chapters").glob("*.md"))
ALL = bank.all_exercises()
BY_KIND = {k: [e for e in ALL if e.kind == k] for k in KINDS}


def page_blocks():
    blocks = {}
    for page in PAGES:
        for block in parse(page.read_text(), page.name):
            if isinstance(block, ExerciseBlock):
                assert block.id not in blocks, f"{block.id} placed twice"
                blocks[block.id] = {"page": page.name, "title": block.title, **{k: block.text(k) for k in block.parts}}
    return blocks


BLOCKS = page_blocks()


# The source workbook's 56 exercises keep their ids and kinds (CONTRACT.md); new ones
# take the ids after the seed's last one in their chapter.
SEED_KINDS = (
    "derive derive trace derive build derive",  # chapter 0
    "derive derive derive trace design",
    "derive trace derive derive derive",
    "derive derive derive derive debug trace",
    "derive derive derive derive build trace",
    "derive derive derive trace derive",
    "derive derive derive trace build",
    "derive derive derive derive debug",
    "derive derive trace build trace derive",
    "design derive derive derive derive derive derive",  # chapter 9
)


def test_the_seed_exercises_keep_their_ids_and_kinds():
    for n, kinds in enumerate(SEED_KINDS):
        for i, kind in enumerate(kinds.split(), start=1):
            assert bank.get(f"{n}.{i}").kind == kind, f"{n}.{i}"
    assert sum(len(k.split()) for k in SEED_KINDS) == 56


def test_ids_run_on_without_gaps_in_every_chapter():
    for n in bank.chapters():
        assert [e.id for e in bank.chapter(n)] == [f"{n}.{i}" for i in range(1, len(bank.chapter(n)) + 1)]


def test_pages_place_every_exercise_exactly_once():
    assert sorted(BLOCKS, key=lambda s: tuple(map(int, s.split(".")))) == [e.id for e in ALL]
    for ex in ALL:
        assert BLOCKS[ex.id]["prompt"].strip(), f"{ex.id} has no prompt"
        assert BLOCKS[ex.id]["solution"].strip(), f"{ex.id} has no derivation or explanation"
        assert BLOCKS[ex.id]["page"].startswith(f"0{ex.id.split('.')[0]}-")


def test_build_functions_follow_the_page_contract():
    assert {e.id: e.signature for e in BY_KIND["build"]} == {
        "0.5": "rotate_2d(x, y, theta)",
        "4.5": "ekf_update(x, P, z, R)",
        "6.5": "forward_kinematics_2link(L1, L2, theta1, theta2)",
        "8.4": "pid_step(e, e_prev, integral, Kp, Ki, Kd, dt)",
    }


NUMBER = re.compile(r"[-−]?\d+(?:\.\d+)?")


def printed_answer(ex: Derive) -> str:
    lines = [l for l in BLOCKS[ex.id]["solution"].splitlines() if l.strip().startswith("**Answer:**")]
    assert len(lines) == 1, f"{ex.id}: the derivation needs exactly one '**Answer:**' line"
    numbers = NUMBER.findall(lines[0].replace("^\\circ", "°"))
    assert numbers, f"{ex.id}: no number in {lines[0]!r}"
    return numbers[-1].replace("−", "-")


@pytest.mark.parametrize("ex", BY_KIND["derive"], ids=lambda e: e.id)
def test_derive_key_matches_the_printed_derivation(ex: Derive):
    shown = printed_answer(ex)
    decimals = len(shown.split(".")[1]) if "." in shown else 0
    assert abs(float(shown) - ex.key) <= 0.5 * 10 ** -decimals + 1e-12, (
        f"{ex.id}: derivation prints {shown}, key is {ex.key!r}"
    )
    text = shown + ("°" if ex.angle == "deg" else "")
    assert check(ex, text).status == "correct", f"{ex.id}: the printed answer {text} is not accepted"
    assert check(ex, repr(ex.key)).status == "correct"


@pytest.mark.parametrize("ex", BY_KIND["derive"], ids=lambda e: e.id)
def test_derive_slips_are_reachable(ex: Derive):
    for slip in ex.slips:
        assert not math.isclose(slip.value, ex.key, abs_tol=1e-9), f"{ex.id}: a slip equals the key"
        result = check(ex, repr(slip.value))
        assert (result.status, result.tag, result.message) == ("incorrect", "slip", slip.message)


@pytest.mark.parametrize("ex", BY_KIND["build"], ids=lambda e: e.id)
def test_build_solution_passes_and_starter_fails(ex: Build):
    assert run_build(ex, ex.solution).status == "correct"
    starter = run_build(ex, ex.starter)
    assert starter.status == "incorrect"
    assert any(not row["passed"] for row in starter.data["tests"])
    page_solution = re.search(r"```python\n(.*?)```", BLOCKS[ex.id]["solution"], re.S)
    assert page_solution, f"{ex.id}: the page shows no Python solution"
    assert run_build(ex, page_solution.group(1)).status == "correct", f"{ex.id}: the page's solution fails"


def load_function(code: str, name: str):
    namespace: dict = {}
    exec(compile(code, "<debug>", "exec"), namespace)
    return namespace[name]


def agrees(fn, ex: Debug, args) -> bool:
    got, want = fn(*args), ex.reference(*args)
    flat = lambda v: [float(x) for x in (sum((list(r) for r in v), []) if hasattr(v[0], "__len__") else v)]  # noqa: E731
    return all(math.isclose(a, b, rel_tol=1e-9, abs_tol=1e-9) for a, b in zip(flat(got), flat(want)))


@pytest.mark.parametrize("ex", BY_KIND["debug"], ids=lambda e: e.id)
def test_debug_program_fails_until_its_marked_line_is_fixed(ex: Debug):
    lines = ex.lines
    assert 1 <= ex.bug_line <= len(lines)
    assert set(ex.notes) == set(range(1, len(lines) + 1)) - {ex.bug_line}, "every other line needs a note"
    buggy = load_function(ex.code, ex.function)
    assert not all(agrees(buggy, ex, args) for args in ex.cases), "the bug must show on the cases"
    fixed_lines = list(lines)
    assert fixed_lines[ex.bug_line - 1] != ex.fixed_line
    fixed_lines[ex.bug_line - 1] = ex.fixed_line
    fixed = load_function("\n".join(fixed_lines), ex.function)
    assert all(agrees(fixed, ex, args) for args in ex.cases)
    assert check(ex, ex.bug_line).status == "correct"
    for n in ex.notes:
        assert check(ex, n).status == "incorrect"


@pytest.mark.parametrize("ex", BY_KIND["design"], ids=lambda e: e.id)
def test_design_solution_passes_and_first_order_does_not(ex: Design):
    assert sorted(ex.shown) == sorted(ex.solution)
    assert tuple(ex.shown) != ex.solution
    assert check(ex, list(ex.solution)).status == "correct"
    assert check(ex, list(ex.shown)).status == "incorrect"


@pytest.mark.parametrize("ex", BY_KIND["trace"], ids=lambda e: e.id)
def test_trace_has_exactly_one_correct_option(ex: Trace):
    assert 3 <= len(ex.options) <= 4
    statuses = {o.key: check(ex, o.key).status for o in ex.options}
    assert list(statuses.values()).count("correct") == 1
    assert statuses[ex.answer] == "correct"
    assert all(o.why.strip() and o.text.strip() for o in ex.options)
