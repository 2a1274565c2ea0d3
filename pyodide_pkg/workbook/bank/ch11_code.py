"""Chapter 11 · Code the robot: fk_poe(M, S_list, theta), forward kinematics as a product of
exponentials in the space frame, for revolute, prismatic and pitched screws."""

from __future__ import annotations

import math
import random

from ..kinds.build import Build
from ..reference.linalg import identity, matmul
from ..reference.screw import arm_home, arm_screws, fk_poe, revolute_screw
from ..reference.se3 import pose

_SOLUTION = '''import math


def fk_poe(M, S_list, theta):
    """T = e^[S1]th1 ... e^[Sn]thn M, the screws (w, v) in the space frame."""
    def mul(A, B):
        return [[sum(A[i][k] * B[k][j] for k in range(4)) for j in range(4)] for i in range(4)]

    T = [[float(i == j) for j in range(4)] for i in range(4)]
    for S, th in zip(S_list, theta):
        (wx, wy, wz), v = S[:3], S[3:]
        W = [[0, -wz, wy], [wz, 0, -wx], [-wy, wx, 0]]
        W2 = [[sum(W[i][k] * W[k][j] for k in range(3)) for j in range(3)] for i in range(3)]
        s, c = math.sin(th), math.cos(th)
        R = [[(i == j) + s * W[i][j] + (1 - c) * W2[i][j] for j in range(3)] for i in range(3)]
        G = [[th * (i == j) + (1 - c) * W[i][j] + (th - s) * W2[i][j] for j in range(3)] for i in range(3)]
        p = [sum(G[i][k] * v[k] for k in range(3)) for i in range(3)]
        T = mul(T, [R[0] + [p[0]], R[1] + [p[1]], R[2] + [p[2]], [0, 0, 0, 1]])
    return mul(T, M)
'''

_STARTER = (
    "import math\n\n\n"
    "def fk_poe(M, S_list, theta):\n"
    '    """T = e^[S1]th1 ... e^[Sn]thn M, the screws (w, v) in the space frame."""\n'
    "    # Your code here: one exponential per joint, multiplied in order, then M.\n"
    "    return [list(row) for row in M]\n"
)

_I = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]


def _rows(T):
    return tuple(tuple(float(v) for v in row) for row in T)


def _arm(L0, L1, L2, *theta):
    return (_rows(arm_home(L0, L1, L2)), tuple(arm_screws(L0, L1)), tuple(float(t) for t in theta))


_R3 = 1 / math.sqrt(3)
_SCARA_M = _rows(pose(_I, (0.7, 0.0, 0.3)))
_SCARA = (revolute_screw((0, 0, 1), (0, 0, 0)), revolute_screw((0, 0, 1), (0.4, 0, 0)), (0.0, 0.0, 0.0, 0.0, 0.0, -1.0))
_UR = tuple(revolute_screw(w, q) for w, q in (
    ((0, 0, 1), (0, 0, 0)), ((0, 1, 0), (0, 0, 0.089)), ((0, 1, 0), (0.425, 0, 0.089)),
    ((0, 1, 0), (0.817, 0, 0.089)), ((0, 0, -1), (0.817, 0.109, 0)), ((0, 1, 0), (0.817, 0, -0.006))))
_UR_M = _rows(pose([[-1.0, 0.0, 0.0], [0.0, 0.0, 1.0], [0.0, 1.0, 0.0]], (0.817, 0.191, -0.006)))

_CASES = {
    "every joint at zero (T = M)": _arm(1.0, 2.0, 1.0, 0.0, 0.0, 0.0),
    "a SCARA arm with a prismatic third joint (ω = 0)": (_SCARA_M, _SCARA, (0.6, -1.1, 0.15)),
    "a prismatic joint drawn in (negative θ)": (_SCARA_M, _SCARA, (0.0, 0.0, -0.25)),
    "a screw along (1, 1, 1)/√3, off the origin": (
        _rows(pose(_I, (1.0, 0.0, 0.0))), (revolute_screw((_R3, _R3, _R3), (0.5, -1.0, 0.0)),), (2.0,)),
    "a screw with pitch 0.1 m/rad (turns and slides)": (
        _rows(pose(_I, (1.0, 0.5, 0.0))), (revolute_screw((0, 0, 1), (0.3, 0.0, 0.0), pitch=0.1),), (1.5,)),
    "angles past ±π (4 rad and −7 rad)": _arm(0.5, 1.5, 1.0, 4.0, -7.0, 3.5),
    "a six-joint arm like a UR5": (_UR_M, _UR, (0.3, -1.2, 1.5, -0.4, 1.0, 2.5)),
    "one joint, a half turn": (_rows(pose(_I, (2.0, 0.0, 0.0))), (revolute_screw((0, 1, 0), (1, 0, 0)),), (math.pi,)),
}
_NAMED = {args: name for name, args in _CASES.items()}


def _describe(M, S_list, theta) -> str:
    key = (_rows(M), tuple(tuple(float(c) for c in S) for S in S_list), tuple(float(t) for t in theta))
    name = _NAMED.get(key)
    return f"fk_poe(M, S_list, theta), {len(S_list)} joints" + (f": {name}" if name else "")


def _unit(rng: random.Random):
    while True:
        v = [rng.gauss(0, 1) for _ in range(3)]
        n = math.sqrt(sum(c * c for c in v))
        if n > 0.1:
            return tuple(c / n for c in v)


def _random(rng: random.Random) -> tuple:
    """1 to 6 joints: revolute about any unit axis through a point in a 2 m cube (some with a pitch), or
    prismatic along any unit direction; angles in [−2π, 2π], slides in [−1, 1] m; M any pose."""
    screws, theta = [], []
    for _ in range(rng.randint(1, 6)):
        if rng.random() < 0.25:
            screws.append((0.0, 0.0, 0.0) + _unit(rng))
            theta.append(rng.uniform(-1, 1))
        else:
            pitch = rng.choice((0.0, 0.0, rng.uniform(-0.2, 0.2)))
            screws.append(revolute_screw(_unit(rng), tuple(rng.uniform(-1, 1) for _ in range(3)), pitch))
            theta.append(rng.uniform(-2 * math.pi, 2 * math.pi))
    M = fk_poe(pose(_I, tuple(rng.uniform(-1, 1) for _ in range(3))),
               [revolute_screw(_unit(rng), (0, 0, 0))], [rng.uniform(-math.pi, math.pi)])
    return _rows(M), tuple(screws), tuple(theta)


def _diagnose(args, got, want) -> str:
    """The two slips the chapter names, told by the numbers: the product reversed, or M on the left."""
    M, S_list, theta = args
    try:
        G = [[float(v) for v in row] for row in got]
        if len(G) != 4 or any(len(row) != 4 for row in G):
            return ""
    except (TypeError, ValueError, IndexError, KeyError):
        return ""

    def near(T):
        return all(abs(G[i][j] - T[i][j]) < 1e-6 for i in range(4) for j in range(4))

    if near(want):
        return ""
    if len(S_list) > 1 and near(fk_poe(M, list(S_list)[::-1], list(theta)[::-1])):
        return ("your T is the product with the exponentials in reverse order (e^[Sn]θn ⋯ e^[S1]θ1 M): the base's "
                "joint comes first, on the left.")
    home = [list(map(float, r)) for r in M]
    if near(matmul(home, fk_poe(identity(4), S_list, theta))):
        return ("your T is M e^[S1]θ1 ⋯ e^[Sn]θn, M on the left: that is the body-frame form, for screws written "
                "in the tool's frame. These S are in the space frame, so M goes last.")
    return ""


EXERCISES = (
    Build(
        id="11.8",
        title="Code the robot: fk_poe",
        function="fk_poe",
        params=("M", "S_list", "theta"),
        starter=_STARTER,
        solution=_SOLUTION,
        reference=fk_poe,
        run_figure="poe",
        examples=(
            _arm(1.0, 2.0, 1.0, math.pi / 2, math.pi / 2, -math.pi / 2),  # 11.3's arm and angles
            (_SCARA_M, _SCARA, (math.pi / 2, -math.pi / 2, 0.1)),
        ),
        edge_cases=tuple(_CASES.values()),
        random_args=_random,
        describe=_describe,
        diagnose=_diagnose,
        abs_tol=1e-6,
    ),
)
