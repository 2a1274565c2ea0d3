"""Chapter 1: world, robot and sensor frames, and one point seen from all three.

The sensor sits at a fixed place on the robot, turned by an adjustable mount
angle; it sees a point at fixed sensor coordinates. The chain
T_world_sensor = T_world_robot · T_robot_sensor carries that point to the world.
"""

from __future__ import annotations

import math

from ..number_format import readout_matrix, readout_vector
from ..reference.transform2d import apply, chain, transform2d
from . import Control, Figure, Readout
from .svg import Canvas

SENSOR_OFFSET = (0.5, 0.0)  # where the sensor is mounted, in the robot frame (m)
POINT_IN_SENSOR = (1.2, 0.4)  # what the sensor sees, in its own frame (m)


def frames(p: dict[str, float]):
    """T_world_robot, T_robot_sensor and their chain for the control values ``p``.

    >>> Twr, Trs, Tws = frames({"x": 1, "y": 0, "heading": 0, "mount": 0})
    >>> apply(Tws, *POINT_IN_SENSOR)
    (2.7, 0.4)
    """
    Twr = transform2d(p["x"], p["y"], math.radians(p["heading"]))
    Trs = transform2d(*SENSOR_OFFSET, math.radians(p["mount"]))
    return Twr, Trs, chain(Twr, Trs)


def _axes(c: Canvas, T, length: float, cls: str, name: str) -> None:
    origin = apply(T, 0, 0)
    c.arrow(origin, apply(T, length, 0), cls)
    c.arrow(origin, apply(T, 0, length), cls)
    c.text(apply(T, length + 0.18, 0), f"x{name}", "wb-fig-label wb-fig-small " + cls.split()[0], dy=4)
    c.text(apply(T, 0, length + 0.18), f"y{name}", "wb-fig-label wb-fig-small " + cls.split()[0], dy=4)


def draw(p: dict[str, float]) -> dict:
    Twr, Trs, Tws = frames(p)
    point_robot = apply(Trs, *POINT_IN_SENSOR)
    point_world = apply(Tws, *POINT_IN_SENSOR)
    c = Canvas(440, 400, (-1.6, 4.6), (-1.6, 4.0))
    c.grid(1.0, labels=False)
    _axes(c, transform2d(0, 0, 0), 1.0, "wb-fig-muted", "w")
    body = [apply(Twr, *q) for q in ((0.35, 0), (-0.25, 0.22), (-0.25, -0.22))]
    c.polygon(body, "wb-fig-a wb-fig-area")
    _axes(c, Twr, 0.8, "wb-fig-a", "r")
    _axes(c, Tws, 0.55, "wb-fig-b wb-fig-thin", "s")
    sensor = apply(Tws, 0, 0)
    c.line(sensor, point_world, "wb-fig-b wb-fig-thin wb-fig-dash")
    c.dot(point_world, 5.5, "wb-fig-c wb-fig-solid")
    c.tag(point_world, "p", "wb-fig-label wb-fig-c")
    svg = c.svg(f"Robot at ({p['x']:g}, {p['y']:g}) heading {p['heading']:g}°, sensor turned {p['mount']:g}°; "
                f"the point p is at {readout_vector(point_world, 2)} in the world")
    return {"svg": svg, "readouts": {
        "sensor": readout_vector(POINT_IN_SENSOR),
        "robot": readout_vector(point_robot),
        "world": readout_vector(point_world),
        "T": readout_matrix(Tws),
    }}


FIGURE = Figure(
    name="frames",
    title="One point, three frames",
    caption="The sensor always reads the same coordinates for p. Move and turn the robot, or turn the sensor "
            "on its mount, and watch the chain T_ws = T_wr · T_rs (T_ab takes frame-b coordinates to frame a) "
            "carry p into the robot and world frames.",
    controls=(
        Control("x", "Robot x", -1, 3, 0.1, 1.0, "m"),
        Control("y", "Robot y", -1, 2.5, 0.1, 0.5, "m"),
        Control("heading", "Robot heading", -180, 180, 1, 30, "°"),
        Control("mount", "Sensor mount angle", -90, 90, 1, 20, "°"),
    ),
    readouts=(
        Readout("sensor", "p in the sensor frame"),
        Readout("robot", "p in the robot frame"),
        Readout("world", "p in the world frame"),
        Readout("T", "T_ws = T_wr · T_rs", matrix=True),
    ),
    draw=draw,
)
