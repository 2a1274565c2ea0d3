"""Chapter 11's reference (reference/screw.py), every Derive key and step, and the Build against
``modern_robotics`` (MatrixExp6, FKinSpace, JacobianSpace, ScrewToAxis, Adjoint) and ``spatialmath``,
used only here as oracles (they never ship in the site), each over at least 300 draws.

spatialmath 1.1.18 has no DH class (its robots live in roboticstoolbox, not installed), so the DH link
transforms are built from spatialmath.base's elementary transforms (``trotz``, ``transl``, ``trotx``):
a second implementation written apart from the reference; and the DH arm is checked against
modern_robotics' product of exponentials of the same arm.

``python tests/unit/test_ch11_oracle.py`` prints the draws and the largest differences, for a
closing note.
"""

from __future__ import annotations

import math
import random

import pytest

from oracle_draws import DRAWS, distinct_variants
from workbook import bank
from workbook.bank.ch11_code import _SOLUTION
from workbook.bank.ch11_screws import AXES
from workbook.reference.screw import (
    adjoint,
    arm_dh,
    arm_home,
    arm_screws,
    dh_modified,
    dh_standard,
    fk_dh,
    fk_poe,
    g_matrix,
    jacobian_space,
    revolute_screw,
    twist_exp,
)

np = pytest.importorskip("numpy")
mr = pytest.importorskip("modern_robotics")
smb = pytest.importorskip("spatialmath.base")

TOL = 1e-9


def _gap(a, b) -> float:
    return float(np.max(np.abs(np.asarray(a, float) - np.asarray(b, float))))


def _unit(rng):
    v = np.array([rng.gauss(0, 1) for _ in range(3)])
    return v / np.linalg.norm(v)


def _screw(rng):
    """A revolute screw about any unit axis through any point (a third with a pitch), or a slide."""
    if rng.random() < 0.25:
        return (0.0, 0.0, 0.0, *_unit(rng))
    q, w = [rng.uniform(-2, 2) for _ in range(3)], _unit(rng)
    h = rng.choice((0.0, 0.0, rng.uniform(-0.3, 0.3)))
    return tuple(mr.ScrewToAxis(np.array(q), w, h))


def _mr_exp(S, th):
    return mr.MatrixExp6(mr.VecTose3(np.asarray(S, float) * th))


def _mr_fk(M, S_list, theta):
    return mr.FKinSpace(np.asarray(M, float), np.asarray(S_list, float).T, np.asarray(theta, float))


def _sm_dh(a, alpha, d, theta, modified=False):
    """A DH link from spatialmath.base's elementary transforms."""
    if modified:
        return smb.trotx(alpha) @ smb.transl(a, 0, 0) @ smb.trotz(theta) @ smb.transl(0, 0, d)
    return smb.trotz(theta) @ smb.transl(0, 0, d) @ smb.transl(a, 0, 0) @ smb.trotx(alpha)


def _arm_draw(rng):
    n = rng.randint(1, 6)
    S_list = [_screw(rng) for _ in range(n)]
    theta = [rng.uniform(-2 * math.pi, 2 * math.pi) for _ in range(n)]
    M = _mr_exp(_screw(rng), rng.uniform(-3, 3)) @ mr.RpToTrans(np.eye(3), np.array([rng.uniform(-1, 1) for _ in range(3)]))
    return M.tolist(), S_list, theta


def _solution():
    space: dict = {}
    exec(compile(_SOLUTION, "<fk_poe solution>", "exec"), space)  # the page's worked solution
    return space["fk_poe"]


def reference_gaps(seed: int = 11) -> dict[str, tuple[int, float]]:
    """The reference's exponential, G(θ), product, Jacobian, adjoint and DH links against the oracles."""
    rng = random.Random(seed)
    solution = _solution()
    out: dict[str, list[float]] = {k: [] for k in ("exp", "G", "fk", "solution", "jacobian", "adjoint", "dh", "dh-arm")}
    for _ in range(DRAWS):
        S, th = _screw(rng), rng.uniform(-2 * math.pi, 2 * math.pi)
        out["exp"].append(_gap(twist_exp(S, th), _mr_exp(S, th)))
        w = np.asarray(S[:3])
        ts = np.linspace(0.0, th, 2001)  # G(θ) = ∫₀^θ e^[ω]t dt, by Simpson's rule on MatrixExp3
        vals = np.array([mr.MatrixExp3(mr.VecToso3(w * t)) for t in ts])
        h = th / 2000
        G = h / 3 * (vals[0] + vals[-1] + 4 * vals[1:-1:2].sum(axis=0) + 2 * vals[2:-1:2].sum(axis=0))
        out["G"].append(_gap(g_matrix(S[:3], th), G))
        M, S_list, theta = _arm_draw(rng)
        want = _mr_fk(M, S_list, theta)
        out["fk"].append(_gap(fk_poe(M, S_list, theta), want))
        out["solution"].append(_gap(solution(M, S_list, theta), want))
        out["jacobian"].append(_gap(np.asarray(jacobian_space(S_list, theta)).T,
                                    mr.JacobianSpace(np.asarray(S_list, float).T, np.asarray(theta, float))))
        out["adjoint"].append(_gap(adjoint(M), mr.Adjoint(np.asarray(M))))
        row = (rng.uniform(-2, 2), rng.uniform(-math.pi, math.pi), rng.uniform(-2, 2), rng.uniform(-4, 4))
        out["dh"].append(max(_gap(dh_standard(*row), _sm_dh(*row)), _gap(dh_modified(*row), _sm_dh(*row, modified=True))))
        L = [rng.uniform(0.2, 2) for _ in range(3)]
        th3 = [rng.uniform(-math.pi, math.pi) for _ in range(3)]
        sm_arm = np.linalg.multi_dot([_sm_dh(*r) for r in arm_dh(*L, th3)])
        out["dh-arm"].append(max(_gap(fk_dh(arm_dh(*L, th3)), sm_arm),
                                 _gap(sm_arm, _mr_fk(arm_home(*L), arm_screws(L[0], L[1]), th3))))
    return {k: (len(v), max(v)) for k, v in out.items()}


def _rad(p, *names):
    return [math.radians(p[n]) for n in names]


def _arm(p):
    M = np.asarray(arm_home(p["L0"], p["L1"], p["L2"]), float)
    return M, [np.asarray(S, float) for S in arm_screws(p["L0"], p["L1"])], _rad(p, "t1", "t2", "t3")


def key_gaps() -> dict[str, tuple[int, float]]:
    """Every Derive key and step of the chapter against the oracles, over its distinct variants."""
    gaps: dict[str, list[float]] = {}

    def add(name, got, want):
        gaps.setdefault(name, []).append(_gap(got, want))

    for v in distinct_variants("11.1"):
        p = v.params
        add("11.1", v.answer.key, np.asarray(mr.ScrewToAxis(np.array([p["qx"], p["qy"], p["qz"]], float),
                                                            np.array(AXES[p["axis"]], float), 0))[:, None])
    for v in distinct_variants("11.2"):
        p = v.params
        S = mr.ScrewToAxis(np.array([p["qx"], p["qy"], p["qz"]], float), np.array(AXES[p["axis"]], float), 0)
        T = _mr_exp(S, math.radians(p["theta"]))
        add("11.2", v.answer.key, T)
        add("11.2 step p", v.step_answers["p"].key, T[:3, 3:])
        q = np.array([p["qx"], p["qy"], p["qz"]], float)  # G(θ) v = (I − R) q, and G's columns from MR's
        add("11.2 step G", np.asarray(v.step_answers["G"].key) @ S[3:], (np.eye(3) - T[:3, :3]) @ q)
    for v in distinct_variants("11.3"):
        M, S, th = _arm(v.params)
        add("11.3", v.answer.key, mr.FKinSpace(M, np.array(S).T, th))
        E3M = _mr_exp(S[2], th[2]) @ M
        add("11.3 step E3M", v.step_answers["E3M"].key, E3M)
        add("11.3 step E23M", v.step_answers["E23M"].key, _mr_exp(S[1], th[1]) @ E3M)
    for v in distinct_variants("11.4"):
        p = v.params
        rows = arm_dh(p["L0"], p["L1"], p["L2"], _rad(p, "t1", "t2", "t3"))
        A = [_sm_dh(*r) for r in rows]
        add("11.4", v.answer.key, A[0] @ A[1] @ A[2])
        add("11.4 step A3", v.step_answers["A3"].key, A[2])
        add("11.4 step A23", v.step_answers["A23"].key, A[1] @ A[2])
    for v in distinct_variants("11.6"):
        M, S, th = _arm(v.params)
        J = mr.JacobianSpace(np.array(S).T, th)
        add("11.6", v.answer.key, J)
        add("11.6 step E12", v.step_answers["E12"].key, _mr_exp(S[0], th[0]) @ _mr_exp(S[1], th[1]))
        add("11.6 step J3", v.step_answers["J3"].key, J[:, 2:])
    return {k: (len(v), max(v)) for k, v in gaps.items()}


def build_gaps() -> tuple[int, float]:
    """11.8's reference on its visible and hidden cases (the review seeds 0-9) against FKinSpace."""
    ex = bank.get("11.8")
    gaps = [_gap(fk_poe(*args), _mr_fk(*args)) for seed in range(10) for args in ex.variant(seed).arguments()]
    return len(gaps), max(gaps)


def test_the_reference_agrees_with_modern_robotics_and_spatialmath():
    for name, (draws, gap) in reference_gaps().items():
        assert draws == DRAWS and gap < (1e-7 if name == "G" else TOL), (name, gap)


def test_every_derive_key_and_step_agrees_with_the_oracles():
    found = key_gaps()
    assert {name.split()[0] for name in found} == {"11.1", "11.2", "11.3", "11.4", "11.6"}
    for name, (draws, gap) in found.items():
        assert draws >= 60, (name, draws)
        assert gap < 1e-9, (name, gap)


def test_the_build_reference_agrees_with_fkinspace_on_every_case():
    count, gap = build_gaps()
    assert count >= 10 * 20 and gap < TOL, (count, gap)


def test_the_two_dh_conventions_differ_for_the_same_numbers():
    # the premise of 11.4's and 11.5's slips: the modified product is another matrix
    assert _gap(dh_standard(1.0, 0.5, 0.3, 0.7), dh_modified(1.0, 0.5, 0.3, 0.7)) > 0.1
    assert revolute_screw((0, 0, 1), (1, 0, 0))[3:] == (0.0, -1.0, 0.0)


if __name__ == "__main__":
    for name, (draws, gap) in reference_gaps().items():
        print(f"reference {name}: {draws} draws, largest gap {gap:.2e}")
    for name, (draws, gap) in key_gaps().items():
        print(f"{name}: {draws} distinct draws, largest gap {gap:.2e}")
    print("11.8 cases: %d, largest gap %.2e" % build_gaps())
