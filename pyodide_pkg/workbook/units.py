"""Units a learner may write after a number, and the dimensions they carry.

A dimension is a triple of exponents (angle, length, time): a speed is
(0, 1, −1). Angles count as a dimension of their own here (SI calls the radian
dimensionless) so that ``2 m`` typed for an angle can be named as a mistake.
Every unit has a factor to its SI unit: rad, m, s (and m/s for speeds).

>>> UNITS["cm"]
(0.01, (0, 1, 0))
>>> dimension_name(SPEED), dimension_name(NONE), dimension_name((0, 2, 0))
('speed', '', 'area')
>>> describe((0, 1, -1)), describe(ANGLE)
('a speed', 'an angle')
"""

from __future__ import annotations

import math

Dim = tuple[int, int, int]

NONE: Dim = (0, 0, 0)
ANGLE: Dim = (1, 0, 0)
LENGTH: Dim = (0, 1, 0)
TIME: Dim = (0, 0, 1)
SPEED: Dim = (0, 1, -1)

_DEG = math.pi / 180

#: unit as typed -> (factor to SI, dimension)
UNITS: dict[str, tuple[float, Dim]] = {
    "°": (_DEG, ANGLE), "deg": (_DEG, ANGLE), "degree": (_DEG, ANGLE), "degrees": (_DEG, ANGLE),
    "rad": (1.0, ANGLE), "radian": (1.0, ANGLE), "radians": (1.0, ANGLE),
    "m": (1.0, LENGTH), "cm": (0.01, LENGTH), "mm": (0.001, LENGTH), "km": (1000.0, LENGTH),
    "s": (1.0, TIME), "ms": (0.001, TIME), "min": (60.0, TIME), "h": (3600.0, TIME),
}

#: angle unit names are read in any case (DEG, Rad); the others only as listed (M is not m).
CASELESS = frozenset({"deg", "degree", "degrees", "rad", "radian", "radians"})

#: how a unit shows in ``Answer.unit`` (only angles have one there)
ANGLE_UNIT = {"°": "deg", "deg": "deg", "degree": "deg", "degrees": "deg",
              "rad": "rad", "radian": "rad", "radians": "rad"}

_NAMES = {
    NONE: "", ANGLE: "angle", LENGTH: "length", TIME: "time", SPEED: "speed",
    (1, 0, -1): "angular speed", (0, 2, 0): "area", (0, 1, -2): "acceleration",
    (0, 0, -1): "rate",
}
_ARTICLE = {"angle": "an angle", "angular speed": "an angular speed", "area": "an area",
            "acceleration": "an acceleration"}

#: what an exercise may ask for: unit -> (factor from SI, dimension, how to say it)
EXPECT: dict[str, tuple[float, Dim, str]] = {
    "deg": (_DEG, ANGLE, "an angle in degrees"),
    "rad": (1.0, ANGLE, "an angle in radians"),
    "m": (1.0, LENGTH, "a length in metres"),
    "m/s": (1.0, SPEED, "a speed in metres per second"),
    "s": (1.0, TIME, "a time in seconds"),
}


def lookup(name: str) -> tuple[float, Dim] | None:
    """The (factor, dimension) of a unit name, or None if it is not a unit.

    >>> lookup("Deg") == lookup("°"), lookup("M"), lookup("km")
    (True, None, (1000.0, (0, 1, 0)))
    """
    if name in UNITS:
        return UNITS[name]
    low = name.lower()
    return UNITS[low] if low in CASELESS else None


def dimension_name(dim: Dim | None) -> str | None:
    """``None`` (no unit written), a name such as ``"length"``, or ``""`` when units cancel.

    >>> dimension_name(None), dimension_name(LENGTH), dimension_name((0, 1, 1))
    (None, 'length', 'length·time')
    """
    if dim is None:
        return None
    if dim in _NAMES:
        return _NAMES[dim]
    parts = []
    for exp, word in zip(dim, ("angle", "length", "time")):
        if exp:
            parts.append(word if exp == 1 else f"{word}^{exp}")
    return "·".join(parts)


def describe(dim: Dim | None) -> str:
    """A dimension with its article, for messages: ``"a length"``, ``"a plain number"``.

    >>> describe(None), describe(NONE), describe(TIME)
    ('a plain number', 'a plain number', 'a time')
    """
    name = dimension_name(dim)
    if not name:
        return "a plain number"
    return _ARTICLE.get(name, f"a {name}" if name in _NAMES.values() else f"a quantity in {name}")
