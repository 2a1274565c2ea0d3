"""Chapter 11 · The chapter's 3R arm (a base about z, a shoulder and an elbow about −y): its forward
kinematics as a product of exponentials (11.3, in checked steps from the right), and the same arm
from its standard DH table (11.4, in checked steps from the right, A₃ and then A₂ A₃).

>>> from workbook import bank
>>> bank.get("11.3").worked_text() == bank.get("11.4").worked_text()
True
>>> bank.get("11.3").worked_text()
'[0 0 1 0; 1 0 0 1; 0 1 0 3; 0 0 0 1]'
"""

from __future__ import annotations

import math

from ..answer_kinds.matrix import matrix
from ..kinds.derive import Derive
from ..number_format import bmatrix, fmt, relation_all
from ..reference.linalg import matmul
from ..reference.screw import arm_dh, arm_home, arm_screws, dh_modified, dh_standard, twist_exp
from ..reference.se3 import compose
from ..steps import Step
from ..variants import Choice, Param, Vary
from . import column
from .ch11_screws import clean, given_rows
from .checks import kept_slips

ARM_DEFAULTS = {"L0": 1, "L1": 2, "L2": 1, "t1": 90, "t2": 90, "t3": -90}
_ANGLES = (90, 30, 45, 60, 120, -30, -45, -60, -90)


def arm_params():
    """The arm's lengths and joint angles, as 11.3 and 11.4 draw them."""
    return (Param("L0", 1, 0.5, 2, 0.5), Param("L1", 2, 0.5, 2, 0.5), Param("L2", 1, 0.5, 2, 0.5),
            Choice("t1", 90, _ANGLES), Choice("t2", 90, _ANGLES), Choice("t3", -90, _ANGLES))


def _theta(p):
    return [math.radians(p[k]) for k in ("t1", "t2", "t3")]


def _arm_values(p):
    S = arm_screws(p["L0"], p["L1"])
    return {
        "L0": fmt(p["L0"]), "L1": fmt(p["L1"]), "L2": fmt(p["L2"]), "L12": fmt(p["L1"] + p["L2"]),
        "t1": fmt(p["t1"]), "t2": fmt(p["t2"]), "t3": fmt(p["t3"]),
        "S1": bmatrix(clean(column(S[0]))), "S2": bmatrix(clean(column(S[1]))), "S3": bmatrix(clean(column(S[2]))),
        "M": bmatrix(clean(arm_home(p["L0"], p["L1"], p["L2"]))),
        "same": ("exercise 11.3's arm, at the same angles" if dict(p) == ARM_DEFAULTS else "an arm built like "
                 "exercise 11.3's, with these numbers"),
    }


# ---- 11.3 Forward kinematics as a product of exponentials ------------------------------------------

def _poe(p, given=None):
    """11.3: T = e^{[S₁]θ₁} e^{[S₂]θ₂} e^{[S₃]θ₃} M, worked from the right (the learner's steps when given)."""
    S, th = arm_screws(p["L0"], p["L1"]), _theta(p)
    M = arm_home(p["L0"], p["L1"], p["L2"])
    e1, e2, e3 = (twist_exp(s, t) for s, t in zip(S, th))
    E3M_key = clean(matmul(e3, M))
    E3M = given_rows(given, "E3M", E3M_key)
    E23M_key = clean(matmul(e2, E3M))
    E23M = given_rows(given, "E23M", E23M_key)
    key = clean(matmul(e1, E23M))
    return {
        "key": key,
        "slips": kept_slips(key, (
            (clean(compose(e3, e2, e1, M)), "The exponentials are in reverse order: that is e^[S₃]θ₃ e^[S₂]θ₂ "
                                            "e^[S₁]θ₁ M. With space-frame screws the base's comes first, "
                                            "T = e^[S₁]θ₁ e^[S₂]θ₂ e^[S₃]θ₃ M.", "poe-reversed"),
            (clean(compose(M, e1, e2, e3)), "That puts M first, on the left, as the body-frame form M e^[B₁]θ₁ ⋯ "
                                            "does. These S are in the space frame: M goes last.", "m-on-the-left"),
            (clean(compose(e1, e2, e3)), "That leaves out M: the product of the exponentials moves the home "
                                         "pose M, so T = e^[S₁]θ₁ e^[S₂]θ₂ e^[S₃]θ₃ M.", "m-left-out"),
            (clean(E23M), "That is the last step, without the base's turn: multiply it by e^[S₁]θ₁ on the left.",
             "base-turn-left-out"),
        )),
        "steps": {
            "E3M": {"key": E3M_key, "slips": kept_slips(E3M_key, (
                (clean(matmul(M, e3)), "That is M e^[S₃]θ₃, the product the other way round. The exponential "
                                       "multiplies M on the left.", "e3-on-the-right"),
                (clean(matmul(twist_exp(S[2], -th[2]), M)), "That turns the elbow by −θ₃: e^[S₃]θ₃ with "
                                                             f"θ₃ = {fmt(p['t3'])}°.", "e3-minus-theta"),
                (clean(M), "That is M itself: the elbow's exponential still has to act on it.", "e3-not-applied"),
            ))},
            "E23M": {"key": E23M_key, "slips": kept_slips(E23M_key, (
                (clean(matmul(E3M, e2)), "That multiplies by e^[S₂]θ₂ on the right. Each exponential goes on the "
                                         "left of what you have: e^[S₂]θ₂ (e^[S₃]θ₃ M).", "e2-on-the-right"),
                (clean(matmul(e2, M)), "That is e^[S₂]θ₂ M, without the elbow's exponential from the step "
                                       "before.", "e3-dropped"),
            ))},
        },
        "values": {**_arm_values(p), "e1": bmatrix(clean(e1)), "e2": bmatrix(clean(e2)), "e3": bmatrix(clean(e3)),
                   "e1rel": relation_all(e1), "e2rel": relation_all(e2), "e3rel": relation_all(e3)},
    }


def _poe_ok(p):
    """No joint at zero (each exponential matters), and every slip told apart."""
    if 0 in (p["t1"], p["t2"], p["t3"]):
        return False
    made = _poe(p)
    return (len(made["slips"]) == 4 and len(made["steps"]["E3M"]["slips"]) == 3
            and len(made["steps"]["E23M"]["slips"]) == 2)


# ---- 11.4 The same arm from its DH table -------------------------------------------------------------

def _dh(p, given=None):
    """11.4: T = A₁ A₂ A₃, A_i = Rot_z(θ_i) Trans_z(d_i) Trans_x(a_i) Rot_x(α_i) (standard DH), worked from
    the right: A₃, then A₂ A₃ (the learner's when given)."""
    rows = arm_dh(p["L0"], p["L1"], p["L2"], _theta(p))
    A1, A2, A3 = (dh_standard(*r) for r in rows)
    A3_key = clean(A3)
    A3g = given_rows(given, "A3", A3_key)
    A23_key = clean(matmul(A2, A3g))
    A23 = given_rows(given, "A23", A23_key)
    key = clean(matmul(A1, A23))
    a, alpha, d, th = rows[0]
    return {
        "key": key,
        "slips": kept_slips(key, (
            (clean(matmul(A23, A1)), "That is A₂A₃ · A₁, the links in reverse order. Each link's transform "
                                     "is in the frame of the link before: T = A₁ (A₂ A₃).", "dh-reversed"),
            (clean(compose(*(dh_modified(*r) for r in rows))),
             "That reads the table as modified DH (Craig's Rot_x(α) Trans_x(a) Rot_z(θ) Trans_z(d)). The table is "
             "standard DH: Rot_z(θ) Trans_z(d) Trans_x(a) Rot_x(α).", "dh-read-as-modified"),
            (clean(matmul(dh_standard(a, -alpha, d, th), A23)),
             "That twists link 1 by α = −90°; the table's α₁ is +90° (it turns z₀ onto z₁ about x₁).",
             "a1-alpha-sign"),
        )),
        "steps": {
            "A3": {"key": A3_key, "slips": kept_slips(A3_key, (
                (clean(dh_modified(*rows[2])), "That is the modified order, Rot_x(α) Trans_x(a) Rot_z(θ) "
                                                "Trans_z(d). Standard DH turns about z first and moves along x "
                                                "after.", "a3-modified-order"),
                (clean(dh_standard(0.0, *rows[2][1:])), "That leaves out the link length a₃: Trans_x(a₃) puts the "
                                                         "frame at the link's far end.", "a3-no-length"),
            ))},
            "A23": {"key": A23_key, "slips": kept_slips(A23_key, (
                (clean(matmul(A3g, A2)), "That is A₃ A₂, the other order. Link 3 sits at the end of link 2: A₂ A₃.",
                 "a23-reversed"),
                (clean(A2), "That is A₂ alone: link 3 is still to add.", "a3-left-out"),
            ))},
        },
        "values": {**_arm_values(p), "A1": bmatrix(clean(A1)), "A2": bmatrix(clean(A2)),
                   "A1rel": relation_all(A1), "A2rel": relation_all(A2)},
    }


def _dh_ok(p):
    """No joint at zero, and every slip told apart."""
    if 0 in (p["t1"], p["t2"], p["t3"]):
        return False
    made = _dh(p)
    return (len(made["slips"]) == 3 and len(made["steps"]["A3"]["slips"]) == 2
            and len(made["steps"]["A23"]["slips"]) == 2)


EXERCISES = (
    Derive(
        id="11.3",
        title="Forward kinematics as a product of exponentials",
        spec=matrix(label="T = e^[S₁]θ₁ e^[S₂]θ₂ e^[S₃]θ₃ M, 4 × 4"),
        vary=Vary(_poe, *arm_params(), valid=_poe_ok),
        steps=(Step("E3M", "e^[S₃]θ₃ M", matrix(label="e^[S₃]θ₃ M, the elbow's turn applied to M")),
               Step("E23M", "e^[S₂]θ₂ e^[S₃]θ₃ M", matrix(label="e^[S₂]θ₂ e^[S₃]θ₃ M, then the shoulder's"))),
    ),
    Derive(
        id="11.4",
        title="The same arm in Denavit–Hartenberg parameters",
        spec=matrix(label="T = A₁ A₂ A₃, 4 × 4"),
        vary=Vary(_dh, *arm_params(), valid=_dh_ok),
        steps=(Step("A3", "A₃", matrix(label="A₃, link 3's transform")),
               Step("A23", "A₂ A₃", matrix(label="A₂ A₃, links 2 and 3 together"))),
    ),
)
