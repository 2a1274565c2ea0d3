"""Chapter 9 · Capstone: one navigation cycle, end to end.

The keys chain: each step starts from the previous step's computed value, at
full precision (the page prints them to four decimals, well within tolerance).
"""

import math

from ..answer_kinds.matrix import MatrixDerive
from ..kinds.derive import Derive, Slip
from ..kinds.design import Design, Step
from ..reference.ekf import ekf_update, motion_jacobian, motion_model, range_bearing
from ..reference.pid import p_term
from . import column

_START = (5.0, 3.0, math.pi / 6)
_V, _OMEGA, _DT = 1.0, 0.1, 1.0
_PRED = motion_model(_START, _V, _OMEGA, _DT)          # (5.8660, 3.5, 0.6236)
_LANDMARK = (10.0, 7.0)
_RANGE = range_bearing(_PRED, _LANDMARK)[0]            # 5.4166
_P, _Z, _R = 0.5, 5.7, 0.2
_X_UPD, _P_UPD = ekf_update(_PRED[0], _P, _Z, _R)      # 5.7474, 0.1429
_K = 1 - _P_UPD / _P                                   # K = P/(P+R), read back from (1−K)P
_TARGET, _KP = 10.0, 0.5
_U = p_term(_TARGET - _X_UPD, _KP)                     # 2.1263
_F = motion_jacobian(_START, _V, _OMEGA, _DT)

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
        key=_PRED[0],
        label="x′ after one step",
        unit="m",
        slips=(
            Slip(motion_model((5.0, 3.0, math.pi / 6 + _OMEGA * _DT), _V, _OMEGA, _DT)[0],
                 "You turned first and then drove. The velocity model moves along the heading at the start "
                 "of the step, θ = π/6; the turn takes effect from the next step."),
            Slip(_START[0] + _V * math.sin(_START[2]) * _DT, "You used sin θ. The x-displacement is v·cos θ·dt."),
            Slip(_PRED[1], "That is y′. The question asks for x′."),
        ),
    ),
    Derive(
        id="9.3",
        title="Predicted range to a landmark",
        key=_RANGE,
        label="predicted range r",
        unit="m",
        slips=(
            Slip(_RANGE ** 2, "That is r², the sum of squares. Take its square root."),
            Slip(math.hypot(*_LANDMARK), "That is the landmark's distance from the origin. Measure from the robot's predicted position."),
        ),
    ),
    Derive(
        id="9.4",
        title="Fuse the measurement",
        key=_X_UPD,
        label="updated x⁺",
        unit="m",
        slips=(
            Slip(ekf_update(_PRED[0], _R, _Z, _P)[0],
                 "You swapped P and R: K = P/(P + R) = 0.5/0.7, the share of trust given to the measurement."),
            Slip(_X_UPD - _PRED[0], "That is the correction K(z − x). Add it to the prediction."),
        ),
    ),
    Derive(
        id="9.5",
        title="Updated covariance",
        key=_P_UPD,
        label="P⁺ = (1 − K)·P",
        slips=(
            Slip(_K * _P, "That is K·P, the variance removed. What is left is (1 − K)·P."),
            Slip(1 - _K, "That is 1 − K. Multiply it by P = 0.5."),
        ),
    ),
    Derive(
        id="9.6",
        title="Velocity command",
        key=_U,
        label="commanded speed u",
        unit="m/s",
        slips=(
            Slip(_TARGET - _X_UPD, "That is the position error. The command multiplies it by Kp = 0.5."),
            Slip(-_U, "Sign: the error is target − position, positive here, so the robot drives forward."),
        ),
    ),
    Derive(
        id="9.7",
        title="An entry of the Jacobian F",
        key=_F[1][2],
        label="F(2,3)",
        slips=(
            Slip(_F[0][2], "That is F(1,3) = −v sin θ dt, in row 1. Row 2 is the derivative of y′."),
            Slip(_V * math.sin(_START[2]) * _DT, "∂(v sin θ dt)/∂θ = v cos θ dt, not v sin θ dt."),
        ),
    ),
    MatrixDerive(
        id="9.8",
        title="The whole predicted state",
        key=column(_PRED),
        label="x′ = (x′, y′, θ′)ᵀ",
        slips=(
            Slip(column(motion_model((_START[0], _START[1], _START[2] + _OMEGA * _DT), _V, _OMEGA, _DT)[:2]
                        + (_PRED[2],)),
                 "You turned first and then drove. The velocity model moves along the heading at the start "
                 "of the step, θ = π/6; the turn takes effect from the next step."),
            Slip(column((_START[0] + _V * math.sin(_START[2]) * _DT, _START[1] + _V * math.cos(_START[2]) * _DT,
                         _PRED[2])),
                 "sin and cos are swapped: x moves by v cos θ dt and y by v sin θ dt."),
            Slip(column(_PRED[:2] + (_START[2],)),
                 "The heading did not change: θ′ = θ + ω dt, and ω = 0.1 rad/s."),
        ),
    ),
)
