"""6.5 forward_kinematics_2link: the arm at each tested pair of angles, the true tip and yours."""

from __future__ import annotations

import math

from ...number_format import compact
from ..svg import Canvas
from . import Drawn, RunFigure
from .marks import INPUT, REFERENCE, YOURS, finite, inside, key, message, off_picture, with_message


def workspace(L1: float, L2: float, reference: str = "reference") -> Canvas:
    """A picture of the arm's reach: the grid, the key, the circle the tip can reach, the base."""
    reach = (abs(L1) + abs(L2)) * 1.2 or 1.0
    c = Canvas(360, 320, (-reach, reach), (-reach, reach), pad=(12, 12, 12, 24))
    c.grid(10 ** math.floor(math.log10(reach)) / 2, labels=False)
    key(c, reference=reference)
    c.circle((0, 0), abs(L1) + abs(L2), f"{INPUT} wb-fig-thin wb-fig-dash")
    if abs(L1 - L2) > 1e-9:
        c.circle((0, 0), abs(L1 - L2), f"{INPUT} wb-fig-thin wb-fig-dash")
    c.dot((0, 0), 6, f"{INPUT} wb-fig-solid")
    return c


def draw_arm(c: Canvas, elbow, tip, cls: str) -> None:
    """The two links, base to elbow to tip; the elbow a dot, the tip a ring."""
    c.polyline([(0, 0), inside(c, elbow), inside(c, tip)], f"{cls} wb-fig-thick")
    colour = cls.split()[0]
    c.dot(inside(c, elbow), 4, f"{colour} wb-fig-solid")
    c.dot(inside(c, tip), 6, colour)
    c.keep_clear([(0, 0), elbow, tip])


def frame(d: Drawn) -> tuple[str, str]:
    L1, L2, t1, t2 = d.args
    elbow = (L1 * math.cos(t1), L1 * math.sin(t1))
    tip = tuple(d.want)
    got = tuple(d.got) if d.got is not None and finite(*d.got) else None
    c = workspace(L1, L2, reference="true arm")
    draw_arm(c, elbow, tip, REFERENCE)
    said = d.message
    if got is not None:
        shown = inside(c, got)
        if off_picture(c, got):
            said = said or "your tip lies beyond the picture's edge"
        c.line(tip, shown, "wb-fig-bad wb-fig-thin")
        c.line(elbow, shown, f"{YOURS} wb-fig-thin")
        c.dot(shown, 5, f"{YOURS} wb-fig-solid")
        c.label(shown, "your tip", "wb-fig-label wb-fig-small "
                                   f"{YOURS}", toward=(shown[0] - elbow[0], shown[1] - elbow[1]))
    c.label(tip, "true tip", "wb-fig-label wb-fig-small wb-fig-c", toward=(tip[0] - elbow[0], tip[1] - elbow[1]))
    below = message(c, said)
    pose = (f"links {compact(L1)} and {compact(L2)} at θ1 = {compact(math.degrees(t1))}°, "
            f"θ2 = {compact(math.degrees(t2))}°")
    where = (f"your function puts the tip at ({compact(got[0])}, {compact(got[1])})" if got is not None
             else "your function gave no tip to draw")
    description = f"{d.label}: {pose}; the true tip is at ({compact(tip[0])}, {compact(tip[1])}); {where}."
    description = with_message(description, said)
    return c.svg(f"forward_kinematics_2link, {d.label}: the arm, its true tip and "
                 "yours", extra_height=below), description


RUN = RunFigure(name="arm", title="Your forward kinematics, drawn", unit="m", frame=frame, points=True)
