"""Chapter 11: the chapter's 3R arm in space (a base about z, a shoulder and an elbow about −y), its
joints moved by sliders, its screw axes drawn where the joints before them carried them (the columns
of the space Jacobian), seen from a viewpoint the reader turns about the vertical.

The tool's pose comes from the product of exponentials (``reference.screw.fk_poe``); the view is
chapter 10's orthographic one (``figures.poses_3d.view``).
"""

from __future__ import annotations

import math

from ..number_format import readout_matrix, readout_vector
from ..reference.screw import arm_home, arm_points, arm_screws, fk_poe, jacobian_space
from ..reference.se3 import rotation_of, translation_of
from . import Control, Figure, Readout
from .poses_3d import COLOURS, view
from .svg import Canvas

L0, L1, L2 = 1.0, 1.2, 0.9  # the drawn arm's lengths (m)
AXIS = 0.45  # drawn length of the tool frame's axes
HALF_AXIS = 0.55  # how far each screw axis is drawn on either side of its joint


def arm(t1: float, t2: float, t3: float):
    """The tool's pose, the joints' positions and the space Jacobian's columns at these angles (degrees).

    >>> T, points, J = arm(0, 90, 0)
    >>> [round(c, 9) + 0.0 for c in translation_of(T)]
    [0.0, 0.0, 3.1]
    """
    theta = [math.radians(t) for t in (t1, t2, t3)]
    S = arm_screws(L0, L1)
    return (fk_poe(arm_home(L0, L1, L2), S, theta), arm_points(L0, L1, L2, theta), jacobian_space(S, theta))


def draw(p: dict[str, float]) -> dict:
    right, up = view(p["view"])

    def at(point) -> tuple[float, float]:
        return (sum(a * b for a, b in zip(point, right)), sum(a * b for a, b in zip(point, up)))

    T, points, J = arm(p["t1"], p["t2"], p["t3"])
    c = Canvas(420, 380, (-3.0, 3.0), (-1.6, 3.8))
    for k in range(5):  # the floor's grid, for depth
        c.line(at((k * 0.8 - 1.6, -1.6, 0)), at((k * 0.8 - 1.6, 1.6, 0)), "wb-fig-muted wb-fig-thin wb-fig-dash")
        c.line(at((-1.6, k * 0.8 - 1.6, 0)), at((1.6, k * 0.8 - 1.6, 0)), "wb-fig-muted wb-fig-thin wb-fig-dash")
    for (w, name), joint in zip(((col[:3], n) for col, n in zip(J, ("S₁", "J_s2", "J_s3"))), points[:3]):
        ends = [[joint[i] + s * HALF_AXIS * w[i] for i in range(3)] for s in (-1, 1)]
        c.line(at(ends[0]), at(ends[1]), "wb-fig-b wb-fig-dash wb-fig-thin")
        c.label(at(ends[1]), name, "wb-fig-label wb-fig-small wb-fig-b", toward=at(joint))
    c.polyline([at(q) for q in points], "wb-fig-a wb-fig-thick")
    for q in points[:3]:
        c.dot(at(q), 4, "wb-fig-a wb-fig-solid")
    o, R = translation_of(T), rotation_of(T)
    for k in range(3):
        tip = [o[i] + AXIS * R[i][k] for i in range(3)]
        c.arrow(at(o), at(tip), COLOURS[k] + " wb-fig-thick")
        c.label(at([o[i] + 1.25 * AXIS * R[i][k] for i in range(3)]), "xyz"[k],
                f"wb-fig-label wb-fig-small {COLOURS[k]}", toward=at(tip))
    svg = c.svg(f"The 3-joint arm at base {p['t1']:g}°, shoulder {p['t2']:g}°, elbow {p['t3']:g}°, seen from "
                f"azimuth {p['view']:g}°: the tool is at ({', '.join(f'{v:.2f}' for v in o)}) m")
    columns = [[col[i] for col in J] for i in range(6)]
    return {"svg": svg, "flags": [], "readouts": {
        "T": readout_matrix(T),
        "p": readout_vector(o),
        "J": readout_matrix(columns),
    }}


FIGURE = Figure(
    name="arm-3d",
    title="A three-joint arm in space",
    caption=f"The chapter's arm with L₀ = {L0:g} m, L₁ = {L1:g} m and L₂ = {L2:g} m: the links (thick), the "
            "tool's frame (x red, y green, z blue), and the three screw axes where the joints before them "
            "have carried them (dashed), which are the columns of the space Jacobian. Turn the view (its "
            "slider, or drag across the picture) to see the arm from another side. The readouts are the "
            "tool's pose T = e^[S₁]θ₁ e^[S₂]θ₂ e^[S₃]θ₃ M, its position, and J_s.",
    controls=(
        Control("t1", "Base θ₁ (about z)", -180, 180, 5, 30, "°"),
        Control("t2", "Shoulder θ₂ (about −y at home)", -90, 135, 5, 40, "°"),
        Control("t3", "Elbow θ₃ (about −y at home)", -150, 150, 5, -60, "°"),
        Control("view", "View from (azimuth)", -180, 180, 5, -55, "°"),
    ),
    readouts=(
        Readout("T", "T, the tool's pose", matrix=True),
        Readout("p", "tool position (m)"),
        Readout("J", "J_s, the space Jacobian (6 × 3)", matrix=True),
    ),
    draw=draw,
    orbit="view",
)
