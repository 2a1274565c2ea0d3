"""The chapters agree with themselves and with the field.

- Chapter 5: one sign for the Gauss–Newton normal equations (b = Σ JᵀΩe, H Δx = −b) in
  the prose, in 5.5 and 5.8 and in the reference, and following the prose lowers the cost.
- 5.8's solution: a heavier edge absorbs less of the mismatch, and the shares it prints
  are the reference's.
- Chapter 3 names its Euler step for what it is; the exact arc model is the one
  *Probabilistic Robotics* calls the velocity motion model.
- Chapter 9's loop promises no world-frame transform that no exercise does.
"""

from __future__ import annotations

import inspect
import math
import random
import re
from pathlib import Path

import pytest

from exercise_text import load_all  # docs/hooks/exercise_text.py
from workbook import bank
from workbook.number_format import fmt
from workbook.reference import pose_graph
from workbook.reference.ekf import motion_model, motion_model_arc
from workbook.reference.pose_graph import gauss_newton_step_1d, graph_cost

ROOT = Path(__file__).resolve().parents[2]
CHAPTERS = ROOT / "docs" / "chapters"
CH5 = (CHAPTERS / "05-pose-graph-slam.md").read_text(encoding="utf-8")
PROSE5 = CH5.split("## Exercises")[0]
TEXTS = load_all(ROOT)

# H Δx = ±b as TeX (page and templates): \Delta with or without \mathbf{x}, b bold or not;
# b = Σ JᵀΩe may sit in an aligned block (&=)
SYSTEM_TEX = re.compile(r"H\s*\\,\s*\\Delta(?:\\mathbf\{x\})?\s*=\s*(-?)\s*(?:\\mathbf\{b\}|b\b)")
SYSTEM_TEXT = re.compile(r"H Δx? = ([−-]?)b\b")  # in the reference's docstrings
B_DEFINED = re.compile(r"\\mathbf\{b\}\s*&?=\s*\\sum_\{\(i,j\)\}\s*J_\{ij\}\^\\top\s*(?:\\,)?\s*\\Omega_\{ij\}\s*(?:\\,)?\s*\\mathbf\{e\}_\{ij\}")


def test_chapter_5_defines_b_and_writes_one_sign_everywhere():
    assert B_DEFINED.search(PROSE5), "the prose must define b = Σ Jᵀ Ω e"
    in_prose = SYSTEM_TEX.findall(PROSE5)
    in_page = SYSTEM_TEX.findall(CH5)
    in_templates = [s for ex_id in ("5.5", "5.8") for part in TEXTS[ex_id].parts() for s in SYSTEM_TEX.findall(part)]
    in_reference = SYSTEM_TEXT.findall(inspect.getsource(pose_graph))
    assert in_prose and len(in_page) >= 3 and len(in_templates) >= 2 and len(in_reference) >= 2
    for where, signs in (("prose", in_prose), ("page", in_page), ("5.5 and 5.8", in_templates),
                         ("reference", in_reference)):
        assert set(signs) <= {"-", "−"}, (where, signs)


def _prose_sign() -> float:
    """The sign the prose puts before b in H Δx = ±b."""
    return -1.0 if SYSTEM_TEX.search(PROSE5).group(1) == "-" else 1.0


def _follow_the_prose(x, edges):
    """One step exactly as the prose says: J = ∂e/∂x, H = Σ JᵀΩJ, b = Σ JᵀΩe, H Δx = ±b,
    over poses 1 and 2 (pose 0 is the anchor)."""
    assert B_DEFINED.search(PROSE5), "the prose must say what b is before it can be followed"
    H = [[0.0, 0.0], [0.0, 0.0]]
    b = [0.0, 0.0]
    for i, j, z, w in edges:
        e = z - (x[j] - x[i])
        J = [0.0, 0.0, 0.0]
        J[i] += 1.0  # e = z − (x_j − x_i)
        J[j] -= 1.0
        for r in (1, 2):
            b[r - 1] += J[r] * w * e
            for c in (1, 2):
                H[r - 1][c - 1] += J[r] * w * J[c]
    det = H[0][0] * H[1][1] - H[0][1] * H[1][0]
    s = _prose_sign()
    d1 = s * (b[0] * H[1][1] - b[1] * H[0][1]) / det
    d2 = s * (b[1] * H[0][0] - b[0] * H[1][0]) / det
    return [x[0], x[1] + d1, x[2] + d2]


def _cost(x, edges) -> float:
    """5.8's cost Σ w e², through the reference's graph cost (poses on the x axis)."""
    poses = [(p, 0.0, 0.0) for p in x]
    weight = [[1.0, 0, 0], [0, 1.0, 0], [0, 0, 1.0]]
    return graph_cost(poses, [(i, j, (z, 0.0, 0.0), [[w * v for v in row] for row in weight]) for i, j, z, w in edges])


def _graphs():
    ex = bank.get("5.8")
    rng = random.Random("chapter 5 sign")
    return [*ex.examples, *(ex.random_args(rng) for _ in range(200))]


@pytest.mark.parametrize("x,edges", _graphs())
def test_following_the_prose_on_5_8_lowers_the_cost(x, edges):
    before = _cost(x, edges)
    if before < 1e-12:
        pytest.skip("nothing to lower")
    after = _follow_the_prose(list(x), edges)
    assert _cost(after, edges) < before
    _, reference = gauss_newton_step_1d(list(x), edges)
    assert all(math.isclose(a, r, rel_tol=1e-9, abs_tol=1e-9) for a, r in zip(after, reference))


def test_5_8_solution_shares_the_mismatch_inversely_to_the_weights():
    solution = TEXTS["5.8"].filled(bank.get("5.8").values).solution
    assert "in proportion to the weights" not in solution.replace("in *inverse* proportion", "")
    assert "inverse" in solution
    equal_graph, heavy_graph = bank.get("5.8").examples[:2]
    _, after = gauss_newton_step_1d(*heavy_graph)
    left = [abs(e) for e in gauss_newton_step_1d(after, heavy_graph[1])[0]]
    odo, closure = left[0], left[2]
    assert closure < odo  # the edge weighted 10 absorbs less
    for printed in (fmt(odo), fmt(closure)):
        assert f"{printed} m" in solution, printed
    _, after = gauss_newton_step_1d(*equal_graph)
    assert f"{fmt(abs(gauss_newton_step_1d(after, equal_graph[1])[0][0]))} m" in solution


def test_on_any_weighted_loop_every_edge_ends_with_the_same_weighted_error():
    """The solution's rule, over many loops: w·|e| is the same on every edge, so shares go as 1/w."""
    rng = random.Random("5.8 shares")
    for _ in range(300):
        x = [0.0, rng.uniform(-2, 2), rng.uniform(-2, 2)]
        w = [rng.uniform(0.2, 20) for _ in range(3)]
        edges = [(0, 1, rng.uniform(-2, 2), w[0]), (1, 2, rng.uniform(-2, 2), w[1]), (0, 2, rng.uniform(-4, 4), w[2])]
        _, after = gauss_newton_step_1d(x, edges)
        forces = [wk * abs(e) for wk, e in zip(w, gauss_newton_step_1d(after, edges)[0])]
        assert max(forces) - min(forces) <= 1e-9 * max(1.0, max(forces))


def test_chapter_3_names_its_euler_step_and_the_arc_model():
    text = (CHAPTERS / "03-ekf-predict.md").read_text(encoding="utf-8")
    headings = [line for line in text.splitlines() if line.startswith("#")]
    assert not any("velocity motion model" in h.lower() for h in headings), headings
    assert "Euler" in text.split("## Explore")[0]
    for line in re.findall(r"[^.]*velocity motion\s+model[^.]*", text):
        assert "Thrun" in line or "Probabilistic Robotics" in line or "arc" in line, line
    for chapter in CHAPTERS.glob("*.md"):
        assert "velocity model" not in chapter.read_text(encoding="utf-8"), chapter.name


@pytest.mark.parametrize("seed", range(50))
def test_the_euler_step_is_the_arc_to_first_order_and_ends_outside_the_turn(seed):
    rng = random.Random(seed)
    state = (rng.uniform(-3, 3), rng.uniform(-3, 3), rng.uniform(-math.pi, math.pi))
    v, omega = rng.uniform(0.2, 2), rng.choice((-1, 1)) * rng.uniform(0.2, 2)
    assert motion_model_arc(state, v, 0.0, 0.3) == motion_model(state, v, 0.0, 0.3)
    for dt in (1e-2, 1e-3):
        euler, arc = motion_model(state, v, omega, dt), motion_model_arc(state, v, omega, dt)
        left = (-math.sin(state[2]), math.cos(state[2]))  # the robot's left at the start
        side = (euler[0] - arc[0]) * left[0] + (euler[1] - arc[1]) * left[1]
        assert math.copysign(1, side) == -math.copysign(1, omega)  # outside the turn
        assert math.isclose(abs(side), 0.5 * v * abs(omega) * dt * dt, rel_tol=0.02)
        assert math.isclose(euler[2], arc[2])


def test_chapter_9_promises_no_world_frame_transform():
    text = (CHAPTERS / "09-capstone.md").read_text(encoding="utf-8")
    intro = text.split("## Explore")[0]
    assert not re.search(r"transform\w* it into the world", intro)
    assert "frames from chapters" not in intro
