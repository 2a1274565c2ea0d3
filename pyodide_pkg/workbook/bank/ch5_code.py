"""Chapter 5 · Code the robot: edge errors and one Gauss–Newton step on a line of three poses."""

from ..kinds.build import Build
from ..number_format import fmt
from ..reference.pose_graph import gauss_newton_step_1d

_SOLUTION = '''def gauss_newton_step(x, edges):
    """Edge errors and the poses after one Gauss-Newton step; pose 0 stays fixed."""
    errors = [z - (x[j] - x[i]) for i, j, z, w in edges]
    H = [[0.0] * 3 for _ in range(3)]
    b = [0.0] * 3
    for (i, j, z, w), e in zip(edges, errors):
        # de/dx_i = +1, de/dx_j = -1
        for a, ja in ((i, 1.0), (j, -1.0)):
            b[a] += w * ja * e
            for c, jc in ((i, 1.0), (j, -1.0)):
                H[a][c] += w * ja * jc
    # Pose 0 is the anchor: solve for poses 1 and 2 only (a 2x2 system).
    h11, h12, h21, h22 = H[1][1], H[1][2], H[2][1], H[2][2]
    det = h11 * h22 - h12 * h21
    if det == 0:
        return None  # a pose that no edge ties to the anchor
    d1 = (-b[1] * h22 + b[2] * h12) / det
    d2 = (-b[2] * h11 + b[1] * h21) / det
    return (errors, [x[0], x[1] + d1, x[2] + d2])
'''

_PAIRS = ((0, 1), (1, 2), (0, 2), (2, 1), (1, 0), (2, 0))

# The examples the page shows: a loop of two odometry edges and a loop closure that
# disagrees by 0.2, the closure weighted like the odometry, then ten times more.
_EQUAL = ((0, 1, 2), ((0, 1, 1, 1), (1, 2, 1, 1), (0, 2, 2.2, 1)))
_HEAVY = ((0, 1, 2), ((0, 1, 1, 1), (1, 2, 1, 1), (0, 2, 2.2, 10)))


def _left(x, edges):
    """Each edge's error after one step (the step lands on the optimum: the errors are linear)."""
    _, after = gauss_newton_step_1d(x, edges)
    return gauss_newton_step_1d(after, edges)[0]


def _shares():
    """What the solution says about who absorbs the loop's mismatch, from the reference.

    At the optimum every edge of the loop carries the same w·|e|, so a heavier edge keeps
    less of the mismatch: the shares go as 1/w.

    >>> v = _shares(); v["mismatch"], v["equal"], v["odo"], v["closure"], v["ratio"]
    ('0.2', '0.06667', '0.09524', '0.009524', '10')
    """
    mismatch = gauss_newton_step_1d(*_EQUAL)[0][2]
    equal = [abs(e) for e in _left(*_EQUAL)]
    heavy = [abs(e) for e in _left(*_HEAVY)]
    forces = [w * e for (*_, w), e in zip(_HEAVY[1], heavy)]
    if len({fmt(e) for e in equal}) != 1 or len({fmt(f) for f in forces}) != 1 or fmt(3 * equal[0]) != fmt(mismatch):
        raise ValueError("5.8's solution says the edges end alike (a third each); the reference disagrees")
    return {"mismatch": fmt(mismatch), "equal": fmt(equal[0]), "odo": fmt(heavy[0]), "closure": fmt(heavy[2]),
            "ratio": fmt(heavy[0] / heavy[2]), "weight": fmt(_HEAVY[1][2][3])}


def _graph(rng):
    x = [rng.uniform(-3, 3) for _ in range(3)]
    n = rng.randint(2, 4)
    while True:
        pairs = [rng.choice(_PAIRS) for _ in range(n)]
        if {0} & {p for pair in pairs for p in pair} and gauss_newton_step_1d(x, [(i, j, 0, 1) for i, j in pairs]):
            break
    return x, [(i, j, rng.uniform(-3, 3), rng.uniform(0.5, 5)) for i, j in pairs]


EXERCISES = (
    Build(
        id="5.8",
        title="Code the robot: gauss_newton_step",
        function="gauss_newton_step",
        params=("x", "edges"),
        starter=(
            "def gauss_newton_step(x, edges):\n"
            '    """Edge errors and the poses after one Gauss-Newton step; pose 0 stays fixed."""\n'
            "    # Your code here: the errors, then H and b, then solve for poses 1 and 2.\n"
            "    errors = [0.0 for edge in edges]\n"
            "    return (errors, list(x))\n"
        ),
        solution=_SOLUTION,
        reference=gauss_newton_step_1d,
        run_figure="pose-graph",
        examples=(
            _EQUAL,
            _HEAVY,
            ((0, 1.1, 1.9), ((0, 1, 1, 2), (1, 2, 1, 2))),
        ),
        edge_cases=(
            ((0, 1, 2), ((0, 1, 1, 1), (0, 1, 1.2, 1))),  # pose 2 tied to nothing: None
            ((0, 1, 2), ((1, 2, 1, 1), (2, 1, -1, 1))),  # poses 1 and 2 never reach the anchor: None
            ((0.5, 1.5, 3), ((0, 1, 1, 3), (1, 2, 1.5, 3), (0, 2, 2.5, 1))),  # already consistent: no move
            ((0, 1, 2), ((2, 1, -1.1, 1), (1, 0, -0.9, 2), (0, 2, 2, 1))),  # edges written backwards
        ),
        random_args=_graph,
        values=_shares(),
    ),
)
