"""6.7 ik_2link: the arm at the angles your inverse kinematics gives, beside the reference's, and the
target both should reach (or a note that it is out of reach)."""

from __future__ import annotations

import math

from ...number_format import compact
from ...reference.arm import forward_kinematics_2link
from . import Drawn, RunFigure
from .arm import draw_arm, workspace
from .marks import REFERENCE, YOURS, finite, message, with_message


def _joints(L1: float, L2: float, angles) -> tuple[tuple[float, float], tuple[float, float]]:
    t1, t2 = angles
    return (L1 * math.cos(t1), L1 * math.sin(t1)), forward_kinematics_2link(L1, L2, t1, t2)


def _angles(pair) -> str:
    return f"θ1 = {compact(math.degrees(pair[0]))}°, θ2 = {compact(math.degrees(pair[1]))}°"


def frame(d: Drawn) -> tuple[str, str]:
    L1, L2, x, y, elbow_up = d.args
    c = workspace(L1, L2)
    c.line((x - 0.1 * L1, y), (x + 0.1 * L1, y), "wb-fig-b")
    c.line((x, y - 0.1 * L1), (x, y + 0.1 * L1), "wb-fig-b")
    c.label((x, y), "target", "wb-fig-label wb-fig-small wb-fig-b", toward=(x, y))
    said = d.message
    if d.want is not None:
        draw_arm(c, *_joints(L1, L2, d.want), REFERENCE)
        truth = f"the reference reaches it with {_angles(d.want)}"
    else:
        truth = "the target is out of reach, and the reference returns None"
    got = d.got if d.got is not None else d.raw  # angles where the reference refuses are still drawn
    if got is not None and len(got) == 2 and finite(*got):
        elbow, tip = _joints(L1, L2, got)
        draw_arm(c, elbow, tip, YOURS)
        miss = math.hypot(tip[0] - x, tip[1] - y)
        yours = f"your angles, {_angles(got)}, put the tip {compact(miss)} m from the target"
    elif got is None and d.want is None and not said:
        yours = "your function returns None too"
    else:
        yours = "your function gave no angles to draw"
    below = message(c, said)
    which = "elbow-up" if elbow_up else "elbow-down"
    description = with_message(f"{d.label}: links {compact(L1)} m and {compact(L2)} m, target ({compact(x)}, "
                               f"{compact(y)}), {which}; {truth}; {yours}.", said)
    return c.svg(f"ik_2link, {d.label}: the arm at your angles and at the reference's", extra_height=below), description


RUN = RunFigure(name="ik", title="Your inverse kinematics, drawn", unit="rad", frame=frame)
