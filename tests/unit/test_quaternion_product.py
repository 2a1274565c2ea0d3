"""The quaternion product of chapter 2 (exercise 2.10), checked against an independent form of it.

``quat_multiply`` writes the Hamilton product with a dot and a cross product. Here the same
product is built another way, with NumPy: as the 4×4 matrix L(p) that multiplies q from the
left (its rows read off from i² = j² = k² = ijk = −1), and as the composition of the rotation
matrices of two unit quaternions. The exercise's key, its swapped-order slip and the
derivation's numbers all come from ``quat_multiply``, so this pins them.
"""

from __future__ import annotations

import math

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from workbook import bank
from workbook.reference.rotation3d import (
    quat_conjugate,
    quat_from_axis_angle,
    quat_multiply,
    quat_rotate,
)

component = st.floats(-5, 5, allow_nan=False)
quaternion = st.tuples(component, component, component, component)


def left_matrix(p) -> np.ndarray:
    """L(p) with p ⊗ q = L(p) q, from the basis products (1, i, j, k): ij = k, jk = i, ki = j."""
    w, x, y, z = p
    return np.array([[w, -x, -y, -z],
                     [x, w, -z, y],
                     [y, z, w, -x],
                     [z, -y, x, w]], dtype=float)


def matrix_of(q) -> np.ndarray:
    """The rotation matrix of a unit quaternion, columns: the turned basis vectors."""
    return np.column_stack([quat_rotate(q, e) for e in np.eye(3)])


@settings(max_examples=300, deadline=None)
@given(quaternion, quaternion)
def test_the_product_is_the_left_multiplication_matrix(p, q):
    want = left_matrix(p) @ np.array(q, dtype=float)
    assert np.allclose(quat_multiply(p, q), want, atol=1e-9)


@settings(max_examples=300, deadline=None)
@given(quaternion, quaternion)
def test_swapping_the_factors_flips_only_the_cross_term(p, q):
    pq, qp = np.array(quat_multiply(p, q)), np.array(quat_multiply(q, p))
    assert math.isclose(pq[0], qp[0], abs_tol=1e-9)
    assert np.allclose((pq - qp)[1:] / 2, np.cross(p[1:], q[1:]), atol=1e-9)


unit_axis = st.tuples(component, component, component).filter(lambda v: math.hypot(*v) > 1e-2)
angle = st.floats(-2 * math.pi, 2 * math.pi, allow_nan=False)


@settings(max_examples=200, deadline=None)
@given(unit_axis, angle, unit_axis, angle)
def test_the_product_of_two_turns_is_the_product_of_their_matrices(a1, t1, a2, t2):
    q1, q2 = quat_from_axis_angle(a1, t1), quat_from_axis_angle(a2, t2)
    assert np.allclose(matrix_of(quat_multiply(q1, q2)), matrix_of(q1) @ matrix_of(q2), atol=1e-9)
    assert np.allclose(quat_multiply(q1, quat_conjugate(q1)), (1, 0, 0, 0), atol=1e-12)


def test_exercise_2_10_keys_and_swapped_slip_match_numpy_over_many_draws():
    ex = bank.get("2.10")
    for seed in range(300):
        v = ex.variant(seed)
        p = tuple(float(v.values[n]) for n in ("w1", "x1", "y1", "z1"))
        q = tuple(float(v.values[n]) for n in ("w2", "x2", "y2", "z2"))
        key = [row[0] for row in v.answer.key]
        assert np.allclose(key, left_matrix(p) @ np.array(q))
        swapped = [row[0] for row in v.answer.slips[0].value]
        assert np.allclose(swapped, left_matrix(q) @ np.array(p))
