"""Chapter 10: a chain of three frames in space, world → base → camera, seen from a viewpoint the
reader turns about the vertical (an orbit), with the chained pose and its quaternion in both
storage orders.

Drawn in an orthographic view: a world point lands on the screen at (p·right, p·up) for the unit
vectors of a camera at azimuth ``view`` and a fixed elevation.
"""

from __future__ import annotations

import math

from ..number_format import readout_matrix, readout_vector
from ..reference.rotation3d import quat_from_matrix, ry, rz
from ..reference.se3 import compose, pose, rotation_of, to_xyzw, transform_point, translation_of
from . import Control, Figure, Readout
from .svg import Canvas

ELEVATION = math.radians(24)
BASE_AT = (0.4, 1.6, 0.0)  # where the base stands in the world
CAM_ON_BASE = (0.6, 0.0, 0.9)  # where the camera sits on the base
AXIS = 0.55  # drawn length of a frame's axes (world units)
COLOURS = ("wb-fig-x", "wb-fig-y", "wb-fig-z")


def view(azimuth_deg: float):
    """The screen's right and up vectors for a viewer at this azimuth (degrees) and the fixed elevation.

    >>> right, up = view(0)
    >>> [round(v, 4) + 0.0 for v in right], [round(v, 4) + 0.0 for v in up]
    ([0.0, 1.0, 0.0], [-0.4067, 0.0, 0.9135])
    """
    a = math.radians(azimuth_deg)
    right = (-math.sin(a), math.cos(a), 0.0)
    up = (-math.sin(ELEVATION) * math.cos(a), -math.sin(ELEVATION) * math.sin(a), math.cos(ELEVATION))
    return right, up


def chain(yaw_deg: float, tilt_deg: float):
    """T_world_base (a yaw about the world's z, at BASE_AT), T_base_cam (a tilt about the base's y, at
    CAM_ON_BASE) and their product T_world_cam.

    >>> T_wb, T_bc, T_wc = chain(90, 0)
    >>> [round(v, 9) + 0.0 for v in translation_of(T_wc)]
    [0.4, 2.2, 0.9]
    """
    T_wb = pose(rz(math.radians(yaw_deg)), BASE_AT)
    T_bc = pose(ry(math.radians(tilt_deg)), CAM_ON_BASE)
    return T_wb, T_bc, compose(T_wb, T_bc)


def draw(p: dict[str, float]) -> dict:
    right, up = view(p["view"])

    def at(point) -> tuple[float, float]:
        return (sum(a * b for a, b in zip(point, right)), sum(a * b for a, b in zip(point, up)))

    T_wb, _T_bc, T_wc = chain(p["yaw"], p["tilt"])
    origins = [(0.0, 0.0, 0.0), translation_of(T_wb), translation_of(T_wc)]
    middle = at([sum(o[i] for o in origins) / 3 + (0.3 if i == 2 else 0.0) for i in range(3)])
    c = Canvas(420, 360, (middle[0] - 1.75, middle[0] + 1.75), (middle[1] - 1.5, middle[1] + 1.5))
    for k in range(4):  # the floor's grid lines, for depth
        c.line(at((k * 0.6 - 0.6, -0.6, 0)), at((k * 0.6 - 0.6, 2.4, 0)), "wb-fig-muted wb-fig-thin wb-fig-dash")
    for k in range(6):
        c.line(at((-0.6, k * 0.6 - 0.6, 0)), at((1.2, k * 0.6 - 0.6, 0)), "wb-fig-muted wb-fig-thin wb-fig-dash")
    c.line(at(origins[0]), at(origins[1]), "wb-fig-muted wb-fig-dash")
    c.line(at(origins[1]), at(origins[2]), "wb-fig-muted wb-fig-dash")
    frames = (("world", [[1.0, 0.0, 0.0, 0.0], [0.0, 1.0, 0.0, 0.0], [0.0, 0.0, 1.0, 0.0], [0.0, 0.0, 0.0, 1.0]]),
              ("base", T_wb), ("cam", T_wc))
    for name, T in frames:
        o = translation_of(T)
        R = rotation_of(T)
        for k in range(3):
            tip = [o[i] + AXIS * R[i][k] for i in range(3)]
            thin = " wb-fig-thin" if name == "world" else " wb-fig-thick"
            c.arrow(at(o), at(tip), COLOURS[k] + thin)
            c.label(at([o[i] + 1.2 * AXIS * R[i][k] for i in range(3)]), "xyz"[k], f"wb-fig-label wb-fig-small "
                    f"{COLOURS[k]}", toward=at(tip))
        c.text(at(o), name, "wb-fig-label wb-fig-small", dy=18)
    ahead = transform_point(T_wc, (0.8, 0.0, 0.0))  # where the camera looks: along its own x
    c.line(at(origins[2]), at(ahead), "wb-fig-b wb-fig-dash wb-fig-thin")
    q = quat_from_matrix(rotation_of(T_wc))
    svg = c.svg(f"Frames world, base and cam: the base yawed {p['yaw']:g}°, the camera tilted {p['tilt']:g}°, "
                f"seen from azimuth {p['view']:g}°")
    return {"svg": svg, "flags": [], "readouts": {
        "T": readout_matrix(T_wc),
        "p": readout_vector(translation_of(T_wc)),
        "wxyz": readout_vector(q),
        "xyzw": readout_vector(to_xyzw(q)),
    }}


FIGURE = Figure(
    name="poses-3d",
    title="A chain of frames in space",
    caption="World, base and camera frames (x red, y green, z blue; the world's axes thin). The dashed lines "
            "follow the chain world → base → cam, and the thin blue dashes show where the camera looks (its x). "
            "Turn the view (its slider, or drag across the picture) to see the frames from another side; "
            "the readouts are T_world_cam = "
            "T_world_base · T_base_cam and its quaternion, scalar first and scalar last.",
    controls=(
        Control("yaw", "Base yaw (about world z)", -180, 180, 5, 30, "°"),
        Control("tilt", "Camera tilt (about base y)", -60, 60, 5, 20, "°"),
        Control("view", "View from (azimuth)", -180, 180, 5, 35, "°"),
    ),
    readouts=(
        Readout("T", "T_world_cam", matrix=True),
        Readout("p", "camera position in the world"),
        Readout("wxyz", "quaternion (w, x, y, z), as this workbook writes it"),
        Readout("xyzw", "the same as ROS and SciPy store it (x, y, z, w)"),
    ),
    draw=draw,
    orbit="view",
)
