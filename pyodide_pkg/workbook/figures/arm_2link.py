"""Chapter 6: the two-link arm. Joint sliders drive forward kinematics; a target
(sliders, or drag it) shows both inverse-kinematics solutions inside the
reachable annulus, or says it is out of reach."""

from __future__ import annotations

import math

from ..number_format import readout, readout_vector
from ..reference.arm import forward_kinematics_2link, inverse_kinematics_2link, is_reachable
from . import Control, Figure, Readout
from .svg import Canvas

L1, L2 = 1.0, 0.6


def _arm(c: Canvas, theta1: float, theta2: float, cls: str, joint_r: float) -> None:
    elbow = (L1 * math.cos(theta1), L1 * math.sin(theta1))
    tip = forward_kinematics_2link(L1, L2, theta1, theta2)
    c.polyline([(0, 0), elbow, tip], cls)
    c.dot(elbow, joint_r, cls + " wb-fig-solid")


def angles_text(pair) -> str:
    """(θ1, θ2) in degrees for a readout.

    >>> angles_text((0.0, math.pi / 2))
    'θ1 = 0.0°, θ2 = 90.0°'
    """
    return f"θ1 = {readout(math.degrees(pair[0]), 1)}°, θ2 = {readout(math.degrees(pair[1]), 1)}°"


def draw(p: dict[str, float]) -> dict:
    t1, t2 = math.radians(p["theta1"]), math.radians(p["theta2"])
    tx, ty = p["tx"], p["ty"]
    c = Canvas(400, 400, (-1.85, 1.85), (-1.85, 1.85))
    outer, inner = L1 + L2, abs(L1 - L2)
    ox, oy = c.xy(0, 0)
    ro, ri = outer * c.scale, inner * c.scale
    c.add(f'<path class="wb-fig-muted wb-fig-annulus" fill-rule="evenodd" d="M {ox - ro:.1f} {oy:.1f} '
          f'a {ro:.1f} {ro:.1f} 0 1 0 {2 * ro:.1f} 0 a {ro:.1f} {ro:.1f} 0 1 0 {-2 * ro:.1f} 0 Z '
          f'M {ox - ri:.1f} {oy:.1f} a {ri:.1f} {ri:.1f} 0 1 0 {2 * ri:.1f} 0 '
          f'a {ri:.1f} {ri:.1f} 0 1 0 {-2 * ri:.1f} 0 Z"/>')
    c.grid(0.5, labels=False)
    reachable = is_reachable(L1, L2, tx, ty)
    flags = [] if reachable else ["unreachable"]
    if reachable:
        sol = inverse_kinematics_2link(L1, L2, tx, ty)
        _arm(c, *sol.elbow_up, "wb-fig-b wb-fig-dash", 4)
        _arm(c, *sol.elbow_down, "wb-fig-c wb-fig-dash", 4)
        for pair, name in ((sol.elbow_up, "up"), (sol.elbow_down, "down")):
            c.tag((L1 * math.cos(pair[0]), L1 * math.sin(pair[0])), name, "wb-fig-label wb-fig-small wb-fig-muted")
        up, down = angles_text(sol.elbow_up), angles_text(sol.elbow_down)
        reach = f"reachable: r = {readout(math.hypot(tx, ty))} m is within [{inner:g}, {outer:g}] m"
    else:
        up = down = "none"
        reach = f"unreachable: r = {readout(math.hypot(tx, ty))} m is outside [{inner:g}, {outer:g}] m"
    _arm(c, t1, t2, "wb-fig-a wb-fig-thick", 6)
    tip = forward_kinematics_2link(L1, L2, t1, t2)
    c.dot(tip, 5, "wb-fig-a wb-fig-solid")
    c.dot((0, 0), 7, "wb-fig-muted wb-fig-solid")
    target_cls = "wb-fig-bad" if flags else "wb-fig-b"
    c.line((tx - 0.12, ty), (tx + 0.12, ty), target_cls)
    c.line((tx, ty - 0.12), (tx, ty + 0.12), target_cls)
    c.add(f'<g transform="{c.frame_transform()}"><circle class="wb-fig-handle {target_cls}" cx="{tx:g}" cy="{ty:g}" '
          f'r="{14 / c.scale:.4f}" data-drag-x="tx" data-drag-y="ty"/></g>')
    c.tag((tx, ty), "target", f"wb-fig-label wb-fig-small {target_cls}")
    svg = c.svg(f"Two-link arm at θ1 = {p['theta1']:g}°, θ2 = {p['theta2']:g}°; target ({tx:g}, {ty:g}) is "
                + ("reachable" if reachable else "out of reach"))
    return {"svg": svg, "flags": flags, "readouts": {
        "tip": readout_vector(tip),
        "reach": reach,
        "elbow_up": up,
        "elbow_down": down,
    }}


FIGURE = Figure(
    name="arm-2link",
    title="Forward and inverse kinematics",
    caption=f"Links L1 = {L1:g} m and L2 = {L2:g} m. The joint sliders pose the solid arm (forward kinematics). "
            "The target, moved by its sliders or dragged, gets both inverse-kinematics answers, elbow-up "
            "and elbow-down (dashed), as long as it lies in the shaded annulus the arm can reach.",
    controls=(
        Control("theta1", "Shoulder θ1", -180, 180, 1, 40, "°"),
        Control("theta2", "Elbow θ2", -180, 180, 1, 60, "°"),
        Control("tx", "Target x", -1.8, 1.8, 0.05, 0.9, "m"),
        Control("ty", "Target y", -1.8, 1.8, 0.05, 0.8, "m"),
    ),
    readouts=(
        Readout("tip", "tip of the solid arm (x, y)"),
        Readout("reach", "target", text=True),
        Readout("elbow_up", "elbow-up solution"),
        Readout("elbow_down", "elbow-down solution"),
    ),
    draw=draw,
)
