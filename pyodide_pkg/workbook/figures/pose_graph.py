"""Chapter 5: a loop driven with a heading bias drifts open; one loop closure
and a few Gauss–Newton iterations pull it shut, sharing the error out."""

from __future__ import annotations

import math
from functools import lru_cache
from html import escape

from ..number_format import readout
from ..reference.pose_graph import compose_pose, gauss_newton, graph_cost, information_matrix
from . import Control, Figure, Readout
from .svg import Canvas, render_svg

SIDES = 8  # an octagon: eight 1 m legs, turning 45° after each
OMEGA = information_matrix([[0.01, 0, 0], [0, 0.01, 0], [0, 0, 0.0025]])
WIDTH, GRAPH_H, CHART_H = 400.0, 300.0, 140.0


@lru_cache(maxsize=64)
def solve(drift_deg: float):
    """Dead-reckoned poses, the edges (odometry and the loop closure), and the optimised poses.

    Returns ``(drifted, edges, optimised, costs)``; ``costs[0]`` is the cost of
    the drifted poses once the loop closure is added.

    >>> drifted, edges, optimised, costs = solve(4.0)
    >>> len(drifted), len(edges), costs[-1] < costs[0]
    (9, 9, True)
    """
    z = (1.0, 0.0, 2 * math.pi / SIDES + math.radians(drift_deg))
    drifted = [(0.0, 0.0, 0.0)]
    for _ in range(SIDES):
        drifted.append(compose_pose(drifted[-1], z))
    edges = [(k, k + 1, z, OMEGA) for k in range(SIDES)] + [(SIDES, 0, (0.0, 0.0, 0.0), OMEGA)]
    optimised, costs = gauss_newton(drifted, edges)
    return drifted, edges, optimised, costs


def _graph(c: Canvas, poses, cls: str, closure_cls: str) -> None:
    c.polyline([q[:2] for q in poses], cls)
    c.line(poses[-1][:2], poses[0][:2], closure_cls)
    for x, y, t in poses:
        c.dot((x, y), 4, cls + " wb-fig-solid")
        c.line((x, y), (x + 0.22 * math.cos(t), y + 0.22 * math.sin(t)), cls)


def _chart(costs, optimise: bool) -> list[str]:
    top = GRAPH_H
    parts = [f'<line x1="40" y1="{top + CHART_H - 24}" x2="{WIDTH - 12}" y2="{top + CHART_H - 24}" '
             'class="wb-fig-axis"/>',
             f'<text x="40" y="{top + 14}" class="wb-fig-label wb-fig-small">total cost F per iteration</text>']
    if not optimise:
        parts.append(f'<text x="{WIDTH / 2}" y="{top + CHART_H / 2 + 8}" text-anchor="middle" '
                     f'class="wb-fig-label wb-fig-muted">Close the loop to optimise</text>')
        return parts
    peak = max(costs) or 1.0
    n = len(costs)
    slot = min(56.0, (WIDTH - 60) / n)
    base = top + CHART_H - 24
    for k, cost in enumerate(costs):
        height = (CHART_H - 60) * cost / peak
        x = 44 + k * slot
        parts.append(f'<rect x="{x:.1f}" y="{base - height:.1f}" width="{slot * 0.7:.1f}" height="{height:.1f}" '
                     f'class="wb-fig-a wb-fig-bar"/>')
        parts.append(f'<text x="{x + slot * 0.35:.1f}" y="{base - height - 5:.1f}" text-anchor="middle" '
                     f'class="wb-fig-label wb-fig-small">{escape(readout(cost, 1))}</text>')
        parts.append(f'<text x="{x + slot * 0.35:.1f}" y="{base + 16:.1f}" text-anchor="middle" '
                     f'class="wb-fig-label wb-fig-small wb-fig-muted">{k}</text>')
    return parts


def draw(p: dict[str, float]) -> dict:
    optimise = p["optimise"] == 1.0
    drifted, edges, optimised, costs = solve(p["drift"])
    shown = optimised if optimise else drifted
    c = Canvas(WIDTH, GRAPH_H, (-1.9, 2.9), (-1.1, 3.3))
    c.grid(1.0, labels=False)
    if optimise:
        _graph(c, drifted, "wb-fig-muted wb-fig-thin", "wb-fig-muted wb-fig-thin wb-fig-dash")
        _graph(c, optimised, "wb-fig-a", "wb-fig-b wb-fig-thick")
    else:
        _graph(c, drifted, "wb-fig-a", "wb-fig-bad wb-fig-thick wb-fig-dash")
    c.text(shown[0][:2], "pose 0 (fixed)", "wb-fig-label wb-fig-small", dx=-10, dy=22, anchor="end")
    c.text(shown[-1][:2], f"pose {SIDES}", "wb-fig-label wb-fig-small", dx=10, dy=22, anchor="start")
    gap = math.dist(shown[-1][:2], shown[0][:2])
    cost = graph_cost(shown, edges)
    title = (f"Pose graph with {SIDES} odometry edges and a loop closure, "
             + ("after Gauss–Newton" if optimise else "before optimisation") + f": cost {readout(cost, 1)}")
    svg = render_svg(WIDTH, GRAPH_H + CHART_H, title, c.parts + _chart(costs, optimise))
    return {"svg": svg, "flags": ["optimised"] if optimise else [], "readouts": {
        "cost": readout(cost, 2),
        "history": " → ".join(readout(v, 2) for v in costs) if optimise else "not optimised yet",
        "gap": f"{readout(gap)} m",
    }}


FIGURE = Figure(
    name="pose-graph",
    title="Closing the loop",
    caption="The robot drives an octagon, but its odometry over-reports each turn by the drift, so the "
            "dead-reckoned loop does not close (red dashed gap). The loop closure says pose 8 is back at "
            "pose 0; Gauss–Newton then moves every pose a little, and the bars show the total cost F falling "
            "at each iteration.",
    controls=(
        Control("drift", "Heading drift per leg", 0, 8, 0.5, 4, "°"),
        Control("optimise", "Close the loop and optimise", 0, 1, 1, 0, kind="toggle"),
    ),
    readouts=(
        Readout("cost", "total cost F"),
        Readout("history", "F per iteration"),
        Readout("gap", "gap between pose 8 and pose 0"),
    ),
    draw=draw,
)
