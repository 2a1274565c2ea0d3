"""Hold-out programs of exercise 5.10 (one Gauss–Newton iteration on an SE(2) pose graph), kept apart
from ``holdout_programs.py`` so that neither file grows past 400 lines; that module merges them in.

``SAYS`` names, for each wrong program, the sentences of ``workbook.bank.pose_graph_slips`` its failing
rows must carry (by their opening words); every other wrong program and every right one must carry none
(tests/unit/test_pose_graph_se2.py)."""

from __future__ import annotations

PURE_PYTHON = '''import math


def wrap(a):
    return math.atan2(math.sin(a), math.cos(a))


def solve(M, v):
    """M y = v by Gauss-Jordan elimination with partial pivoting."""
    n = len(v)
    rows = [list(M[r]) + [v[r]] for r in range(n)]
    for col in range(n):
        pivot = max(range(col, n), key=lambda r: abs(rows[r][col]))
        rows[col], rows[pivot] = rows[pivot], rows[col]
        for r in range(n):
            if r != col:
                f = rows[r][col] / rows[col][col]
                rows[r] = [a - f * b for a, b in zip(rows[r], rows[col])]
    return [rows[r][n] / rows[r][r] for r in range(n)]


def gauss_newton_se2(poses, edges):
    n = 3 * len(poses)
    H = [[0.0] * n for _ in range(n)]
    b = [0.0] * n
    for i, j, z, W in edges:
        (xi, yi, ti), (xj, yj, tj) = poses[i], poses[j]
        c, s = math.cos(ti), math.sin(ti)
        dx, dy = xj - xi, yj - yi
        hx, hy = c * dx + s * dy, -s * dx + c * dy
        e = [z[0] - hx, z[1] - hy, wrap(z[2] - (tj - ti))]
        A = [[c, s, -hy], [-s, c, hx], [0, 0, 1]]
        B = [[-c, -s, 0], [s, -c, 0], [0, 0, -1]]
        for p, P in ((i, A), (j, B)):
            PtW = [[sum(P[k][r] * W[k][m] for k in range(3)) for m in range(3)] for r in range(3)]
            for r in range(3):
                b[3 * p + r] += sum(PtW[r][m] * e[m] for m in range(3))
                for q, Q in ((i, A), (j, B)):
                    for col in range(3):
                        H[3 * p + r][3 * q + col] += sum(PtW[r][m] * Q[m][col] for m in range(3))
    step = solve([row[3:] for row in H[3:]], [-v for v in b[3:]])
    out = [list(poses[0])]
    for k in range(1, len(poses)):
        x, y, t = poses[k]
        out.append([x + step[3 * k - 3], y + step[3 * k - 2], wrap(t + step[3 * k - 1])])
    return out
'''

NUMERIC_JACOBIANS = '''import numpy as np


def wrap(a):
    return np.arctan2(np.sin(a), np.cos(a))


def error(xi, xj, z):
    c, s = np.cos(xi[2]), np.sin(xi[2])
    d = xj[:2] - xi[:2]
    h = np.array([c * d[0] + s * d[1], -s * d[0] + c * d[1], xj[2] - xi[2]])
    e = np.asarray(z, float) - h
    e[2] = wrap(e[2])
    return e


def gauss_newton_se2(poses, edges):
    x = np.asarray(poses, float)
    n = 3 * len(x)
    H, b = np.zeros((n, n)), np.zeros(n)
    eps = 1e-6
    for i, j, z, omega in edges:
        e = error(x[i], x[j], z)
        J = np.zeros((3, n))
        for k in range(3):
            for p in (i, j):
                up, down = x.copy(), x.copy()
                up[p, k] += eps
                down[p, k] -= eps
                diff = error(up[i], up[j], z) - error(down[i], down[j], z)
                diff[2] = wrap(diff[2])
                J[:, 3 * p + k] = diff / (2 * eps)
        W = np.asarray(omega, float)
        H += J.T @ W @ J
        b += J.T @ W @ e
    dx = np.concatenate([np.zeros(3), np.linalg.solve(H[3:, 3:], -b[3:])])
    new = x + dx.reshape(-1, 3)
    new[:, 2] = wrap(new[:, 2])
    return new
'''

WRONG = {
    "step taken uphill": [("np.linalg.solve(H[3:, 3:], -b[3:])", "np.linalg.solve(H[3:, 3:], b[3:])")],
    "error the other way round, Jacobians kept": [("e = np.array(z, dtype=float) - h", "e = h - np.array(z, dtype=float)")],
    "edge angle error not wrapped": [("        e[2] = wrap(e[2])\n", "")],
    "result angles not wrapped": [("    new[:, 2] = wrap(new[:, 2])\n", "")],
    "the prediction's angle wrapped, not the error's": [
        ("h = np.append(Rt @ d, x[j, 2] - x[i, 2])", "h = np.append(Rt @ d, wrap(x[j, 2] - x[i, 2]))"),
        ("        e[2] = wrap(e[2])\n", "")],
    "nothing wrapped": [("        e[2] = wrap(e[2])\n", ""), ("    new[:, 2] = wrap(new[:, 2])\n", "")],
    "pose 0 not anchored (least squares)": [("    dx = np.zeros(3 * n)\n    dx[3:] = np.linalg.solve(H[3:, 3:], -b[3:])",
                                             "    dx = np.linalg.lstsq(H, -b, rcond=None)[0]")],
    "pose 0 put at the origin": [("    new[:, 2] = wrap(new[:, 2])\n", "    new[:, 2] = wrap(new[:, 2])\n    new[0] = 0.0\n")],
    "every Omega taken as the identity": [("W = np.array(omega, dtype=float)", "W = np.eye(3)")],
    "A and B swapped": [("for p, Jp in ((i, A), (j, B)):", "for p, Jp in ((i, B), (j, A)):"),
                        ("for q, Jq in ((i, A), (j, B)):", "for q, Jq in ((i, B), (j, A)):")],
    "turn column of A with the wrong sign": [("A[:2, :2], A[:2, 2], A[2, 2] = Rt, -dRt @ d, 1.0", "A[:2, :2], A[:2, 2], A[2, 2] = Rt, dRt @ d, 1.0")],
    "R(theta_i) for its transpose": [("Rt = np.array([[c, s], [-s, c]])", "Rt = np.array([[c, -s], [s, c]])")],
    "b without Omega": [("b[3 * p:3 * p + 3] += Jp.T @ W @ e", "b[3 * p:3 * p + 3] += Jp.T @ e")],
}

SAYS = {
    "step taken uphill": ("Every pose moved by exactly minus",),
    "error the other way round, Jacobians kept": ("Every pose moved by exactly minus",),
    "edge angle error not wrapped": ("These are the poses of a step whose edge angle",),
    "result angles not wrapped": ("The angle of pose",),
    "the prediction's angle wrapped, not the error's": ("These are the poses of a step whose edge angle",),
    "nothing wrapped": ("The angle of pose", "These are the poses of a step whose edge angle"),
    "pose 0 not anchored (least squares)": ("Pose 0 moved",),
    "pose 0 put at the origin": ("Pose 0 moved",),
    "every Omega taken as the identity": ("These are the poses of a step with every Ω",),
}

RIGHT = {
    "anchored by adding the identity": [(
        "    dx = np.zeros(3 * n)\n    dx[3:] = np.linalg.solve(H[3:, 3:], -b[3:])",
        "    H[:3, :3] += np.eye(3)\n    dx = np.linalg.solve(H, -b)")],
    "pure Python lists": PURE_PYTHON,
    "numerical Jacobians, an array out": NUMERIC_JACOBIANS,
    "inverse instead of solve": [("np.linalg.solve(H[3:, 3:], -b[3:])", "-np.linalg.inv(H[3:, 3:]) @ b[3:]")],
    "wrap by remainder": [("return np.arctan2(np.sin(a), np.cos(a))",
                           "return np.remainder(np.asarray(a) + np.pi, 2 * np.pi) - np.pi")],
    "tuples out": [("return new.tolist()", "return tuple(tuple(float(v) for v in row) for row in new)")],
}
