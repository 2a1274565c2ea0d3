"""Chapter 3 · EKF prediction step."""

import math

from .. import chains
from ..answer_kinds.base import Slip
from ..answer_kinds.expression import formula
from ..answer_kinds.matrix import matrix
from ..answer_kinds.number import number
from ..kinds.debug import Debug
from ..kinds.derive import Derive
from ..kinds.trace import Option, Trace
from ..number_format import bmatrix, fmt, pi_frac, relation
from ..reference.ekf import ekf_predict, motion_jacobian, motion_model  # noqa: F401 (ekf_predict: the doctests)
from ..reference.linalg import add, matmul, transpose
from ..steps import Step
from ..tolerance import clean
from ..variants import Choice, Param, Vary
from . import grid
from .checks import apart, slips_apart
from .heading_column import heading_column_formula

_P: list[list[float]] = [[1, 0, 0], [0, 1, 0], [0, 0, 0.1]]  # exercise 3.4's P and Q (variant 0), kept by 3.8
_Q: list[list[float]] = [[0.01, 0, 0], [0, 0.01, 0], [0, 0, 0.001]]
_EAST, _NORTH = 0.0, math.pi / 2


# ---- helpers for the variants -------------------------------------------------
def _diag(a: float, b: float, c: float):
    return [[a, 0, 0], [0, b, 0], [0, 0, c]]


def _metres(d: float, one: str) -> str:
    """A distance in words: ``one`` (e.g. "one metre") for exactly 1 m, else "1.5 metres"."""
    return one if math.isclose(d, 1.0) else f"{fmt(d)} metres"


def _tfrac(deg: int) -> str:
    """An angle of whole degrees as a small fraction of π in TeX: 45 -> ``\\tfrac{\\pi}{4}`` (``pi_frac`` prints it).

    >>> _tfrac(45), _tfrac(-35), _tfrac(180)
    ('\\\\tfrac{\\\\pi}{4}', '-\\\\tfrac{7\\\\pi}{36}', '\\\\pi')
    """
    top, _, bottom = pi_frac(abs(deg)).partition("/")
    return ("-" if deg < 0 else "") + (f"\\tfrac{{{top}}}{{{bottom}}}" if bottom else top)


# ---- 3.1 ------------------------------------------------------------------------
def _compass(x0: int, y0: int) -> str:
    """Where the start lies, in words (3.1's statement).

    >>> _compass(0, 0), _compass(2, -1), _compass(0, 3)
    ('the origin', '2 m east and 1 m south of the origin', '3 m north of the origin')
    """
    parts = [f"{abs(c)} m "
             f"{(pos if c > 0 else neg)}" for c, pos, neg in ((x0, "east", "west"), (y0, "north", "south")) if c]
    return " and ".join(parts) + " of the origin" if parts else "the origin"


def _drive_east(p):
    """3.1: from (x0, y0) facing east at v for dt; asked: the new x."""
    x0, y0, v, dt = p["x0"], p["y0"], p["v"], p["dt"]
    xn, yn, _ = motion_model((x0, y0, _EAST), v, 0, dt)
    dx, dy, _ = motion_model((0, 0, _EAST), v, 0, dt)  # the displacement alone
    east = "Facing east, all the motion goes into x: cos 0 = 1."
    if x0 == y0:  # y′ and "sin used for x" are the same number
        slips = [Slip(yn, f"That is y (or you used sin for x). {east}", name="y-used-sin")]
    else:
        slips = [Slip(yn, f"That is y. {east}", name="y"),
                 Slip(x0 + dy, f"That leaves x where it started: you used sin for x. {east}",
                     name="leaves-where-started-used")]
    if x0:
        slips.append(Slip(dx, f"That is the distance driven alone. x′ = x + v·cosθ·dt starts from x = {fmt(x0)}.",
            name="distance-driven-alone-xp"))
    if dt != 1:
        slips.append(Slip(motion_model((x0, y0, _EAST), v, 0, 1)[0],
                          f"You left out dt. The robot drives for {fmt(dt)} s, so it covers v·dt = {fmt(dx)} m, "
                          f"not {fmt(v)} m.", name="left-out-dt-robot"))
    return {
        "key": xn,
        "slips": tuple(slips),
        "values": {"where": _compass(x0, y0), "xn": fmt(xn), "yn": fmt(yn), "dist": _metres(dx, "one metre")},
    }


def _drive_east_ok(p) -> bool:
    """The slips (y′, sin for x, no start, no dt) are told apart from the key and each other."""
    return slips_apart(_drive_east(p))


# ---- 3.2 ------------------------------------------------------------------------
def _drive_at_heading(p):
    """3.2: from the origin at heading θ, v for dt; asked: the new y."""
    deg, v, dt = p["theta"], p["v"], p["dt"]
    theta = math.radians(deg)
    xn, yn, _ = motion_model((0, 0, theta), v, 0, dt)
    d = v * dt
    slips = [Slip(motion_model((0, 0, theta), v, 0, 1)[1],
                  f"You left out dt. The robot drives for {fmt(dt)} s, so it covers v·dt = {fmt(d)} m, not {fmt(v)} "
                  "m.", name="left-out-dt-robot")]
    if apart(xn, yn):
        slips.append(Slip(xn, "That is x′, the cosine share. The new y takes the sine: y′ = y + v·sinθ·dt.",
            name="xp-cosine-share-new"))
    even = math.isclose(abs(math.cos(theta)), abs(math.sin(theta)))
    arg = _tfrac(deg)
    return {
        "key": yn,
        "slips": tuple(slips),
        "values": {
            "rad": pi_frac(deg),
            "targ": arg if deg > 0 else f"\\left({arg}\\right)",
            "vdt": "" if math.isclose(d, 1.0) else fmt(d),
            "sdeg": f"{fmt(deg)}°" if deg > 0 else f"({fmt(deg)}°)",
            "xn": fmt(xn), "yn": fmt(yn), "x_rel": relation(xn), "y_rel": relation(yn), "d": fmt(d),
            "split": "evenly" if even else "by the cosine and sine of the heading",
        },
    }


def _drive_at_heading_ok(p) -> bool:
    """Neither coordinate is zero (no heading along an axis), and the slips stay apart."""
    x, y = motion_model((0, 0, math.radians(p["theta"])), p["v"], 0, p["dt"])[:2]
    return abs(x) >= 0.01 and abs(y) >= 0.01 and slips_apart(_drive_at_heading(p))


# ---- 3.3 ------------------------------------------------------------------------
def _north_f13(p):
    """3.3: F(1,3) facing north at v for dt."""
    v, dt = p["v"], p["dt"]
    F = motion_jacobian((0, 0, _NORTH), v, 0, dt)
    return {
        "key": F[0][2],
        "slips": (
            Slip(motion_jacobian((0, 0, _NORTH), v, 0, 1)[0][2],
                 f"You left out dt: F(1,3) = −v·sinθ·dt, and dt = {fmt(dt)}.", name="left-out-dt-f"),
            Slip(clean(-F[1][2]), "That uses cos θ. Differentiating v·cosθ·dt with respect to θ gives −v·sinθ·dt.",
                name="uses-cos-theta-differentiating"),
        ),
        "values": {"f13": fmt(F[0][2])},
    }


def _north_f13_ok(p) -> bool:
    """Leaving out dt must give another number (dt ≠ 1 is also excluded from the grid)."""
    return slips_apart(_north_f13(p))


# ---- 3.4 (3.8: ch3_whole_matrices.py) ------------------------------------------------------------------
def _pushed_forward(F, P, Q, given=None):
    """F P, F P Fᵀ and P⁻ = F P Fᵀ + Q for any F (3.4 and 3.8), each step from the learner's own
    previous one when ``given`` has it (steps FP and FPF). The reference's predict step agrees:

    >>> F = motion_jacobian((0, 0, _EAST), 1, 0, 1)
    >>> _pushed_forward(F, _P, _Q)[2] == ekf_predict((0, 0, _EAST), _P, 1, 0, 1, _Q)[1]
    True
    """
    FP = [list(r) for r in chains.given(given, "FP", matmul(F, P))]
    FPF = [list(r) for r in chains.given(given, "FPF", matmul(FP, transpose(F)))]
    return FP, FPF, add(FPF, Q)


PUSH_STEPS = (Step("FP", "F P", matrix(label="F P")), Step("FPF", "F P Fᵀ", matrix(label="F P Fᵀ")))


def push_steps(F, P, Q, FP, FPF) -> dict:
    """The steps F P and F P Fᵀ (3.4 and 3.8): their keys and the slips made at each."""
    return {
        "FP": {"key": grid(FP), "slips": (
            Slip(grid(matmul(P, F)), "That is P F, the product in the wrong order: F comes first, so row i "
                                     "of F P is row i of F times P.", name="p-f-product-wrong"),)},
        "FPF": {"key": grid(FPF), "slips": (
            Slip(grid(matmul(FP, F)), "That is (F P) F: the second factor is Fᵀ, the transpose of F.",
                name="f-p-f-second"),
            Slip(grid(add(FPF, Q)), "That already adds Q: this step is F P Fᵀ alone; Q comes last.",
                name="already-adds-q-step")),
        },
    }


def _heading_gain(f: float, p33: float, name: str = "F_{23}") -> str:
    """What a coordinate gains from the heading: ``0.1`` when F = ±1, else ``0.1 \\cdot F_{23}^2 = 0.4``."""
    if math.isclose(abs(f), 1.0):
        return fmt(p33)
    return f"{fmt(p33)} \\cdot {name}^2 = {fmt(f * f * p33)}"


_ASKED = {"1,1": (0, "P^-_{11}"), "2,2": (1, "P^-_{22}")}


def _covariance_entry(p, given=None):
    """3.4: one diagonal entry of P⁻ = F P Fᵀ + Q facing east, worked in steps (F P, then F P Fᵀ);
    ``given`` holds the learner's own steps."""
    v, dt, entry = p["v"], p["dt"], p["entry"]
    P = _diag(p["p11"], p["p22"], p["p33"])
    Q = _diag(p["q11"], p["q22"], p["q33"])
    F = motion_jacobian((0, 0, _EAST), v, 0, dt)
    FP, FPF, Pm = _pushed_forward(F, P, Q, given)
    f23 = F[1][2]
    i, asked = _ASKED[entry]
    if entry == "1,1":
        slips = [Slip(Pm[1][1], "That is P⁻(2,2), the y variance. The question asks for the top-left entry.",
            name="p-2-2-y"),
                 Slip(FPF[0][0], f"That is F P Fᵀ alone. Add the process noise Q: its (1,1) entry is {fmt(Q[0][0])}.",
                     name="f-p-ft-alone")]
    else:
        slips = [Slip(Pm[0][0], "That is P⁻(1,1), the x variance. The question asks for the (2,2) entry, the y "
                                "variance.", name="p-1-1-variance"),
                 Slip(FPF[1][1], f"That is F P Fᵀ alone. Add the process noise Q: its (2,2) entry is {fmt(Q[1][1])}.",
                     name="f-p-ft-alone"),
                 Slip(add(P, Q)[1][1], "That is P + Q: you left F out. F passes the heading uncertainty into y: "
                                       f"add F₂₃²·P₃₃ = {fmt(f23 * f23 * P[2][2])}.", name="p-q-left-f")]
        if not math.isclose(f23, 1.0):
            slips.append(Slip(P[1][1] + f23 * P[2][2] + Q[1][1],
                              f"F₂₃ enters twice, once from F and once from Fᵀ: the heading adds F₂₃²·P₃₃ = "
                              f"{fmt(f23 * f23 * P[2][2])}, not F₂₃·P₃₃.", name="f2-enters-twice-once"))
    return {
        "key": Pm[i][i],
        "label": f"P⁻({entry})",
        "slips": tuple(slips),
        "steps": push_steps(F, P, Q, FP, FPF),
        "values": {"f23": fmt(f23), "Pm": bmatrix(Pm), "p22m": fmt(Pm[1][1]), "p23m": fmt(Pm[1][2]), "asked": asked},
    }


def _covariance_entry_ok(p) -> bool:
    """y grows more than x (the derivation says so), and the slips stay apart."""
    if not p["q22"] + (p["v"] * p["dt"]) ** 2 * p["p33"] > p["q11"]:
        return False
    return slips_apart(_covariance_entry(p))


def _predict_pose(x, y, theta, v, omega, dt):
    """The correct answer to exercise 3.5, as a flat tuple."""
    return motion_model((x, y, theta), v, omega, dt)


EXERCISES = (
    Derive(
        id="3.1",
        title="Predict the new position",
        spec=number(label="x", unit="m"),
        vary=Vary(_drive_east, Param("x0", 0, -3, 3, 1, unit=" m"), Param("y0", 0, -3, 3, 1, unit=" m"),
                  Param("v", 1, 0.1, 4, 0.1, unit=" m/s"), Param("dt", 1, 0.1, 2, 0.1, unit=" s"),
                  valid=_drive_east_ok),
    ),
    Derive(
        id="3.2",
        title="Predict at a heading",
        spec=number(label="y", unit="m"),
        vary=Vary(_drive_at_heading, Param("theta", 45, -175, 175, 5, unit="°", avoid=(0, 90, -90)),
                  Param("v", 2, 0.5, 3, 0.5, unit=" m/s"), Param("dt", 0.5, 0.1, 2, 0.1, unit=" s", avoid=(1,)),
                  valid=_drive_at_heading_ok),
    ),
    Derive(
        id="3.3",
        title="An entry of the Jacobian F",
        spec=number(label="F(1,3)"),
        vary=Vary(_north_f13, Param("v", 1, 0.1, 4, 0.1, unit=" m/s"),
                  Param("dt", 0.5, 0.1, 2, 0.1, unit=" s", avoid=(1,)), valid=_north_f13_ok),
    ),
    Derive(
        id="3.4",
        title="Predict the covariance",
        spec=number(),
        vary=Vary(_covariance_entry, Param("v", 1, 0.5, 2, 0.1, unit=" m/s"), Param("dt", 1, 0.2, 2, 0.2, unit=" s"),
                  Param("p11", 1, 0.5, 2, 0.01), Param("p22", 1, 0.5, 2, 0.01), Param("p33", 0.1, 0.01, 0.2, 0.01),
                  Param("q11", 0.01, 0.01, 0.05, 0.01), Param("q22", 0.01, 0.01, 0.05, 0.01),
                  Param("q33", 0.001, 0.001, 0.005, 0.001), Choice("entry", "1,1", ("1,1", "2,2")),
                  valid=_covariance_entry_ok),
        steps=PUSH_STEPS,
    ),
    Debug(
        id="3.5",
        title="Find the bug",
        code=(
            "import math\n"
            "def ekf_predict_pose(x, y, theta, v, omega, dt):\n"
            "    x_new = x + v * math.cos(theta) * dt\n"
            "    y_new = y + v * math.cos(theta) * dt\n"
            "    theta_new = theta + omega * dt\n"
            "    return (x_new, y_new, theta_new)\n"
        ),
        bug_line=4,
        fixed_line="    y_new = y + v * math.sin(theta) * dt",
        bug=("The y update uses cos θ where it needs sin θ. Facing north (θ = π/2) both cos terms vanish, "
             "so the robot never moves; facing east it climbs in y as fast as it moves in x. "
             "Fix: y_new = y + v * math.sin(theta) * dt."),
        notes={
            1: "imports math for cos and sin",
            2: "takes the pose and the controls",
            3: "correct: x moves by v·cosθ·dt",
            5: "correct: the heading turns by ω·dt",
            6: "returns the new pose",
        },
        function="ekf_predict_pose",
        reference=_predict_pose,
        cases=(
            (0.0, 0.0, math.pi / 2, 1.0, 0.0, 1.0),
            (0.0, 0.0, 0.0, 1.0, 0.0, 1.0),
            (5.0, 3.0, math.pi / 6, 1.0, 0.1, 1.0),
            (1.0, -2.0, -math.pi / 3, 2.0, 0.5, 0.5),
        ),
    ),
    Trace(
        id="3.6",
        title="The diagonal of F",
        answer="b",
        options=(
            Option("a", "Because the robot moves with constant speed",
                   "Constant speed is not needed: even with v changing from step to step, ∂x'/∂x stays 1. "
                   "The diagonal comes from the form of the model, not from v."),
            Option("b", "Because each new coordinate is the old one plus a change, e.g. $x' = x + \\Delta x$",
                   "Right. The motion model adds a displacement to each coordinate, and the displacement does "
                   "not depend on x, y (only on θ), so ∂x'/∂x = ∂y'/∂y = ∂θ'/∂θ = 1 and F = I plus off-diagonal "
                   "terms."),
            Option("c", "Because F is a rotation matrix, and those have ones on the diagonal",
                   "F is not a rotation, and rotations have cos θ on their diagonal, not 1."),
            Option("d", "Because dt is small, so the nonlinear terms round to zero",
                   "Nothing is rounded: the ones are exact for any dt. The dt-dependent terms sit off the diagonal, "
                   "in the θ column."),
        ),
    ),
    Derive(
        id="3.9",
        title="F(1,3) as a formula",
        same_answer="A formula in v, θ and dt: students differ only in which of two entries they are asked.",
        spec=formula(
            variables=("v", "theta", "dt"),
            domain={"v": (0.2, 3.0), "theta": (-3.0, 3.0), "dt": (0.05, 1.0)},
        ),
        vary=Vary(heading_column_formula, Choice("entry", "1,3", ("1,3", "2,3"))),
    ),
)
