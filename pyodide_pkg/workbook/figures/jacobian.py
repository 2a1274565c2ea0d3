"""Chapter 7: the velocity (manipulability) ellipse of the two-link arm.

Every joint-rate vector of length 1 maps through J to a tip velocity; together
they trace an ellipse at the tip. It flattens to a line as det J → 0.
"""

from __future__ import annotations

import math

from ..number_format import prose, readout, readout_matrix
from ..reference.arm import (
    end_effector_velocity,
    forward_kinematics_2link,
    jacobian_2link,
    jacobian_det,
    manipulability,
)
from . import Control, Figure, Readout
from .svg import Canvas

L1, L2 = 1.0, 0.7
SCALE = 0.45  # draw a velocity of 1 m/s as 0.45 m
NEAR_SINGULAR = 0.15  # |det J| below this fraction of its peak L1·L2 counts as near a singularity


def velocity_ellipse(J, n: int = 72) -> list[tuple[float, ...]]:
    """J·(cos t, sin t) for t around the circle: the tip velocities of unit joint rates.

    >>> [tuple(round(v, 6) + 0.0 for v in p) for p in velocity_ellipse([[1, 0], [0, 2]], n=4)]
    [(1.0, 0.0), (0.0, 2.0), (-1.0, 0.0), (0.0, -2.0)]
    """
    return [tuple(end_effector_velocity(J, (math.cos(2 * math.pi * k / n), math.sin(2 * math.pi * k / n))))
            for k in range(n)]


def draw(p: dict[str, float]) -> dict:
    t1, t2 = math.radians(p["theta1"]), math.radians(p["theta2"])
    J = jacobian_2link(L1, L2, t1, t2)
    det = jacobian_det(L1, L2, t1, t2)
    w = manipulability(J)
    singular = w < NEAR_SINGULAR * L1 * L2
    flags = ["singular"] if singular else []
    tip = forward_kinematics_2link(L1, L2, t1, t2)
    elbow = (L1 * math.cos(t1), L1 * math.sin(t1))
    c = Canvas(400, 400, (-2.2, 2.2), (-2.2, 2.2))
    c.grid(0.5, labels=False)
    ring = [(tip[0] + SCALE * vx, tip[1] + SCALE * vy) for vx, vy in velocity_ellipse(J)]
    tone = "wb-fig-bad" if singular else "wb-fig-b"
    c.polygon(ring, f"{tone} wb-fig-area")
    for k in (0, 1):
        end = (tip[0] + SCALE * J[0][k], tip[1] + SCALE * J[1][k])
        c.arrow(tip, end, "wb-fig-c")
        # placed when the picture is done: clear of the arm, the arrows and each other
        c.label(end, f"col {k + 1}", "wb-fig-label wb-fig-small wb-fig-c", toward=(J[0][k], J[1][k]))
    c.polyline([(0, 0), elbow, tip], "wb-fig-a wb-fig-thick")
    c.keep_clear([(0, 0), elbow, tip])
    c.dot(elbow, 6, "wb-fig-a wb-fig-solid")
    c.dot((0, 0), 7, "wb-fig-muted wb-fig-solid")
    c.dot(tip, 4, "wb-fig-a wb-fig-solid")
    svg = c.svg(f"Arm at θ1 = {prose(p['theta1'])}°, θ2 = {prose(p['theta2'])}°; det J = {readout(det)}"
                + (", near a singularity" if singular else ""), css=" ".join(flags))
    return {"svg": svg, "flags": flags, "readouts": {
        "J": readout_matrix(J),
        "det": readout(det),
        "status": ("near a singularity: the tip barely moves along the arm" if singular
                   else "well away from a singularity"),
    }}


FIGURE = Figure(
    name="jacobian",
    title="Velocity ellipse",
    caption=f"Links L1 = {L1:g} m and L2 = {L2:g} m. The shaded ellipse holds every tip velocity the joints can "
            "make with unit total joint rate (arrows: the columns of J, one joint at a time). As θ2 nears 0° or "
            "±180° it flattens, det J = L1·L2·sin θ2 heads to zero, and the figure turns red.",
    controls=(
        Control("theta1", "Shoulder θ1", -180, 180, 1, 30, "°"),
        Control("theta2", "Elbow θ2", -180, 180, 1, 70, "°"),
    ),
    readouts=(
        Readout("J", "J", matrix=True),
        Readout("det", "det J"),
        Readout("status", "status", text=True),
    ),
    draw=draw,
)
