"""Chapter 13's reference (reference/alignment.py), its Derive keys and its Build against SciPy, used
only here as an oracle (it never ships in the site): ``Rotation.align_vectors`` for the best rotation,
``scipy.linalg.svd`` for the SVD route with the reflection fix, and ``cKDTree`` for ICP's nearest
neighbours, each over at least 300 random draws.

The plane sits in space as z = 0. ``align_vectors(a, b)`` finds the rotation C with a ≈ C b; the pair
(0, 0, 1) ↔ (0, 0, 1) with an infinite weight is aligned exactly, so C turns about z only and cannot
turn the plane over (in 3-D, a mirror image in the plane is a half turn about an axis in it).

``python tests/unit/test_ch13_oracle.py`` prints the draws and the largest differences, for a
closing note.
"""

from __future__ import annotations

import math
import random

import pytest

from oracle_draws import DRAWS, distinct_variants
from workbook import bank
from workbook.bank.ch13_code import _SOLUTION
from workbook.bank.ch13_points import point_sets
from workbook.bank.ch13_rotation import _svd_parts
from workbook.reference.alignment import align_2d, angle_from_h, centroid, cross_covariance, nearest, rot

np = pytest.importorskip("numpy")
transform = pytest.importorskip("scipy.spatial.transform")
linalg = pytest.importorskip("scipy.linalg")
spatial = pytest.importorskip("scipy.spatial")
Rotation = transform.Rotation

TOL = 1e-9


def _scipy_align(P, Q):
    """SciPy's best rotation (2 × 2, about z) and translation mapping P onto Q."""
    P, Q = np.asarray(P, float), np.asarray(Q, float)
    pm, qm = P.mean(axis=0), Q.mean(axis=0)
    a = np.vstack([[0.0, 0.0, 1.0], np.column_stack([Q - qm, np.zeros(len(Q))])])
    b = np.vstack([[0.0, 0.0, 1.0], np.column_stack([P - pm, np.zeros(len(P))])])
    C = Rotation.align_vectors(a, b, weights=[np.inf] + [1.0] * len(P))[0].as_matrix()
    R = C[:2, :2]
    return R, qm - R @ pm


def _scipy_svd_rotation(H):
    """R = V diag(1, det(V Uᵀ)) Uᵀ from SciPy's SVD of H."""
    U, _, Vt = linalg.svd(np.asarray(H, float))
    d = np.sign(np.linalg.det(Vt.T @ U.T))
    return Vt.T @ np.diag([1.0, d]) @ U.T


def _sets(rng, mirror=False):
    """3 to 9 points in a 10 m square, turned by any angle, moved, with noise of up to 0.3 m; or their
    mirror image (x → −x first), which no rotation maps exactly."""
    n = rng.randint(3, 9)
    P = [(rng.uniform(-5, 5), rng.uniform(-5, 5)) for _ in range(n)]
    R, t = rot(rng.uniform(-math.pi, math.pi)), (rng.uniform(-4, 4), rng.uniform(-4, 4))
    noise = rng.choice((0.0, 0.02, 0.3))
    Q = []
    for x, y in P:
        x = -x if mirror else x
        Q.append((R[0][0] * x + R[0][1] * y + t[0] + rng.gauss(0, noise),
                  R[1][0] * x + R[1][1] * y + t[1] + rng.gauss(0, noise)))
    return P, Q


def _gap(a, b) -> float:
    return float(np.max(np.abs(np.asarray(a, float) - np.asarray(b, float))))


def _solution():
    space: dict = {}
    exec(compile(_SOLUTION, "<align_2d solution>", "exec"), space)  # the page's worked solution
    return space["align_2d"]


def rotation_gaps(seed: int = 13) -> list[float]:
    """align_2d and the worked solution against SciPy, over noisy and mirrored draws: the largest gap of each."""
    rng = random.Random(seed)
    solution = _solution()
    gaps = []
    for k in range(DRAWS):
        P, Q = _sets(rng, mirror=k % 3 == 0)
        R, t = _scipy_align(P, Q)
        for mine in (align_2d(P, Q), solution(P, Q)):
            gaps.append(max(_gap(mine[0], R), _gap(mine[1], t)))
            assert np.linalg.det(np.asarray(mine[0])) == pytest.approx(1.0, abs=1e-12)
    return gaps


def svd_gaps(seed: int = 31) -> list[float]:
    """The angle atan2(H₁₂ − H₂₁, H₁₁ + H₂₂) against SciPy's SVD with the reflection fix, on random H."""
    rng = random.Random(seed)
    gaps = []
    for _ in range(DRAWS):
        H = [[rng.uniform(-9, 9) for _ in range(2)] for _ in range(2)]
        gaps.append(_gap(rot(angle_from_h(H)), _scipy_svd_rotation(H)))
    return gaps


def nearest_mismatches(seed: int = 7) -> tuple[int, int]:
    """nearest() against cKDTree.query: how many draws disagree, out of how many."""
    rng = random.Random(seed)
    wrong = 0
    for _ in range(DRAWS):
        S = [(rng.uniform(0, 10), rng.uniform(0, 10)) for _ in range(rng.randint(1, 8))]
        M = [(rng.uniform(0, 10), rng.uniform(0, 10)) for _ in range(rng.randint(1, 12))]
        _, index = spatial.cKDTree(np.asarray(M)).query(np.asarray(S))
        wrong += nearest(S, M) != [int(i) + 1 for i in np.atleast_1d(index)]
    return wrong, DRAWS


def key_gaps() -> dict[str, tuple[int, float]]:
    """Each Derive key of the chapter against SciPy, over its distinct variants: (draws, largest gap)."""
    out: dict[str, tuple[int, float]] = {}
    gaps = []
    for v in distinct_variants("13.2"):
        P, Q = point_sets(v.params)
        Pc = np.asarray(P, float) - np.mean(P, axis=0)
        Qc = np.asarray(Q, float) - np.mean(Q, axis=0)
        gaps.append(_gap(v.answer.key, Pc.T @ Qc))
    out["13.2"] = (len(gaps), max(gaps))
    gaps = []
    for v in distinct_variants("13.3"):
        H = [[v.params["h11"], v.params["h12"]], [v.params["h21"], v.params["h22"]]]
        R = _scipy_svd_rotation(H)
        gaps.append(abs(math.remainder(v.answer.key - math.degrees(math.atan2(R[1, 0], R[0, 0])), 360)))
    out["13.3"] = (len(gaps), max(gaps))
    gaps = []
    for v in distinct_variants("13.4"):
        H = _svd_parts(v.params)[2]  # SciPy's own SVD of the printed H, not the bank's factors
        gaps.append(_gap(v.answer.key, _scipy_svd_rotation(H)))
    out["13.4"] = (len(gaps), max(gaps))
    gaps = []
    for v in distinct_variants("13.5"):
        p = v.params
        C = Rotation.from_euler("z", p["theta"], degrees=True).as_matrix()[:2, :2]
        t = np.asarray([p["qmx"], p["qmy"]], float) - C @ np.asarray([p["pmx"], p["pmy"]], float)
        gaps.append(_gap([r[0] for r in v.answer.key], t))
    out["13.5"] = (len(gaps), max(gaps))
    wrong = 0
    draws = distinct_variants("13.6")
    for v in draws:
        p = v.params
        S = np.asarray([[p[f"s{i}x"], p[f"s{i}y"]] for i in (1, 2, 3)], float)
        M = np.asarray([[p[f"m{i}x"], p[f"m{i}y"]] for i in (1, 2, 3, 4)], float)
        _, index = spatial.cKDTree(M).query(S)
        wrong += [r[0] for r in v.answer.key] != [float(i) + 1 for i in index]
    out["13.6"] = (len(draws), float(wrong))
    return out


def build_gaps() -> tuple[int, float]:
    """13.9's reference on its visible and hidden cases (the review seeds 0-9) against SciPy."""
    ex = bank.get("13.9")
    gaps = []
    for seed in range(10):
        for args in ex.variant(seed).arguments():
            P, Q = args
            if cross_covariance(P, Q) == [[0.0, 0.0], [0.0, 0.0]]:
                mine = align_2d(P, Q)  # every turn fits: the statement's identity and q̄ − p̄
                want = (np.eye(2), np.asarray(centroid(Q)) - np.asarray(centroid(P)))
            else:
                mine, want = align_2d(P, Q), _scipy_align(P, Q)
            gaps.append(max(_gap(mine[0], want[0]), _gap(mine[1], want[1])))
    return len(gaps), max(gaps)


def test_align_2d_and_the_worked_solution_agree_with_scipy_noisy_and_mirrored():
    gaps = rotation_gaps()
    assert len(gaps) == 2 * DRAWS and max(gaps) < TOL, max(gaps)


def test_the_atan2_angle_is_the_svd_rotation_with_the_reflection_fix():
    assert max(svd_gaps()) < TOL


def test_nearest_neighbours_agree_with_ckdtree():
    assert nearest_mismatches() == (0, DRAWS)


def test_every_derive_key_of_the_chapter_agrees_with_scipy():
    for ex_id, (draws, gap) in key_gaps().items():
        assert draws >= min(DRAWS, 60), (ex_id, draws)
        assert gap == 0 if ex_id == "13.6" else gap < 1e-6, (ex_id, gap)  # 13.6: pairings that differ


def test_the_build_reference_agrees_with_scipy_on_every_case():
    count, gap = build_gaps()
    assert count >= 10 * 20 and gap < TOL, (count, gap)


if __name__ == "__main__":
    print(f"align_2d and the solution: {2 * DRAWS} fits, largest gap {max(rotation_gaps()):.2e}")
    print(f"atan2 angle vs SVD with the fix: {DRAWS} matrices H, largest gap {max(svd_gaps()):.2e}")
    print("nearest vs cKDTree: %d of %d draws disagree" % nearest_mismatches())
    for ex_id, (draws, gap) in key_gaps().items():
        print(f"{ex_id}: {draws} distinct draws, largest gap {gap:.2e}" + (" (mismatches)" if ex_id == "13.6" else ""))
    print("13.9 cases: %d, largest gap %.2e" % build_gaps())
