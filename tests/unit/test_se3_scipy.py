"""Chapter 10's reference (reference/se3.py) against SciPy's ``Rotation`` over random inputs,
q and −q, and turns near 180°. SciPy stores quaternions scalar last, (x, y, z, w); the
workbook writes them scalar first, so every quaternion crosses through ``to_xyzw``."""

from __future__ import annotations

import math
import random

import pytest

from workbook.reference.rotation3d import quat_multiply
from workbook.reference.se3 import (
    angle_between,
    compose,
    from_xyzw,
    invert,
    pose,
    quat_to_matrix,
    slerp,
    to_xyzw,
    transform_point,
)

np = pytest.importorskip("numpy")
transform = pytest.importorskip("scipy.spatial.transform")
Rotation, Slerp = transform.Rotation, transform.Slerp

DRAWS = 300


def _unit(rng):
    q = [rng.gauss(0, 1) for _ in range(4)]
    n = math.sqrt(sum(c * c for c in q))
    return tuple(c / n for c in q)


def _neg(q):
    return tuple(-c for c in q)


def _about(axis, angle):
    n = math.sqrt(sum(a * a for a in axis))
    s = math.sin(angle / 2) / n
    return (math.cos(angle / 2), s * axis[0], s * axis[1], s * axis[2])


def _rot(q):
    return Rotation.from_quat(to_xyzw(q))


def _quats(seed):
    """Random unit quaternions, each also negated, and turns within 1e-6 rad of 180° about random axes."""
    rng = random.Random(seed)
    out = []
    for _ in range(DRAWS):
        q = _unit(rng)
        out += [q, _neg(q)]
    for _ in range(20):
        axis = _unit(rng)[:3]
        out.append(_about(axis, math.pi - rng.uniform(0, 1e-6)))
    return out


def test_scalar_last_is_scipys_order():
    """SciPy's ``as_quat()`` is (x, y, z, w): ``from_xyzw`` reads it into (w, x, y, z) and ``to_xyzw`` back."""
    for q in _quats(1):
        back = from_xyzw(_rot(q).as_quat())
        assert np.allclose(back, q) or np.allclose(back, _neg(q))
        assert np.allclose(Rotation.from_quat(q, scalar_first=True).as_matrix(), _rot(q).as_matrix())


def test_quaternion_to_matrix_agrees_with_scipy_for_q_and_minus_q():
    for q in _quats(2):
        assert np.allclose(quat_to_matrix(q), _rot(q).as_matrix(), atol=1e-12)
        assert np.allclose(quat_to_matrix(_neg(q)), _rot(q).as_matrix(), atol=1e-12)


def test_product_is_scipys_composition():
    """p ⊗ q turns by q first, then p: SciPy's ``r_p * r_q``."""
    qs = _quats(3)
    for p, q in zip(qs, reversed(qs)):
        assert np.allclose(quat_to_matrix(quat_multiply(p, q)), (_rot(p) * _rot(q)).as_matrix(), atol=1e-12)


def test_angle_between_agrees_with_scipy_and_ignores_the_sign():
    qs = _quats(4)
    for q0, q1 in zip(qs, qs[7:] + qs[:7]):
        want = (_rot(q0).inv() * _rot(q1)).magnitude()
        assert angle_between(q0, q1) == pytest.approx(want, abs=1e-9)
        assert angle_between(q0, _neg(q1)) == pytest.approx(want, abs=1e-9)
        assert 0 <= angle_between(q0, q1) <= math.pi
        assert angle_between(q0, _neg(q0)) == pytest.approx(0, abs=1e-9)


def test_angle_near_a_half_turn():
    rng = random.Random(5)
    for _ in range(50):
        q0, axis = _unit(rng), _unit(rng)[:3]
        q1 = quat_multiply(q0, _about(axis, math.pi - 1e-7))
        assert angle_between(q0, q1) == pytest.approx(math.pi - 1e-7, abs=1e-9)
        assert angle_between(q0, q1) == pytest.approx((_rot(q0).inv() * _rot(q1)).magnitude(), abs=1e-9)


def test_slerp_agrees_with_scipy_the_short_way():
    """SciPy's Slerp turns the short way; ours must too, whichever sign q₁ arrives with. Pairs within 1°
    of a half turn are left out (both ways are then nearly as short, and either is right)."""
    rng = random.Random(6)
    checked = 0
    while checked < DRAWS:
        q0, q1 = _unit(rng), _unit(rng)
        if angle_between(q0, q1) > math.pi - math.radians(1):
            continue
        checked += 1
        path = Slerp([0, 1], Rotation.concatenate([_rot(q0), _rot(q1)]))
        for t in (0.0, 0.25, 0.5, rng.random(), 1.0):
            want = path([t]).as_matrix()[0]
            assert np.allclose(quat_to_matrix(slerp(q0, q1, t)), want, atol=1e-9)
            assert np.allclose(quat_to_matrix(slerp(q0, _neg(q1), t)), want, atol=1e-9)


def test_slerp_edge_cases():
    rng = random.Random(7)
    for _ in range(DRAWS):
        q0 = _unit(rng)
        assert np.allclose(slerp(q0, _neg(q0), rng.random()), q0)  # no turn at all
        q1 = quat_multiply(q0, _about(_unit(rng)[:3], 1e-8))
        mid = slerp(q0, q1, 0.5)
        assert all(math.isfinite(c) for c in mid)
        assert math.isclose(math.sqrt(sum(c * c for c in mid)), 1.0, abs_tol=1e-12)
        assert angle_between(q0, mid) == pytest.approx(0.5e-8, abs=1e-12)


def test_poses_agree_with_scipy():
    rng = random.Random(8)
    for _ in range(DRAWS):
        qa, qb = _unit(rng), _unit(rng)
        ta, tb, p = ([rng.uniform(-5, 5) for _ in range(3)] for _ in range(3))
        A, B = pose(quat_to_matrix(qa), ta), pose(quat_to_matrix(qb), tb)
        want = _rot(qa).apply(_rot(qb).apply(p) + tb) + ta
        assert np.allclose(transform_point(compose(A, B), p), want, atol=1e-9)
        back = _rot(qa).inv().apply(np.array(p) - ta)
        assert np.allclose(transform_point(invert(A), p), back, atol=1e-9)
        assert np.allclose(compose(A, invert(A)), np.eye(4), atol=1e-12)
