"""Chapter 9: the whole loop. A robot steers through waypoints from its EKF
estimate; odometry drifts, landmark sightings pull the estimate back.

The noise is drawn from a seeded generator, so every run (native or in the
browser) is the same and a step slider can replay it.
"""

from __future__ import annotations

import math
import random
from functools import lru_cache
from typing import NamedTuple

from ..number_format import readout
from ..reference.ekf import (
    covariance_ellipse,
    ekf_predict,
    ekf_update_matrix,
    measurement_jacobian,
    motion_model,
    range_bearing,
)
from ..reference.pose_graph import wrap_angle
from . import Control, Figure, Readout
from .svg import Canvas

WAYPOINTS = ((3.0, 0.0), (3.0, 3.0), (0.0, 3.0), (0.0, 0.0))
LANDMARKS = ((1.5, -1.0), (4.3, 1.5), (1.5, 4.1), (-1.1, 1.5))
DT, SPEED, HEADING_GAIN, MAX_TURN = 0.5, 0.5, 1.5, 1.0
SENSOR_RANGE = 1.8
STEPS = 50
P0 = [[0.01, 0.0, 0.0], [0.0, 0.01, 0.0], [0.0, 0.0, 0.001]]
Q = [[0.05 ** 2, 0.0, 0.0], [0.0, 0.05 ** 2, 0.0], [0.0, 0.0, 0.05 ** 2]]
R = [[0.1 ** 2, 0.0], [0.0, math.radians(2) ** 2]]
TURN_BIAS = 0.06  # rad/s the wheels turn more than commanded: the drift


class Step(NamedTuple):
    true: tuple[float, float, float]
    estimate: tuple[float, float, float]
    P: list[list[float]]
    sighted: tuple[int, ...]  # indices of the landmarks used in this step's update
    waypoint: int  # index of the waypoint being steered to (len(WAYPOINTS) when done)


def command(estimate, waypoint: int) -> tuple[float, float]:
    """Speed and turn rate toward the waypoint, from the *estimated* pose (a P controller on heading).

    >>> command((0, 0, 0), 0)
    (0.5, 0.0)
    """
    if waypoint >= len(WAYPOINTS):
        return 0.0, 0.0
    wx, wy = WAYPOINTS[waypoint]
    error = wrap_angle(math.atan2(wy - estimate[1], wx - estimate[0]) - estimate[2])
    return SPEED, max(-MAX_TURN, min(MAX_TURN, HEADING_GAIN * error))


@lru_cache(maxsize=4)
def simulate(sensor: bool = True) -> tuple[Step, ...]:
    """Every step of the run, from step 0 (the start) to ``STEPS``.

    >>> run = simulate(True)
    >>> len(run), run[0].true
    (51, (0.0, 0.0, 0.0))
    >>> with_sensor = math.dist(run[-1].true[:2], run[-1].estimate[:2])
    >>> blind = simulate(False)[-1]
    >>> with_sensor < math.dist(blind.true[:2], blind.estimate[:2])
    True
    """
    rng = random.Random(7)
    noise = [(rng.gauss(0, 0.05), rng.gauss(0, 0.03), [(rng.gauss(0, 0.1), rng.gauss(0, math.radians(2)))
                                                       for _ in LANDMARKS]) for _ in range(STEPS)]
    true, est, P, wp = (0.0, 0.0, 0.0), (0.0, 0.0, 0.0), P0, 0
    steps = [Step(true, est, P, (), wp)]
    for k in range(STEPS):
        v, omega = command(est, wp)
        dv, dw, sensed = noise[k]
        moving = v > 0
        true = motion_model(true, v * (1 + dv), (omega + TURN_BIAS + dw) if moving else 0.0, DT)
        est, P = ekf_predict(est, P, v, omega, DT, Q if moving else [[0.0] * 3 for _ in range(3)])
        sighted = []
        for j, landmark in enumerate(LANDMARKS):
            r_true, phi_true = range_bearing(true, landmark)
            if not sensor or r_true > SENSOR_RANGE:
                continue
            z = [r_true + sensed[j][0], phi_true + sensed[j][1]]
            h = list(range_bearing(est, landmark))
            h[1] = z[1] - wrap_angle(z[1] - h[1])
            x_new, P = ekf_update_matrix(list(est), P, z, h, measurement_jacobian(est, landmark), R)
            est = (x_new[0], x_new[1], wrap_angle(x_new[2]))
            sighted.append(j)
        if wp < len(WAYPOINTS) and math.dist(est[:2], WAYPOINTS[wp]) < 0.3:
            wp += 1
        steps.append(Step(true, est, P, tuple(sighted), wp))
    return tuple(steps)


def _robot(c: Canvas, pose, cls: str) -> None:
    x, y, t = pose
    c.polygon([(x + 0.3 * math.cos(t), y + 0.3 * math.sin(t)),
               (x + 0.18 * math.cos(t + 2.5), y + 0.18 * math.sin(t + 2.5)),
               (x + 0.18 * math.cos(t - 2.5), y + 0.18 * math.sin(t - 2.5))], cls)


def pose_text(pose) -> str:
    """(x, y, θ) for a readout, θ in degrees.

    >>> pose_text((1, 2, math.pi))
    '(1.000, 2.000, 180.0°)'
    """
    return f"({readout(pose[0])}, {readout(pose[1])}, {readout(math.degrees(pose[2]), 1)}°)"


def draw(p: dict[str, float]) -> dict:
    sensor = p["sensor"] == 1.0
    run = simulate(sensor)
    k = int(p["step"])
    now = run[k]
    c = Canvas(420, 400, (-1.7, 4.9), (-1.6, 4.7))
    c.grid(1.0, labels=False)
    for n, (wx, wy) in enumerate(WAYPOINTS):
        c.polygon([(wx - 0.1, wy - 0.1), (wx + 0.1, wy - 0.1), (wx + 0.1, wy + 0.1), (wx - 0.1, wy + 0.1)],
                  "wb-fig-muted" + (" wb-fig-solid" if n < now.waypoint else ""))
        c.text((wx, wy), f"{n + 1}", "wb-fig-label wb-fig-small wb-fig-muted", dx=12, dy=-8)
    for j, (lx, ly) in enumerate(LANDMARKS):
        if j in now.sighted:
            c.line(now.estimate[:2], (lx, ly), "wb-fig-c wb-fig-thin wb-fig-dash")
        c.polygon([(lx, ly + 0.18), (lx + 0.13, ly), (lx, ly - 0.18), (lx - 0.13, ly)], "wb-fig-c wb-fig-solid")
    if sensor:
        c.circle(now.true[:2], SENSOR_RANGE, "wb-fig-muted wb-fig-thin wb-fig-dash wb-fig-faint")
    c.polyline([s.true[:2] for s in run[: k + 1]], "wb-fig-muted")
    c.polyline([s.estimate[:2] for s in run[: k + 1]], "wb-fig-a wb-fig-dash")
    a, b, angle = covariance_ellipse(now.P, n_sigma=2)
    c.ellipse(now.estimate[:2], a, b, angle, "wb-fig-b wb-fig-area")
    _robot(c, now.estimate, "wb-fig-a wb-fig-solid")
    _robot(c, now.true, "wb-fig-muted wb-fig-thin")
    error = math.dist(now.true[:2], now.estimate[:2])
    sx, sy = math.sqrt(now.P[0][0]), math.sqrt(now.P[1][1])
    target = (f"waypoint {now.waypoint + 1} of {len(WAYPOINTS)}" if now.waypoint < len(WAYPOINTS)
              else "all waypoints reached")
    svg = c.svg(f"Step {k}: true pose {pose_text(now.true)}, estimate {pose_text(now.estimate)}, "
                f"error {readout(error, 2)} m")
    return {"svg": svg, "readouts": {
        "time": f"{readout(k * DT, 1)} s",
        "true": pose_text(now.true),
        "estimate": pose_text(now.estimate),
        "error": f"{readout(error)} m",
        "sigma": f"σx = {readout(sx)} m, σy = {readout(sy)} m",
        "sighted": f"{len(now.sighted)} landmark{'s' if len(now.sighted) != 1 else ''}; steering to {target}"
                   if now.sighted else f"none; steering to {target}",
    }}


FIGURE = Figure(
    name="capstone",
    title="One robot, the whole loop",
    caption="Grey: the true path and pose. Dashed, with a triangle: the EKF estimate the controller steers by, with "
            "its "
            "2σ ellipse. The wheels turn a little more than commanded, so prediction alone drifts; within "
            "1.8 m of a landmark (diamonds) the LiDAR's range and bearing pull the estimate back. Switch "
            "the updates off to watch the drift grow.",
    controls=(
        Control("step", "Step", 0, STEPS, 1, 20),
        Control("sensor", "LiDAR updates", 0, 1, 1, 1, kind="toggle"),
    ),
    readouts=(
        Readout("time", "time"),
        Readout("true", "true pose"),
        Readout("estimate", "EKF estimate"),
        Readout("error", "position error"),
        Readout("sigma", "uncertainty"),
        Readout("sighted", "landmarks used", text=True),
    ),
    draw=draw,
)
