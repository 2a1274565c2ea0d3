"""Chapter 3 · Code the robot: the whole EKF prediction of the unicycle."""

import math

from ..kinds.build import Build
from ..reference.ekf import ekf_predict_wrapped

_SOLUTION = '''import math


def ekf_predict(x, P, v, omega, dt, Q):
    """Predicted pose (x, y, theta) and covariance P- = F P F^T + Q."""
    px, py, theta = x
    c, s = math.cos(theta), math.sin(theta)
    # F is the Jacobian at the old heading.
    F = [[1.0, 0.0, -v * s * dt],
         [0.0, 1.0, v * c * dt],
         [0.0, 0.0, 1.0]]
    FP = [[sum(F[i][k] * P[k][j] for k in range(3)) for j in range(3)] for i in range(3)]
    P_new = [[sum(FP[i][k] * F[j][k] for k in range(3)) + Q[i][j] for j in range(3)] for i in range(3)]
    heading = theta + omega * dt
    heading = math.atan2(math.sin(heading), math.cos(heading))  # into [-pi, pi]
    return ((px + v * c * dt, py + v * s * dt, heading), P_new)
'''

_P34 = ((1, 0, 0), (0, 1, 0), (0, 0, 0.1))
_Q34 = ((0.01, 0, 0), (0, 0.01, 0), (0, 0, 0.001))


def _covariance(rng, size):
    """A random symmetric positive semi-definite 3×3 matrix (A Aᵀ)."""
    a = [[rng.uniform(-size, size) for _ in range(3)] for _ in range(3)]
    return tuple(tuple(sum(a[i][k] * a[j][k] for k in range(3)) for j in range(3)) for i in range(3))


def _diagonal(rng):
    return tuple(tuple(rng.uniform(0, 0.05) if i == j else 0.0 for j in range(3)) for i in range(3))


EXERCISES = (
    Build(
        id="3.10",
        title="Code the robot: ekf_predict",
        function="ekf_predict",
        params=("x", "P", "v", "omega", "dt", "Q"),
        starter=(
            "import math\n\n\n"
            "def ekf_predict(x, P, v, omega, dt, Q):\n"
            '    """Predicted pose (x, y, theta) and covariance P- = F P F^T + Q."""\n'
            "    # Your code here: move the pose, then propagate P through F.\n"
            "    return (tuple(x), P)\n"
        ),
        solution=_SOLUTION,
        reference=ekf_predict_wrapped,
        run_figure="ekf-predict",
        examples=(
            ((0, 0, 0), _P34, 1, 0, 1, _Q34),
            ((0, 0, math.pi / 2), _P34, 1, 0, 0.5, _Q34),
            ((1, 2, math.pi / 4), _P34, 2, 0.5, 0.5, _Q34),
        ),
        edge_cases=(
            ((1, 2, 0.3), _P34, 1.5, 0.4, 0.0, _Q34),  # dt = 0: nothing moves, P gains Q only
            ((0, 0, 3.0), _P34, 1, 1, 0.5, _Q34),  # the heading passes π and wraps
            ((0, 0, -3.0), _P34, 1, -1, 0.5, _Q34),  # and −π the other way
            ((2, -1, 1.0), _P34, 0, 0.8, 1, _Q34),  # v = 0: the robot turns on the spot
            ((1, 1, -math.pi), _P34, 1, 0, 0.5, _Q34),  # heading west, exactly a half-turn: π or −π
        ),
        angles=("[0][2]",),
        random_args=lambda rng: ((rng.uniform(-5, 5), rng.uniform(-5, 5), rng.uniform(-math.pi, math.pi)),
                                 _covariance(rng, 1), rng.uniform(-2, 2), rng.uniform(-1, 1),
                                 rng.uniform(0.01, 1), _diagonal(rng)),
    ),
)
