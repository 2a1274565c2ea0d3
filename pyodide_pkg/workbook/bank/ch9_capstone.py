"""Chapter 9 · Capstone: one navigation cycle, end to end.

The keys chain as a learner carries the numbers by hand: each step starts from
the previous step's answer *as the page prints it* (four decimals), states that
value, and computes its own key from it with the reference code. So 9.3 and 9.4
start from 9.2's printed pose (5.8660, 3.5, 0.6236), 9.5 from 9.4's printed K
(0.7143), and 9.6 from 9.4's printed x⁺ (5.7474).

Every Derive exercise draws variants. 9.2, 9.7 and 9.8 draw the predict step's
own inputs (pose, v, ω, dt; they live in ``ch9_predict``); 9.3, 9.4 and 9.6 keep
the value carried in from the step before (the workbook's chain) and draw the
inputs they bring in (the landmark; P, z and R; the waypoint and Kp); 9.5 draws
P and K. A sentence that names an earlier exercise ("from exercise 9.4") is only
printed when the numbers are that exercise's own.

9.3 and 9.4 can be worked in checked steps: the offset (Δx, Δy) to the landmark
and then Δx² + Δy²; the gain K and then the correction K·(z − x). Each step starts
from the learner's own previous step, and from the learner's own x′ of 9.2.

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

from .. import chains
from ..answer_kinds.base import Slip
from ..answer_kinds.matrix import matrix
from ..answer_kinds.number import number
from ..chains import Uses
from ..kinds.derive import Derive
from ..kinds.design import Design, Step
from ..number_format import fmt, paren, relation, shown, signed
from ..reference.ekf import ekf_update, kalman_gain, range_bearing
from ..reference.pid import p_term
from ..steps import Step as WorkStep
from ..variants import Param, Vary
from . import column
from .ch9_predict import PRED_FULL  # where the capstone's chain starts: 9.2's predicted pose
from .checks import kept_slips, slips_apart

_PRED_FULL = PRED_FULL                                 # 9.2's answer, printed (5.8660, 3.5, 0.6236)
_PRED = tuple(shown(v) for v in _PRED_FULL)            # ... and carried as printed into 9.3 and 9.4
_LANDMARK = (10.0, 7.0)                                # range 5.4166 from _PRED
_P, _Z, _R = 0.5, 5.7, 0.2
_X_UPD = shown(ekf_update(_PRED[0], _P, _Z, _R)[0])    # 9.4's answer as printed, 5.7474, carried into 9.6
_K = shown(_P / (_P + _R))                             # 9.4's K as printed, 0.7143, carried into 9.5
_TARGET, _KP = 10.0, 0.5                               # command 2.1263 m/s from _X_UPD


# ---- Sensing, fusing, steering: 9.3 to 9.6 ---------------------------------------
def _carried_pose() -> dict[str, str]:
    """9.2's predicted pose as the page prints it (9.3 and 9.4 start from it)."""
    return {"px": fmt(_PRED_FULL[0]), "py": fmt(_PRED_FULL[1]), "pth": fmt(_PRED_FULL[2])}


def _predicted_range(p, given=None):
    """9.3: the range from 9.2's printed pose (or the learner's own x′, ``given``) to the drawn landmark.
    Steps: the offset (Δx, Δy) to the landmark, then Δx² + Δy², each from the learner's own previous
    one (``given``); the range is its square root. Without ``given`` that is the reference's range:

    >>> made = _predicted_range({"lx": 10, "ly": 7})
    >>> math.isclose(made["key"], range_bearing(_PRED, _LANDMARK)[0])
    True
    """
    landmark = (p["lx"], p["ly"])
    pred = (chains.given(given, "x", _PRED[0]), _PRED[1], _PRED[2])
    offset = chains.given(given, "d", column((landmark[0] - pred[0], landmark[1] - pred[1])))
    (dx,), (dy,) = offset
    q = chains.given(given, "q", dx * dx + dy * dy)
    r = math.sqrt(q)  # ValueError when a learner's Δx² + Δy² is negative: nothing to carry
    true_r = range_bearing(_PRED, landmark)[0]
    ddx, ddy = landmark[0] - _PRED[0], landmark[1] - _PRED[1]
    exactly = 10  # significant figures enough to print the squares of Δx, Δy (three decimals each) in full
    reading = round(true_r - 0.1, 1)  # a LiDAR reading a little short of the prediction
    return {
        "key": r,
        "slips": (
            Slip(true_r ** 2, "That is r², the sum of squares. Take its square root.", name="r2-sum-squares-take"),
            Slip(math.hypot(*landmark),
                 "That is the landmark's distance from the origin. Measure from the robot's predicted position.",
                     name="landmark-s-distance-origin"),
        ),
        "steps": {
            "d": {"key": offset, "slips": kept_slips(offset, (
                (column((-ddx, -ddy)), "That is the robot's position minus the landmark's. The offset runs from "
                                       "the robot to the landmark: landmark minus robot.", "robot-s-position-minus"),
                (column(landmark), "That is where the landmark is, seen from the origin. Take away the robot's "
                                   "predicted position.", "where-landmark-seen-origin"),
            ))},
            "q": {"key": q, "slips": kept_slips(q, (
                ((dx + dy) ** 2, "That squares the sum, (Δx + Δy)². Square each offset first, then add.",
                    "squares-sum-dx-dy"),
                (abs(dx) + abs(dy), "That adds the offsets themselves. Pythagoras adds their squares.",
                    "adds-offsets-themselves-pythagoras"),
            ))},
        },
        "values": {
            **_carried_pose(),
            "dx2": fmt(ddx * ddx, exactly), "dy2": fmt(ddy * ddy, exactly),
            "rq": relation(ddx * ddx + ddy * ddy, shown(ddx * ddx) + shown(ddy * ddy)),
            "rr": relation(true_r), "r": fmt(true_r), "reading": fmt(reading),
            "innovation": fmt(reading - true_r), "ri": relation(reading - true_r, reading - shown(true_r)),
        },
    }


def _range_well_posed(p) -> bool:
    """9.3: the landmark is at least 2 m away, and neither slip is the range."""
    made = _predicted_range(p)
    return made["key"] >= 2 and slips_apart(made)


def _fused(p, given=None):
    """9.4: the scalar Kalman update of 9.2's printed x (or the learner's own, ``given``) with the drawn P, z and R.
    Steps: the gain K, then the correction K·(z − x), each from the learner's own previous one
    (``given``); x⁺ adds the correction to x. Without ``given`` that is the reference's update:

    >>> made = _fused({"P": _P, "z": _Z, "R": _R})
    >>> math.isclose(made["key"], ekf_update(_PRED[0], _P, _Z, _R)[0])
    True
    """
    P, z, R = p["P"], p["z"], p["R"]
    x = chains.given(given, "x", _PRED[0])
    gain = kalman_gain([[P]], [[1.0]], [[R]])[0][0]  # P/(P + R)
    K = chains.given(given, "K", gain)
    correction = chains.given(given, "corr", K * (z - x))
    x_upd = x + correction
    x0 = _PRED[0]  # what the page prints: 9.2's x, the right gain and correction
    printed_corr = gain * (z - x0)
    return {
        "key": x_upd,
        "slips": (
            Slip(ekf_update(x, R, z, P)[0],
                 f"You swapped P and R: K = P/(P + R) = {fmt(P)}/{fmt(P + R)}, "
                 "the share of trust given to the measurement.", name="swapped-p-r-k"),
            Slip(correction, "That is the correction K(z − x). Add it to the prediction.", name="correction-k-z-add"),
        ),
        "steps": {
            "K": {"key": K, "slips": kept_slips(K, (
                (1 - gain, f"That is R/(P + R), the prediction's share. K puts the prediction's variance "
                           f"P = {fmt(P)} on top.", "r-p-r-prediction"),
                (P / R, "That is P/R. The gain divides by P + R, the variance of the innovation.", "p-r-gain-divides"),
            ))},
            "corr": {"key": correction, "slips": kept_slips(correction, (
                (K * (x - z), "Check the sign: the innovation is z − x, the measurement minus the prediction.",
                    "check-sign-innovation-z"),
                (z - x, f"That is the innovation z − x alone. The correction scales it by K = {fmt(K)}.",
                    "innovation-z-alone-correction"),
            ))},
        },
        "values": {
            "px": _carried_pose()["px"],
            "S": fmt(P + R), "K": fmt(gain), "rk": relation(gain), "innov": fmt(z - x0), "innov_p": paren(z - x0),
            "corr": signed(printed_corr), "rc": relation(printed_corr, shown(gain) * (z - x0)),
            "xu": fmt(x0 + printed_corr), "rx": relation(x0 + printed_corr, x0 + shown(printed_corr)),
            "pct": _percent(gain),
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
            Slip(K * P, "That is K·P, the variance removed. What is left is (1 − K)·P.", name="k-p-variance-removed"),
            Slip(1 - K, f"That is 1 − K. Multiply it by P = {fmt(P)}.", name="1-k-multiply-p"),
        ),
        "values": {
            "from94": "from exercise 9.4" if own else "from a scalar Kalman update",
            "one_minus_k": fmt(1 - K), "Pu": fmt(P_upd), "rp": relation(P_upd, shown(1 - K) * P),
            "sensor": f"R = {fmt(_R)}" if own else f"R = P(1 - K)/K {relation(R)} {fmt(R)}",
        },
    }


def _command(p, given=None):
    """9.6: the P controller's speed command from 9.4's printed x⁺ (or the learner's own, ``given``)
    to the drawn waypoint."""
    target, Kp = p["target"], p["Kp"]
    e = target - chains.given(given, "xu", _X_UPD)
    u = p_term(e, Kp)
    return {
        "key": u,
        "slips": (
            Slip(e, f"That is the position error. The command multiplies it by Kp = {fmt(Kp)}.",
                name="position-error-command-multiplies"),
            Slip(-u, "Sign: the error is target − position, positive here, so the robot drives forward.",
                name="sign-error-target-position"),
        ),
        "values": {"xu": fmt(_X_UPD), "e": fmt(e), "u": fmt(u), "ru": relation(u, Kp * shown(e))},
    }


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
        id="9.3",
        title="Predicted range to a landmark",
        spec=number(label="predicted range r", unit="m"),
        vary=Vary(_predicted_range, Param("lx", _LANDMARK[0], 0, 15, 0.5), Param("ly", _LANDMARK[1], 0, 12, 0.5),
                  valid=_range_well_posed),
        uses=(Uses("9.2", "x", "x′"),),
        steps=(WorkStep("d", "(Δx, Δy)", matrix(label="(Δx, Δy), from the robot to the landmark", unit="m")),
               WorkStep("q", "Δx² + Δy²", number(label="Δx² + Δy²"))),
    ),
    Derive(
        id="9.4",
        title="Fuse the measurement",
        spec=number(label="updated x⁺", unit="m"),
        vary=Vary(_fused, Param("P", _P, 0.2, 1, 0.1), Param("z", _Z, 3.5, 8, 0.01, unit=" m"),
                  Param("R", _R, 0.1, 0.9, 0.1), valid=_fused_well_posed),
        uses=(Uses("9.2", "x", "x′"),),
        steps=(WorkStep("K", "K", number(label="the gain K = P/(P + R)")),
               WorkStep("corr", "K·(z − x)", number(label="the correction K·(z − x)", unit="m"))),
    ),
    Derive(
        id="9.5",
        title="Updated covariance",
        spec=number(label="P⁺ = (1 − K)·P"),
        vary=Vary(_updated_variance, Param("P", _P, 0.1, 0.9, 0.01), Param("K", _K, 0.1, 0.9, 0.05, avoid=(0.5,)),
                  valid=lambda p: slips_apart(_updated_variance(p))),
    ),
    Derive(
        id="9.6",
        title="Velocity command",
        spec=number(label="commanded speed u", unit="m/s"),
        vary=Vary(_command, Param("target", _TARGET, 6, 15, 0.5, unit=" m"),
                  Param("Kp", _KP, 0.1, 1.5, 0.05, avoid=(1,)),
                  valid=lambda p: slips_apart(_command(p))),
        uses=(Uses("9.4", "xu", "x⁺"),),
    ),
)
