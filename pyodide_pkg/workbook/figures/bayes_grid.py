"""Chapter 12: the discrete Bayes filter on a ring of twelve cells with three doors. The robot starts in
cell 1, not knowing where it is (a uniform belief); each step it moves one cell forward (with the
slider's chance of slipping a cell short or long), the filter predicts, the door sensor reads the
true cell (door or wall) and the filter updates. The reader sets the steps, the motion noise and
how often the sensor is right; the figure draws the belief over the cells after the last update.

>>> draw({"steps": 0, "noise": 0.2, "hit": 0.8})["readouts"]["best"]
'cells 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11 and 12 (uniform)'
>>> draw({"steps": 4, "noise": 0.0, "hit": 0.9})["readouts"]["best"]
'cells 2, 5 and 10'
>>> draw({"steps": 8, "noise": 0.2, "hit": 0.8})["readouts"]["best"]
'cell 9'
"""

from __future__ import annotations

from ..number_format import readout
from ..reference.particles import predict, update
from . import Control, Figure, Readout
from .svg import Canvas

CELLS = 12
DOORS = (1, 4, 9)  # the cells (from 1) with a door


def beliefs(steps: int, noise: float, hit: float) -> tuple[list[float], int, bool]:
    """The belief after ``steps`` moves and door readings, the true cell (from 1), and the last reading
    (True: a door); with no steps, the uniform prior and the first reading not yet used."""
    bel = [1.0 / CELLS] * CELLS
    kernel = {0: noise / 2, 1: 1.0 - noise, 2: noise / 2}
    cell = 1
    for _ in range(steps):
        cell = cell % CELLS + 1
        bel = predict(bel, kernel)
        seen = cell in DOORS
        bel = update(bel, [hit if (i + 1 in DOORS) == seen else 1 - hit for i in range(CELLS)])
    return bel, cell, cell in DOORS


def _cells(ids: list[int]) -> str:
    words = [str(i) for i in ids]
    return "cell " + words[0] if len(words) == 1 else "cells " + ", ".join(words[:-1]) + " and " + words[-1]


def draw(p: dict[str, float]) -> dict:
    steps = int(p["steps"])
    bel, cell, door = beliefs(steps, float(p["noise"]), float(p["hit"]))
    top = max(bel)
    best = [i + 1 for i, b in enumerate(bel) if b > top - 1e-9]
    c = Canvas(420, 240, (0.0, CELLS), (-0.22, 1.0), pad=(14, 12, 14, 24), aspect=False)
    for y in (0.25, 0.5, 0.75, 1.0):
        c.line((0, y), (CELLS, y), "wb-fig-grid")
        c.text((0, y), f"{y:g}", "wb-fig-label wb-fig-small wb-fig-muted", dx=2, dy=-3)
    c.line((0, 0), (CELLS, 0), "wb-fig-axis")
    for i in range(CELLS):
        if i + 1 in DOORS:
            c.polygon([(i + 0.08, -0.2), (i + 0.92, -0.2), (i + 0.92, -0.04), (i + 0.08, -0.04)],
                      "wb-fig-b wb-fig-face")
        c.polygon([(i + 0.15, 0), (i + 0.85, 0), (i + 0.85, bel[i]), (i + 0.15, bel[i])], "wb-fig-a wb-fig-bar")
        c.text((i + 0.5, -0.22), str(i + 1), "wb-fig-label wb-fig-small wb-fig-muted", dy=14, anchor="middle")
    c.arrow((cell - 0.5, 0.97), (cell - 0.5, max(bel[cell - 1], 0.02) + 0.03), "wb-fig-c wb-fig-thick")
    c.text((cell - 0.5, 0.97), "robot", "wb-fig-label wb-fig-small wb-fig-c", dx=6, dy=4)
    uniform = top - min(bel) < 1e-9
    where = _cells(best) + (" (uniform)" if uniform else "")
    reading = ("no reading yet" if steps == 0 else f"the last reading was {'a door' if door else 'a wall'}")
    svg = c.svg(f"Belief over {CELLS} cells after {steps} steps (motion noise {p['noise']:g}, sensor right "
                f"{p['hit']:g} of the time): most likely {where}, {readout(top, 3)}; the robot is in cell "
                f"{cell}; {reading}; doors at cells 1, 4 and 9")
    return {
        "svg": svg,
        "flags": [] if best == [cell] else ["unsure"],
        "readouts": {
            "best": where,
            "prob": readout(top, 3),
            "truth": f"cell {cell}" + ("" if steps == 0 else f" ({'door' if door else 'wall'} seen)"),
            "verdict": ("no information yet: every cell is as likely" if uniform else
                        "the belief's peak is on the robot" if best == [cell] else
                        "the robot's cell shares the peak: the readings so far fit the others as well" if cell in best
                        else
                        "the belief's peak is elsewhere: the doors do not yet tell the cells apart"),
        },
    }


FIGURE = Figure(
    name="bayes-grid",
    title="A Bayes filter on a ring of cells",
    caption="Bars: the belief over twelve cells of a circular corridor, doors under cells 1, 4 and 9. "
            "Each step the robot moves one cell (slipping a cell short or long with the motion noise): "
            "the prediction shifts the bars and smears them; the door sensor's reading then multiplies each "
            "bar by its likelihood and the bars are normalised. Watch the peak find the robot, and how noise "
            "or an unreliable sensor keeps it spread.",
    controls=(
        Control("steps", "Steps (move, then sense)", 0, 10, 1, 3),
        Control("noise", "Motion noise: chance of slipping a cell", 0, 0.4, 0.05, 0.2),
        Control("hit", "Door sensor: chance it reads right", 0.5, 0.95, 0.05, 0.8),
    ),
    readouts=(Readout("best", "Most likely", text=True), Readout("prob", "Its probability"),
              Readout("truth", "The robot is in", text=True), Readout("verdict", "So", text=True)),
    draw=draw,
)
