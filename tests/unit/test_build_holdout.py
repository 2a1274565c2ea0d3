"""A hold-out of hand-written learner programs (tests/unit/holdout_programs.py) against every Build exercise.

Every wrong program fails, in the exercise's own hidden cases and in a review's fresh ones (several
seeds), with a failing row that names its case; every correct rewrite passes in all of them. The edge
cases a statement names are in every run, so a slip that only shows there cannot slip through a draw.
"""

from __future__ import annotations

import pytest

import many_draws
from holdout_programs import RIGHT, WRONG
from workbook import bank

SEEDS = many_draws.share_of((0, 17, 4321))  # 0: the exercise's own hidden cases; then a review's fresh ones
BUILDS = sorted({ex.id for ex in bank.all_exercises() if ex.kind == "build"}, key=lambda i: tuple(map(int, i.split("."))))


def program(ex, spec) -> str:
    if isinstance(spec, str):
        return spec
    code = ex.solution
    for old, new in spec:
        assert old in code, f"{ex.id}: {old!r} is not in the solution"
        code = code.replace(old, new)
    return code


def test_every_build_exercise_has_a_hold_out():
    assert set(WRONG) == set(RIGHT) == set(BUILDS) and len(BUILDS) >= 12  # every Build exercise (AUTHORING.md: "Adding a Build exercise")
    assert all(len(WRONG[i]) + len(RIGHT[i]) >= 8 for i in BUILDS)
    assert sum(len(WRONG[i]) + len(RIGHT[i]) for i in BUILDS) >= 120


@pytest.mark.parametrize("ex_id,name", [(i, n) for i in BUILDS for n in many_draws.share_of(tuple(WRONG[i]))])
def test_a_wrong_program_fails_in_every_run_and_names_its_case(ex_id, name):
    ex = bank.get(ex_id)
    code = program(ex, WRONG[ex_id][name])
    for seed in SEEDS:
        verdict = ex.variant(seed).check(code)
        assert verdict.status == "incorrect", f"{ex_id} {name!r} accepted with seed {seed}"
        failing = [r for r in verdict.data["tests"] if not r["passed"]]
        assert failing, verdict.message
        for row in failing:
            assert row["input"] and row["input"] != "—", row
            assert row["input"].startswith(ex.function) or row["input"].startswith(f"{ex.function} run"), row
            assert row["actual"] and (row["actual"] != row["expected"] or row["message"]), row


@pytest.mark.parametrize("ex_id,name", [(i, n) for i in BUILDS for n in many_draws.share_of(tuple(RIGHT[i]))])
def test_a_correct_rewrite_passes_in_every_run(ex_id, name):
    ex = bank.get(ex_id)
    code = program(ex, RIGHT[ex_id][name])
    for seed in SEEDS:
        verdict = ex.variant(seed).check(code)
        assert verdict.status == "correct", (seed, [r for r in verdict.data["tests"] if not r["passed"]])
