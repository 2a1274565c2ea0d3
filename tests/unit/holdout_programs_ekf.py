"""Hold-out programs of exercise 4.10 (a range–bearing EKF update), kept apart from
``holdout_programs.py`` so that neither file grows past 400 lines; that module merges them in."""

from __future__ import annotations

NUMPY_JOSEPH = '''import numpy as np


def ekf_update_rb(x, P, z, landmark, R):
    x, P, R = np.array(x, float), np.array(P, float), np.array(R, float)
    d = np.array(landmark, float) - x[:2]
    q = d @ d
    if q == 0:
        return None
    r = np.sqrt(q)
    h = np.array([r, np.arctan2(d[1], d[0]) - x[2]])
    H = np.array([[-d[0] / r, -d[1] / r, 0.0], [d[1] / q, -d[0] / q, -1.0]])
    y = np.array(z, float) - h
    y[1] = (y[1] + np.pi) % (2 * np.pi) - np.pi
    K = P @ H.T @ np.linalg.inv(H @ P @ H.T + R)
    x_new = x + K @ y
    x_new[2] = np.arctan2(np.sin(x_new[2]), np.cos(x_new[2]))
    A = np.eye(3) - K @ H
    return (x_new, A @ P @ A.T + K @ R @ K.T)  # the Joseph form: the same P+ with this K
'''

WRONG = {
    "bearing innovation not wrapped": [("y = [z[0] - h[0], wrap(z[1] - h[1])]", "y = [z[0] - h[0], z[1] - h[1]]")],
    "heading not wrapped": [("x_new = [moved[0], moved[1], wrap(moved[2])]", "x_new = moved")],
    "gain without S inverse": [("K = [[sum(PHt[i][k] * S_inv[k][j]", "K = [[sum(PHt[i][j] * (k == j)")],
    "bearing row of H with the wrong sign": [("[dy / q, -dx / q, -1.0]", "[-dy / q, dx / q, 1.0]")],
    "range row divided by q": [("[-dx / r, -dy / r, 0.0]", "[-dx / q, -dy / q, 0.0]")],
    "covariance not updated": [("return (x_new, P_new)", "return (x_new, P)")],
    "innovation reversed": [("y = [z[0] - h[0], wrap(z[1] - h[1])]", "y = [h[0] - z[0], wrap(h[1] - z[1])]")],
    "S without R": [("for k in range(3)) + R[i][j] for j", "for k in range(3)) for j")],
    "R's diagonal only": [("for k in range(3)) + R[i][j] for j", "for k in range(3)) + (R[i][j] if i == j else 0.0) for j")],
    "no refusal at the landmark": [("    if q == 0:\n        return None  # the landmark is where the robot is: no bearing, no H\n", "")],
}

RIGHT = {
    "numpy and the Joseph form": NUMPY_JOSEPH,
    "wrap by remainder": [("return math.atan2(math.sin(a), math.cos(a))", "return math.remainder(a, 2 * math.pi)")],
    "Joseph form in lists": [(
        "    P_new = [[sum(IKH[i][k] * P[k][j] for k in range(3)) for j in range(3)] for i in range(3)]\n",
        "    A = [[sum(IKH[i][k] * P[k][j] for k in range(3)) for j in range(3)] for i in range(3)]\n"
        "    APAt = [[sum(A[i][k] * IKH[j][k] for k in range(3)) for j in range(3)] for i in range(3)]\n"
        "    KR = [[sum(K[i][k] * R[k][j] for k in range(2)) for j in range(2)] for i in range(3)]\n"
        "    P_new = [[APAt[i][j] + sum(KR[i][k] * K[j][k] for k in range(2)) for j in range(3)] for i in range(3)]\n")],
    "tuples out": [("return (x_new, P_new)", "return tuple(x_new), tuple(tuple(row) for row in P_new)")],
}
