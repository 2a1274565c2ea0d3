"""Chapter 11 · Arm kinematics in 3-D: the screw axis of a revolute joint (11.1) and the exponential of
its twist (11.2, in checked steps: G(θ), then the shift G(θ) v), which carries the learner's own S
from 11.1.

>>> from workbook import bank
>>> bank.get("11.1").worked_text()
'[0; 0; 1; 1; -2; 0]'
>>> bank.get("11.2").worked_text()
'[0 -1 0 3; 1 0 0 -1; 0 0 1 0; 0 0 0 1]'
"""

from __future__ import annotations

import math

from .. import chains
from ..answer_kinds.matrix import matrix
from ..chains import Uses
from ..kinds.derive import Derive
from ..number_format import bmatrix, fmt, relation, relation_all, shown
from ..reference.linalg import matmul, matvec
from ..reference.screw import cross, g_matrix, revolute_screw, rotation_exp, skew, terms
from ..reference.se3 import pose
from ..steps import Step
from ..tolerance import agrees
from ..tolerance import clean as clean_float
from ..variants import Choice, Param, Vary
from . import column, grid
from .checks import kept_slips

AXES = {"x": (1, 0, 0), "-x": (-1, 0, 0), "y": (0, 1, 0), "-y": (0, -1, 0), "z": (0, 0, 1), "-z": (0, 0, -1)}
_AXIS_TEX = {"x": "x", "-x": "-x", "y": "y", "-y": "-y", "z": "z", "-z": "-z"}


def clean(rows):
    """A matrix (rows) with rounding noise taken off: entries within 1e-12 of a whole number are that number."""
    return grid([[float(round(v)) + 0.0 if abs(v - round(v)) < 1e-12 else round(v, 15) + 0.0 for v in row]
                 for row in rows])


def given_rows(given, name, key):
    """What make() carries for a step or an earlier answer: the learner's rows when given, but the key
    itself when every entry of theirs agrees with it (as the grader accepted it), so that a product of
    printed, rounded steps does not carry their rounding into the next step's key."""
    value = chains.given(given, name, key)
    if value is key:
        return [list(r) for r in key]
    rows = [list(r) for r in value]
    if len(rows) == len(key) and all(len(r) == len(k) and all(agrees(a, clean_float(b)) for a, b in zip(r, k))
                                     for r, k in zip(rows, key)):
        return [list(r) for r in key]
    return rows


def flat(col):
    """A column (one-entry rows) as a flat list."""
    return [float(r[0]) for r in col]


def _axis(p):
    return AXES[p["axis"]]


def _q(p):
    return (p["qx"], p["qy"], p["qz"])


# ---- 11.1 The screw axis of a revolute joint ------------------------------------------------------

_S_DEFAULTS = {"axis": "z", "qx": 2, "qy": 1, "qz": 0}


def _screw(p):
    """11.1: S = (ω, v) with v = −ω × q."""
    w, q = _axis(p), _q(p)
    S = revolute_screw(w, q)
    wq = cross(w, q)
    key = clean(column(S))
    return {
        "key": key,
        "slips": kept_slips(key, (
            (clean(column(tuple(w) + wq)), "That is ω × q, the sign turned round: v = −ω × q (or q × ω), the "
                                           "velocity the turn gives a point at the origin.", "v-sign-turned"),
            (clean(column(S[3:] + S[:3])), "That lists v first. This chapter writes S = (ω, v), the turn on top, "
                                           "as Lynch and Park do (some libraries store (v, ω)).", "v-first"),
            (clean(column(tuple(w) + tuple(q))), "That puts the point q where v goes. v = −ω × q is what the turn "
                                                  "does to the origin, not a point on the axis.", "q-for-v"),
        )),
        "values": {"w": bmatrix(column(w)), "q": bmatrix(column(q)), "wq": bmatrix(clean(column(wq))),
                   "qx": fmt(p["qx"]), "qy": fmt(p["qy"]), "qz": fmt(p["qz"]), "axis": _AXIS_TEX[p["axis"]]},
    }


def _screw_ok(p):
    """The axis does not pass through the origin (v ≠ 0), and every slip is told apart."""
    if not any(cross(_axis(p), _q(p))):
        return False
    return len(_screw(p)["slips"]) == 3


# ---- 11.2 The exponential of the twist, with the learner's S --------------------------------------

def _carries_111(p):
    """11.1's variant whose printed S this draw carries: the workbook's own numbers carry variant 0's."""
    return 0 if {k: p[k] for k in _S_DEFAULTS} == _S_DEFAULTS else None


def _exp(p, given=None):
    """11.2: e^{[S]θ} = [R  G(θ) v; 0 1], with the learner's S (from 11.1), G(θ) and shift when given."""
    S_key = clean(column(revolute_screw(_axis(p), _q(p))))
    S = flat(given_rows(given, "S", S_key))
    w, v = S[:3], S[3:]
    th = math.radians(p["theta"])
    deg = float(p["theta"])
    R = clean(rotation_exp(w, th))
    G_key = clean(g_matrix(w, th))
    G = given_rows(given, "G", G_key)
    shift_key = clean(column(matvec(G, v)))
    shift = flat(given_rows(given, "p", shift_key))
    key = clean(pose(R, shift))
    return {
        "key": key,
        "slips": kept_slips(key, (
            (clean(pose(rotation_exp(w, -th), shift)), "The rotation block turns by −θ: in I + sin θ [ω] + "
                                                       "(1 − cos θ)[ω]², sin θ multiplies [ω] with its own sign.",
             "r-minus-theta"),
            (clean(pose(rotation_exp(w, deg), shift)), f"The rotation block uses the sine and cosine of {fmt(deg)} "
                                                       "radians. θ is in degrees here.", "r-radians-not-degrees"),
            (clean(pose(terms(1.0, math.sin(th), -(1 - math.cos(th)), w), shift)),
             "The rotation block's [ω]² term has the wrong sign: Rodrigues' formula adds (1 − cos θ)[ω]².",
             "r-square-sign"),
            (clean(pose(R, [c * th for c in v])), "That shifts by v θ, a prismatic joint's shift. This joint turns "
                                                  "(ω ≠ 0), so the shift is G(θ) v.", "v-theta-shift"),
        )),
        "steps": {
            "G": {"key": G_key, "slips": kept_slips(G_key, (
                (clean(terms(deg, 1 - math.cos(th), deg - math.sin(th), w)),
                 f"That puts θ = {fmt(deg)}, in degrees, into I θ and (θ − sin θ). There θ must be in radians, "
                 f"{fmt(th)}.", "g-degrees"),
                (clean(terms(0.0, 1 - math.cos(th), th - math.sin(th), w)),
                 "The I θ term is missing: G(θ) = I θ + (1 − cos θ)[ω] + (θ − sin θ)[ω]².", "g-without-i-theta"),
                (R, "That is e^{[ω]θ}, the rotation. G(θ) has I θ, (1 − cos θ)[ω] and (θ − sin θ)[ω]².", "g-is-r"),
            ))},
            "p": {"key": shift_key, "slips": kept_slips(shift_key, (
                (clean(column([c * th for c in v])), "That is v θ, a prismatic joint's shift. This joint turns, so "
                                                     "the shift is G(θ) v.", "p-v-theta"),
                (clean(column(v)), "That is v itself: multiply it by G(θ) from the step before.", "p-v-unmultiplied"),
            ))},
        },
        "values": {
            "w": bmatrix(column(_axis(p))), "q": bmatrix(column(_q(p))), "theta": fmt(deg), "rad": fmt(th),
            "axis": _AXIS_TEX[p["axis"]], "qx": fmt(p["qx"]), "qy": fmt(p["qy"]), "qz": fmt(p["qz"]),
            "radrel": relation(th), "S": bmatrix(S_key), "vcol": bmatrix(column(v)),
            "W": bmatrix(clean(skew(w))), "W2": bmatrix(clean(matmul(skew(w), skew(w)))),
            "sin": fmt(math.sin(th)), "cos": fmt(math.cos(th)), "one_cos": fmt(1 - math.cos(th)),
            "th_sin": fmt(th - math.sin(th)),
            "sinr": relation(math.sin(th)), "cosr": relation(math.cos(th)), "ocr": relation(1 - math.cos(th)),
            "tsr": relation(th - math.sin(th), shown(th) - shown(math.sin(th))),
            "R": bmatrix(R), "Rrel": relation_all(R), "Grel": relation_all(G_key),
            "from111": ("exercise 11.1's answer" if _carries_111(p) == 0 else "found as in exercise 11.1"),
        },
    }


def _exp_ok(p):
    """A joint off the origin, a turn that moves it, and every slip of the answer and the steps told apart."""
    if not _screw_ok(p):
        return False
    made = _exp(p)
    return (len(made["slips"]) == 4 and len(made["steps"]["G"]["slips"]) == 3
            and len(made["steps"]["p"]["slips"]) == 2)


_THETAS = (90, 30, 45, 60, 120, 135, 150, 180, -30, -45, -60, -90, -120, -135, -150)

EXERCISES = (
    Derive(
        id="11.1",
        title="The screw axis of a revolute joint",
        spec=matrix(label="S = (ω, v), six numbers, ω on top"),
        vary=Vary(_screw, Choice("axis", "z", tuple(AXES)), Param("qx", 2, -3, 3, 1), Param("qy", 1, -3, 3, 1),
                  Param("qz", 0, -3, 3, 1), valid=_screw_ok),
    ),
    Derive(
        id="11.2",
        title="The exponential of a twist",
        spec=matrix(label="T = e^[S]θ, 4 × 4"),
        vary=Vary(_exp, Choice("axis", "z", tuple(AXES)), Param("qx", 2, -3, 3, 1), Param("qy", 1, -3, 3, 1),
                  Param("qz", 0, -3, 3, 1), Choice("theta", 90, _THETAS), valid=_exp_ok),
        uses=(Uses("11.1", "S", "the screw axis S", variant=_carries_111),),
        steps=(Step("G", "G(θ)", matrix(label="G(θ) = Iθ + (1 − cos θ)[ω] + (θ − sin θ)[ω]²")),
               Step("p", "G(θ) v", matrix(label="the shift G(θ) v", names=("x", "y", "z")))),
    ),
)
