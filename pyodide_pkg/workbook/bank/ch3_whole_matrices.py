"""Chapter 3's whole matrices: the Jacobian F facing north (3.7) and the predicted covariance
P⁻ = F P Fᵀ + Q built from it (3.8), which can be worked in checked steps (F P, then F P Fᵀ)."""

import math

from .. import chains
from ..answer_kinds.base import Slip
from ..answer_kinds.matrix import matrix
from ..chains import Uses
from ..kinds.derive import Derive
from ..number_format import bmatrix, fmt
from ..reference.ekf import ekf_predict, motion_jacobian  # noqa: F401 (ekf_predict: the doctests)
from ..reference.linalg import add, identity, matmul, sub, transpose
from ..variants import Param, Vary
from . import grid
from .ch3_ekf_predict import (  # the chapter's shared numbers, and the steps F P, F P Fᵀ (3.4's too)
    _EAST,
    _NORTH,
    _P,
    _Q,
    PUSH_STEPS,
    _heading_gain,
    _metres,
    _pushed_forward,
    push_steps,
)
from .checks import slips_apart

_PRINTED_37 = (2, 0.5)  # (v, dt) as the workbook prints 3.7 (variant 0); 3.8's variant 0 carries its F


# ---- 3.8 ------------------------------------------------------------------------
def _predicted_covariance(p, given=None):
    """3.8: the whole P⁻ = F P Fᵀ + Q facing north with 3.7's F (or the learner's own, ``given``),
    and exercise 3.4's P and Q. The reference's own predict step agrees with the printed F:

    >>> F = motion_jacobian((0, 0, _NORTH), 2, 0, 0.5)
    >>> _pushed_forward(F, _P, _Q)[2] == ekf_predict((0, 0, _NORTH), _P, 2, 0, 0.5, _Q)[1]
    True
    """
    v, dt = p["v"], p["dt"]
    F = [list(row) for row in chains.given(given, "F", motion_jacobian((0, 0, _NORTH), v, 0, dt))]
    FP, FPF, Pm = _pushed_forward(F, _P, _Q, given)
    f13 = F[0][2]
    printed = (v, dt) == _PRINTED_37
    slips = [
        Slip(grid(FPF), "That is F P Fᵀ without the process noise. Add Q: the motion itself is uncertain."),
        Slip(grid(add(_P, _Q)), "That is P + Q: you left F out. F passes the heading uncertainty into x, which is "
                                "where the off-diagonal terms come from."),
        Slip(grid(add(matmul(matmul(transpose(F), _P), F), _Q)),
             "That is Fᵀ P F + Q, the product in the wrong order. The covariance is pushed forward as F P Fᵀ."),
    ]
    if not math.isclose(abs(f13), 1.0):
        once = [row[:] for row in Pm]
        once[0][0] = _P[0][0] + abs(f13) * _P[2][2] + _Q[0][0]
        slips.append(Slip(grid(once), "Check P⁻(1,1): F₁₃ enters twice, once from F and once from Fᵀ, so x gains "
                                      f"F₁₃²·P₃₃ = {fmt(f13 * f13 * _P[2][2])}, not |F₁₃|·P₃₃."))
    return {
        "key": grid(Pm),
        "slips": tuple(slips),
        "steps": push_steps(F, _P, _Q, FP, FPF),
        "values": {
            "src": "the robot of exercise 3.7" if printed else "the robot",
            "pdef": f"\\operatorname{{diag}}({fmt(_P[0][0])}, {fmt(_P[1][1])}, {fmt(_P[2][2])})",
            "qdef": f"\\operatorname{{diag}}({fmt(_Q[0][0])}, {fmt(_Q[1][1])}, {fmt(_Q[2][2])})",
            **{f"q{i}{i}": fmt(_Q[i - 1][i - 1]) for i in (1, 2, 3)},
            "F": bmatrix(F), "f13": fmt(f13),
            "gain": _heading_gain(f13, _P[2][2], "F_{13}"), "metres": _metres(abs(f13), "a metre"),
            "p13m": fmt(Pm[0][2]),
            "of37": "exercise 3.7's" if printed else "the",
        },
    }


def _predicted_covariance_ok(p) -> bool:
    """The slips (no Q, no F, Fᵀ P F, F₁₃ once) stay apart from the key and from each other."""
    return slips_apart(_predicted_covariance(p))


# ---- 3.7 ------------------------------------------------------------------------
def _north_jacobian(p):
    """3.7: the whole F facing north at v for dt."""
    v, dt = p["v"], p["dt"]
    F = motion_jacobian((0, 0, _NORTH), v, 0, dt)
    d = v * dt
    return {
        "key": grid(F),
        "slips": (
            Slip(grid(motion_jacobian((0, 0, _EAST), v, 0, dt)),
                 "That is F at θ = 0 (or sin and cos swapped). Facing north, sin θ = 1 and cos θ = 0: the "
                 "heading column is (−v·dt, 0, 1)."),
            Slip(grid(motion_jacobian((0, 0, _NORTH), v, 0, 1)),
                 f"You left out dt: F(1,3) = −v·sin θ·dt = −{fmt(v)} · 1 · {fmt(dt)}."),
            Slip(grid(sub(F, identity(3))),
                 "That is the derivative of the displacement alone. x′ = x + v cos θ dt also contains x itself, "
                 "so F carries the identity on its diagonal."),
            Slip(grid(motion_jacobian((0, 0, -_NORTH), v, 0, dt)),
                 "The sign of F(1,3) is flipped: the derivative of cos θ is −sin θ, so F(1,3) = −v sin θ dt."),
        ),
        "values": {
            "f13": fmt(F[0][2]),
            "travel": _metres(d, "one metre"),
            "dx": "-\\delta\\theta" if math.isclose(d, 1.0) else f"-{fmt(d)}\\,\\delta\\theta",
            "vdt": fmt(d),
        },
    }


def _north_jacobian_ok(p) -> bool:
    """Leaving out dt must change F (dt ≠ 1 is also excluded from the grid); the slips stay apart."""
    return slips_apart(_north_jacobian(p))



EXERCISES = (
    Derive(
        id="3.7",
        title="The whole Jacobian F facing north",
        answer=matrix(label="F"),
        vary=Vary(_north_jacobian, Param("v", 2, 0.5, 3, 0.5, unit=" m/s"),
                  Param("dt", 0.5, 0.1, 2, 0.1, unit=" s", avoid=(1,)), valid=_north_jacobian_ok),
    ),
    Derive(
        id="3.8",
        title="The whole predicted covariance",
        answer=matrix(label="P⁻ = F P Fᵀ + Q"),
        vary=Vary(_predicted_covariance, Param("v", _PRINTED_37[0], 0.5, 2, 0.5, unit=" m/s"),
                  Param("dt", _PRINTED_37[1], 0.2, 2, 0.2, unit=" s"), valid=_predicted_covariance_ok),
        uses=(Uses("3.7", "F", "F", variant=lambda p: 0 if (p["v"], p["dt"]) == _PRINTED_37 else None),),
        steps=PUSH_STEPS,
    ),
)
