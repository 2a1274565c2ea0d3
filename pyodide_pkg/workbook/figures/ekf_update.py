"""Chapter 4: one range-and-bearing sighting of a known landmark shrinks the
prediction's ellipse; the sensor noise R sets how much."""

from __future__ import annotations

import math

from ..number_format import readout, readout_matrix
from ..reference.ekf import covariance_ellipse, ekf_update_matrix, kalman_gain, measurement_jacobian, range_bearing
from ..reference.pose_graph import wrap_angle
from . import Control, Figure, Readout
from .svg import Canvas

PREDICTED = (2.0, 1.0, math.radians(30))
TRUE_POSE = (2.4, 0.7, math.radians(27))
LANDMARK = (4.5, 3.0)
THETA_SIGMA = math.radians(5)


def update(p: dict[str, float]):
    """Prior, measurement and posterior for the slider values ``p``.

    Returns ``(P_prior, z, h, K, x_post, P_post)``.

    >>> P, z, h, K, x, Pn = update({"sigma_prior": 0.5, "sigma_r": 0.2, "sigma_phi": 3})
    >>> round(z[0], 4), round(h[0], 4)
    (3.1145, 3.2016)
    """
    s = p["sigma_prior"]
    P = [[s * s, 0.0, 0.0], [0.0, s * s, 0.0], [0.0, 0.0, THETA_SIGMA ** 2]]
    R = [[p["sigma_r"] ** 2, 0.0], [0.0, math.radians(p["sigma_phi"]) ** 2]]
    z = range_bearing(TRUE_POSE, LANDMARK)
    h = list(range_bearing(PREDICTED, LANDMARK))
    h[1] = z[1] - wrap_angle(z[1] - h[1])  # compare bearings the short way round
    H = measurement_jacobian(PREDICTED, LANDMARK)
    x_post, P_post = ekf_update_matrix(list(PREDICTED), P, list(z), h, H, R)
    return P, z, h, kalman_gain(P, H, R), x_post, P_post


def _robot(c: Canvas, pose, cls: str) -> None:
    x, y, t = pose
    pts = [(x + 0.32 * math.cos(t), y + 0.32 * math.sin(t)),
           (x + 0.2 * math.cos(t + 2.5), y + 0.2 * math.sin(t + 2.5)),
           (x + 0.2 * math.cos(t - 2.5), y + 0.2 * math.sin(t - 2.5))]
    c.polygon(pts, cls)


def draw(p: dict[str, float]) -> dict:
    P, z, h, K, x_post, P_post = update(p)
    prior, post = covariance_ellipse(P), covariance_ellipse(P_post)
    c = Canvas(440, 320, (0.4, 5.4), (-0.2, 3.6))
    c.grid(1.0, labels=False)
    lx, ly = LANDMARK
    c.polygon([(lx, ly + 0.22), (lx + 0.16, ly), (lx, ly - 0.22), (lx - 0.16, ly)], "wb-fig-c wb-fig-solid")
    c.text(LANDMARK, "landmark", "wb-fig-label wb-fig-c", dy=-18)
    seen = (PREDICTED[0] + z[0] * math.cos(PREDICTED[2] + z[1]), PREDICTED[1] + z[0] * math.sin(PREDICTED[2] + z[1]))
    c.line(PREDICTED[:2], seen, "wb-fig-c wb-fig-thin wb-fig-dash")
    c.dot(seen, 4, "wb-fig-c")
    c.ellipse(PREDICTED[:2], *prior, "wb-fig-muted wb-fig-dash")
    c.ellipse(x_post[:2], *post, "wb-fig-b wb-fig-area")
    _robot(c, PREDICTED, "wb-fig-muted wb-fig-area")
    _robot(c, x_post, "wb-fig-b wb-fig-solid")
    c.dot(TRUE_POSE[:2], 3, "wb-fig-a wb-fig-solid")
    c.text(PREDICTED[:2], "x⁻", "wb-fig-label wb-fig-muted", dx=-14, dy=22)
    c.tag(TRUE_POSE[:2], "true", "wb-fig-label wb-fig-small wb-fig-a")
    c.text(x_post[:2], "x⁺", "wb-fig-label wb-fig-b", dx=-14, dy=-12)
    shrink = math.sqrt((post[0] * post[1]) / (prior[0] * prior[1]))
    svg = c.svg(f"The update moves the estimate from x⁻ toward the true pose and shrinks its ellipse to "
                f"{readout(100 * shrink, 0)}% of its linear size")
    return {"svg": svg, "readouts": {
        "K": readout_matrix(K),
        "innovation": f"({readout(z[0] - h[0])} m, {readout(math.degrees(z[1] - h[1]), 2)}°)",
        "posterior": f"({readout(x_post[0])}, {readout(x_post[1])}, {readout(math.degrees(x_post[2]), 2)}°)",
        "ellipses": f"{readout(prior[0], 2)} × {readout(prior[1], 2)} m → {readout(post[0], 2)} × "
                    f"{readout(post[1], 2)} m",
    }}


FIGURE = Figure(
    name="ekf-update",
    title="A landmark sighting shrinks the ellipse",
    caption="The dashed ray is the measured range and bearing drawn from the predicted pose x⁻; it misses "
            "the landmark, and that miss (the innovation) pulls the estimate to x⁺. A noisy sensor (large R) "
            "gets a small gain K and barely moves it; a precise one shrinks the ellipse along the range.",
    controls=(
        Control("sigma_r", "Range noise σr", 0.02, 1.0, 0.02, 0.2, "m"),
        Control("sigma_phi", "Bearing noise σφ", 0.5, 20, 0.5, 3, "°"),
        Control("sigma_prior", "Prior σ (x, y)", 0.1, 1.0, 0.05, 0.5, "m"),
    ),
    readouts=(
        Readout("K", "Kalman gain K (3 × 2)", matrix=True),
        Readout("innovation", "innovation z − h(x⁻)"),
        Readout("posterior", "x⁺ (x, y, θ)"),
        Readout("ellipses", "1σ ellipse: before → after"),
    ),
    draw=draw,
)
