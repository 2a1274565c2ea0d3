"""Chapter 0: a point p and its image R(θ)p, the arc between them, and R(θ) itself."""

from __future__ import annotations

import math

from ..number_format import readout_matrix, readout_vector
from ..reference.rotation2d import rot2, rotate_2d
from . import Control, Figure, Readout
from .svg import Canvas


def arc_points(radius: float, start: float, sweep: float, n: int = 48) -> list[tuple[float, float]]:
    """Points on a circle about the origin from angle ``start`` through ``sweep`` (radians).

    >>> [tuple(round(v, 3) + 0.0 for v in p) for p in arc_points(1, 0, math.pi / 2, n=2)]
    [(1.0, 0.0), (0.0, 1.0)]
    """
    return [(radius * math.cos(start + sweep * k / (n - 1)), radius * math.sin(start + sweep * k / (n - 1)))
            for k in range(n)]


def draw(p: dict[str, float]) -> dict:
    theta = math.radians(p["theta"])
    px, py = p["px"], p["py"]
    qx, qy = rotate_2d(px, py, theta)
    R = rot2(theta)
    c = Canvas(400, 400, (-2.3, 2.3), (-2.3, 2.3))
    c.grid(1.0, labels=False)  # the axis names are placed labels (below), clear of the arrows
    # the rotated basis: the columns of R(θ)
    c.arrow((0, 0), (R[0][0], R[1][0]), "wb-fig-c wb-fig-thin")
    c.arrow((0, 0), (R[0][1], R[1][1]), "wb-fig-c wb-fig-thin")
    radius = math.hypot(px, py)
    if radius > 1e-9:
        start = math.atan2(py, px)
        c.polyline(arc_points(radius, 0, 2 * math.pi, 96), "wb-fig-muted wb-fig-thin wb-fig-dash")
        if abs(theta) > 1e-9:
            pts = arc_points(radius * 0.45, start, theta)
            c.polyline(pts[:-1], "wb-fig-b wb-fig-thin")
            c.keep_clear(pts[::6] + pts[-1:])  # the arc, coarsely: enough to keep labels off it
            c.arrow(pts[-4], pts[-1], "wb-fig-b wb-fig-thin", head=8)
            arc_mid = arc_points(radius * 0.45, start, theta / 2, n=2)[-1]
    c.arrow((0, 0), (px, py), "wb-fig-a wb-fig-thick")
    c.arrow((0, 0), (qx, qy), "wb-fig-b wb-fig-thick")
    c.dot((px, py), 5, "wb-fig-a wb-fig-solid")
    c.dot((qx, qy), 5, "wb-fig-b wb-fig-solid")
    # Labels are placed last, clear of each other and of every arrow, in this
    # order (the points first, the axes' names last); each prefers to sit beyond the tip of its vector.
    c.label((px, py), "p", "wb-fig-label wb-fig-a", toward=(px, py))
    c.label((qx, qy), "p′ = R(θ)p", "wb-fig-label wb-fig-b", toward=(qx, qy))
    if radius > 1e-9 and abs(theta) > 1e-9:
        c.label(arc_mid, "θ", "wb-fig-label wb-fig-b", toward=arc_mid)
    for k in (0, 1):
        col = (R[0][k], R[1][k])
        c.label(col, f"col {k + 1}", "wb-fig-label wb-fig-small wb-fig-c", toward=col)
    c.label((2.3, 0), "x", "wb-fig-label wb-fig-small", toward=(-1, -1))
    c.label((0, 2.3), "y", "wb-fig-label wb-fig-small", toward=(1, -1))
    svg = c.svg(f"The point p = ({px:g}, {py:g}) turned by {p['theta']:g}° about the origin")
    return {
        "svg": svg,
        "readouts": {"R": readout_matrix(R), "point": readout_vector((px, py)), "image": readout_vector((qx, qy))},
    }


FIGURE = Figure(
    name="rotation-2d",
    title="Rotating a point",
    caption="Drag the angle: p′ = R(θ)p swings along the dashed circle, and the columns of R(θ) "
            "are where the x- and y-axes land.",
    controls=(
        Control("theta", "Angle θ", -180, 180, 1, 30, "°"),
        Control("px", "Point x", -2, 2, 0.1, 1.5),
        Control("py", "Point y", -2, 2, 0.1, 0.5),
    ),
    readouts=(Readout("R", "R(θ)", matrix=True), Readout("point", "p"), Readout("image", "p′ = R(θ)p")),
    draw=draw,
)
