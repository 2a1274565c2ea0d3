"""Chapter 11 · The space Jacobian of the chapter's 3R arm, column by column (11.6, in checked steps:
e^[S₁]θ₁ e^[S₂]θ₂, then J_s3 = Ad(e^[S₁]θ₁ e^[S₂]θ₂) S₃; J_s2 = Ad(e^[S₁]θ₁) S₂ is printed).

>>> from workbook import bank
>>> bank.get("11.6").worked_text()
'[0 1 1; 0 0 0; 1 0 0; 0 0 0; 0 1 3; 0 0 0]'
"""

from __future__ import annotations

import math

from ..answer_kinds.matrix import matrix
from ..kinds.derive import Derive
from ..number_format import bmatrix, fmt, relation_all
from ..reference.linalg import matvec
from ..reference.screw import adjoint, arm_home, arm_screws, fk_poe, twist_exp, twist_moved
from ..reference.se3 import compose, invert, rotation_of
from ..steps import Step
from ..variants import Choice, Param, Vary
from . import column
from .ch11_arm import ARM_DEFAULTS
from .ch11_screws import clean, flat, given_rows
from .checks import kept_slips

_ANGLES = (90, 30, 45, 60, 120, 150, -30, -45, -60, -90, -120)
_DEFAULTS = {"L0": 1, "L1": 2, "L2": 1, "t1": 90, "t2": 90, "t3": -90}
assert _DEFAULTS == ARM_DEFAULTS  # the arm of 11.3 at 11.3's angles


def _matrix(columns):
    return clean([[c[i] for c in columns] for i in range(6)])


def _jacobian(p, given=None):
    """11.6: J_s = [S₁, Ad(e₁) S₂, Ad(e₁ e₂) S₃], with the learner's e₁ e₂ and third column when given."""
    S = arm_screws(p["L0"], p["L1"])
    th = [math.radians(p[k]) for k in ("t1", "t2", "t3")]
    e1, e2 = twist_exp(S[0], th[0]), twist_exp(S[1], th[1])
    E12_key = clean(compose(e1, e2))
    E12 = given_rows(given, "E12", E12_key)
    J2 = twist_moved(e1, S[1])
    J3_key = clean(column(twist_moved(E12, S[2])))
    J3 = flat(given_rows(given, "J3", J3_key))
    key = _matrix([S[0], J2, J3])
    T = fk_poe(arm_home(p["L0"], p["L1"], p["L2"]), S, th)
    Ad_inv = adjoint(invert(T))
    R12 = rotation_of(E12)
    turned_only = matvec(R12, list(S[2][:3])) + matvec(R12, list(S[2][3:]))
    return {
        "key": key,
        "slips": kept_slips(key, (
            (_matrix(S), "Those are the screw axes at home, S₁, S₂ and S₃. At these angles the shoulder and the "
                         "elbow have been carried by the joints before them: J_si = Ad(e^[S₁]θ₁ ⋯) S_i.",
             "home-columns"),
            (_matrix([S[0], S[1], J3]), "The second column is S₂ at home. The base has turned the shoulder's "
                                        "axis by θ₁: J_s2 = Ad(e^[S₁]θ₁) S₂.", "j2-at-home"),
            (_matrix([S[0], twist_moved(invert(e1), S[1]), J3]),
             f"The second column carries S₂ by the inverse of e^[S₁]θ₁, a turn of {fmt(-p['t1'])}°. Use "
             "e^[S₁]θ₁ itself.", "j2-inverse"),
            (_matrix([matvec(Ad_inv, list(c)) for c in (S[0], J2, J3)]),
             "That is the body Jacobian J_b = Ad(T⁻¹) J_s, the columns seen from the tool frame. The space "
             "Jacobian keeps them in the fixed base frame.", "body-jacobian"),
        )),
        "steps": {
            "E12": {"key": E12_key, "slips": kept_slips(E12_key, (
                (clean(compose(e2, e1)), "That is e^[S₂]θ₂ e^[S₁]θ₁, the product the other way round: the base's "
                                         "exponential comes first, on the left.", "e12-reversed"),
                (clean(e2), "That is the shoulder's exponential alone: the base's e^[S₁]θ₁ multiplies it on the "
                            "left.", "e12-shoulder-only"),
            ))},
            "J3": {"key": J3_key, "slips": kept_slips(J3_key, (
                (clean(column(S[2])), "That is S₃ at home. The base and the shoulder have carried the elbow's axis: "
                                      "J_s3 = Ad(e^[S₁]θ₁ e^[S₂]θ₂) S₃.", "j3-at-home"),
                (clean(column(twist_moved(e1, S[2]))), "That carries S₃ by the base's exponential only. The "
                                                       "shoulder moves the elbow too: J_s3 = Ad(e^[S₁]θ₁ "
                                                       "e^[S₂]θ₂) S₃.", "j3-shoulder-left-out"),
                (clean(column(turned_only)), "That turns ω and v by R but leaves out the [p] R ω part of the "
                                             "adjoint, the shift p of e^[S₁]θ₁ e^[S₂]θ₂: "
                                             "Ad_T = [R 0; [p]R R].", "j3-without-p"),
            ))},
        },
        "values": {
            "L0": fmt(p["L0"]), "L1": fmt(p["L1"]), "L2": fmt(p["L2"]),
            "t1": fmt(p["t1"]), "t2": fmt(p["t2"]), "t3": fmt(p["t3"]),
            "S1": bmatrix(clean(column(S[0]))), "S2": bmatrix(clean(column(S[1]))), "S3": bmatrix(clean(column(S[2]))),
            "e1": bmatrix(clean(e1)), "e1rel": relation_all(e1), "e2": bmatrix(clean(e2)), "e2rel": relation_all(e2),
            "J2": bmatrix(clean(column(J2))), "J2rel": relation_all(J2),
            "same": ("exercise 11.3's arm, at the same angles" if dict(p) == _DEFAULTS else "an arm built like "
                     "exercise 11.3's"),
        },
    }


def _jacobian_ok(p):
    """The base and the shoulder turned (so both adjoints matter), and every slip told apart."""
    if 0 in (p["t1"], p["t2"]):
        return False
    made = _jacobian(p)
    return (len(made["slips"]) == 4 and len(made["steps"]["E12"]["slips"]) == 2
            and len(made["steps"]["J3"]["slips"]) == 3)


EXERCISES = (
    Derive(
        id="11.6",
        title="The space Jacobian, column by column",
        spec=matrix(label="J_s, 6 × 3"),
        vary=Vary(_jacobian, Param("L0", 1, 0.5, 2, 0.5), Param("L1", 2, 0.5, 2, 0.5), Param("L2", 1, 0.5, 2, 0.5),
                  Choice("t1", 90, _ANGLES), Choice("t2", 90, _ANGLES), Choice("t3", -90, _ANGLES),
                  valid=_jacobian_ok),
        steps=(Step("E12", "e^[S₁]θ₁ e^[S₂]θ₂",
                    matrix(label="e^[S₁]θ₁ e^[S₂]θ₂, the motion that carries the elbow's axis")),
               Step("J3", "J_s3", matrix(label="J_s3 = Ad(e^[S₁]θ₁ e^[S₂]θ₂) S₃, the third column"))),
    ),
)
