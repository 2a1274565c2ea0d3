"""Hold-out programs of exercise 13.9 (align_2d), kept apart from ``holdout_programs.py`` so that
neither file grows past 400 lines; that module merges them in."""

from __future__ import annotations

_NUMPY_SVD = '''import numpy as np


def align_2d(P, Q):
    P, Q = np.asarray(P, dtype=float), np.asarray(Q, dtype=float)
    pm, qm = P.mean(axis=0), Q.mean(axis=0)
    H = (P - pm).T @ (Q - qm)
    if abs(H[0, 1] - H[1, 0]) < 1e-9 and abs(H[0, 0] + H[1, 1]) < 1e-9:
        R = np.eye(2)
    else:
        U, _, Vt = np.linalg.svd(H)
        R = Vt.T @ U.T{fix}
    return R.tolist(), (qm - R @ pm).tolist()
'''

WRONG: dict[str, object] = {
    "H transposed": [("s, c = h12 - h21, h11 + h22", "s, c = h21 - h12, h11 + h22")],
    "atan in place of atan2": [("        theta = math.atan2(s, c)", "        theta = math.atan(s / c)")],
    "points not centred": [("ax, ay, bx, by = ax - px, ay - py, bx - qx, by - qy", "ax, ay, bx, by = ax, ay, bx, by")],
    "t from the centroids alone": [("t = [qx - (R[0][0] * px + R[0][1] * py), qy - (R[1][0] * px + R[1][1] * py)]",
                                    "t = [qx - px, qy - py]")],
    "R(−θ)": [("R = [[math.cos(theta), -math.sin(theta)], [math.sin(theta), math.cos(theta)]]",
               "R = [[math.cos(theta), math.sin(theta)], [-math.sin(theta), math.cos(theta)]]")],
    "None when every turn fits": [("        theta = 0.0\n", "        return None\n")],
    "an SVD with the mirror left in": _NUMPY_SVD.replace("{fix}", ""),
}

RIGHT: dict[str, object] = {
    "an SVD with the reflection fix": _NUMPY_SVD.replace(
        "{fix}", "\n        if np.linalg.det(R) < 0:\n            R = Vt.T @ np.diag([1.0, -1.0]) @ U.T"),
    "complex numbers": '''import cmath


def align_2d(P, Q):
    n = len(P)
    p = [complex(x, y) for x, y in P]
    q = [complex(x, y) for x, y in Q]
    pm, qm = sum(p) / n, sum(q) / n
    z = sum((a - pm).conjugate() * (b - qm) for a, b in zip(p, q))  # (H11 + H22) + i (H12 - H21)
    turn = z / abs(z) if abs(z.real) >= 1e-9 or abs(z.imag) >= 1e-9 else 1
    t = qm - turn * pm
    return ((turn.real, -turn.imag), (turn.imag, turn.real)), (t.real, t.imag)
''',
}
