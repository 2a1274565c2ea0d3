"""Exercise 5.10, one Gauss–Newton iteration on an SE(2) pose graph: the reference, the edge cases the
statement names, and the sentences its test rows say.

- ``gauss_newton_se2`` against an independent NumPy step (Jacobians by central differences of the
  chapter's wrapped error) over random graphs, angles near and past ±π included; anchoring by adding the
  identity to H's pose-0 block gives the same step; pose 0 never moves; every angle comes out in (−π, π];
- the edge cases every run tries are the ones the statement and the brief name;
- every sentence of ``pose_graph_slips`` is said to the hold-out program that makes exactly that slip,
  on every failing row of every run, and to no other program (right ones never fail a row at all).
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from holdout_programs_se2 import RIGHT, SAYS, WRONG
from test_build_holdout import SEEDS, program
from workbook import bank, build_judge
from workbook.build_judge import Case
from workbook.reference.pose_graph import edge_error_relative
from workbook.reference.pose_graph_step import gauss_newton_se2, linear_system
from workbook_sandbox import runner
from workbook_sandbox.restore import STDLIB_HOMES, Restore

EX = bank.get("5.10")
OPENINGS = ("Pose 0 moved", "The angle of pose", "Poses 1 and 2 came back", "Every pose moved by exactly minus",
            "These are the poses of a step whose edge angle", "These are the poses of a step with every Ω")

coord = st.floats(-5, 5, allow_nan=False)
angle = st.floats(-math.pi + 1e-6, math.pi, allow_nan=False)
pose = st.tuples(coord, coord, angle)
step = st.tuples(st.floats(0.3, 2), st.floats(-1, 1), st.floats(-3, 3))


def numeric_step(poses, edges, anchor_with_identity=False):
    """One iteration with Jacobians by central differences (a wrap between two samples is no slope)."""
    x = np.array(poses, float)
    n = 3 * len(x)
    H, b = np.zeros((n, n)), np.zeros(n)
    for i, j, z, omega in edges:
        e = np.array(edge_error_relative(x[i], x[j], z))
        J = np.zeros((3, n))
        for p in (i, j):
            for k in range(3):
                up, down = x.copy(), x.copy()
                up[p, k] += 1e-6
                down[p, k] -= 1e-6
                d = np.array(edge_error_relative(up[i], up[j], z)) - np.array(edge_error_relative(down[i], down[j], z))
                d[2] = math.remainder(d[2], 2 * math.pi)
                J[:, 3 * p + k] += d / 2e-6
        H += J.T @ np.array(omega) @ J
        b += J.T @ np.array(omega) @ e
    if anchor_with_identity:
        H[:3, :3] += np.eye(3)
        dx = np.linalg.solve(H, -b)
    else:
        dx = np.concatenate([np.zeros(3), np.linalg.solve(H[3:, 3:], -b[3:])])
    new = x + dx.reshape(-1, 3)
    new[:, 2] = np.arctan2(np.sin(new[:, 2]), np.cos(new[:, 2]))
    return new


def same_poses(a, b, tol):
    a, b = np.array(a, float), np.array(b, float)
    turn = np.abs(np.remainder(a[:, 2] - b[:, 2] + math.pi, 2 * math.pi) - math.pi)
    return np.abs(a[:, :2] - b[:, :2]).max() < tol and turn.max() < tol


@settings(max_examples=150, deadline=None)
@given(st.lists(pose, min_size=3, max_size=3), st.lists(step, min_size=3, max_size=3),
       st.sampled_from([((0, 1), (1, 2), (0, 2)), ((2, 1), (0, 2)), ((1, 0), (2, 1), (2, 0)), ((0, 1), (2, 1))]),
       st.floats(0.5, 20), st.floats(-0.6, 0.6))
def test_the_reference_is_the_step_numeric_jacobians_give(poses, zs, pairs, weight, rho):
    omega = [[weight, rho * weight, 0.0], [rho * weight, weight, 0.0], [0.0, 0.0, 3 * weight]]
    edges = [(i, j, z, omega) for (i, j), z in zip(pairs, zs)]
    got = gauss_newton_se2(poses, edges)
    assert got[0] == [float(v) for v in poses[0]], "pose 0 is the anchor"
    assert all(-math.pi < p[2] <= math.pi for p in got)
    assert same_poses(got, numeric_step(poses, edges), 1e-5)
    assert same_poses(got, numeric_step(poses, edges, anchor_with_identity=True), 1e-5)


@settings(max_examples=60, deadline=None)
@given(pose, step, step)
def test_poses_that_agree_with_every_edge_do_not_move(p0, z01, z12):
    from workbook.reference.pose_graph import compose_pose, relative_pose
    p1 = compose_pose(p0, z01)
    p2 = compose_pose(p1, z12)
    W = [[2.0, 0.5, 0.0], [0.5, 1.0, 0.0], [0.0, 0.0, 9.0]]
    edges = [(0, 1, z01, W), (1, 2, z12, W), (2, 0, relative_pose(p2, p0), W)]
    assert same_poses(gauss_newton_se2([p0, p1, p2], edges), [p0, p1, p2], 1e-9)


def test_the_edge_cases_are_those_the_statement_names():
    cases = [(poses, edges, gauss_newton_se2(poses, edges)) for poses, edges in EX.edge_cases]
    assert any(same_poses(after, poses, 1e-12) for poses, _, after in cases), "a graph already at its optimum"
    assert any(abs(z[2] - (p[j][2] - p[i][2])) > math.pi for p, edges, _ in cases for i, j, z, _ in edges), \
        "an edge whose plain angle difference is past ±π"
    H, b = linear_system(*EX.edge_cases[2])
    plain = [p[2] + d for p, d in zip(EX.edge_cases[2][0], np.linalg.solve(np.array(H)[3:, 3:], -np.array(b)[3:])[2::3])]
    assert any(abs(t) > math.pi for t in plain), "a heading the step pushes past π"
    assert any(any(w[r][c] for r in range(3) for c in range(3) if r != c) for _, edges, _ in cases
               for *_, w in edges), "an Ω with off-diagonal entries"
    assert any(all(0 not in (i, j) or {i, j} != {0, 1} for i, j, *_ in edges) and any(0 not in (i, j) for i, j, *_ in edges)
               for _, edges, _ in cases), "pose 1 tied to pose 0 only through pose 2"
    assert any(i > j for _, edges, _ in cases for i, j, *_ in edges), "an edge written backwards"
    assert any(list(p[0][:2]) != [0.0, 0.0] and p[0][2] == math.pi for p, _, _ in cases), "pose 0 off the origin, at π"


def rows(ex, code):
    """Every case's row (not only the verdict's first failing hidden one)."""
    report = runner.run_json(ex.job(), code, Restore(STDLIB_HOMES + ("workbook",), []))
    arguments = ex.arguments()
    return build_judge.compare(build_judge.read_report(report, len(arguments)), ex.cases(arguments), ex.rel_tol,
                               ex.abs_tol, ex.angles)


def said(row) -> set[str]:
    return {opening for opening in OPENINGS if opening in row["message"]}


@pytest.mark.parametrize("name", list(WRONG))
def test_each_sentence_is_said_to_its_slip_and_to_no_other(name):
    for seed in SEEDS:
        failing = [r for r in rows(EX.variant(seed), program(EX, WRONG[name])) if not r["passed"]]
        assert failing, (name, seed)
        for row in failing:
            assert said(row) <= set(SAYS.get(name, ())), (name, seed, row["input"], row["message"])
            if name in SAYS:
                assert said(row), (name, seed, row["input"], row["message"])
        assert set().union(*map(said, failing)) == set(SAYS.get(name, ())), (name, seed)


def test_the_starter_is_told_no_step_was_applied():
    failing = [r for r in rows(EX, EX.starter) if not r["passed"]]
    assert failing and all(said(r) == {"Poses 1 and 2 came back"} for r in failing)


@pytest.mark.parametrize("name", list(RIGHT))
def test_a_correct_program_fails_no_row(name):
    for seed in SEEDS:
        assert all(r["passed"] for r in rows(EX.variant(seed), program(EX, RIGHT[name]))), (name, seed)


def test_the_wrapped_clause_is_said_only_when_true():
    poses, edges = EX.edge_cases[2]
    want = gauss_newton_se2(poses, edges)
    past = [[x, y, t + 2 * math.pi if t < 0 else t] for x, y, t in want]
    assert "wrapped, it agrees with the reference" in EX.diagnose((poses, edges), past, want)
    off = [[x, y, t + 0.1] for x, y, t in past]
    text = EX.diagnose((poses, edges), off, want)
    assert "lies outside (−π, π]." in text and "agrees" not in text


def test_a_fault_of_a_diagnosis_costs_nothing_and_a_passing_row_gets_none():
    def broken(got):
        raise ZeroDivisionError
    value = {"type": "list", "text": "[1.0]", "length": 1, "items": [{"type": "float", "text": "1.0", "number": 1.0}]}
    row = build_judge.row(Case("example", "f(1)", [2.0], broken), {"value": value}, 1e-6, 1e-9)
    assert not row["passed"] and row["message"] == "first difference at [0]: expected 2.0, got 1.0"
    row = build_judge.row(Case("example", "f(1)", [1.0], lambda got: "never said"), {"value": value}, 1e-6, 1e-9)
    assert row["passed"] and row["message"] == ""
    row = build_judge.row(Case("example", "f(1)", [2.0], lambda got: "It is one."), {"value": value}, 1e-6, 1e-9)
    assert row["message"] == "It is one. (first difference at [0]: expected 2.0, got 1.0)"
