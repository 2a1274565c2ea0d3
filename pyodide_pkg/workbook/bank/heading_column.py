"""Exercise 3.9's two cases: an entry of the EKF Jacobian's heading column as a formula in v, θ and dt.

``heading_column_formula(p)`` is the generator (``p["entry"]`` is ``"1,3"`` or
``"2,3"``); each case names its key, its worked formula, its slips and the text
that fills the chapter's placeholders, with the value at the workbook's own
numbers of the exercise it generalises.

>>> made = heading_column_formula({"entry": "2,3"})
>>> made["answer_text"], made["values"]["rval"]
('v*cos(theta)*dt', '1')
"""

import math
from typing import Any

from ..answer_kinds.base import Slip
from ..number_format import fmt
from ..reference.ekf import motion_jacobian


def _f13(v, theta, dt):
    return motion_jacobian((0.0, 0.0, theta), v, 0.0, dt)[0][2]


def _f23(v, theta, dt):
    return motion_jacobian((0.0, 0.0, theta), v, 0.0, dt)[1][2]


_HEADING_COLUMN: dict[str, dict[str, Any]] = {
    "1,3": {
        "key": _f13, "answer_text": "-v*sin(theta)*dt",
        "values": {"Fij": "F_{13}", "coord": "x", "model": "x' = x + v\\cos\\theta\\,dt",
                   "rhs": "x + v\\cos\\theta\\,dt", "deriv": "-v\\sin\\theta\\,dt", "trig": "\\cos\\theta",
                   "ref": "Exercise 3.3, with the workbook's numbers,"},
        "at": (1, math.pi / 2, 0.5, "\\pi/2"),
        "slips": (
            Slip(lambda v, theta, dt: v * math.sin(theta) * dt,
                 "The sign is flipped: the derivative of cos θ is −sin θ.", name="sign-flipped-derivative-cos"),
            Slip(lambda v, theta, dt: -v * math.cos(theta) * dt,
                 "That differentiates to cos θ. x′ contains v cos θ dt, whose derivative by θ is −v sin θ dt.",
                     name="differentiates-cos-theta-xp"),
            Slip(lambda v, theta, dt: -v * math.sin(theta),
                 "You left out dt: the robot drives for dt seconds, so every displacement carries a factor dt.",
                     name="left-out-dt-robot"),
            Slip(lambda v, theta, dt: v * math.cos(theta) * dt,
                 "That is F(2,3), the derivative of y′. F(1,3) is the derivative of x′ = x + v cos θ dt.",
                     name="f-2-3-derivative"),
        ),
    },
    "2,3": {
        "key": _f23, "answer_text": "v*cos(theta)*dt",
        "values": {"Fij": "F_{23}", "coord": "y", "model": "y' = y + v\\sin\\theta\\,dt",
                   "rhs": "y + v\\sin\\theta\\,dt", "deriv": "v\\cos\\theta\\,dt", "trig": "\\sin\\theta",
                   "ref": "The (2,3) entry of exercise 3.4's F, with the workbook's numbers,"},
        "at": (1, 0.0, 1, "0"),
        "slips": (
            Slip(lambda v, theta, dt: -v * math.cos(theta) * dt,
                 "The sign is flipped: the derivative of sin θ is +cos θ, with no minus.",
                     name="sign-flipped-derivative-sin"),
            Slip(lambda v, theta, dt: v * math.sin(theta) * dt,
                 "That is the term itself, not its derivative. y′ contains v sin θ dt, whose derivative by θ "
                 "is v cos θ dt.", name="term-itself-derivative-yp"),
            Slip(lambda v, theta, dt: v * math.cos(theta),
                 "You left out dt: the robot drives for dt seconds, so every displacement carries a factor dt.",
                     name="left-out-dt-robot"),
            Slip(lambda v, theta, dt: -v * math.sin(theta) * dt,
                 "That is F(1,3), the derivative of x′. F(2,3) is the derivative of y′ = y + v sin θ dt.",
                     name="f-1-3-derivative"),
        ),
    },
}


def heading_column_formula(p):
    """3.9: an entry of F's heading column, F(1,3) or F(2,3), as a formula in v, θ, dt."""
    case = _HEADING_COLUMN[p["entry"]]
    v, theta, dt, theta_tex = case["at"]
    return {
        "title": f"F({p['entry']}) as a formula",
        "label": f"F({p['entry']})",
        "key": case["key"],
        "answer_text": case["answer_text"],
        "slips": case["slips"],
        "values": {**case["values"], "rv": fmt(v), "rth": theta_tex, "rdt": fmt(dt),
                   "rval": fmt(case["key"](v, theta, dt))},
    }
