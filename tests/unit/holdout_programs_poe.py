"""Hold-out programs of exercise 11.8 (fk_poe), kept apart from ``holdout_programs.py`` so that
neither file grows past 400 lines; that module merges them in."""

from __future__ import annotations

_NUMPY = '''import numpy as np


def _exp6(S, th):
    w, v = np.asarray(S[:3], float), np.asarray(S[3:], float)
    W = np.array([[0, -w[2], w[1]], [w[2], 0, -w[0]], [-w[1], w[0], 0]])
    R = np.eye(3) + np.sin(th) * W + (1 - np.cos(th)) * W @ W
    G = np.eye(3) * th + (1 - np.cos(th)) * W + (th - np.sin(th)) * W @ W
    T = np.eye(4)
    T[:3, :3], T[:3, 3] = R, G @ v
    return T


def fk_poe(M, S_list, theta):
    T = np.eye(4)
    for S, th in zip(S_list, theta):
        T = {product}
    return ({tail}).tolist()
'''

_CLOSED_FORM = '''import math


def fk_poe(M, S_list, theta):
    T = [[1.0, 0, 0, 0], [0, 1.0, 0, 0], [0, 0, 1.0, 0], [0, 0, 0, 1.0]]
    for S, th in zip(S_list, theta):
        w, v = list(S[:3]), list(S[3:])
        if max(abs(c) for c in w) < 1e-12:  # a slide: p = v th
            R, p = [[1.0, 0, 0], [0, 1.0, 0], [0, 0, 1.0]], [c * th for c in v]
        else:  # p = (I - R)(w x v) + w w^T v th
            c, s = math.cos(th), math.sin(th)
            R = [[c * (i == j) + w[i] * w[j] * (1 - c) + s * e for j, e in enumerate(row)]
                 for i, row in enumerate([[0, -w[2], w[1]], [w[2], 0, -w[0]], [-w[1], w[0], 0]])]
            q = [w[1] * v[2] - w[2] * v[1], w[2] * v[0] - w[0] * v[2], w[0] * v[1] - w[1] * v[0]]
            h = sum(a * b for a, b in zip(w, v)) * th
            p = [q[i] - sum(R[i][k] * q[k] for k in range(3)) + w[i] * h for i in range(3)]
        E = [R[0] + [p[0]], R[1] + [p[1]], R[2] + [p[2]], [0, 0, 0, 1.0]]
        T = [[sum(T[i][k] * E[k][j] for k in range(4)) for j in range(4)] for i in range(4)]
    return [[sum(T[i][k] * M[k][j] for k in range(4)) for j in range(4)] for i in range(4)]
'''

WRONG: dict[str, object] = {
    "the exponentials in reverse order": _NUMPY.replace("{product}", "_exp6(S, th) @ T").replace(
        "{tail}", "T @ np.asarray(M, float)"),
    "M on the left (the body form)": _NUMPY.replace("{product}", "T @ _exp6(S, th)").replace(
        "{tail}", "np.asarray(M, float) @ T"),
    "M left out": _NUMPY.replace("{product}", "T @ _exp6(S, th)").replace("{tail}", "T"),
    "the shift v θ, without G": [("        p = [sum(G[i][k] * v[k] for k in range(3)) for i in range(3)]",
                                  "        p = [v[i] * th for i in range(3)]")],
    "R(−θ): sin θ with the wrong sign": [("R = [[(i == j) + s * W[i][j]", "R = [[(i == j) - s * W[i][j]")],
    "G without the I θ term": [("G = [[th * (i == j) + (1 - c)", "G = [[(1 - c)")],
    "v taken first, S read as (v, ω)": [("(wx, wy, wz), v = S[:3], S[3:]", "v, (wx, wy, wz) = S[:3], S[3:]")],
    "θ wrapped into [−π, π] (a prismatic joint's metres too)": [
        ("        s, c = math.sin(th), math.cos(th)",
         "        th = math.atan2(math.sin(th), math.cos(th))\n        s, c = math.sin(th), math.cos(th)")],
}

RIGHT: dict[str, object] = {
    "NumPy, the space form": _NUMPY.replace("{product}", "T @ _exp6(S, th)").replace(
        "{tail}", "T @ np.asarray(M, float)"),
    "the closed form p = (I − R)(ω × v) + ω ωᵀ v θ, a branch for slides": _CLOSED_FORM,
}
