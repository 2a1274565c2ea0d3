"""Chapter 3's whole matrices: the Jacobian F facing north (3.7, worked in checked steps: the move
(Δx, Δy), then F's θ column) and the predicted covariance P⁻ = F P Fᵀ + Q built from it (3.8, in
steps F P, then F P Fᵀ).

3.8 carries 3.7's F in every draw: it draws one of 3.7's sets of numbers (``set37``, the variant
of 3.7 whose printed F it uses) and takes that set's v and dt, so the chain holds over the grid.
"""

import math
from functools import cache

from .. import chains
from ..answer_kinds.base import Slip
from ..answer_kinds.matrix import matrix
from ..chains import Uses
from ..kinds.derive import Derive
from ..number_format import bmatrix, fmt
from ..reference.ekf import ekf_predict, motion_jacobian, motion_model  # noqa: F401 (ekf_predict: the doctests)
from ..reference.linalg import add, identity, matmul, sub, transpose
from ..steps import Step
from ..variants import Choice, Param, Vary
from . import column, grid
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
from .checks import kept_slips, slips_apart

_SETS_37 = tuple(range(400))  # the sets of numbers (variants) of 3.7 that 3.8 draws from; 0 is the workbook's


@cache
def _numbers_of_37(n: int) -> tuple[float, float]:
    """(v, dt) of exercise 3.7's variant ``n``: its generator's first well-posed draw for that
    variant (tests/unit/test_steps_bank.py checks it is the draw 3.7 shows, for every set 3.8 uses)."""
    p = next(_VARY_37.candidates("3.7", n))
    return p["v"], p["dt"]


def _set_words(n: int) -> str:
    """Which of exercise 3.7's sets of numbers a 3.8 draw builds on, in words."""
    if n == 0:
        return "with the workbook's numbers"
    return f"with its set of numbers {n} (the link that ends “variant=3.7-{n}” opens it)"


# ---- 3.8 ------------------------------------------------------------------------
def _predicted_covariance(p, given=None):
    """3.8: the whole P⁻ = F P Fᵀ + Q facing north with 3.7's F (or the learner's own, ``given``),
    and exercise 3.4's P and Q. The reference's own predict step agrees with the printed F:

    >>> F = motion_jacobian((0, 0, _NORTH), 2, 0, 0.5)
    >>> _pushed_forward(F, _P, _Q)[2] == ekf_predict((0, 0, _NORTH), _P, 2, 0, 0.5, _Q)[1]
    True
    """
    v, dt = _numbers_of_37(p["set37"])
    F = [list(row) for row in chains.given(given, "F", motion_jacobian((0, 0, _NORTH), v, 0, dt))]
    FP, FPF, Pm = _pushed_forward(F, _P, _Q, given)
    f13 = F[0][2]
    slips = [
        Slip(grid(FPF), "That is F P Fᵀ without the process noise. Add Q: the motion itself is uncertain.",
            name="f-p-ft-without"),
        Slip(grid(add(_P, _Q)), "That is P + Q: you left F out. F passes the heading uncertainty into x, which is "
                                "where the off-diagonal terms come from.", name="p-q-left-f"),
        Slip(grid(add(matmul(matmul(transpose(F), _P), F), _Q)),
             "That is Fᵀ P F + Q, the product in the wrong order. The covariance is pushed forward as F P Fᵀ.",
                 name="ft-p-f-q"),
    ]
    if not math.isclose(abs(f13), 1.0):
        once = [row[:] for row in Pm]
        once[0][0] = _P[0][0] + abs(f13) * _P[2][2] + _Q[0][0]
        slips.append(Slip(grid(once), "Check P⁻(1,1): F₁₃ enters twice, once from F and once from Fᵀ, so x gains "
                                      f"F₁₃²·P₃₃ = {fmt(f13 * f13 * _P[2][2])}, not |F₁₃|·P₃₃.", name="check-p-1-1"))
    return {
        "key": grid(Pm),
        "slips": tuple(slips),
        "steps": push_steps(F, _P, _Q, FP, FPF),
        "values": {
            "v": fmt(v), "dt": fmt(dt), "set37": _set_words(p["set37"]),
            "pdef": f"\\operatorname{{diag}}({fmt(_P[0][0])}, {fmt(_P[1][1])}, {fmt(_P[2][2])})",
            "qdef": f"\\operatorname{{diag}}({fmt(_Q[0][0])}, {fmt(_Q[1][1])}, {fmt(_Q[2][2])})",
            **{f"q{i}{i}": fmt(_Q[i - 1][i - 1]) for i in (1, 2, 3)},
            "F": bmatrix(F), "f13": fmt(f13),
            "gain": _heading_gain(f13, _P[2][2], "F_{13}"), "metres": _metres(abs(f13), "a metre"),
            "p13m": fmt(Pm[0][2]),
        },
    }


def _predicted_covariance_ok(p) -> bool:
    """The slips (no Q, no F, Fᵀ P F, F₁₃ once) stay apart from the key and from each other."""
    return slips_apart(_predicted_covariance(p))


# ---- 3.7 ------------------------------------------------------------------------
def _heading_column(p, given=None):
    """3.7's steps: the move (Δx, Δy) = (v cos θ dt, v sin θ dt) facing north, then F's θ column
    (−Δy, Δx, 1) from the learner's own move (each the learner's own when ``given`` has it), since
    ∂(v cos θ dt)/∂θ = −v sin θ dt = −Δy and ∂(v sin θ dt)/∂θ = Δx. With the printed move the column
    is the reference's:

    >>> column = _heading_column({"v": 2, "dt": 0.5})[0]
    >>> column == [row[2] for row in motion_jacobian((0, 0, _NORTH), 2, 0, 0.5)]
    True
    """
    v, dt = p["v"], p["dt"]
    moved = motion_model((0, 0, _NORTH), v, 0, dt)[:2]
    east = motion_model((0, 0, _EAST), v, 0, dt)[:2]
    ax, ay = (row[0] for row in chains.given(given, "move", column(moved)))
    key = (-ay, ax, 1.0)
    theta_col = [r[0] for r in chains.given(given, "col", column(key))]
    return theta_col, {
        "move": {"key": column(moved), "slips": kept_slips(column(moved), (
            (column(east), "That is the move facing east (or cos and sin swapped). Facing north, cos θ = 0 and "
                           f"sin θ = 1: all of v·dt = {fmt(v * dt)} m goes into y.", "move-facing-east-cos"),
            (column(motion_model((0, 0, _NORTH), v, 0, 1)[:2]),
             f"You left out dt: in {fmt(dt)} s the robot covers v·dt = {fmt(v * dt)} m, not {fmt(v)} m.",
                 "left-out-dt-s"),
        ))},
        "col": {"key": column(key), "slips": kept_slips(column(key), (
            (column((ax, ay, 1.0)), "That is the move (Δx, Δy) itself. The θ column holds its derivatives by θ: "
                                    "∂(v cos θ dt)/∂θ = −v sin θ dt = −Δy, and ∂(v sin θ dt)/∂θ = Δx.",
                                        "move-dx-dy-itself"),
            (column((ay, -ax, 1.0)), "The signs are flipped: the derivative of cos θ is −sin θ (and that of sin θ "
                                     "is cos θ), so F(1,3) = −v sin θ dt = −Δy and F(2,3) = Δx.",
                                         "signs-flipped-derivative-cos"),
            (column((-ay, ax, 0.0)), "F(3,3) is 1, not 0: θ′ = θ + ω dt contains θ itself, so ∂θ′/∂θ = 1.", "f-3-3-1"),
        ))},
    }


def _north_jacobian(p, given=None):
    """3.7: the whole F facing north at v for dt, in steps: the move (Δx, Δy), then the θ column."""
    v, dt = p["v"], p["dt"]
    F = motion_jacobian((0, 0, _NORTH), v, 0, dt)
    theta_col, worked = _heading_column(p, given)
    d = v * dt
    return {
        "key": grid([[*row[:2], c] for row, c in zip(F, theta_col)]),
        "slips": (
            Slip(grid(motion_jacobian((0, 0, _EAST), v, 0, dt)),
                 "That is F at θ = 0 (or sin and cos swapped). Facing north, sin θ = 1 and cos θ = 0: the "
                 "heading column is (−v·dt, 0, 1).", name="f-theta-0-sin"),
            Slip(grid(motion_jacobian((0, 0, _NORTH), v, 0, 1)),
                 f"You left out dt: F(1,3) = −v·sin θ·dt = −{fmt(v)} · 1 · {fmt(dt)}.", name="left-out-dt-f"),
            Slip(grid(sub(F, identity(3))),
                 "That is the derivative of the displacement alone. x′ = x + v cos θ dt also contains x itself, "
                 "so F carries the identity on its diagonal.", name="derivative-displacement-alone-xp"),
            Slip(grid(motion_jacobian((0, 0, -_NORTH), v, 0, dt)),
                 "The sign of F(1,3) is flipped: the derivative of cos θ is −sin θ, so F(1,3) = −v sin θ dt.",
                     name="sign-f-1-3"),
        ),
        "steps": worked,
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



_VARY_37 = Vary(_north_jacobian, Param("v", 2, 0.1, 4, 0.1, unit=" m/s"),
                Param("dt", 0.5, 0.1, 2, 0.1, unit=" s", avoid=(1,)), valid=_north_jacobian_ok)

EXERCISES = (
    Derive(
        id="3.7",
        title="The whole Jacobian F facing north",
        spec=matrix(label="F"),
        vary=_VARY_37,
        steps=(Step("move", "the move (Δx, "
                            "Δy)", matrix(label="the move (Δx, Δy) = (v cos θ dt, v sin θ dt)", unit="m")),
               Step("col", "F's θ column (F₁₃, F₂₃, F₃₃)", matrix(label="the θ column of F: F(1,3), F(2,3), F(3,3)"))),
    ),
    Derive(
        id="3.8",
        title="The whole predicted covariance",
        spec=matrix(label="P⁻ = F P Fᵀ + Q"),
        vary=Vary(_predicted_covariance, Choice("set37", 0, _SETS_37), valid=_predicted_covariance_ok),
        uses=(Uses("3.7", "F", "F", variant=lambda p: p["set37"]),),
        steps=PUSH_STEPS,
    ),
)
