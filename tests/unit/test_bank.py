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
import sys
from pathlib import Path

import pytest

from blocks import ExerciseBlock, parse  # docs/hooks/blocks.py
from exercise_text import source_of  # docs/hooks/exercise_text.py
from workbook import bank
from workbook.answer_kinds.expression.mark import equivalent
from workbook.contract import KINDS
from workbook.kinds.build import Build
from workbook.kinds.debug import Debug
from workbook.kinds.derive import Derive
from workbook.kinds.design import Design
from workbook.kinds.trace import Trace
from workbook.variants import fill

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "golden"))
from transcript import SLIP_TEXTS


def check(ex, answer):
    return ex.check(answer)


run_build = check

ROOT = Path(__file__).resolve().parents[2]
PAGES = sorted((ROOT / "docs" / "chapters").glob("*.md"))
ALL = bank.all_exercises()
BY_KIND = {k: [e for e in ALL if e.kind == k] for k in KINDS}
BY_ANSWER = {a: [e for e in BY_KIND["derive"] if e.answer_kind == a] for a in ("number", "matrix", "expression")}


def page_blocks():
    blocks = {}
    for page in PAGES:
        for block in parse(page.read_text(), page.name):
            if isinstance(block, ExerciseBlock):
                assert block.id not in blocks, f"{block.id} placed twice"
                ex = bank.get(block.id)
                values = getattr(ex, "values", {})  # variant 0's numbers in the {{name}} places
                source = source_of(block, ex.solution if ex.kind == "build" else None)  # as the build shows it
                blocks[block.id] = {"page": page.name, "title": fill(block.title, values, html=False),
                                    "written": block.text("solution"),
                                    **{k: fill(source[k], values, html=False) for k in block.parts}}
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
        ids = [e.id for e in bank.chapter(n)]
        last = max(int(i.split(".")[1]) for i in ids)
        expected = [f"{n}.{i}" for i in range(1, last + 1)]
        assert ids == expected, f"chapter {n} skips an id"


def test_pages_place_every_exercise_exactly_once():
    assert sorted(BLOCKS, key=lambda s: tuple(map(int, s.split(".")))) == [e.id for e in ALL]
    for ex in ALL:
        assert BLOCKS[ex.id]["prompt"].strip(), f"{ex.id} has no prompt"
        assert BLOCKS[ex.id]["solution"].strip(), f"{ex.id} has no derivation or explanation"
        assert BLOCKS[ex.id]["page"].startswith(f"{int(ex.id.split('.')[0]):02d}-")  # the chapter's number on two digits


def test_the_readme_states_the_number_of_exercises():
    assert f"{len(ALL)} exercises" in (ROOT / "README.md").read_text()


NUMBER = re.compile(r"[-−]?\d+(?:\.\d+)?")


def printed_answer(ex: Derive) -> str:
    lines = [line for line in BLOCKS[ex.id]["solution"].splitlines() if line.strip().startswith("**Answer:**")]
    assert len(lines) == 1, f"{ex.id}: the derivation needs exactly one '**Answer:**' line"
    numbers = NUMBER.findall(lines[0].replace("^\\circ", "°"))
    assert numbers, f"{ex.id}: no number in {lines[0]!r}"
    return numbers[-1].replace("−", "-")


@pytest.mark.parametrize("ex", BY_ANSWER["number"], ids=lambda e: e.id)
def test_derive_key_matches_the_printed_derivation(ex: Derive):
    shown = printed_answer(ex)
    decimals = len(shown.split(".")[1]) if "." in shown else 0
    assert abs(float(shown) - ex.answer.key) <= 0.5 * 10 ** -decimals + 1e-12, (
        f"{ex.id}: derivation prints {shown}, key is {ex.answer.key!r}"
    )
    text = shown + ("°" if ex.answer.angle == "deg" else "")
    assert check(ex, text).status == "correct", f"{ex.id}: the printed answer {text} is not accepted"
    assert check(ex, repr(ex.answer.key)).status == "correct"


@pytest.mark.parametrize("ex", BY_ANSWER["number"], ids=lambda e: e.id)
def test_derive_slips_are_reachable(ex: Derive):
    for slip in ex.answer.slips:
        assert not math.isclose(slip.value, ex.answer.key, abs_tol=1e-9), f"{ex.id}: a slip equals the key"
        result = check(ex, repr(slip.value))
        assert (result.status, result.tag, result.message) == ("incorrect", "slip", slip.message)


def test_every_derive_answer_kind_is_walked():
    assert sum(map(len, BY_ANSWER.values())) == len(BY_KIND["derive"])


# ---------------------------------------------------------------- vector and matrix answers

BMATRIX = re.compile(r"\\begin\{bmatrix\}(.*?)\\end\{bmatrix\}", re.S)


def printed_matrix(ex: Derive) -> list[list[str]]:
    """The entries of the last bmatrix on the ``**Answer:**`` line, as printed, row by row."""
    lines = [line for line in BLOCKS[ex.id]["solution"].splitlines() if line.strip().startswith("**Answer:**")]
    assert len(lines) == 1, f"{ex.id}: the derivation needs exactly one '**Answer:**' line"
    found = BMATRIX.findall(lines[0])
    assert found, f"{ex.id}: the answer line has no bmatrix: {lines[0]!r}"
    rows = [r.split("&") for r in found[-1].split(r"\\")]
    return [[cell.strip() for cell in row] for row in rows]


def as_text(grid) -> list[list[str]]:
    return [[repr(float(v)) for v in row] for row in grid]


@pytest.mark.parametrize("ex", BY_ANSWER["matrix"], ids=lambda e: e.id)
def test_matrix_key_matches_the_printed_derivation(ex: Derive):
    shown = printed_matrix(ex)
    assert [len(row) for row in shown] == [len(row) for row in ex.answer.key], f"{ex.id}: printed shape differs from the key"
    for i, (row, key_row) in enumerate(zip(shown, ex.answer.key), 1):
        for j, (text, want) in enumerate(zip(row, key_row), 1):
            assert NUMBER.fullmatch(text), f"{ex.id} ({i},{j}): print a plain number, not {text!r}"
            value = float(text.replace("−", "-"))
            decimals = len(text.split(".")[1]) if "." in text else 0
            assert abs(value - want) <= 0.5 * 10 ** -decimals + 1e-12, f"{ex.id} ({i},{j}): prints {text}, key {want!r}"
    assert check(ex, shown).status == "correct", f"{ex.id}: the printed answer is not accepted"
    assert check(ex, ex.worked_text()).status == "correct", f"{ex.id}: the worked text {ex.worked_text()!r}"
    assert check(ex, as_text(ex.answer.key)).status == "correct"


@pytest.mark.parametrize("ex", BY_ANSWER["matrix"], ids=lambda e: e.id)
def test_matrix_slips_are_reachable(ex: Derive):
    assert ex.answer.slips, f"{ex.id}: name at least one slip of its own"
    for slip in ex.answer.slips:
        assert [len(r) for r in slip.value] == [len(r) for r in ex.answer.key], f"{ex.id}: a slip of another shape"
        assert check(ex, as_text(slip.value)).status != "correct", f"{ex.id}: a slip equals the key"
        result = check(ex, as_text(slip.value))
        assert (result.status, result.tag, result.message) == ("incorrect", "slip", slip.message), ex.id
        assert result.data["wrong"], f"{ex.id}: a slip marks no entry wrong"


@pytest.mark.parametrize("ex", BY_ANSWER["matrix"], ids=lambda e: e.id)
def test_matrix_transpose_is_named_or_refused(ex: Derive):
    t = [list(col) for col in zip(*ex.answer.cleaned)]
    result = check(ex, as_text(t))
    if len(t) != len(ex.answer.key):  # a vector or a non-square matrix: the transpose has the wrong shape
        assert result.status == "invalid" and "×" in result.message, (ex.id, result)
    elif result.status != "correct":  # a symmetric key is its own transpose
        assert result.status == "incorrect" and result.tag, (ex.id, result)
        assert result.data["wrong"]


def test_a_quaternion_and_its_negative_are_both_right():
    ex = bank.get("2.7")
    negated = [[repr(-v) for v in row] for row in ex.answer.cleaned]
    result = check(ex, negated)
    assert result.status == "correct" and "same rotation" in result.message


# ---------------------------------------------------------------- formula answers

# A rewriting of each formula by hand: expanded, reordered, or through an identity.
EQUIVALENT_FORMS = {
    "3.9": "-dt*v*cos(θ - pi/2)",
    "4.8": "1/(dy + dx^2/dy)",
    "6.6": "L1*cos(theta1) + L2*(cos(theta1)*cos(theta2) - sin(theta1)*sin(theta2))",
    "7.7": "-(L₁*sin(θ₁) + L2*(sin(θ1)*cos(θ2) + cos(θ1)*sin(θ2)))",
}


def test_every_formula_exercise_has_a_hand_written_equivalent():
    assert sorted(EQUIVALENT_FORMS) == sorted(e.id for e in BY_ANSWER["expression"])


@pytest.mark.parametrize("ex", BY_ANSWER["expression"], ids=lambda e: e.id)
def test_formula_answer_and_equivalent_are_right(ex: Derive):
    lines = [line for line in BLOCKS[ex.id]["solution"].splitlines() if line.strip().startswith("**Answer:**")]
    assert len(lines) == 1, f"{ex.id}: the derivation needs exactly one '**Answer:**' line"
    assert ex.worked_text() == ex.answer.answer_text
    for text in (ex.answer.answer_text, EQUIVALENT_FORMS[ex.id]):
        result = check(ex, text)
        assert result.status == "correct", (ex.id, text, result.message)
        assert result.data["latex"]


@pytest.mark.parametrize("ex", BY_ANSWER["expression"], ids=lambda e: e.id)
def test_formula_slips_are_reachable(ex: Derive):
    assert ex.answer.slips
    for slip in ex.answer.slips:
        result = check(ex, slip_text(ex, slip))
        assert (result.status, result.tag, result.message) == ("incorrect", "slip", slip.message), (ex.id, slip.message)
        assert not equivalent(_formula(ex, slip_text(ex, slip)), ex.answer.key, ex.answer.domain)


@pytest.mark.parametrize("ex", BY_ANSWER["expression"], ids=lambda e: e.id)
def test_formula_with_an_unknown_name_is_invalid_and_lists_the_names(ex: Derive):
    result = check(ex, ex.answer.answer_text + " + q7")
    assert result.status == "invalid"
    assert all(name in result.message for name in ex.answer.variables), result.message
    assert "q7" in result.message


def _formula(ex, text):
    from workbook.expr import parse_formula

    return parse_formula(text, ex.answer.variables)


def slip_text(ex, slip) -> str:
    text = SLIP_TEXTS[ex.id][ex.answer.slips.index(slip)]
    assert equivalent(_formula(ex, text), slip.value, ex.answer.domain), f"{ex.id}: {text!r} is not the slip it stands for"
    return text


def test_every_formula_slip_has_a_typed_form():
    assert {e.id: len(e.answer.slips) for e in BY_ANSWER["expression"]} == {k: len(v) for k, v in SLIP_TEXTS.items()}


@pytest.mark.parametrize("ex", BY_KIND["build"], ids=lambda e: e.id)
def test_build_solution_passes_and_starter_fails(ex: Build):
    assert run_build(ex, ex.solution).status == "correct"
    starter = run_build(ex, ex.starter)
    assert starter.status == "incorrect"
    assert any(not row["passed"] for row in starter.data["tests"])
    assert "```" not in BLOCKS[ex.id]["written"], f"{ex.id}: the page writes code of its own; show the bank's with {{{{solution_code}}}}"
    page_solution = re.search(r"```python\n(.*?)```", BLOCKS[ex.id]["solution"], re.S)
    assert page_solution and page_solution.group(1).strip() == ex.solution.strip(), f"{ex.id}: the page shows no Python solution"
    assert run_build(ex, page_solution.group(1)).status == "correct", f"{ex.id}: the page's solution fails"


def load_function(code: str, name: str):
    namespace: dict = {}
    exec(compile(code, "<debug>", "exec"), namespace)
    return namespace[name]


def agrees(fn, ex: Debug, args) -> bool:
    got, want = fn(*args), ex.reference(*args)
    flat = lambda v: [float(x) for x in ([y for r in v for y in r] if hasattr(v[0], "__len__") else v)]  # noqa: E731
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


@pytest.mark.parametrize("ex", BY_KIND["derive"], ids=lambda ex: ex.id)
def test_a_label_does_not_repeat_the_unit_the_widget_adds(ex: Derive):
    """The widget writes the unit after the label ("x (m)"); a label that holds it too read "x (m) (m)"."""
    for seed in (0, 1):
        v = ex.variant(seed)
        unit = getattr(v.answer, "unit", "")
        named = {"°": "(degrees)"}.get(unit, f"({unit})") if unit else None
        assert not named or named not in v.answer.label, (ex.id, seed, v.answer.label)
