"""Chapter 13: ICP on a scan of eight posts. The reader sets the first guess (a turn about the
scan's centroid and a shift, away from the truth) and the number of iterations; the figure draws the
map, where the scan started, where ICP has moved it, and each scan point's nearest-neighbour pair,
with how far ICP still is from the true pose.

The scan is the map itself seen from the true pose, so the truth is the identity: whatever pose ICP
ends at is its error.

>>> out = draw({"turn": 15, "shift": 0.3, "steps": 8})
>>> out["readouts"]["error"]
'0.0°, 0.000 m'
>>> draw({"turn": 80, "shift": 0.0, "steps": 8})["flags"]
['wrong']
"""

from __future__ import annotations

import math

from ..number_format import readout, readout_matrix
from ..reference.alignment import align_2d, centroid, nearest, rot
from . import Control, Figure, Readout
from .svg import Canvas

# eight posts in no symmetric pattern, so only one pose fits them all
MAP = [(0.0, 0.0), (2.0, 0.5), (3.5, 0.0), (4.0, 2.0), (2.5, 3.0), (0.5, 2.5), (1.5, 1.5), (3.0, 1.2)]


def _moved(R, t, points):
    return [(R[0][0] * x + R[0][1] * y + t[0], R[1][0] * x + R[1][1] * y + t[1]) for x, y in points]


def icp(start, steps: int):
    """The scan after ``steps`` point-to-point ICP iterations against MAP, and the pairs of the last one."""
    scan = list(start)
    pairs = nearest(scan, MAP)
    for _ in range(steps):
        R, t = align_2d(scan, [MAP[j - 1] for j in pairs])
        scan = _moved(R, t, scan)
        pairs = nearest(scan, MAP)
    return scan, pairs


def _pose_of(scan):
    """The pose (R, t) that takes the map onto where the scan now is (the true pose is the identity)."""
    return align_2d(MAP, scan)


def draw(p: dict[str, float]) -> dict:
    c0 = centroid(MAP)
    R0 = rot(math.radians(p["turn"]))
    about = (c0[0] - (R0[0][0] * c0[0] + R0[0][1] * c0[1]) + p["shift"],
             c0[1] - (R0[1][0] * c0[0] + R0[1][1] * c0[1]) + p["shift"])
    start = _moved(R0, about, MAP)
    scan, pairs = icp(start, int(p["steps"]))
    R, t = _pose_of(scan)
    turn = math.degrees(math.atan2(R[1][0], R[0][0]))
    shift = math.hypot(*t)
    wrong = abs(turn) > 1 or shift > 0.05
    c = Canvas(400, 360, (-2.5, 6.5), (-2.5, 5.5))
    c.grid(1.0, labels=False)
    for pt, j in zip(scan, pairs):
        c.line(pt, MAP[j - 1], "wb-fig-muted wb-fig-thin")
    for pt in MAP:
        c.dot(pt, 4, "wb-fig-c wb-fig-solid")
    for pt in start:
        c.dot(pt, 2.5, "wb-fig-muted wb-fig-solid")
    for pt in scan:
        c.dot(pt, 4, "wb-fig-a wb-fig-thin")
    c.label(MAP[2], "map", "wb-fig-label wb-fig-small wb-fig-c", toward=(1, -1))
    c.label(scan[len(MAP) - 1], "scan", "wb-fig-label wb-fig-small wb-fig-a", toward=(1, 1))
    svg = c.svg(f"ICP from a first guess {p['turn']:g}° and {p['shift']:g} m off, after {int(p['steps'])} "
                f"iterations: {'still off' if wrong else 'on the map'}")
    mse = sum((x - MAP[j - 1][0]) ** 2 + (y - MAP[j - 1][1]) ** 2 for (x, y), j in zip(scan, pairs)) / len(scan)
    return {
        "svg": svg,
        "flags": ["wrong"] if wrong else [],
        "readouts": {
            "pose": readout_matrix(R),
            "error": f"{readout(abs(turn), 1)}°, {readout(shift)} m",
            "mse": readout(mse, 4),
            "verdict": ("ICP has not reached the true pose (yet, or ever: a wrong valley)" if wrong
                        else "ICP has reached the true pose"),
        },
    }


FIGURE = Figure(
    name="align-icp",
    title="ICP from a first guess",
    caption="Set how far the first guess is off, then step the iterations: each one pairs every scan point "
            "(hollow; the small dots are where it started) with its nearest map point (filled) and fits "
            "the best turn and shift to those pairs. "
            "From a small error it lands on the map; from a large turn it can settle in a wrong pose.",
    controls=(
        Control("turn", "First guess: turn off by", -120, 120, 5, 15, "°"),
        Control("shift", "First guess: shift off by", -1.5, 1.5, 0.1, 0.3, " m"),
        Control("steps", "ICP iterations", 0, 12, 1, 0),
    ),
    readouts=(Readout("pose", "Pose error R (identity when right)", matrix=True),
              Readout("error", "Left to correct: turn, shift"), Readout("mse", "Mean squared pair distance (m²)"),
              Readout("verdict", "Where it is", text=True)),
    draw=draw,
)
