"""Chapter 10 · 3-D poses: chains of SE(3) transforms and their inverse."""

from __future__ import annotations

import math

from .. import chains
from ..answer_kinds.matrix import matrix
from ..answer_kinds.number import number
from ..kinds.derive import Derive
from ..number_format import bmatrix, fmt
from ..reference.linalg import matmul, matvec, transpose
from ..reference.rotation3d import rx, rz
from ..reference.se3 import compose, invert, pose, transform_point
from ..steps import Step
from ..variants import Choice, Param, Vary
from . import column
from .checks import apart, kept_slips


def _exact(R):
    """A rotation by whole quarter turns with its rounding noise removed: entries 0, 1 or −1."""
    return [[float(round(v)) + 0.0 for v in row] for row in R]


def _yaw(deg):
    return _exact(rz(math.radians(deg)))


def _roll(deg):
    return _exact(rx(math.radians(deg)))


def _vec(v):
    return ", ".join(fmt(c) for c in v)


def _chain(p, given=None):
    """10.1: a point seen by a camera on a pan-tilt base, taken to the world in two steps
    (the learner's own point in the base frame carried into the last step when ``given`` has it)."""
    t1, t2, pc = [p["ax"], p["ay"], p["az"]], [p["bx"], p["by"], p["bz"]], [p["px"], p["py"], p["pz"]]
    R1, R2 = _yaw(p["yaw"]), _roll(p["roll"])
    T_wb, T_bc = pose(R1, t1), pose(R2, t2)
    in_base = transform_point(T_bc, pc)
    mine = [r[0] for r in chains.given(given, "pb", column(in_base))]
    turned_key = matvec(R1, mine)
    turned = [r[0] for r in chains.given(given, "Rb", column(turned_key))]
    world = [a + b for a, b in zip(turned, t1)]
    return {
        "key": column(world),
        "slips": kept_slips(column(world), (
            (column(transform_point(compose(T_bc, T_wb), pc)),
             "The chain is reversed: that is T_base_cam · T_world_base · p. The inner names must meet: "
             "T_world_base · T_base_cam · p_cam, so the camera's transform acts on the point first.",
                 "chain-reversed-t-base"),
            (column(mine), "That is the point in the base frame, one step short. Apply T_world_base to it too.",
                "point-base-frame-step"),
            (column(transform_point(invert(T_wb), mine)),
             "That applies the inverse of T_world_base, which takes world points into the base frame. "
             "The point is in the base frame already: apply T_world_base itself, R₁ p + t₁.",
                 "applies-inverse-t-world"),
            (column([a + b for a, b in zip(mine, t1)]),
             f"That adds the base's position but skips its turn: R₁ (a yaw of {fmt(p['yaw'])}°) must turn "
             "the point before t₁ is added.", "adds-base-s-position"),
            (column(turned), "That is R₁ p_base, the point turned but not yet shifted: add t₁, the base's position.",
                "r1-p-base-point"),
        )),
        "steps": {"pb": {"key": column(in_base), "slips": kept_slips(column(in_base), (
            (column(transform_point(invert(T_bc), pc)),
             "That applies the inverse of T_base_cam. The point is in the camera frame, and T_base_cam takes "
             "camera coordinates to base coordinates: R₂ p + t₂.", "applies-inverse-t-base"),
            (column([a + b for a, b in zip(pc, t2)]),
             f"That adds t₂ but skips the camera's roll of {fmt(p['roll'])}°: turn the point with R₂ first.",
                 "adds-t2-but-skips"),
            (column(matvec(R2, [a + b for a, b in zip(pc, t2)])),
             "That turns p + t₂; the transform turns p and then adds t₂: R₂ p + t₂.", "turns-p-t2-transform"),
        ))},
            "Rb": {"key": column(turned_key), "slips": kept_slips(column(turned_key), (
                (column(matvec(transpose(R1), mine)),
                 f"That turns by R₁ᵀ, a yaw of {fmt(-p['yaw'])}°. The base's transform turns by R₁ itself.",
                     "turns-r1t-yaw-base"),
                (column(mine), "That is p_base unturned: multiply it by R₁.", "p-base-unturned-multiply"),
            ))},
        },
        "values": {
            "R1": bmatrix(R1), "R2": bmatrix(R2), "t1": _vec(t1), "t2": _vec(t2), "p": _vec(pc),
            "Rp": bmatrix([[v] for v in matvec(R2, pc)]), "t2col": bmatrix([[v] for v in t2]),
            "t1col": bmatrix([[v] for v in t1]),
            "yaw": fmt(p["yaw"]), "roll": fmt(p["roll"]),
        },
    }


def _chain_ok(p):
    """The roll moves the point (it is off the x-axis), both offsets are non-zero, and the slips that
    name the chain's mistakes are told apart from the key."""
    if (p["py"], p["pz"]) == (0, 0) or not any((p["ax"], p["ay"], p["az"])) or not any((p["bx"], p["by"], p["bz"])):
        return False
    made = _chain(p)
    if not all(r[0] for r in made["steps"]["pb"]["key"]):  # no zero entry: each step moves every coordinate
        return False
    return len(made["slips"]) == 5 and len(made["steps"]["pb"]["slips"]) == 3 and len(made["steps"]["Rb"]["slips"]) == 2


def _inverse_entry(p):
    """10.2: one entry of the translation column of T⁻¹ = [Rᵀ −Rᵀt; 0 1]."""
    R = _exact(matmul(_yaw(p["yaw"]), _roll(p["roll"])))
    t = [p["tx"], p["ty"], p["tz"]]
    T = pose(R, t)
    i = p["row"] - 1
    RT = transpose(R)
    RTt = matvec(RT, t)
    key = invert(T)[i][3]
    name = "xyz"[i]
    return {
        "key": key,
        "slips": kept_slips(key, (
            (float(-t[i]), f"That is −t_{name}, the position negated in world axes. T⁻¹'s translation is −Rᵀt: the "
                    "old origin seen along the frame's own axes.", "t-position-negated-world"),
            (RTt[i], "The sign is off: the translation of T⁻¹ is −Rᵀt, not Rᵀt. Check: T⁻¹ must send the "
                     f"position ({_vec(t)}) to the origin.", "sign-off-translation-t"),
            (-matvec(R, t)[i], "That multiplies t by R. Undoing the turn takes Rᵀ: row "
                               f"{p['row']} of Rᵀ is column {p['row']} of R.", "multiplies-t-r-undoing"),
        )),
        "label": f"row {p['row']}, column 4 of T⁻¹",
        "values": {
            "T": bmatrix(T), "RT": bmatrix(RT), "t": _vec(t), "tcol": bmatrix([[v] for v in t]),
            "RTt": bmatrix([[v] for v in RTt]), "mRTt": bmatrix([[-v] for v in RTt]),
            "row": str(p["row"]), "name": name,
            "terms": " + ".join(f"{fmt(a)} \\cdot {fmt(b) if b >= 0 else '(' + fmt(b) + ')'}"
                                for a, b in zip(RT[i], t)),
            "RTti": fmt(RTt[i]),
        },
    }


def _inverse_ok(p):
    """The translation is not zero, and the three slips are all told apart from the key (so the
    turn matters for the entry asked)."""
    if not any((p["tx"], p["ty"], p["tz"])):
        return False
    made = _inverse_entry(p)
    return len(made["slips"]) == 3 and apart(made["key"], *(s.value for s in made["slips"]))


_ANGLES = (90, 180, -90)

EXERCISES = (
    Derive(
        id="10.1",
        title="A point through a two-link chain",
        spec=matrix(label="p_world = (x, y, z)ᵀ", names=("x", "y", "z")),
        vary=Vary(_chain, Choice("yaw", 90, _ANGLES), Choice("roll", 90, _ANGLES),
                  Param("ax", 2, -2, 3, 1), Param("ay", 1, -3, 3, 1), Param("az", 1, 0, 2, 1),
                  Param("bx", 1, -2, 2, 1), Param("by", 1, -2, 2, 1), Param("bz", 0.5, 0, 1.5, 0.5),
                  Param("px", 3, 1, 4, 1), Param("py", 1, -2, 2, 1), Param("pz", 0, -3, 3, 1),
                  valid=_chain_ok),
        steps=(Step("pb", "p_base", matrix(label="p_base = T_base_cam · p_cam, the point in the base frame",
                                          names=("x", "y", "z"))),
               Step("Rb", "R₁ p_base", matrix(label="R₁ · p_base, the point turned by the base's yaw",
                                              names=("x", "y", "z")))),
    ),
    Derive(
        id="10.2",
        title="An entry of the inverse pose",
        spec=number(label="row 1, column 4 of T⁻¹"),
        vary=Vary(_inverse_entry, Choice("yaw", 90, _ANGLES), Choice("roll", 90, _ANGLES),
                  Param("tx", 2, -9.9, 9.9, 0.1), Param("ty", -1, -9.9, 9.9, 0.1), Param("tz", 3, -9.9, 9.9, 0.1),
                  Choice("row", 1, (1, 2, 3)), valid=_inverse_ok),
    ),
)
