"""Chapter 5's SE(2) edge Jacobians (prose and exercise 5.9), checked against numbers.

- ``edge_jacobians`` (closed form) against central differences of ``edge_error_relative`` over
  random poses, angles past ±π included;
- exercise 5.9's key is the entry of ``edge_jacobians``' A over many draws;
- what the prose says about anchoring: H = Σ JᵀΩJ is flat (H v = 0) along a shift and a turn of
  the whole graph, and anchoring one pose makes it invertible.
"""

from __future__ import annotations

import math

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from workbook import bank
from workbook.reference.pose_graph import edge_error_relative
from workbook.reference.pose_graph_jacobian import edge_jacobians, heading_column_entry

coord = st.floats(-5, 5, allow_nan=False)
angle = st.floats(-4, 4, allow_nan=False)
pose = st.tuples(coord, coord, angle)


def numeric(xi, xj, z, h=1e-6):
    """(∂e/∂xi, ∂e/∂xj) by central differences."""
    blocks = []
    for which in (0, 1):
        cols = []
        for k in range(3):
            plus, minus = [list(xi), list(xj)], [list(xi), list(xj)]
            plus[which][k] += h
            minus[which][k] -= h
            ep, em = np.array(edge_error_relative(*plus, z)), np.array(edge_error_relative(*minus, z))
            d = ep - em
            d[2] = math.remainder(d[2], 2 * math.pi)  # a wrap between the two samples is not a slope
            cols.append(d / (2 * h))
        blocks.append(np.column_stack(cols))
    return blocks


@settings(max_examples=300, deadline=None)
@given(pose, pose, pose)
def test_the_closed_form_jacobians_are_the_slopes_of_the_error(xi, xj, z):
    A, B = edge_jacobians(xi, xj)
    nA, nB = numeric(xi, xj, z)
    assert np.allclose(A, nA, atol=1e-5) and np.allclose(B, nB, atol=1e-5)


def test_exercise_5_9_asks_an_entry_of_the_reference_jacobian():
    ex = bank.get("5.9")
    rows = set()
    for seed in range(400):
        v = ex.variant(seed)
        p = v.params
        xi, xj = (p["xi"], p["yi"], math.radians(p["ti"])), (p["xj"], p["yj"], math.radians(p["tj"]))
        row = 0 if p["entry"] == "x" else 1
        rows.add(row)
        assert math.isclose(v.answer.key, heading_column_entry(xi, xj, row), abs_tol=1e-12)
        assert math.isclose(v.answer.key, edge_jacobians(xi, xj)[0][row][2], abs_tol=1e-12)
    assert rows == {0, 1}


def _hessian(poses, edges):
    n = len(poses)
    H = np.zeros((3 * n, 3 * n))
    for i, j, omega in edges:
        A, B = edge_jacobians(poses[i], poses[j])
        J = np.zeros((3, 3 * n))
        J[:, 3 * i:3 * i + 3], J[:, 3 * j:3 * j + 3] = A, B
        H += J.T @ np.array(omega) @ J
    return H


@settings(max_examples=100, deadline=None)
@given(st.lists(pose, min_size=3, max_size=3))
def test_h_is_flat_along_moves_of_the_whole_graph_and_anchoring_fixes_it(poses):
    omega = [[50, 5, 0], [5, 80, 0], [0, 0, 200]]
    H = _hessian(poses, [(0, 1, omega), (1, 2, omega), (0, 2, omega)])
    shift_x = np.tile([1.0, 0.0, 0.0], 3)
    shift_y = np.tile([0.0, 1.0, 0.0], 3)
    turn = np.concatenate([[-y, x, 1.0] for x, y, _ in poses])  # every pose turned about the origin
    for v in (shift_x, shift_y, turn):
        assert np.allclose(H @ v, 0, atol=1e-8 * max(1.0, np.abs(H).max()))
    free = H[3:, 3:]  # pose 0 anchored
    assert np.linalg.matrix_rank(free) == 6
