"""Chapter 13 · Code the robot: align_2d(P, Q), the rotation (never a mirror) and translation that best
map one set of paired points onto another."""

from __future__ import annotations

import math
import random

from ..kinds.build import Build
from ..reference.alignment import align_2d, det2

_SOLUTION = '''import math


def align_2d(P, Q):
    """R (2 x 2, det +1) and t with R p + t as close to q as can be, over the pairs (p, q)."""
    n = len(P)
    px, py = sum(p[0] for p in P) / n, sum(p[1] for p in P) / n
    qx, qy = sum(q[0] for q in Q) / n, sum(q[1] for q in Q) / n
    h11 = h12 = h21 = h22 = 0.0
    for (ax, ay), (bx, by) in zip(P, Q):
        ax, ay, bx, by = ax - px, ay - py, bx - qx, by - qy
        h11 += ax * bx
        h12 += ax * by
        h21 += ay * bx
        h22 += ay * by
    s, c = h12 - h21, h11 + h22
    if abs(s) < 1e-9 and abs(c) < 1e-9:  # every turn fits as well: keep the identity
        theta = 0.0
    else:
        theta = math.atan2(s, c)
    R = [[math.cos(theta), -math.sin(theta)], [math.sin(theta), math.cos(theta)]]
    t = [qx - (R[0][0] * px + R[0][1] * py), qy - (R[1][0] * px + R[1][1] * py)]
    return R, t
'''

_STARTER = (
    "import math\n\n\n"
    "def align_2d(P, Q):\n"
    '    """R (2 x 2, det +1) and t with R p + t as close to q as can be, over the pairs (p, q)."""\n'
    "    # Your code here: centroids, H, the angle, then t. This only moves the centroids together.\n"
    "    t = [sum(q[k] for q in Q) / len(Q) - sum(p[k] for p in P) / len(P) for k in (0, 1)]\n"
    "    return [[1.0, 0.0], [0.0, 1.0]], t\n"
)


def _moved(P, deg, t, mirror=False):
    c, s = math.cos(math.radians(deg)), math.sin(math.radians(deg))
    if deg == 180:
        c, s = -1.0, 0.0
    out = []
    for x, y in P:
        if mirror:
            x = -x
        out.append((c * x - s * y + t[0], s * x + c * y + t[1]))
    return tuple(out)


_TRI = ((0.0, 0.0), (2.0, 0.0), (1.0, 1.5))
_QUAD = ((0.0, 0.0), (3.0, 0.5), (2.5, 2.0), (-0.5, 1.5))
_LINE = ((-1.0, -0.5), (0.0, 0.0), (1.0, 0.5), (3.0, 1.5))
_NOISE = ((0.02, -0.01), (-0.03, 0.02), (0.01, 0.03), (0.0, -0.02), (-0.02, -0.01))
_FIVE = ((0.0, 0.0), (1.0, 2.0), (3.0, 1.0), (2.0, -1.0), (-1.0, 1.0))
_NOISY_Q = tuple((x + e[0], y + e[1]) for (x, y), e in zip(_moved(_FIVE, 35, (1.0, -2.0)), _NOISE))

_CASES = {
    "a pure translation": (_QUAD, _moved(_QUAD, 0, (2.0, -1.0))),
    "a turn of exactly 180°": (_TRI, _moved(_TRI, 180, (1.0, 1.0))),
    "collinear points": (_LINE, _moved(_LINE, 40, (0.5, 2.0))),
    "noisy points": (_FIVE, _NOISY_Q),
    "a mirror image (no rotation maps it exactly)": (_QUAD, _moved(_QUAD, 30, (1.0, 0.0), mirror=True)),
    "all of P at one point (every turn fits as well)": (((1.0, 1.0),) * 3, ((0.0, 0.0), (2.0, 0.0), (1.0, 3.0))),
    "two pairs only": (((0.0, 0.0), (1.0, 0.0)), ((1.0, 1.0), (1.0, 2.0))),
}
_NAMED = {(P, Q): name for name, (P, Q) in _CASES.items()}


def _describe(P, Q) -> str:
    name = _NAMED.get((tuple(map(tuple, P)), tuple(map(tuple, Q))))
    return f"align_2d(P, Q), {len(P)} pairs" + (f": {name}" if name else "")


def _random(rng: random.Random) -> tuple:
    """3 to 8 points in a 10 m square, turned by any angle, moved, with centimetre noise."""
    n = rng.randint(3, 8)
    P = tuple((rng.uniform(-5, 5), rng.uniform(-5, 5)) for _ in range(n))
    Q = _moved(P, rng.uniform(-180, 180), (rng.uniform(-4, 4), rng.uniform(-4, 4)))
    return P, tuple((x + rng.gauss(0, 0.02), y + rng.gauss(0, 0.02)) for x, y in Q)


def _diagnose(args, got, want) -> str:
    """A mirror, or the turn the wrong way round, named in words."""
    try:
        R = [[float(v) for v in row] for row in got[0]]
        if len(R) != 2 or any(len(row) != 2 for row in R):
            return ""
    except (TypeError, ValueError, IndexError, KeyError):
        return ""
    if det2(R) < -0.5:
        return ("your R has determinant " + f"{det2(R):.3g}" + ": it is a reflection, a mirror image, not a turn. "
                "Keep det R = +1 (atan2 of H's entries gives a rotation; an SVD needs the fix diag(1, det(V Uᵀ))).")
    W = want[0]
    if all(abs(R[i][j] - W[j][i]) < 1e-6 for i in range(2) for j in range(2)) and abs(W[0][1]) > 1e-6:
        return "your R is the reference's transposed: it turns the other way, from Q back onto P (H transposed?)."
    return ""


EXERCISES = (
    Build(
        id="13.9",
        title="Code the robot: align_2d",
        function="align_2d",
        params=("P", "Q"),
        starter=_STARTER,
        solution=_SOLUTION,
        reference=align_2d,
        run_figure="align",
        examples=(
            (((0.0, 0.0), (2.0, 0.0), (0.0, 1.0)), ((1.0, 1.0), (1.0, 3.0), (0.0, 1.0))),
            (((0.0, 0.0), (3.0, 0.0), (3.0, 3.0)), ((4.0, 1.0), (5.0, 3.0), (3.0, 5.0))),  # 13.2's sets
        ),
        edge_cases=tuple(_CASES.values()),
        random_args=_random,
        describe=_describe,
        diagnose=_diagnose,
        abs_tol=1e-6,
    ),
)
