"""Interactive figures: one module per figure, each drawn as SVG from the
reference implementations.

A figure declares its controls (sliders, or toggle buttons with the values 0
and 1) and its readouts, and ``render(params)`` returns::

    {"svg": "<svg …>…</svg>", "readouts": {"key": "text", …}, "flags": ["…"]}

``flags`` name states the page styles (``singular``, ``unreachable``, …). The
page never computes anything: it sends the control values (``api`` op
``figure``) and swaps in what comes back. ``html.figure_html`` renders the
first frame at build time.

>>> "rotation-2d" in names()
True
>>> sorted(render("rotation-2d", {"theta": 90})["readouts"])
['R', 'image', 'point']
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

from ..registry import FIGURES


class FigureError(ValueError):
    """An unknown figure or a parameter it cannot draw."""


@dataclass(frozen=True)
class Control:
    """A slider (``kind="range"``) or a toggle button (``kind="toggle"``, values 0 and 1)."""

    name: str
    label: str
    min: float = 0.0
    max: float = 1.0
    step: float = 1.0
    default: float = 0.0
    unit: str = ""
    kind: str = "range"


@dataclass(frozen=True)
class Readout:
    """A live value; ``matrix`` readouts hold one row per line, ``text`` ones a sentence."""

    key: str
    label: str
    matrix: bool = False
    text: bool = False


@dataclass(frozen=True)
class Figure:
    """``orbit`` names the slider a sideways drag across the picture turns (a 3-D view's azimuth)."""

    name: str
    title: str
    caption: str
    controls: tuple[Control, ...]
    readouts: tuple[Readout, ...]
    draw: Callable[[dict[str, float]], dict[str, Any]] = field(repr=False)
    orbit: str = ""

    def __post_init__(self) -> None:
        if self.orbit and not any(c.name == self.orbit and c.kind == "range" for c in self.controls):
            raise ValueError(f"figure {self.name!r}: its orbit {self.orbit!r} is none of its sliders")

    def defaults(self) -> dict[str, float]:
        return {c.name: c.default for c in self.controls}

    def params(self, given: dict[str, Any] | None) -> dict[str, float]:
        """The defaults overridden by ``given``; raises FigureError on anything odd."""
        if given is None:
            given = {}
        if not isinstance(given, dict):
            raise FigureError("The figure's parameters must be a dictionary.")
        controls = {c.name: c for c in self.controls}
        unknown = sorted(set(given) - set(controls))
        if unknown:
            raise FigureError(f"Figure {self.name!r} has no control {unknown[0]!r}.")
        out = self.defaults()
        for name, raw in given.items():
            c = controls[name]
            try:
                value = float(raw)
            except (TypeError, ValueError):
                raise FigureError(f"{c.label}: {raw!r} is not a number.") from None
            if isinstance(raw, bool) or not math.isfinite(value):
                raise FigureError(f"{c.label}: {raw!r} is not a number.")
            span = 1e-9 * max(1.0, abs(c.max - c.min))
            if not c.min - span <= value <= c.max + span:
                raise FigureError(f"{c.label}: {value:g} is outside [{c.min:g}, {c.max:g}].")
            if c.kind == "toggle" and value not in (0.0, 1.0):
                raise FigureError(f"{c.label}: a toggle is 0 or 1, not {value:g}.")
            out[name] = value
        return out

    def render(self, given: dict[str, Any] | None = None) -> dict[str, Any]:
        result = self.draw(self.params(given))
        result.setdefault("flags", [])
        return result


def names() -> list[str]:
    """Every figure's name (:data:`workbook.registry.FIGURES`: one module each)."""
    return FIGURES.names()


def get(name: str) -> Figure:
    """The figure called ``name``; its module is imported on first use."""
    if name not in FIGURES.names():
        raise FigureError(f"There is no figure called {name!r}.")
    return FIGURES.get(name)


def render(name: str, params: dict[str, Any] | None = None) -> dict[str, Any]:
    return get(name).render(params)
