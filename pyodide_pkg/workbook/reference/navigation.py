"""Exercise 9.9: one step of the navigation loop, and the steering law it ends with.

The loop of chapter 9: predict with the last command, correct with the landmark when it
is seen, then steer to the waypoint from the corrected estimate.
"""

from __future__ import annotations

import math

from .ekf import ekf_predict_wrapped, ekf_update_matrix, measurement_jacobian, range_bearing
from .pose_graph import wrap_angle

SPEED, HEADING_GAIN, MAX_TURN = 0.5, 1.5, 1.0  # m/s, (rad/s) per rad, rad/s


def steer(pose, waypoint) -> tuple[float, float]:
    """(v, ω) toward ``waypoint``: constant speed, turn rate proportional to the heading error, capped.

    >>> steer((0, 0, 0), (3, 0))
    (0.5, 0.0)
    >>> steer((0, 0, 0), (0, 3))
    (0.5, 1.0)
    """
    error = wrap_angle(math.atan2(waypoint[1] - pose[1], waypoint[0] - pose[0]) - pose[2])
    return SPEED, max(-MAX_TURN, min(MAX_TURN, HEADING_GAIN * error))


def nav_step(x, P, u, z, landmark, waypoint, dt: float, Q, R):
    """Predict with the command ``u`` = (v, ω), update with ``z`` = (range, bearing) to ``landmark`` unless
    it is None (the bearing innovation wrapped), bring the heading into (−π, π], then steer to ``waypoint``.
    Returns ``(x, P, (v, ω))``.

    Chapter 9's numbers: from the origin facing east at 0.5 m/s for 0.5 s, the landmark (2, 1) seen.

    >>> P0 = [[0.01, 0, 0], [0, 0.01, 0], [0, 0, 0.001]]
    >>> Q = [[0.0025, 0, 0], [0, 0.0025, 0], [0, 0, 0.0025]]
    >>> R = [[0.01, 0], [0, 0.0012]]
    >>> x, P, u = nav_step((0, 0, 0), P0, (0.5, 0), (2.0, 0.6), (2, 1), (3, 0), 0.5, Q, R)
    >>> [round(a, 3) + 0.0 for a in x], [round(a, 3) for a in u]
    ([0.289, -0.053, -0.036], [0.5, 0.084])
    """
    x, P = ekf_predict_wrapped(x, P, u[0], u[1], dt, Q)
    if z is not None:
        h = list(range_bearing(x, landmark))
        h[1] = z[1] - wrap_angle(z[1] - h[1])  # the predicted bearing on the measured one's side of ±π
        new, P = ekf_update_matrix(list(x), P, list(z), h, measurement_jacobian(x, landmark), R)
        x = (new[0], new[1], wrap_angle(new[2]))
    return x, P, steer(x, waypoint)
