"""Chapter 4 · Code the robot: one matrix EKF update on a range–bearing sighting (4.10)."""

import math

from ..kinds.build import Build
from ..number_format import fmt
from ..reference.ekf import (
    ekf_update_matrix,
    ekf_update_range_bearing,
    innovation_wrapped,
    measurement_jacobian,
    range_bearing,
)

_SOLUTION = '''import math


def wrap(a):
    """An angle brought into (-pi, pi]."""
    return math.atan2(math.sin(a), math.cos(a))


def ekf_update_rb(x, P, z, landmark, R):
    """One EKF update of the pose x = [x, y, theta] on a range-bearing sighting z = (r, phi)."""
    dx, dy = landmark[0] - x[0], landmark[1] - x[1]
    q = dx * dx + dy * dy
    if q == 0:
        return None  # the landmark is where the robot is: no bearing, no H
    r = math.sqrt(q)
    h = [r, math.atan2(dy, dx) - x[2]]
    H = [[-dx / r, -dy / r, 0.0], [dy / q, -dx / q, -1.0]]
    y = [z[0] - h[0], wrap(z[1] - h[1])]  # the bearing innovation wrapped
    PHt = [[sum(P[i][k] * H[j][k] for k in range(3)) for j in range(2)] for i in range(3)]  # P H^T, 3x2
    S = [[sum(H[i][k] * PHt[k][j] for k in range(3)) + R[i][j] for j in range(2)] for i in range(2)]
    det = S[0][0] * S[1][1] - S[0][1] * S[1][0]
    S_inv = [[S[1][1] / det, -S[0][1] / det], [-S[1][0] / det, S[0][0] / det]]
    K = [[sum(PHt[i][k] * S_inv[k][j] for k in range(2)) for j in range(2)] for i in range(3)]  # 3x2
    moved = [x[i] + K[i][0] * y[0] + K[i][1] * y[1] for i in range(3)]
    x_new = [moved[0], moved[1], wrap(moved[2])]
    # the simple form: P+ = (I - K H) P
    IKH = [[(1.0 if i == j else 0.0) - sum(K[i][k] * H[k][j] for k in range(2)) for j in range(3)]
           for i in range(3)]
    P_new = [[sum(IKH[i][k] * P[k][j] for k in range(3)) for j in range(3)] for i in range(3)]
    return (x_new, P_new)
'''

# The chapter's sighting (exercises 4.1 to 4.4): the robot at the origin facing east, the landmark at (3, 4).
_P0 = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 0.1]]
_R0 = [[0.1, 0.0], [0.0, 0.01]]
_AHEAD = ([0.0, 0.0, 0.0], _P0, (4.8, 0.95), (3.0, 4.0), _R0)
# Behind the robot: predicted at atan2(0.1, -4) = 3.1166 rad, seen at -3.13 rad, just across -pi.
_BEHIND = ([0.0, 0.0, 0.0], [[0.1, 0.0, 0.0], [0.0, 0.1, 0.0], [0.0, 0.0, 0.05]], (4.0, -3.13), (-4.0, 0.1),
           [[0.01, 0.0], [0.0, 0.001]])


def _spd(rng, scale):
    """A random covariance: positive variances, a correlation of the first two below 0.6 in size."""
    a, b = rng.uniform(0.05, 1.0) * scale, rng.uniform(0.05, 1.0) * scale
    rho = rng.uniform(-0.6, 0.6)
    c = rng.uniform(0.01, 0.3)
    return [[a, rho * math.sqrt(a * b), 0.0], [rho * math.sqrt(a * b), b, 0.0], [0.0, 0.0, c]]


def _sighting(rng):
    """A pose, its covariance, a landmark 1 to 8 m away in any direction, and a noisy sighting of it."""
    x = [rng.uniform(-5, 5), rng.uniform(-5, 5), rng.uniform(-math.pi, math.pi)]
    far, at = rng.uniform(1, 8), rng.uniform(-math.pi, math.pi)
    landmark = (x[0] + far * math.cos(at), x[1] + far * math.sin(at))
    bearing = math.atan2(math.sin(at - x[2] + rng.gauss(0, 0.1)), math.cos(at - x[2] + rng.gauss(0, 0.1)))
    z = (far + rng.gauss(0, 0.2), bearing)
    R = [[rng.uniform(0.01, 0.5), 0.0], [0.0, rng.uniform(0.001, 0.05)]]
    return x, _spd(rng, 1.0), z, landmark, R


def _moves():
    """What the derivation says the wrap is worth, from the reference: the behind-the-robot example,
    wrapped and not.

    >>> v = _moves(); v["predicted"], v["wrapped"], v["plain"], v["swing"]
    ('3.1166', '0.03659', '-6.2466', '5.4559')
    """
    x, P, z, landmark, R = _BEHIND
    h = range_bearing(x, landmark)
    x_new = ekf_update_range_bearing(*_BEHIND)[0]
    unwrapped = ekf_update_matrix(x, P, z, h, measurement_jacobian(x, landmark), R)[0]
    return {"behind_y": fmt(x_new[1]), "behind_t": fmt(x_new[2]), "predicted": fmt(h[1]),
            "wrapped": fmt(innovation_wrapped(z, h)[1]), "plain": fmt(z[1] - h[1]),
            "swing": fmt(unwrapped[2] - x[2])}


EXERCISES = (
    Build(
        id="4.10",
        title="Code the robot: a range–bearing EKF update",
        function="ekf_update_rb",
        params=("x", "P", "z", "landmark", "R"),
        starter=(
            "import math\n\n\n"
            "def ekf_update_rb(x, P, z, landmark, R):\n"
            '    """One EKF update of the pose x = [x, y, theta] on a range-bearing sighting z = (r, phi)."""\n'
            "    # Your code here: h and H at x, the innovation (bearing wrapped), S, K, then x+ and P+.\n"
            "    return (list(x), [row[:] for row in P])\n"
        ),
        solution=_SOLUTION,
        reference=ekf_update_range_bearing,
        run_figure="ekf-range-bearing",
        examples=(
            _AHEAD,
            _BEHIND,
            ([2.0, 1.0, math.pi / 2], [[0.5, 0.1, 0.0], [0.1, 0.3, 0.0], [0.0, 0.0, 0.2]], (2.9, 0.4), (1.0, 4.0),
             [[0.05, 0.0], [0.0, 0.02]]),
        ),
        edge_cases=(
            # the bearing innovation across +pi the other way: predicted just past -pi, seen just under pi
            ([0.0, 0.0, 0.0], [[0.2, 0.0, 0.0], [0.0, 0.2, 0.0], [0.0, 0.0, 0.1]], (3.0, 3.12), (-3.0, -0.1),
             [[0.02, 0.0], [0.0, 0.002]]),
            # the predicted bearing itself beyond pi: atan2 = 2.0 with the heading at -2.5 (phi = 4.5)
            ([0.0, 0.0, -2.5], [[0.3, 0.0, 0.0], [0.0, 0.3, 0.0], [0.0, 0.0, 0.1]],
             (5.0, 4.5 - 2 * math.pi + 0.05), (5 * math.cos(2.0), 5 * math.sin(2.0)), [[0.05, 0.0], [0.0, 0.01]]),
            # the heading pushed past pi by the update: x+'s heading must come back into (-pi, pi]
            ([0.0, 0.0, 3.1], [[0.1, 0.0, 0.0], [0.0, 0.1, 0.0], [0.0, 0.0, 0.5]], (4.0, -0.3),
             (4 * math.cos(3.1), 4 * math.sin(3.1)), [[0.05, 0.0], [0.0, 0.001]]),
            # the landmark where the robot is: no bearing, so None
            ([1.0, 2.0, 0.3], [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 0.1]], (0.5, 0.2), (1.0, 2.0), _R0),
            # the chapter's sighting with range and bearing noise correlated: R's off-diagonal counts
            ([0.0, 0.0, 0.0], _P0, (4.8, 0.95), (3.0, 4.0), [[0.1, 0.02], [0.02, 0.01]]),
            # a sighting exactly as predicted: x stays, P shrinks
            ([1.0, -1.0, 0.5], _P0, (5.0, math.atan2(3.0, 4.0) - 0.5), (5.0, 2.0), _R0),
        ),
        angles=("[0][2]",),
        random_args=_sighting,
        values=_moves(),
    ),
)
