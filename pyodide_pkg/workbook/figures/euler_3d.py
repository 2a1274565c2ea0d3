"""Chapter 2: ZYX Euler angles turning a body in space, its quaternion, and
gimbal lock as the pitch reaches ±90°.

Drawn in an orthographic view: a world point (x, y, z) lands on the screen at
(p·right, p·up) for two fixed unit vectors of the camera.
"""

from __future__ import annotations

import math

from ..number_format import readout, readout_matrix, readout_vector
from ..reference.linalg import matvec
from ..reference.rotation3d import euler_zyx, gimbal_lock_angle, gimbal_locked, quat_from_matrix
from . import Control, Figure, Readout
from .svg import Canvas

AZIMUTH, ELEVATION = math.radians(35), math.radians(22)
RIGHT = (-math.sin(AZIMUTH), math.cos(AZIMUTH), 0.0)
UP = (-math.sin(ELEVATION) * math.cos(AZIMUTH), -math.sin(ELEVATION) * math.sin(AZIMUTH), math.cos(ELEVATION))
TOWARD_VIEWER = (math.cos(ELEVATION) * math.cos(AZIMUTH), math.cos(ELEVATION) * math.sin(AZIMUTH), math.sin(ELEVATION))
BOX = (1.0, 0.6, 0.15)  # half sizes of the body along its x, y, z
NEAR_LOCK_DEG = 10.0


def project(p) -> tuple[float, float]:
    """Screen coordinates of a 3D point in the orthographic view.

    >>> [round(v, 4) + 0.0 for v in project((0, 0, 1))]
    [0.0, 0.9272]
    """
    return (sum(a * b for a, b in zip(p, RIGHT)), sum(a * b for a, b in zip(p, UP)))


def depth(p) -> float:
    return sum(a * b for a, b in zip(p, TOWARD_VIEWER))


def axes_angle_deg(R) -> float:
    """The angle between the yaw axis (world z) and the roll axis (the body's x, R's first column).

    >>> round(axes_angle_deg(euler_zyx(0.3, math.radians(60), 0.1)), 6)
    30.0
    """
    return math.degrees(math.acos(min(1.0, abs(R[2][0]))))


def _box_faces(R):
    hx, hy, hz = BOX
    corners = {
        (sx, sy, sz): matvec(R, [sx * hx, sy * hy, sz * hz]) for sx in (-1, 1) for sy in (-1, 1) for sz in (-1, 1)
    }
    faces = []
    for axis in range(3):
        for sign in (-1, 1):
            keys = [k for k in corners if k[axis] == sign]
            a, b = [i for i in range(3) if i != axis]
            keys.sort(key=lambda k: math.atan2(k[b], k[a]))
            pts = [corners[k] for k in keys]
            faces.append((sum(depth(q) for q in pts) / 4, axis == 2 and sign == 1, pts))
    return sorted(faces, key=lambda f: f[0])


def draw(p: dict[str, float]) -> dict:
    yaw, pitch, roll = (math.radians(p[k]) for k in ("yaw", "pitch", "roll"))
    R = euler_zyx(yaw, pitch, roll)
    q = quat_from_matrix(R)
    apart = axes_angle_deg(R)
    locked = gimbal_locked(pitch)
    flags = []
    if locked:
        psi = gimbal_lock_angle(yaw, 1 if pitch > 0 else -1, roll)
        combo = "yaw − roll" if pitch > 0 else "yaw + roll"
        status = f"locked: yaw and roll turn about one axis; only {combo} = {readout(math.degrees(psi), 0)}° counts"
        flags.append("gimbal-lock")
    elif apart < NEAR_LOCK_DEG:
        status = f"nearly locked: the yaw and roll axes are {readout(apart, 0)}° apart"
        flags.append("gimbal-lock")
    else:
        status = f"free: the yaw and roll axes are {readout(apart, 0)}° apart"

    c = Canvas(400, 360, (-1.9, 1.9), (-1.7, 1.7))
    for k, name in enumerate("XYZ"):
        tip = [1.55 if i == k else 0.0 for i in range(3)]
        cls = "wb-fig-warn" if (k == 2 and flags) else "wb-fig-muted"
        c.arrow(project((0, 0, 0)), project(tip), f"{cls} wb-fig-thin")
        c.text(project([1.72 if i == k else 0.0 for i in range(3)]), name, f"wb-fig-label wb-fig-small {cls}", dy=5)
    c.text(project((0, 0, 1.72)), "yaw axis", "wb-fig-label wb-fig-small wb-fig-muted", dx=14, dy=5, anchor="start")
    for _, top, pts in _box_faces(R):
        c.polygon([project(v) for v in pts], "wb-fig-a wb-fig-face" + (" wb-fig-top" if top else ""))
    colours = ("wb-fig-x", "wb-fig-y", "wb-fig-z")
    for k in range(3):
        tip = [R[i][k] * 1.35 for i in range(3)]
        cls = colours[k] + (" wb-fig-warn" if (k == 0 and flags) else "")
        c.arrow(project((0, 0, 0)), project(tip), f"{cls} wb-fig-thick")
        c.text(project([R[i][k] * 1.52 for i in range(3)]), "xyz"[k] + "′", f"wb-fig-label {colours[k]}", dy=5)
    svg = c.svg(f"A body turned by yaw {p['yaw']:g}°, pitch {p['pitch']:g}°, roll {p['roll']:g}° (ZYX)")
    return {"svg": svg, "flags": flags, "readouts": {
        "R": readout_matrix(R),
        "q": readout_vector(q),
        "gimbal": status,
        "apart": f"{readout(apart, 1)}°",
    }}


FIGURE = Figure(
    name="euler-3d",
    title="Yaw, pitch, roll",
    caption="R = Rz(yaw) · Ry(pitch) · Rx(roll), seen at an angle: x′ (the roll axis) in red, y′ green, z′ blue; "
            "Z is the yaw axis. Push the pitch to ±90°: x′ swings onto Z, and yaw and roll do the same job.",
    controls=(
        Control("yaw", "Yaw (about Z)", -180, 180, 1, 30, "°"),
        Control("pitch", "Pitch (about y)", -90, 90, 1, 20, "°"),
        Control("roll", "Roll (about x)", -180, 180, 1, 10, "°"),
    ),
    readouts=(
        Readout("R", "R", matrix=True),
        Readout("q", "quaternion (w, x, y, z)"),
        Readout("apart", "angle between yaw and roll axes"),
        Readout("gimbal", "gimbal", text=True),
    ),
    draw=draw,
)
