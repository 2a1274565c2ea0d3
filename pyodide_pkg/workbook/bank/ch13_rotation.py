"""Chapter 13 · Aligning point sets: the best rotation's angle from H (13.3), the rotation from H's
SVD with the reflection fix (13.4), and the translation from the centroids (13.5), which carries the
learner's own angle from 13.3.

The convention: R maps P onto Q (qᵢ ≈ R pᵢ + t), H = Σ p′ q′ᵀ, θ = atan2(H₁₂ − H₂₁, H₁₁ + H₂₂).

>>> from workbook import bank
>>> bank.get("13.3").worked_text(), bank.get("13.5").values["theta"]
('53.1301°', '53.13')
>>> bank.get("13.4").worked_text()
'[0.936 -0.352; 0.352 0.936]'
"""

from __future__ import annotations

import math

from .. import chains
from ..answer_kinds.matrix import matrix
from ..answer_kinds.number import number
from ..chains import Uses
from ..kinds.derive import Derive
from ..number_format import bmatrix, fmt, paren, relation_all, shown
from ..reference.alignment import det2, rot, rotation_from_svd
from ..steps import Step
from ..variants import Choice, Param, Vary
from . import column, grid
from .checks import apart, kept_slips


def _deg(x: float) -> float:
    return math.degrees(x)


# ---- 13.3 The angle from H ---------------------------------------------------------------------

_H_DEFAULT = (6, 3, -13, 6)  # 13.2's H for its own numbers
_H_NAMES = ("h11", "h12", "h21", "h22")


def _h_of(p):
    return [[float(p["h11"]), float(p["h12"])], [float(p["h21"]), float(p["h22"])]]


def _angle(p):
    """13.3: θ = atan2(H₁₂ − H₂₁, H₁₁ + H₂₂)."""
    H = _h_of(p)
    s_key, c_key = H[0][1] - H[1][0], H[0][0] + H[1][1]
    s, c = s_key, c_key
    key = _deg(math.atan2(s, c))
    return {
        "key": key,
        "slips": kept_slips(key, (
            (-key, "That is atan2(H₂₁ − H₁₂, H₁₁ + H₂₂), from H transposed: the turn that takes Q back onto P. "
                   "Here R maps P onto Q, so θ = atan2(H₁₂ − H₂₁, H₁₁ + H₂₂).", "h-transposed-angle"),
            (_deg(math.atan(s / c)) if c else None,
             "That is arctan(s/c), which cannot tell the quadrants apart: H₁₁ + H₂₂ is negative here, so the "
             "turn is more than 90° either way. Use atan2(s, c).", "arctan-s-c-which"),
            (_deg(math.atan2(c, s)), "That swaps atan2's arguments: the sine part, H₁₂ − H₂₁, comes first, "
                                     "then the cosine part, H₁₁ + H₂₂.", "swaps-atan-s-arguments"),
        ), turn=360),
        "values": {"h21p": paren(H[1][0]), "h22p": paren(H[1][1]), "sv": fmt(s), "cv": fmt(c),
                   "from132": ("the H of exercise 13.2's scans" if tuple(p[n] for n in _H_NAMES) == _H_DEFAULT
                               else "the H of two other scans")},
    }


def _angle_ok(p):
    """A turn of at least 10° either way, and every slip of the answer and the steps told apart."""
    if p["h12"] - p["h21"] == 0 and p["h11"] + p["h22"] == 0:
        return False
    made = _angle(p)
    return abs(made["key"]) >= 10 and len(made["slips"]) >= 2


# ---- 13.4 The rotation from the SVD, with the reflection fix -----------------------------------

# First columns (c, s) of U and V: turns of Pythagorean triangles with exact decimal sides (3-4-5,
# 7-24-25, 44-117-125, 336-527-625): c any of 16 values, s = ±√(1 − c²) by its sign, 32 directions
# each, so that two students of a class rarely get the same R (variant 0: U from 3-4-5, V from 7-24-25).
_PARTNER = {a: b for x, y in ((0.6, 0.8), (0.28, 0.96), (0.352, 0.936), (0.5376, 0.8432)) for a, b in ((x, y), (y, x))}
_COSINES = tuple(sign * c for c in _PARTNER for sign in (1, -1))


def _column(p, name: str) -> tuple[float, float]:
    c = p[f"{name}c"]
    return c, p[f"{name}s_sign"] * _PARTNER[abs(c)]


def _orthogonal(c: float, s: float, det: int):
    """The 2 × 2 orthogonal matrix with first column (c, s) and determinant ``det``."""
    return [[c, -s], [s, c]] if det > 0 else [[c, s], [s, -c]]


def _svd_parts(p):
    U = _orthogonal(*_column(p, "u"), p["du"])
    V = _orthogonal(*_column(p, "v"), p["dv"])
    S = [[float(p["s1"]), 0.0], [0.0, float(p["s2"])]]
    Vt = [[V[j][i] for j in range(2)] for i in range(2)]
    US = [[U[i][k] * S[k][k] for k in range(2)] for i in range(2)]
    H = [[sum(US[i][k] * Vt[k][j] for k in range(2)) for j in range(2)] for i in range(2)]
    return U, V, H


def _mul(A, B):
    return [[sum(A[i][k] * B[k][j] for k in range(2)) for j in range(2)] for i in range(2)]


def _t(A):
    return [[A[j][i] for j in range(2)] for i in range(2)]


def _svd(p, given=None):
    """13.4: R = V diag(1, d) Uᵀ with d = det(V Uᵀ) (the learner's own d when given)."""
    U, V, H = _svd_parts(p)
    d_key = det2(V) * det2(U)
    d = chains.given(given, "d", d_key)
    Vd_key = grid(_mul(V, [[1.0, 0.0], [0.0, d]]))
    Vd = [list(r) for r in chains.given(given, "Vd", Vd_key)]
    key = _mul(Vd, _t(U))
    reflection = _mul(V, _t(U))
    return {
        "key": grid(key),
        "rotation_angle": math.atan2(key[1][0], key[0][0]),
        "slips": kept_slips(grid(key), (
            (grid(reflection), "That is V Uᵀ with the reflection left in (in the plane a reflection is "
                               "symmetric, so U Vᵀ is the same matrix): its determinant is −1, a mirror image, not a "
                               "turn. Put d = det(V Uᵀ) = −1 in R = V diag(1, d) Uᵀ.", "reflection-left-in"),
            (grid(_mul(_mul(U, [[1.0, 0.0], [0.0, d]]), _t(V))),
             "That is U diag(1, d) Vᵀ, the transpose of R: the rotation that maps Q back onto P. With "
             "H = Σ p′ q′ᵀ = U S Vᵀ, the rotation from P onto Q is V diag(1, d) Uᵀ.", "u-and-v-swapped"),
        )),
        "steps": {
            "d": {"key": d_key, "slips": kept_slips(d_key, (
                (-d_key, "det(V Uᵀ) = det V · det U, and one of the two is a reflection here (its determinant is "
                         "−1), so V Uᵀ is a reflection: d = −1.", "d-sign-wrong"),
            ))},
            "Vd": {"key": Vd_key, "slips": kept_slips(Vd_key, (
                (grid(_mul([[1.0, 0.0], [0.0, d]], V)), "That multiplies V's second row by d. diag(1, d) on the "
                                                          "right of V scales V's second column.",
                                                           "d-on-the-wrong-side"),
                (grid(V), "That is V itself: its second column is still to be multiplied by d.", "v-without-d"),
            ))},
        },
        "values": {"U": bmatrix(U), "V": bmatrix(V), "H": bmatrix(H), "hrel": relation_all(H),
                   "dU": fmt(det2(U)), "dV": fmt(det2(V)), "VUt": bmatrix(reflection),
                   "ang": fmt(_deg(math.atan2(key[1][0], key[0][0])))},
    }


def _svd_ok(p):
    """U and V orthogonal (unit first columns by construction), one of them a reflection, s₁ > s₂, the slips told apart,
    and the key the reference's."""
    if p["du"] * p["dv"] != -1:
        return False
    made = _svd(p)
    U, V, _ = _svd_parts(p)
    by_reference = rotation_from_svd(U, V)
    return (p["s1"] > p["s2"] and len(made["slips"]) == 2 and len(made["steps"]["Vd"]["slips"]) == 2
            and 0.1 < abs(made["rotation_angle"]) < math.pi - 0.1
            and not apart(grid(by_reference), made["key"], rel=1e-9))


# ---- 13.5 The translation from the centroids, with the learner's θ -------------------------------

_THETA = 53.13  # 13.3's answer for its own numbers, as printed
_T_DEFAULTS = {"pmx": 1, "pmy": 2, "qmx": 3, "qmy": 3, "theta": _THETA}  # 13.2's centroids


def _carries_133(p):
    """13.3's variant whose printed θ this draw carries: the workbook's own numbers carry variant 0's."""
    return 0 if dict(p) == _T_DEFAULTS else None


def _translation(p, given=None):
    """13.5: t = q̄ − R(θ) p̄, with θ as 13.3 prints it (or the learner's own) and the learner's R p̄."""
    pm, qm = (float(p["pmx"]), float(p["pmy"])), (float(p["qmx"]), float(p["qmy"]))
    theta = chains.given(given, "theta", float(p["theta"]))
    R_key = grid(rot(math.radians(theta)))
    R = [list(r) for r in chains.given(given, "R", R_key)]
    Rp_key = (R[0][0] * pm[0] + R[0][1] * pm[1], R[1][0] * pm[0] + R[1][1] * pm[1])
    Rp = [r[0] for r in chains.given(given, "Rp", column(Rp_key))]
    key = (qm[0] - Rp[0], qm[1] - Rp[1])
    Rt_p = (R[0][0] * pm[0] + R[1][0] * pm[1], R[0][1] * pm[0] + R[1][1] * pm[1])
    Rt_q = (R[0][0] * qm[0] + R[1][0] * qm[1], R[0][1] * qm[0] + R[1][1] * qm[1])
    return {
        "key": column(key),
        "slips": kept_slips(column(key), (
            (column((qm[0] - pm[0], qm[1] - pm[1])),
             "That is q̄ − p̄, the centroids subtracted with no turn: the translation must undo where the "
             "rotation moves p̄, so t = q̄ − R p̄.", "centroids-subtracted-unturned"),
            (column((qm[0] - Rt_p[0], qm[1] - Rt_p[1])),
             "That turns p̄ by Rᵀ, the turn of −θ. R maps P onto Q: t = q̄ − R(θ) p̄.", "turned-by-transpose"),
            (column((pm[0] - Rt_q[0], pm[1] - Rt_q[1])),
             "That is p̄ − Rᵀ q̄, the translation of the inverse map (from Q back onto P). This exercise's R and "
             "t map P onto Q.", "inverse-map-translation"),
            (column((-key[0], -key[1])), "The sign is turned round: t = q̄ − R p̄, Q's centroid minus P's turned one.",
             "sign-turned-round-t"),
        )),
        "steps": {
            "R": {"key": R_key, "slips": kept_slips(R_key, (
                (grid(_t(R_key)), "That is R(−θ), the transpose: the minus sign belongs in the first row, "
                                  "R(θ) = [cos θ, −sin θ; sin θ, cos θ].", "r-transposed"),
                (grid(rot(theta)), f"Those are the cosine and sine of {fmt(theta)} radians. θ is in degrees.",
                 "radians-not-degrees"),
            ))},
            "Rp": {"key": column(Rp_key), "slips": kept_slips(column(Rp_key), (
                (column(Rt_p), "That turns p̄ by −θ (Rᵀ in place of R). R(θ) = [cos θ, −sin θ; sin θ, cos θ].",
                 "rp-turned-by-transpose"),
                (column(pm), "That is p̄ itself. Turn it by R(θ) first.", "p-bar-unturned"),
            ))},
        },
        "values": {
            "Rrel": relation_all(R_key),
            "Rprel": relation_all(Rp_key, [sum(shown(R_key[i][k]) * pm[k] for k in range(2)) for i in range(2)]),
            "pmcol": bmatrix(column(pm)),
            "qmcol": bmatrix(column(qm)),
            "from133": ("the angle of exercise 13.3, whose H came from exercise 13.2's scans, with these centroids"
                        if dict(p) == _T_DEFAULTS else "the best angle for two scans with these centroids"),
        },
    }


def _translation_ok(p):
    """Centroids apart, and every slip told apart."""
    if (p["pmx"], p["pmy"]) == (p["qmx"], p["qmy"]) or (p["pmx"], p["pmy"]) == (0, 0):
        return False
    made = _translation(p)
    return (len(made["slips"]) == 4 and len(made["steps"]["Rp"]["slips"]) == 2
            and len(made["steps"]["R"]["slips"]) == 2)


EXERCISES = (
    Derive(
        id="13.3",
        title="The best rotation's angle, from H",
        spec=number(label="θ", unit="°", angle="deg"),
        vary=Vary(_angle, *(Param(n, v, -9, 9, 1) for n, v in zip(_H_NAMES, _H_DEFAULT)), valid=_angle_ok),
    ),
    Derive(
        id="13.4",
        title="The rotation from the SVD, without the mirror",
        same_answer=("R is built from exact turns of Pythagorean triangles (32 directions for U and for V), a "
                     "short list of rotations that the grader's tolerance cannot tell apart closely: about 2 % of "
                     "pairs of students share one."),
        spec=matrix(label="R"),
        vary=Vary(_svd, Choice("uc", 0.6, _COSINES), Choice("us_sign", 1, (1, -1)), Choice("du", 1, (1, -1)),
                  Choice("vc", 0.28, _COSINES), Choice("vs_sign", 1, (1, -1)), Choice("dv", -1, (1, -1)),
                  Param("s1", 5, 2, 9, 1), Param("s2", 2, 1, 4, 1), valid=_svd_ok),
        steps=(Step("d", "d = det(V Uᵀ)", number(label="d = det(V Uᵀ)")),
               Step("Vd", "V diag(1, d)", matrix(label="V diag(1, d), V with its second column times d"))),
    ),
    Derive(
        id="13.5",
        title="The translation from the centroids",
        spec=matrix(label="t = (tₓ, tᵧ)ᵀ", names=("x", "y")),
        vary=Vary(_translation, Param("pmx", 1, -3, 5, 1), Param("pmy", 2, -3, 5, 1), Param("qmx", 3, -3, 5, 1),
                  Param("qmy", 3, -3, 5, 1),
                  Choice("theta", _THETA, (_THETA, 30, 45, 60, 90, 120, 135, 150, -30, -45, -60, -90, -120, -150)),
                  valid=_translation_ok),
        uses=(Uses("13.3", "theta", "θ", variant=_carries_133),),
        steps=(Step("R", "R(θ)", matrix(label="R(θ)")),
               Step("Rp", "R p̄", matrix(label="R p̄, P's centroid turned", names=("x", "y")))),
    ),
)
