"""Chapter 5 · Code the robot: one Gauss–Newton iteration on a 3-pose SE(2) graph (5.10)."""

import math

from ..kinds.build import Build
from ..number_format import fmt
from ..reference.pose_graph import compose_pose, edge_error_relative, relative_pose, wrap_angle
from ..reference.pose_graph_step import gauss_newton_se2
from .pose_graph_slips import diagnose, step_with, unwrapped_error

_SOLUTION = '''import numpy as np


def wrap(a):
    """Angles brought into (-pi, pi]."""
    return np.arctan2(np.sin(a), np.cos(a))


def gauss_newton_se2(poses, edges):
    """The poses after one Gauss-Newton iteration; pose 0 is the anchor."""
    x = np.array(poses, dtype=float)  # one row (x, y, theta) per pose
    n = len(x)
    H, b = np.zeros((3 * n, 3 * n)), np.zeros(3 * n)
    for i, j, z, omega in edges:
        c, s = np.cos(x[i, 2]), np.sin(x[i, 2])
        Rt = np.array([[c, s], [-s, c]])  # R(theta_i)^T
        dRt = np.array([[-s, c], [-c, -s]])  # its derivative, R'(theta_i)^T
        d = x[j, :2] - x[i, :2]
        h = np.append(Rt @ d, x[j, 2] - x[i, 2])  # pose j seen from pose i
        e = np.array(z, dtype=float) - h
        e[2] = wrap(e[2])
        A = np.zeros((3, 3))
        A[:2, :2], A[:2, 2], A[2, 2] = Rt, -dRt @ d, 1.0
        B = np.zeros((3, 3))
        B[:2, :2], B[2, 2] = -Rt, -1.0
        W = np.array(omega, dtype=float)
        for p, Jp in ((i, A), (j, B)):
            b[3 * p:3 * p + 3] += Jp.T @ W @ e
            for q, Jq in ((i, A), (j, B)):
                H[3 * p:3 * p + 3, 3 * q:3 * q + 3] += Jp.T @ W @ Jq
    dx = np.zeros(3 * n)
    dx[3:] = np.linalg.solve(H[3:, 3:], -b[3:])  # pose 0's rows and columns dropped
    new = x + dx.reshape(n, 3)
    new[:, 2] = wrap(new[:, 2])
    return new.tolist()
'''

_W = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 10.0]]
_DIAG = [[10.0, 0.0, 0.0], [0.0, 10.0, 0.0], [0.0, 0.0, 5.0]]
_CORRELATED = [[4.0, 1.0, 0.0], [1.0, 2.0, 0.0], [0.0, 0.0, 20.0]]

Pose = tuple[float, float, float]
Edge = tuple[int, int, Pose, list[list[float]]]
Graph = tuple[tuple[Pose, ...], tuple[Edge, ...]]

# The chapter's example: two odometry legs of 1 m turning 90° each, a loop closure that puts pose 2
# 0.2 m further from pose 0 than the odometry does.
_CORNER: Graph = (((0.0, 0.0, 0.0), (1.0, 0.0, math.pi / 2), (1.0, 1.0, math.pi)),
                  ((0, 1, (1.0, 0.0, math.pi / 2), _W), (1, 2, (1.0, 0.0, math.pi / 2), _W),
                   (0, 2, (1.0, 1.2, math.pi), _W)))
# Driving west, headings either side of ±π: θ1 − θ0 = −6.1 rad as plain numbers, 0.18 rad once wrapped.
_WEST: Graph = (((2.0, 1.0, 3.0), (1.0, 1.1, -3.1), (0.0, 1.05, -3.0)),
                ((0, 1, (1.0, 0.0, 0.2), _W), (1, 2, (1.0, 0.0, 0.1), _W), (2, 0, (-1.95, 0.3, -0.3), _CORRELATED)))


def _consistent() -> Graph:
    """Three poses that agree with every edge exactly (loop closure included): the step is zero."""
    z01, z12 = (1.2, 0.3, 0.8), (0.9, -0.2, 2.0)
    p0 = (1.0, -2.0, 2.5)
    p1 = compose_pose(p0, z01)
    p2 = compose_pose(p1, z12)
    return ((p0, p1, p2), ((0, 1, z01, _CORRELATED), (1, 2, z12, _W), (0, 2, relative_pose(p0, p2), _W)))


_EDGE_CASES: tuple[Graph, ...] = (
    # already at the optimum: every edge agrees, so b = 0 and nothing moves
    _consistent(),
    # a loop closure across the ±π wrap: θ2 − θ0 is 6.08 rad as plain numbers, −0.2 once wrapped
    (((0.0, 0.0, 3.05), (-1.0, 0.1, -3.1), (-2.1, 0.2, -3.0)),
     ((0, 1, (1.0, -0.1, 0.15), _W), (1, 2, (1.0, 0.0, 0.1), _W), (2, 0, (-2.0, 0.2, -0.2), _CORRELATED))),
    # a heading pushed past π by the step: the result's angle must come back into (−π, π]
    (((0.0, 0.0, 3.0), (-1.0, 0.1, 3.1), (-2.0, 0.3, 3.12)),
     ((0, 1, (1.0, -0.1, 0.25), [[2.0, 0.0, 0.0], [0.0, 2.0, 0.0], [0.0, 0.0, 50.0]]),
      (1, 2, (1.0, 0.0, 0.2), _W))),
    # the measured turn and the predicted one on opposite sides of ±π: the error, −6.22 rad as plain
    # numbers, is 0.06 once wrapped (wrapping the prediction alone leaves it −6.22)
    (((0.0, 0.0, 0.0), (1.0, 0.0, 3.1), (1.1, -1.0, 3.1)),
     ((0, 1, (1.0, 0.0, -3.12), _DIAG), (1, 2, (1.0, 0.1, 0.0), _DIAG))),
    # no edge from pose 0 to pose 1: pose 1 hangs on pose 2; edges written backwards; pose 0 turned, off the origin
    (((3.0, 1.0, math.pi), (1.2, 0.8, -2.0), (2.0, 1.1, 2.8)),
     ((2, 1, (1.0, -0.5, 1.2), _CORRELATED),
      (2, 0, (-1.0, 0.2, 0.4), [[5.0, -2.0, 0.5], [-2.0, 3.0, 0.0], [0.5, 0.0, 8.0]]))),
)


def _information(rng):
    """A random information matrix: positive definite, x and y correlated, sometimes θ too."""
    a, b, t = rng.uniform(1, 50), rng.uniform(1, 50), rng.uniform(5, 100)
    xy = rng.uniform(-0.6, 0.6) * math.sqrt(a * b)
    xt = rng.uniform(-0.3, 0.3) * math.sqrt(a * t) if rng.random() < 0.3 else 0.0
    return [[a, xy, xt], [xy, b, 0.0], [xt, 0.0, t]]


def _graph(rng):
    """Three poses drifted off a true path, the odometry chain in a random order (pose 0 may touch one edge
    only), maybe a loop closure, edges maybe written backwards; noisy measurements, random Ω."""
    truth = [(rng.uniform(-4, 4), rng.uniform(-4, 4), rng.uniform(-math.pi, math.pi))]
    for _ in range(2):
        truth.append(compose_pose(truth[-1], (rng.uniform(0.5, 2), rng.uniform(-0.5, 0.5), rng.uniform(-2, 2))))
    poses = [list(truth[0])] + [[x + rng.gauss(0, 0.2), y + rng.gauss(0, 0.2), wrap_angle(t + rng.gauss(0, 0.15))]
                                for x, y, t in truth[1:]]
    a, c = (1, 2) if rng.random() < 0.5 else (2, 1)
    pairs = [(0, a), (a, c)] + ([(0, c)] if rng.random() < 0.7 else [])
    edges = []
    for i, j in pairs:
        i, j = (j, i) if rng.random() < 0.3 else (i, j)
        dx, dy, dt = relative_pose(truth[i], truth[j])
        z = [dx + rng.gauss(0, 0.05), dy + rng.gauss(0, 0.05), wrap_angle(dt + rng.gauss(0, 0.03))]
        edges.append([i, j, z, _information(rng)])
    rng.shuffle(edges)
    return poses, edges


def _describe(poses, edges) -> str:
    """A case as a test row names it: the poses and each edge's ends (the numbers to four figures)."""
    shown = ", ".join("(" + ", ".join(fmt(v) for v in p) + ")" for p in poses)
    ties = ", ".join(f"{int(i)}→{int(j)}" for i, j, _, _ in edges)
    return f"gauss_newton_se2 on poses {shown}; edges {ties}"


def _told():
    """What the chapter's paragraph after the solution says, from the reference: how far the corner's
    loop closure disagrees, how far the step moves poses 1 and 2 and what each edge keeps of the
    disagreement (a third each, as on exercise 5.8's line); then the western example's headings, its
    first edge's angle error wrapped and not, and how far pose 2 would land without the wrap.

    >>> v = _told(); v["gap"], v["left"], v["moved1"], v["moved2"]
    ('0.2', '0.06667', '0.06667', '0.1333')
    >>> v["plain"], v["wrapped"], v["raw_error"], v["error"], v["swing"], v["legs"], v["closure"]
    ('-6.1', '0.1832', '6.3', '0.01681', '11.1171', '1, 1', '1, 1.2')
    """
    poses, edges = _CORNER
    after = gauss_newton_se2(poses, edges)
    gap = abs(edge_error_relative(poses[0], poses[2], edges[2][2])[1])
    left = [max(abs(v) for v in edge_error_relative(after[i], after[j], z)) for i, j, z, _ in edges]
    moved = [math.dist(a[:2], p[:2]) for a, p in zip(after, poses)]
    if len({fmt(v) for v in left}) != 1 or fmt(3 * left[0]) != fmt(gap) or fmt(2 * moved[1]) != fmt(moved[2]):
        raise ValueError("5.10's solution says each edge keeps a third of the gap; the reference disagrees")
    legs = compose_pose(compose_pose(poses[0], edges[0][2]), edges[1][2])
    if not math.isclose(legs[0], edges[2][2][0]) or fmt(edges[2][2][1] - legs[1]) != fmt(gap):
        raise ValueError("5.10's solution says the legs and the loop closure differ in y only")
    said = {"legs": f"{fmt(legs[0])}, {fmt(legs[1])}", "closure": f"{fmt(edges[2][2][0])}, {fmt(edges[2][2][1])}"}
    poses, edges = _WEST
    (i, j, z, _), plain = edges[0], poses[1][2] - poses[0][2]
    wrong = step_with(poses, edges, unwrapped_error)
    once = gauss_newton_se2(poses, edges)
    said["again"] = fmt(math.dist(gauss_newton_se2(once, edges)[2][:2], once[2][:2]))
    return {**said, "gap": fmt(gap), "left": fmt(left[0]), "moved1": fmt(moved[1]), "moved2": fmt(moved[2]),
            "plain": fmt(plain), "wrapped": fmt(wrap_angle(plain)), "raw_error": fmt(z[2] - plain),
            "error": fmt(edge_error_relative(poses[i], poses[j], z)[2]),
            "swing": fmt(math.dist(wrong[2][:2], once[2][:2]))}


EXERCISES = (
    Build(
        id="5.10",
        title="Code the robot: one Gauss–Newton iteration in SE(2)",
        function="gauss_newton_se2",
        params=("poses", "edges"),
        starter=(
            "import numpy as np\n\n\n"
            "def gauss_newton_se2(poses, edges):\n"
            '    """The poses after one Gauss-Newton iteration; pose 0 is the anchor."""\n'
            "    # Your code here: e, A and B for every edge, then H and b, drop pose 0, solve, wrap.\n"
            "    return [list(p) for p in poses]\n"
        ),
        solution=_SOLUTION,
        reference=gauss_newton_se2,
        run_figure="pose-graph-se2",
        describe=_describe,
        diagnose=diagnose,
        examples=(_CORNER, _WEST),
        edge_cases=_EDGE_CASES,
        angles=("[*][2]",),
        random_args=_graph,
        values=_told(),
    ),
)
