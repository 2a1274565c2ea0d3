"""Chapter 9 · Code the robot: the navigation loop, run closed loop step by step.

The learner writes one step (predict, update on the landmark, steer); the harness driver
``nav_loop`` (``workbook_sandbox.harness``) moves a true robot with its commands, feeds it
noisy sightings and the current waypoint, and returns the estimated path.
"""

import math

from workbook_sandbox.values import show

from ..kinds.build import Build
from ..reference.navigation import nav_step

_SOLUTION = '''import math


def wrap(a):
    return math.atan2(math.sin(a), math.cos(a))


def matmul(A, B):
    return [[sum(A[i][k] * B[k][j] for k in range(len(B))) for j in range(len(B[0]))] for i in range(len(A))]


def transpose(A):
    return [list(row) for row in zip(*A)]


def nav_step(x, P, u, z, landmark, waypoint, dt, Q, R):
    """One loop: predict with u, update on the landmark (z may be None), steer to the waypoint."""
    v, omega = u
    px, py, th = x
    # Predict (F at the old heading).
    F = [[1, 0, -v * math.sin(th) * dt], [0, 1, v * math.cos(th) * dt], [0, 0, 1]]
    x = [px + v * math.cos(th) * dt, py + v * math.sin(th) * dt, wrap(th + omega * dt)]
    P = [[a + q for a, q in zip(ra, rq)] for ra, rq in zip(matmul(matmul(F, P), transpose(F)), Q)]
    # Update on the landmark, when it is seen.
    if z is not None:
        dx, dy = landmark[0] - x[0], landmark[1] - x[1]
        q = dx * dx + dy * dy
        r = math.sqrt(q)
        y = [z[0] - r, wrap(z[1] - (math.atan2(dy, dx) - x[2]))]
        H = [[-dx / r, -dy / r, 0], [dy / q, -dx / q, -1]]
        S = [[a + b for a, b in zip(ra, rb)] for ra, rb in zip(matmul(matmul(H, P), transpose(H)), R)]
        det = S[0][0] * S[1][1] - S[0][1] * S[1][0]
        S_inv = [[S[1][1] / det, -S[0][1] / det], [-S[1][0] / det, S[0][0] / det]]
        K = matmul(matmul(P, transpose(H)), S_inv)
        x = [x[i] + K[i][0] * y[0] + K[i][1] * y[1] for i in range(3)]
        x[2] = wrap(x[2])
        KH = matmul(K, H)
        P = matmul([[(i == j) - KH[i][j] for j in range(3)] for i in range(3)], P)
    # Steer: constant speed, a capped turn rate toward the waypoint.
    error = wrap(math.atan2(waypoint[1] - x[1], waypoint[0] - x[0]) - x[2])
    return (x, P, (0.5, max(-1.0, min(1.0, 1.5 * error))))
'''

_P0 = ((0.01, 0, 0), (0, 0.01, 0), (0, 0, 0.001))
_Q = ((0.0025, 0, 0), (0, 0.0025, 0), (0, 0, 0.0025))
_R = ((0.01, 0), (0, math.radians(2) ** 2))
STEPS = 20


def _run(rng):
    start = (rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-math.pi, math.pi))
    waypoints = tuple((rng.uniform(-4, 4), rng.uniform(-4, 4)) for _ in range(rng.randint(2, 3)))
    landmark = (rng.uniform(-3, 3), rng.uniform(-3, 3))
    return (start, _P0, landmark, waypoints, rng.uniform(0.2, 0.6), _Q, _R, STEPS, rng.randrange(10_000))


def _describe(start, P, landmark, waypoints, dt, Q, R, steps, seed) -> str:
    """A closed-loop case as a test row names it: where the run starts and what it steers through."""
    return (f"nav_step run: {steps} steps of dt = {show(dt)} from {show(start)}, waypoints {show(waypoints)}, "
            f"landmark {show(landmark)}, noise seed {seed}")


EXERCISES = (
    Build(
        id="9.9",
        title="Code the robot: nav_step, closed loop",
        function="nav_step",
        params=("x", "P", "u", "z", "landmark", "waypoint", "dt", "Q", "R"),
        starter=(
            "import math\n\n\n"
            "def nav_step(x, P, u, z, landmark, waypoint, dt, Q, R):\n"
            '    """One loop: predict with u, update on the landmark (z may be None), steer to the waypoint."""\n'
            "    # Your code here: predict, update when z is not None, then the new command.\n"
            "    return (x, P, (0.5, 0.0))\n"
        ),
        solution=_SOLUTION,
        reference=nav_step,
        run_figure="capstone",
        harness="nav_loop",
        describe=_describe,
        examples=(
            ((0, 0, 0), _P0, (1.5, -1.0), ((3, 0), (3, 3)), 0.5, _Q, _R, STEPS, 7),
            ((3, 3, math.pi), _P0, (1.5, 4.1), ((0, 3), (0, 0)), 0.5, _Q, _R, STEPS, 8),
        ),
        edge_cases=(
            ((0, 0, 0), _P0, (1, 1), ((2, 0), (2, 2)), 0.0, _Q, _R, 10, 1),  # dt = 0: nothing moves, P grows
            ((0, 0, 3.0), _P0, (-2, 0.5), ((-3, -0.5), (-3, 2)), 0.5, _Q, _R, STEPS, 2),  # heading across ±π
            ((0, 0, 0), _P0, (20, 20), ((2, 1), (0, 2)), 0.5, _Q, _R, STEPS, 3),  # landmark never seen: z None
            # heading a half-turn: π or −π
            ((0, 0, -math.pi), _P0, (20, 20), ((-2, 0), (-2, 2)), 0.5, _Q, _R, STEPS, 4),
            # landmark seen, lost (steps 16-25), seen again
            ((0, 0, 0), _P0, (1, 0.5), ((3.8, 0), (0, 0)), 0.5, _Q, _R, 40, 5),
        ),
        angles=("[*][2]",),
        random_args=_run,
        hidden_count=4,
        rel_tol=1e-5,
        abs_tol=1e-7,
    ),
)
