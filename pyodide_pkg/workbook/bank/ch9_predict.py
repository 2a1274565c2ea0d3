"""Chapter 9 · Capstone, the predict step: x′ (9.2), an entry of the motion Jacobian F (9.7)
and the whole predicted state (9.8).

The three draw the predict step's own inputs (pose, v, ω, dt). 9.2 and 9.8 can be
worked in checked steps: the distance driven, v·dt, then the move it makes along
the heading at the start of the step (its x part for 9.2; Δx, Δy and the turn
Δθ for 9.8), each from the learner's own previous step. The pose 9.2 predicts
(``PRED_FULL``) is where 9.3 and 9.4 start (``ch9_capstone``).

>>> made = _new_x(_NINE_TWO, given={"vdt": 2.0})  # a learner who drove 2 m instead of 1 m
>>> round(made["steps"]["dx"]["key"], 4), round(made["key"], 4)
(1.7321, 6.7321)
"""

import math

from .. import chains
from ..answer_kinds.base import Slip
from ..answer_kinds.matrix import matrix
from ..answer_kinds.number import number
from ..kinds.derive import Derive
from ..number_format import approx, fmt, pi_frac, relation, shown
from ..reference.ekf import motion_jacobian, motion_model
from ..steps import Step
from ..variants import Choice, Param, Vary
from . import column
from .checks import kept_slips, slips_apart

START = (5.0, 3.0, math.pi / 6)
V, OMEGA, DT = 1.0, 0.1, 1.0
PRED_FULL = motion_model(START, V, OMEGA, DT)  # 9.2's answer, printed (5.8660, 3.5, 0.6236)
_DEGREES = {pi_frac(d): d for d in range(5, 90, 5) if d != 45}  # 45° would make cos θ = sin θ
_HEADING = ("theta", pi_frac(30), tuple(_DEGREES))
_NINE_TWO = {"x": START[0], "y": START[1], "theta": pi_frac(30), "v": V, "omega": OMEGA, "dt": DT}  # 9.2's own


def _heading(p) -> tuple[int, float]:
    """The drawn heading: whole degrees and radians."""
    deg = _DEGREES[p["theta"]]
    return deg, math.radians(deg)


def _predicted_pose(p):
    """The predict step (the motion model) from the drawn pose, with its intermediate numbers."""
    deg, th = _heading(p)
    x, y, v, omega, dt = p["x"], p["y"], p["v"], p["omega"], p["dt"]
    pred = motion_model((x, y, th), v, omega, dt)
    turned = motion_model((x, y, th + omega * dt), v, omega, dt)  # the slip: turn first, then drive
    swapped = (x + v * math.sin(th) * dt, y + v * math.cos(th) * dt)  # the slip: sin and cos swapped
    moved_x, moved_y = pred[0] - x, pred[1] - y
    values = {
        "deg": fmt(deg),
        "cos": f"= \\sqrt3/2 {approx(math.cos(th))}" if deg == 30 else approx(math.cos(th)),
        "dx": fmt(moved_x), "dy": fmt(moved_y),
        "xp": fmt(pred[0]), "yp": fmt(pred[1]),
        "rx": relation(pred[0], x + shown(moved_x)), "ry": relation(pred[1], y + shown(moved_y)),
        "th": fmt(th), "omdt": fmt(omega * dt), "thp": fmt(pred[2]), "rth": relation(pred[2], shown(th) + omega * dt),
        "thp_deg": fmt(math.degrees(pred[2])), "omdt_deg": approx(math.degrees(omega * dt)),
        "most": "x" if moved_x > moved_y else "y", "cmp": ">" if moved_x > moved_y else "<",
        "as92": " as in exercise 9.2" if p == _NINE_TWO else "",
        "next92": ("Exercises 9.3 and 9.4 start from this pose." if p == _NINE_TWO
                   else "Exercises 9.3 and 9.4 start from the pose of this exercise's first numbers."),
        "used92": ("Exercise 9.2 used only the first entry." if p == _NINE_TWO
                   else "Exercise 9.2 asks for the first entry alone."),
    }
    return pred, turned, swapped, values


def _turned_first(p) -> str:
    """The message for driving along the new heading."""
    return ("You turned first and then drove. The motion model moves along the heading at the start "
            f"of the step, θ = {pi_frac(_heading(p)[0], tex=False)}; the turn takes effect from the next step.")


def _driven(p, given=None):
    """Step 1 of 9.2 and 9.8: the distance driven, v·dt (the learner's own when ``given`` has it),
    and its slips, each kept where it differs from the key and the slips before it."""
    v, omega, dt = p["v"], p["omega"], p["dt"]
    vdt = chains.given(given, "vdt", motion_model((0.0, 0.0, 0.0), v, 0.0, dt)[0])  # along the x-axis: v·dt
    slips = kept_slips(v * dt, (
        (omega * dt, f"That is ω·dt, the turn in radians. The distance driven is v·dt, with v = {fmt(v)} m/s.",
            "omega-dt-turn-radians"),
        (v, f"That is v alone: it is a speed. Driving for dt = {fmt(dt)} s covers v·dt.", "v-alone-speed-driving"),
        (v / dt, "That is v/dt. Distance is speed times time: v·dt.", "v-dt-distance-speed"),
    ))
    return vdt, {"key": vdt, "slips": slips}


def _move_slips(p, vdt: float, key, entries):
    """The slips in the move along the heading, ``entries(dx, dy, dθ)`` being what the step asks
    (x alone for 9.2, the whole move for 9.8); each kept where it differs from ``key``."""
    deg, th = _heading(p)
    turn = p["omega"] * p["dt"]
    ahead = motion_model((0.0, 0.0, th + turn), vdt, 0.0, 1.0)  # driven along the new heading
    along = motion_model((0.0, 0.0, th), vdt, 0.0, 1.0)
    return kept_slips(key, (
        (entries(along[1], along[0], turn), "sin and cos are swapped: the move in x is v·dt·cos θ, in y v·dt·sin θ.",
            "sin-cos-swapped-move"),
        (entries(ahead[0], ahead[1], turn), _turned_first(p), "turned-first-then-drove"),
        (entries(vdt * math.cos(deg), vdt * math.sin(deg), turn),
         f"Your calculator took θ = {fmt(deg)} as radians. Work in radians throughout "
         f"(θ = {pi_frac(deg, tex=False)}), or take cos {fmt(deg)}°.", "calculator-took-theta-radians"),
        (entries(vdt, 0.0, turn), "That leaves out cos θ: the robot drives along its heading, and only "
                                  "v·dt·cos θ of that is in x.", "leaves-out-cos-theta"),
        (entries(along[0], along[1], 0.0), f"The heading did not change: Δθ = ω·dt, and ω = {fmt(p['omega'])} rad/s.",
            "heading-did-change-dtheta"),
    ))


def _new_x(p, given=None):
    """9.2: x′ after one predict step of the motion model. Steps: v·dt, then its part in x."""
    pred, turned, swapped, values = _predicted_pose(p)
    th = _heading(p)[1]
    vdt, driven = _driven(p, given)
    dx = chains.given(given, "dx", motion_model((0.0, 0.0, th), vdt, 0.0, 1.0)[0])  # v·dt·cos θ
    return {
        "key": p["x"] + dx,
        "slips": (
            Slip(turned[0], _turned_first(p), name="turned-first-then-drove"),
            Slip(swapped[0], "You used sin θ. The x-displacement is v·cos θ·dt.", name="used-sin-theta-displacement"),
            Slip(pred[1], "That is y′. The question asks for x′.", name="yp-question-asks-xp"),
        ),
        "steps": {
            "vdt": driven,
            "dx": {"key": dx, "slips": _move_slips(p, vdt, dx, lambda dx, dy, turn: dx if turn else None)},
        },
        "values": {**{key: value for key, value in values.items() if key != "dx"}, "rdx": relation(pred[0] - p["x"])},
    }


def _new_state(p, given=None):
    """9.8: the whole predicted state (x′, y′, θ′) of the motion model. Steps: v·dt, then the
    move (Δx, Δy, Δθ) it makes."""
    pred, turned, swapped, values = _predicted_pose(p)
    _deg, th = _heading(p)
    vdt, driven = _driven(p, given)
    along = motion_model((0.0, 0.0, th), vdt, 0.0, 1.0)  # (v·dt·cos θ, v·dt·sin θ)
    turn = motion_model((0.0, 0.0, 0.0), 0.0, p["omega"], p["dt"])[2]  # ω·dt
    move = chains.given(given, "move", column((along[0], along[1], turn)))
    return {
        "key": column(tuple(a + m for a, (m,) in zip((p["x"], p["y"], th), move))),
        "slips": (
            Slip(column(turned[:2] + (pred[2],)), _turned_first(p), name="turned-first-then-drove"),
            Slip(column(swapped + (pred[2],)), "sin and cos are swapped: x moves by v cos θ dt and y by v sin θ dt.",
                name="sin-cos-swapped-moves"),
            Slip(column(pred[:2] + (th,)),
                 f"The heading did not change: θ′ = θ + ω dt, and ω = {fmt(p['omega'])} rad/s.",
                     name="heading-did-change-thetap"),
        ),
        "steps": {
            "vdt": driven,
            "move": {"key": move, "slips": _move_slips(p, vdt, move, lambda dx, dy, turn: column((dx, dy, turn)))},
        },
        "values": values,
    }


def _jacobian_entry(p):
    """9.7: F(2,3) = v cos θ dt of the motion Jacobian (and F(1,3) beside it)."""
    deg, th = _heading(p)
    F = motion_jacobian((0.0, 0.0, th), p["v"], 0.0, p["dt"])
    f23 = (f"= \\frac{{\\sqrt3}}{{2}} {approx(F[1][2])}" if deg == 30 and p["v"] * p["dt"] == 1
           else approx(F[1][2]))  # the exact form only where it is cos 30° itself
    return {
        "key": F[1][2],
        "slips": (
            Slip(F[0][2], "That is F(1,3) = −v sin θ dt, in row 1. Row 2 is the derivative of y′.", name="f-1-3-v"),
            Slip(-F[0][2], "∂(v sin θ dt)/∂θ = v cos θ dt, not v sin θ dt.", name="v-sin-theta-dt"),
        ),
        "values": {
            "of92": " of exercise 9.2" if (p["theta"], p["v"], p["dt"]) == (pi_frac(30), V, DT) else "",
            "f23_tex": f23, "f13": fmt(F[0][2]), "f23": fmt(F[1][2]),
        },
    }


def _pose_params():
    """9.2 and 9.8 draw the same predict step: start pose, speed, turn rate, time step."""
    return (Param("x", START[0], 0, 9, 1), Param("y", START[1], 0, 9, 1), Choice(*_HEADING),
            Param("v", V, 0.5, 2, 0.1, unit=" m/s"), Param("omega", OMEGA, 0.05, 0.3, 0.05, unit=" rad/s"),
            Param("dt", DT, 0.5, 2, 0.5, unit=" s"))


_DRIVEN = Step("vdt", "v·dt", number(label="v·dt, the distance driven", unit="m"))

EXERCISES = (
    Derive(
        id="9.2",
        title="The full predict step",
        spec=number(label="x′ after one step", unit="m"),
        vary=Vary(_new_x, *_pose_params(), valid=lambda p: slips_apart(_new_x(p))),
        steps=(_DRIVEN, Step("dx", "the move in x", number(label="v·dt·cos θ, the move in x", unit="m"))),
    ),
    Derive(
        id="9.7",
        title="An entry of the Jacobian F",
        spec=number(label="F(2,3)"),
        vary=Vary(_jacobian_entry, Choice(*_HEADING), Param("v", V, 0.5, 2, 0.1, unit=" m/s"),
                  Param("dt", DT, 0.5, 2, 0.5, unit=" s"), valid=lambda p: slips_apart(_jacobian_entry(p))),
    ),
    Derive(
        id="9.8",
        title="The whole predicted state",
        spec=matrix(label="predicted state", names=("x′", "y′", "θ′"), units=("m", "m", "rad")),
        vary=Vary(_new_state, *_pose_params(), valid=lambda p: slips_apart(_new_state(p))),
        steps=(_DRIVEN, Step("move", "the move (Δx, Δy, Δθ)",
                             matrix(label="the move (Δx, Δy, Δθ)", units=("m", "m", "rad")))),
    ),
)
