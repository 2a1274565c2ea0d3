"""Chapter 9 · Capstone: one navigation cycle, end to end.

The keys chain as a learner carries the numbers by hand: each step starts from
the previous step's answer *as the page prints it* (four decimals), states that
value, and computes its own key from it with the reference code. So 9.3 and 9.4
start from 9.2's printed pose (5.8660, 3.5, 0.6236), 9.5 from 9.4's printed K
(0.7143), and 9.6 from 9.4's printed x⁺ (5.7474).

Every Derive exercise draws variants. 9.2, 9.7 and 9.8 draw the predict step's
own inputs (pose, v, ω, dt); 9.3, 9.4 and 9.6 keep the value carried in from
the step before (the workbook's chain) and draw the inputs they bring in (the
landmark; P, z and R; the waypoint and Kp); 9.5 draws P and K. A sentence that
names an earlier exercise ("from exercise 9.4") is only printed when the
numbers are that exercise's own.

The values carried in are the answers printed before them (variant 0):

>>> from workbook import bank
>>> ex = {i: bank.get(i) for i in ("9.2", "9.3", "9.4", "9.5", "9.6", "9.8")}
>>> pose = ex["9.3"].values
>>> f"[{pose['px']}; {pose['py']}; {pose['pth']}]" == ex["9.8"].worked_text(), pose["px"] == ex["9.2"].worked_text()
(True, True)
>>> ex["9.4"].values["px"] == pose["px"], ex["9.6"].values["xu"] == ex["9.4"].worked_text()
(True, True)
>>> ex["9.5"].values["K"] == ex["9.4"].values["K"], ex["9.5"].worked_text()
(True, '0.1429')
"""

import math

from ..answer_kinds.base import Slip
from ..answer_kinds.number import number
from ..answer_kinds.matrix import matrix
from ..kinds.derive import Derive
from ..kinds.design import Design, Step
from ..number_format import approx, fmt, paren, pi_frac, relation, shown, signed
from ..reference.ekf import ekf_update, motion_jacobian, motion_model, range_bearing
from ..reference.pid import p_term
from ..variants import Choice, Param, Vary
from .. import chains
from ..chains import Uses
from . import column
from .checks import slips_apart

_START = (5.0, 3.0, math.pi / 6)
_V, _OMEGA, _DT = 1.0, 0.1, 1.0
_PRED_FULL = motion_model(_START, _V, _OMEGA, _DT)     # 9.2's answer, printed (5.8660, 3.5, 0.6236)
_PRED = tuple(shown(v) for v in _PRED_FULL)            # ... and carried as printed into 9.3 and 9.4
_LANDMARK = (10.0, 7.0)                                # range 5.4166 from _PRED
_P, _Z, _R = 0.5, 5.7, 0.2
_X_UPD = shown(ekf_update(_PRED[0], _P, _Z, _R)[0])    # 9.4's answer as printed, 5.7474, carried into 9.6
_K = shown(_P / (_P + _R))                             # 9.4's K as printed, 0.7143, carried into 9.5
_TARGET, _KP = 10.0, 0.5                               # command 2.1263 m/s from _X_UPD


# ---- The predict step: 9.2, 9.7, 9.8 ------------------------------------------
_DEGREES = {pi_frac(d): d for d in range(5, 90, 5) if d != 45}  # 45° would make cos θ = sin θ
_HEADING = ("theta", pi_frac(30), tuple(_DEGREES))
_NINE_TWO = {"x": _START[0], "y": _START[1], "theta": pi_frac(30), "v": _V, "omega": _OMEGA, "dt": _DT}  # 9.2's own


def _heading(p) -> tuple[int, float]:
    """The drawn heading: whole degrees and radians."""
    deg = _DEGREES[p["theta"]]
    return deg, math.radians(deg)


def _predicted_pose(p):
    """The predict step (velocity model) from the drawn pose, with its intermediate numbers."""
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
    return ("You turned first and then drove. The velocity model moves along the heading at the start "
            f"of the step, θ = {pi_frac(_heading(p)[0], tex=False)}; the turn takes effect from the next step.")


def _new_x(p):
    """9.2: x′ after one predict step of the velocity model."""
    pred, turned, swapped, values = _predicted_pose(p)
    return {
        "key": pred[0],
        "slips": (
            Slip(turned[0], _turned_first(p)),
            Slip(swapped[0], "You used sin θ. The x-displacement is v·cos θ·dt."),
            Slip(pred[1], "That is y′. The question asks for x′."),
        ),
        "values": values,
    }


def _new_state(p):
    """9.8: the whole predicted state (x′, y′, θ′) of the velocity model."""
    pred, turned, swapped, values = _predicted_pose(p)
    return {
        "key": column(pred),
        "slips": (
            Slip(column(turned[:2] + (pred[2],)), _turned_first(p)),
            Slip(column(swapped + (pred[2],)), "sin and cos are swapped: x moves by v cos θ dt and y by v sin θ dt."),
            Slip(column(pred[:2] + (_heading(p)[1],)),
                 f"The heading did not change: θ′ = θ + ω dt, and ω = {fmt(p['omega'])} rad/s."),
        ),
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
            Slip(F[0][2], "That is F(1,3) = −v sin θ dt, in row 1. Row 2 is the derivative of y′."),
            Slip(-F[0][2], "∂(v sin θ dt)/∂θ = v cos θ dt, not v sin θ dt."),
        ),
        "values": {
            "of92": " of exercise 9.2" if (p["theta"], p["v"], p["dt"]) == (pi_frac(30), _V, _DT) else "",
            "f23_tex": f23, "f13": fmt(F[0][2]), "f23": fmt(F[1][2]),
        },
    }


# ---- Sensing, fusing, steering: 9.3 to 9.6 ---------------------------------------
def _carried_pose() -> dict[str, str]:
    """9.2's predicted pose as the page prints it (9.3 and 9.4 start from it)."""
    return {"px": fmt(_PRED_FULL[0]), "py": fmt(_PRED_FULL[1]), "pth": fmt(_PRED_FULL[2])}


def _predicted_range(p, given=None):
    """9.3: the range from 9.2's printed pose (or the learner's own x′, ``given``) to the drawn landmark."""
    landmark = (p["lx"], p["ly"])
    pred = (chains.given(given, "x", _PRED[0]), _PRED[1], _PRED[2])
    r = range_bearing(pred, landmark)[0]
    dx, dy = landmark[0] - pred[0], landmark[1] - pred[1]
    exactly = 10  # significant figures enough to print the squares of Δx, Δy (three decimals each) in full
    reading = round(r - 0.1, 1)  # a LiDAR reading a little short of the prediction
    return {
        "key": r,
        "slips": (
            Slip(r ** 2, "That is r², the sum of squares. Take its square root."),
            Slip(math.hypot(*landmark),
                 "That is the landmark's distance from the origin. Measure from the robot's predicted position."),
        ),
        "values": {
            **_carried_pose(),
            "dx": fmt(dx), "dy": fmt(dy), "dx2": fmt(dx * dx, exactly), "dy2": fmt(dy * dy, exactly),
            "q": fmt(dx * dx + dy * dy, exactly), "rr": relation(r), "r": fmt(r), "reading": fmt(reading),
            "innovation": fmt(reading - r), "ri": relation(reading - r, reading - shown(r)),
        },
    }


def _range_well_posed(p) -> bool:
    """9.3: the landmark is at least 2 m away, and neither slip is the range."""
    made = _predicted_range(p)
    return made["key"] >= 2 and slips_apart(made)


def _fused(p, given=None):
    """9.4: the scalar Kalman update of 9.2's printed x (or the learner's own, ``given``) with the drawn P, z and R."""
    P, z, R = p["P"], p["z"], p["R"]
    x = chains.given(given, "x", _PRED[0])
    x_upd, _ = ekf_update(x, P, z, R)
    K = P / (P + R)
    correction = K * (z - x)
    return {
        "key": x_upd,
        "slips": (
            Slip(ekf_update(x, R, z, P)[0],
                 f"You swapped P and R: K = P/(P + R) = {fmt(P)}/{fmt(P + R)}, "
                 "the share of trust given to the measurement."),
            Slip(x_upd - x, "That is the correction K(z − x). Add it to the prediction."),
        ),
        "values": {
            "px": _carried_pose()["px"],
            "S": fmt(P + R), "K": fmt(K), "rk": relation(K), "innov": fmt(z - x), "innov_p": paren(z - x),
            "corr": signed(correction), "rc": relation(correction, shown(K) * (z - x)),
            "xu": fmt(x_upd), "rx": relation(x_upd, x + shown(correction)),
            "pct": _percent(K),
            "next94": ("Exercise 9.6 steers from this x⁺." if (P, z, R) == (_P, _Z, _R)
                       else "Exercise 9.6 steers from the x⁺ of this exercise's first numbers."),
        },
    }


def _percent(share: float) -> str:
    """A share as a whole percentage in words: ``75`` when it is one, else ``about 71``."""
    whole = round(100 * share)
    return str(whole) if math.isclose(100 * share, whole, abs_tol=1e-9) else f"about {whole}"


def _fused_well_posed(p) -> bool:
    """9.4: the sensor is the less noisy (R < P, as the text says), and the slips are apart."""
    return p["R"] < p["P"] and slips_apart(_fused(p))


def _updated_variance(p):
    """9.5: P⁺ = (1 − K)·P, with the sensor's R that gives this K."""
    P, K = p["P"], p["K"]
    R = P * (1 - K) / K  # K = P/(P + R)
    _, P_upd = ekf_update(0.0, P, 0.0, R)
    own = (P, K) == (_P, _K)  # exercise 9.4's numbers: its sensor's R is the one printed there
    return {
        "key": P_upd,
        "slips": (
            Slip(K * P, "That is K·P, the variance removed. What is left is (1 − K)·P."),
            Slip(1 - K, f"That is 1 − K. Multiply it by P = {fmt(P)}."),
        ),
        "values": {
            "from94": "from exercise 9.4" if own else "from a scalar Kalman update",
            "one_minus_k": fmt(1 - K), "Pu": fmt(P_upd), "rp": relation(P_upd, shown(1 - K) * P),
            "sensor": f"R = {fmt(_R)}" if own else f"R = P(1 - K)/K {relation(R)} {fmt(R)}",
        },
    }


def _command(p, given=None):
    """9.6: the P controller's speed command from 9.4's printed x⁺ (or the learner's own, ``given``) to the drawn waypoint."""
    target, Kp = p["target"], p["Kp"]
    e = target - chains.given(given, "xu", _X_UPD)
    u = p_term(e, Kp)
    return {
        "key": u,
        "slips": (
            Slip(e, f"That is the position error. The command multiplies it by Kp = {fmt(Kp)}."),
            Slip(-u, "Sign: the error is target − position, positive here, so the robot drives forward."),
        ),
        "values": {"xu": fmt(_X_UPD), "e": fmt(e), "u": fmt(u), "ru": relation(u, Kp * shown(e))},
    }


def _pose_params():
    """9.2 and 9.8 draw the same predict step: start pose, speed, turn rate, time step."""
    return (Param("x", _START[0], 0, 9, 1), Param("y", _START[1], 0, 9, 1), Choice(*_HEADING),
            Param("v", _V, 0.5, 2, 0.1, unit=" m/s"), Param("omega", _OMEGA, 0.05, 0.3, 0.05, unit=" rad/s"),
            Param("dt", _DT, 0.5, 2, 0.5, unit=" s"))


EXERCISES = (
    Design(
        id="9.1",
        title="Order the navigation loop",
        steps=(
            Step("predict", "Predict the pose with the motion model"),
            Step("detect", "Detect a landmark with the LiDAR"),
            Step("innovate", "Compute the innovation: measured minus predicted"),
            Step("update", "EKF update: gain K, state x⁺, covariance P⁺"),
            Step("control", "PID: compute the next motor command"),
        ),
        shown=("update", "control", "detect", "predict", "innovate"),
    ),
    Derive(
        id="9.2",
        title="The full predict step",
        answer=number(label="x′ after one step", unit="m"),
        vary=Vary(_new_x, *_pose_params(), valid=lambda p: slips_apart(_new_x(p))),
    ),
    Derive(
        id="9.3",
        title="Predicted range to a landmark",
        answer=number(label="predicted range r", unit="m"),
        vary=Vary(_predicted_range, Param("lx", _LANDMARK[0], 0, 15, 1), Param("ly", _LANDMARK[1], 0, 12, 1), valid=_range_well_posed),
        uses=(Uses("9.2", "x", "x′"),),
    ),
    Derive(
        id="9.4",
        title="Fuse the measurement",
        answer=number(label="updated x⁺", unit="m"),
        vary=Vary(_fused, Param("P", _P, 0.2, 1, 0.1), Param("z", _Z, 4.8, 6.9, 0.1, unit=" m"),
                  Param("R", _R, 0.1, 0.9, 0.1), valid=_fused_well_posed),
        uses=(Uses("9.2", "x", "x′"),),
    ),
    Derive(
        id="9.5",
        title="Updated covariance",
        answer=number(label="P⁺ = (1 − K)·P"),
        vary=Vary(_updated_variance, Param("P", _P, 0.1, 0.9, 0.1), Param("K", _K, 0.1, 0.9, 0.05, avoid=(0.5,)),
                  valid=lambda p: slips_apart(_updated_variance(p))),
    ),
    Derive(
        id="9.6",
        title="Velocity command",
        answer=number(label="commanded speed u", unit="m/s"),
        vary=Vary(_command, Param("target", _TARGET, 6, 15, 1, unit=" m"), Param("Kp", _KP, 0.1, 1.5, 0.1, avoid=(1,)),
                  valid=lambda p: slips_apart(_command(p))),
        uses=(Uses("9.4", "xu", "x⁺"),),
    ),
    Derive(
        id="9.7",
        title="An entry of the Jacobian F",
        answer=number(label="F(2,3)"),
        vary=Vary(_jacobian_entry, Choice(*_HEADING), Param("v", _V, 0.5, 2, 0.1, unit=" m/s"),
                  Param("dt", _DT, 0.5, 2, 0.5, unit=" s"), valid=lambda p: slips_apart(_jacobian_entry(p))),
    ),
    Derive(
        id="9.8",
        title="The whole predicted state",
        answer=matrix(label="predicted state", names=("x′", "y′", "θ′"), units=("m", "m", "rad")),
        vary=Vary(_new_state, *_pose_params(), valid=lambda p: slips_apart(_new_state(p))),
    ),
)
