"""Chapter 3: predict steps only. The mean follows the motion model and the
covariance grows, P⁻ = F P Fᵀ + Q, drawn as one 1σ ellipse per step."""

from __future__ import annotations

import math

from ..number_format import readout, readout_matrix
from ..reference.ekf import covariance_ellipse, ekf_predict
from . import Control, Figure, Readout
from .svg import Canvas

P0 = [[0.05 ** 2, 0.0, 0.0], [0.0, 0.05 ** 2, 0.0], [0.0, 0.0, math.radians(1) ** 2]]


def process_noise(sigma_xy: float, sigma_theta_deg: float) -> list[list[float]]:
    """Q = diag(σxy², σxy², σθ²) from the two sliders (σθ given in degrees).

    >>> process_noise(0.1, 0)
    [[0.010000000000000002, 0.0, 0.0], [0.0, 0.010000000000000002, 0.0], [0.0, 0.0, 0.0]]
    """
    s = math.radians(sigma_theta_deg)
    return [[sigma_xy ** 2, 0.0, 0.0], [0.0, sigma_xy ** 2, 0.0], [0.0, 0.0, s * s]]


def predict_path(p: dict[str, float]):
    """The states and covariances from the start through ``steps`` predict steps.

    >>> states, Ps = predict_path({"v": 1, "omega": 0, "dt": 1, "steps": 2, "q_xy": 0, "q_theta": 0})
    >>> states[-1]
    (2.0, 0.0, 0.0)
    """
    Q = process_noise(p["q_xy"], p["q_theta"])
    states, Ps = [(0.0, 0.0, 0.0)], [P0]
    for _ in range(int(p["steps"])):
        s, P = ekf_predict(states[-1], Ps[-1], p["v"], p["omega"], p["dt"], Q)
        states.append(s)
        Ps.append(P)
    return states, Ps


def view_box(states, ellipses) -> tuple[tuple[float, float], tuple[float, float], float]:
    """Bounds that hold every mean and ellipse, on whole metres (the view only jumps by a grid step)."""
    xs = [s[0] for s in states]
    ys = [s[1] for s in states]
    reach = max(a for a, _, _ in ellipses)
    x0, x1 = min(xs) - reach - 0.5, max(xs) + reach + 0.5
    y0, y1 = min(ys) - reach - 0.5, max(ys) + reach + 0.5
    step = 1.0 if max(x1 - x0, y1 - y0) <= 8 else 2.0
    x0, y0 = step * math.floor(x0 / step), step * math.floor(y0 / step)
    x1, y1 = step * math.ceil(x1 / step), step * math.ceil(y1 / step)
    return (x0, max(x1, x0 + 4)), (y0, max(y1, y0 + 3)), step


def draw(p: dict[str, float]) -> dict:
    states, Ps = predict_path(p)
    ellipses = [covariance_ellipse(P) for P in Ps]
    xr, yr, step = view_box(states, ellipses)
    c = Canvas(440, 330, xr, yr)
    c.grid(step)
    last = len(states) - 1
    for k, (s, (a, b, ang)) in enumerate(zip(states, ellipses)):
        cls = "wb-fig-b wb-fig-area" if k == last else "wb-fig-b wb-fig-thin wb-fig-faint"
        c.ellipse(s[:2], a, b, ang, cls)
    c.polyline([s[:2] for s in states], "wb-fig-a")
    for s in states:
        c.dot(s[:2], 3.5, "wb-fig-a wb-fig-solid")
    x, y, th = states[-1]
    c.arrow((x, y), (x + 0.6 * math.cos(th), y + 0.6 * math.sin(th)), "wb-fig-a wb-fig-thick")
    c.tag((0, 0), "start", "wb-fig-label wb-fig-small")
    a, b, _ = ellipses[-1]
    svg = c.svg(f"{last} predict steps: the robot ends at ({readout(x, 2)}, {readout(y, 2)}) and its 1σ ellipse is "
                f"{readout(a, 2)} m by {readout(b, 2)} m")
    return {"svg": svg, "readouts": {
        "pose": f"({readout(x)}, {readout(y)}, {readout(math.degrees(th), 1)}°)",
        "P": readout_matrix(Ps[-1], 4),
        "ellipse": f"{readout(a)} m × {readout(b)} m",
    }}


FIGURE = Figure(
    name="ekf-predict",
    title="Prediction spreads uncertainty",
    caption="Each step moves the estimate by the motion model and pushes the covariance forward with "
            "P⁻ = F P Fᵀ + Q. The ellipses (one standard deviation in x and y) only grow; a heading error "
            "stretches them sideways as the robot drives on.",
    controls=(
        Control("v", "Speed v", 0, 1.5, 0.1, 1.0, "m/s"),
        Control("omega", "Turn rate ω", -1, 1, 0.05, 0.3, "rad/s"),
        Control("dt", "Time step dt", 0.1, 1, 0.1, 0.5, "s"),
        Control("steps", "Steps", 1, 10, 1, 6),
        Control("q_xy", "Process noise σ (x, y)", 0, 0.3, 0.01, 0.05, "m"),
        Control("q_theta", "Process noise σ (θ)", 0, 10, 0.5, 2, "°"),
    ),
    readouts=(
        Readout("pose", "final estimate (x, y, θ)"),
        Readout("ellipse", "1σ ellipse semi-axes"),
        Readout("P", "P⁻ after the last step", matrix=True),
    ),
    draw=draw,
)
