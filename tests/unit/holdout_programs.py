"""A hold-out of hand-written learner programs for every Build exercise (tests/unit/test_build_holdout.py).

Each exercise has WRONG programs (classic slips a learner makes: each breaks what the statement asks on
some input) and RIGHT ones (correct rewrites in another style). A program is either a list of
(old, new) changes to the exercise's model solution, or a whole program (a string).
"""

from __future__ import annotations

import holdout_programs_align
import holdout_programs_ekf
import holdout_programs_particles
import holdout_programs_poe
import holdout_programs_poses
import holdout_programs_se2

ROT = "import math\n\n\ndef rotate_2d(x, y, theta):\n    c, s = math.cos(theta), math.sin(theta)\n"
EKF = "def ekf_update(x, P, z, R):\n"
FK = "import math\n\n\ndef forward_kinematics_2link(L1, L2, theta1, theta2):\n"
PID = "def pid_step(e, e_prev, integral, Kp, Ki, Kd, dt):\n"

IK_HEAD = '''import math


def ik_2link(L1, L2, x, y, elbow_up):
'''
IK_REACH = '''    r = math.hypot(x, y)
    if r > L1 + L2 + 1e-9 or r < abs(L1 - L2) - 1e-9:
        return None
    c2 = (x * x + y * y - L1 * L1 - L2 * L2) / (2 * L1 * L2)
    c2 = max(-1.0, min(1.0, c2))
'''
IK_ANGLES = '''    t2 = math.acos(c2)
    if elbow_up:
        t2 = -t2
    t1 = math.atan2(y, x) - math.atan2(L2 * math.sin(t2), L1 + L2 * math.cos(t2))
'''
IK_WRAP = "    t1 = math.atan2(math.sin(t1), math.cos(t1))\n    return (t1, t2)\n"


def ik(reach: str = IK_REACH, angles: str = IK_ANGLES, wrap: str = IK_WRAP) -> str:
    return IK_HEAD + reach + angles + wrap


WRONG: dict[str, dict[str, object]] = {
    "0.5": {
        "turned clockwise": ROT + "    return (c * x + s * y, -s * x + c * y)\n",
        "theta read as degrees": ROT + "    t = math.radians(theta)\n    return (math.cos(t) * x - math.sin(t) * y, math.sin(t) * x + math.cos(t) * y)\n",
        "sin and cos swapped": ROT + "    return (s * x - c * y, c * x + s * y)\n",
        "y from the new x": ROT + "    x = c * x - s * y\n    y = s * x + c * y\n    return (x, y)\n",
        "sign slip in y": ROT + "    return (c * x - s * y, s * x - c * y)\n",
        "coordinates swapped in the result": ROT + "    return (s * x + c * y, c * x - s * y)\n",
        "rounded to 2 places": ROT + "    return (round(c * x - s * y, 2), round(s * x + c * y, 2))\n",
    },
    "4.5": {
        "gain upside down": EKF + "    K = R / (P + R)\n    return (x + K * (z - x), (1 - K) * P)\n",
        "innovation reversed": EKF + "    K = P / (P + R)\n    return (x + K * (x - z), (1 - K) * P)\n",
        "P minus K": EKF + "    K = P / (P + R)\n    return (x + K * (z - x), P - K)\n",
        "gain P over R": EKF + "    K = P / R if R else 1.0\n    return (x + K * (z - x), (1 - K) * P)\n",
        "covariance not updated": EKF + "    K = P / (P + R)\n    return (x + K * (z - x), P)\n",
        "new covariance K P": EKF + "    K = P / (P + R)\n    return (x + K * (z - x), K * P)\n",
    },
    "6.5": {
        "link 2 at theta2 alone": FK + "    return (L1 * math.cos(theta1) + L2 * math.cos(theta2), L1 * math.sin(theta1) + L2 * math.sin(theta2))\n",
        "degrees": FK + "    a, b = math.radians(theta1), math.radians(theta1 + theta2)\n    return (L1 * math.cos(a) + L2 * math.cos(b), L1 * math.sin(a) + L2 * math.sin(b))\n",
        "links swapped": FK + "    p = theta1 + theta2\n    return (L2 * math.cos(theta1) + L1 * math.cos(p), L2 * math.sin(theta1) + L1 * math.sin(p))\n",
        "sin and cos swapped": FK + "    p = theta1 + theta2\n    return (L1 * math.sin(theta1) + L2 * math.sin(p), L1 * math.cos(theta1) + L2 * math.cos(p))\n",
        "difference of angles": FK + "    p = theta1 - theta2\n    return (L1 * math.cos(theta1) + L2 * math.cos(p), L1 * math.sin(theta1) + L2 * math.sin(p))\n",
        "y misses link 1": FK + "    p = theta1 + theta2\n    return (L1 * math.cos(theta1) + L2 * math.cos(p), L2 * math.sin(p))\n",
    },
    "8.4": {
        "old integral in u": PID + "    u = Kp * e + Ki * integral + Kd * (e - e_prev) / dt\n    return (u, integral + e * dt)\n",
        "derivative reversed": PID + "    i = integral + e * dt\n    return (Kp * e + Ki * i + Kd * (e_prev - e) / dt, i)\n",
        "derivative not divided by dt": PID + "    i = integral + e * dt\n    return (Kp * e + Ki * i + Kd * (e - e_prev), i)\n",
        "integral without dt": PID + "    i = integral + e\n    return (Kp * e + Ki * i + Kd * (e - e_prev) / dt, i)\n",
        "integral not returned": PID + "    i = integral + e * dt\n    return (Kp * e + Ki * i + Kd * (e - e_prev) / dt, integral)\n",
        "derivative times dt": PID + "    i = integral + e * dt\n    return (Kp * e + Ki * i + Kd * (e - e_prev) * dt, i)\n",
    },
    "1.7": {
        "R instead of its transpose": [("x = c * dx + s * dy", "x = c * dx - s * dy"), ("y = -s * dx + c * dy", "y = s * dx + c * dy")],
        "offset not rotated": [("x = c * dx + s * dy", "x = dx"), ("y = -s * dx + c * dy", "y = dy")],
        "heading not wrapped": [("math.atan2(math.sin(tb - ta), math.cos(tb - ta))", "tb - ta")],
        "frames swapped": [("xa, ya, ta = a\n    xb, yb, tb = b", "xa, ya, ta = b\n    xb, yb, tb = a")],
        "wrapped into [0, 2pi)": [("math.atan2(math.sin(tb - ta), math.cos(tb - ta))", "(tb - ta) % (2 * math.pi)")],
        "wrapped on one side only": [("math.atan2(math.sin(tb - ta), math.cos(tb - ta))",
                                      "tb - ta - 2 * math.pi if tb - ta > math.pi else tb - ta")],
        "rotated by B's heading": [("c, s = math.cos(ta), math.sin(ta)", "c, s = math.cos(tb), math.sin(tb)")],
        "heading a minus b": [("math.atan2(math.sin(tb - ta), math.cos(tb - ta))", "math.atan2(math.sin(ta - tb), math.cos(ta - tb))")],
    },
    "2.8": {
        "whole angle, not half": [("math.sin(angle / 2) / n", "math.sin(angle) / n"), ("math.cos(angle / 2)", "math.cos(angle)")],
        "axis not made unit": [("math.sin(angle / 2) / n", "math.sin(angle / 2)")],
        "turned the other way": [("2 * w * t[i]", "-2 * w * t[i]")],
        "w last": [("return (q, turned)", "return (q[1:] + q[:1], turned)")],
        "w made non-negative": [("return (q, turned)", "return (q if q[0] >= 0 else tuple(-c for c in q), turned)")],
        "degrees": [("n = math.sqrt", "angle = math.radians(angle)\n    n = math.sqrt")],
        "one cross product only": [("turned = tuple(v[i] + 2 * w * t[i] + 2 * tt[i] for i in range(3))",
                                    "turned = tuple(v[i] + 2 * w * t[i] for i in range(3))")],
    },
    "3.10": {
        "P = F P F, no transpose": [("FP[i][k] * F[j][k]", "FP[i][k] * F[k][j]")],
        "Q forgotten": [(" + Q[i][j] for j", " for j")],
        "F at the new heading": [("c, s = math.cos(theta), math.sin(theta)",
                                  "c, s = math.cos(theta + omega * dt), math.sin(theta + omega * dt)")],
        "heading not wrapped": [("heading = math.atan2(math.sin(heading), math.cos(heading))", "pass")],
        "sign of F(1,3)": [("[1.0, 0.0, -v * s * dt]", "[1.0, 0.0, v * s * dt]")],
        "wrapped on one side only": [("heading = math.atan2(math.sin(heading), math.cos(heading))",
                                      "heading = heading - 2 * math.pi if heading > math.pi else heading")],
        "omega without dt": [("heading = theta + omega * dt", "heading = theta + omega")],
        "Q added before the product": [("FP = [[sum(F[i][k] * P[k][j]", "FP = [[sum(F[i][k] * (P[k][j] + Q[k][j])"),
                                       (" + Q[i][j] for j", " for j")],
    },
    "5.8": {
        "step taken uphill": [("x[1] + d1, x[2] + d2", "x[1] - d1, x[2] - d2")],
        "weights ignored": [("b[a] += w * ja * e", "b[a] += ja * e"), ("H[a][c] += w * ja * jc", "H[a][c] += ja * jc")],
        "error with the wrong sign": [("z - (x[j] - x[i])", "(x[j] - x[i]) - z"), ("((i, 1.0), (j, -1.0))", "((i, -1.0), (j, 1.0))")],
        "singular H not refused": [("if det == 0:\n        return None", "")],
        "only the diagonal of H": [("h11, h12, h21, h22 = H[1][1], H[1][2], H[2][1], H[2][2]",
                                    "h11, h12, h21, h22 = H[1][1], 0.0, 0.0, H[2][2]")],
        "errors after the step": [("return (errors, [x[0], x[1] + d1, x[2] + d2])",
                                   "y = [x[0], x[1] + d1, x[2] + d2]\n    return ([z - (y[j] - y[i]) for i, j, z, w in edges], y)")],
        "anchor moved too": [("return (errors, [x[0], x[1] + d1, x[2] + d2])",
                              "return (errors, [x[0] - (d1 + d2) / 3, x[1] + d1, x[2] + d2])")],
    },
    "6.7": {
        "elbow sign flipped": ik(angles=IK_ANGLES.replace("if elbow_up:", "if not elbow_up:")),
        "unreachable not refused": ik(reach=IK_REACH.replace("        return None\n", "        pass\n")),
        "refused by raising": ik(reach=IK_REACH.replace("        return None\n", "        raise ValueError('out of reach')\n")),
        "acos not clamped": ik(reach=IK_REACH.replace("    c2 = max(-1.0, min(1.0, c2))\n", "")),
        "refused where c2 is past 1 by round-off": ik(reach=(
            "    c2 = (x * x + y * y - L1 * L1 - L2 * L2) / (2 * L1 * L2)\n"
            "    if abs(c2) > 1:\n        return None\n")),
        "theta1 not wrapped": ik(wrap="    return (t1, t2)\n"),
        "atan instead of atan2": ik(angles=IK_ANGLES.replace("math.atan2(y, x) -", "math.atan(y / x) -")),
        "wrapped on one side only": ik(wrap="    if t1 > math.pi:\n        t1 -= 2 * math.pi\n    return (t1, t2)\n"),
        "shoulder from the target alone": ik(angles=IK_ANGLES.replace(
            " - math.atan2(L2 * math.sin(t2), L1 + L2 * math.cos(t2))", "")),
    },
    "7.8": {
        "det == 0 as the test": [("abs(det) < 1e-9", "det == 0")],
        "second column at theta2 alone": [("-L2 * s12]", "-L2 * math.sin(theta2)]"), ("L2 * c12]]", "L2 * math.cos(theta2)]]")],
        "sign slip in J11": [("[[-L1 * s1 - L2 * s12", "[[L1 * s1 - L2 * s12")],
        "det returned for the test": [("return (J, abs(det) < 1e-9)", "return (J, det)")],
        "a looser threshold": [("abs(det) < 1e-9", "abs(det) < 1e-6")],
        "isclose to zero": [("abs(det) < 1e-9", "math.isclose(det, 0)")],
        "J transposed": [("return (J, abs(det) < 1e-9)", "return ([[J[0][0], J[1][0]], [J[0][1], J[1][1]]], abs(det) < 1e-9)")],
        "the test reversed": [("abs(det) < 1e-9", "abs(det) > 1e-9")],
    },
    "8.8": {
        "no clamping": [("return (min(u_max, max(u_min, u)), new_integral)", "return (u, new_integral)")],
        "no anti-windup": [("new_integral = integral  # integrating", "pass  # integrating"), ("u = Kp * e + Ki * integral + d", "pass")],
        "integral frozen whenever saturated": [("(u > u_max and e > 0) or (u < u_min and e < 0)", "u > u_max or u < u_min")],
        "dt = 0 divides": [("if dt > 0 else 0.0", "")],
        "u not recomputed with the integral kept": [("        u = Kp * e + Ki * integral + d\n", "")],
        "saturation judged with the old integral": [
            ("    if (u > u_max and e > 0)", "    u_old = Kp * e + Ki * integral + d\n    if (u_old > u_max and e > 0)"),
            ("or (u < u_min and e < 0)", "or (u_old < u_min and e < 0)")],
        "integral clipped to the limits": [("        new_integral = integral  # integrating", "        new_integral = min(new_integral, u_max) if e > 0 else max(new_integral, u_min)  # integrating")],
        "dt = 0 still integrates": [("new_integral = integral + e * dt", "new_integral = integral + e * (dt or 1)")],
        "at the limit taken as above it": [("(u > u_max and e > 0) or (u < u_min and e < 0)",
                                            "(u >= u_max and e > 0) or (u <= u_min and e < 0)")],
    },
    "9.9": {
        "bearing innovation not wrapped": [("wrap(z[1] - (math.atan2(dy, dx) - x[2]))", "z[1] - (math.atan2(dy, dx) - x[2])")],
        "heading not wrapped": [("wrap(th + omega * dt)", "th + omega * dt"), ("x[2] = wrap(x[2])", "pass")],
        "no update": [("if z is not None:", "if False:")],
        "turn rate not capped": [("max(-1.0, min(1.0, 1.5 * error))", "1.5 * error")],
        "P = F P F + Q": [("matmul(matmul(F, P), transpose(F))", "matmul(matmul(F, P), F)")],
        "never updates again once the landmark is lost": [
            ("def nav_step(", "LOST = []\n\n\ndef nav_step("),
            ("    if z is not None:", "    if z is None:\n        LOST.append(True)\n    if z is not None and not LOST:")],
        "steers from the prediction": [("    # Update on the landmark, when it is seen.", "    pred = list(x)\n    # Update on the landmark, when it is seen."),
                                       ("math.atan2(waypoint[1] - x[1], waypoint[0] - x[0]) - x[2]",
                                        "math.atan2(waypoint[1] - pred[1], waypoint[0] - pred[0]) - pred[2]")],
        "H with the bearing row's sign flipped": [("[dy / q, -dx / q, -1]", "[-dy / q, dx / q, 1]")],
    },
}

RIGHT: dict[str, dict[str, object]] = {
    "0.5": {
        "complex numbers": "import cmath\n\n\ndef rotate_2d(x, y, theta):\n    z = complex(x, y) * cmath.exp(1j * theta)\n    return (z.real, z.imag)\n",
        "polar": "import math\n\n\ndef rotate_2d(x, y, theta):\n    r, a = math.hypot(x, y), math.atan2(y, x) + theta\n    return [r * math.cos(a), r * math.sin(a)]\n",
        "numpy": "import numpy as np\n\n\ndef rotate_2d(x, y, theta):\n    c, s = np.cos(theta), np.sin(theta)\n    return np.array([[c, -s], [s, c]]) @ np.array([x, y])\n",
    },
    "4.5": {
        "information form": EKF + "    return ((x * R + z * P) / (P + R), P * R / (P + R))\n",
        "blend": EKF + "    K = P / (P + R)\n    return ((1 - K) * x + K * z, P - K * P)\n",
        "list": EKF + "    K = P / (P + R)\n    innovation = z - x\n    return [x + K * innovation, (1 - K) * P]\n",
        "numpy": "import numpy as np\n\n\n" + EKF + "    K = np.float64(P) / (P + R)\n    return np.array([x + K * (z - x), (1 - K) * P])\n",
    },
    "6.5": {
        "complex numbers": "import cmath\n\n\ndef forward_kinematics_2link(L1, L2, theta1, theta2):\n    tip = L1 * cmath.exp(1j * theta1) + L2 * cmath.exp(1j * (theta1 + theta2))\n    return (tip.real, tip.imag)\n",
        "addition formulas": FK + "    c1, s1, c2, s2 = math.cos(theta1), math.sin(theta1), math.cos(theta2), math.sin(theta2)\n"
                             "    return (L1 * c1 + L2 * (c1 * c2 - s1 * s2), L1 * s1 + L2 * (s1 * c2 + c1 * s2))\n",
        "numpy": "import numpy as np\n\n\ndef forward_kinematics_2link(L1, L2, theta1, theta2):\n    a = np.array([theta1, theta1 + theta2])\n    return (float(np.dot([L1, L2], np.cos(a))), float(np.dot([L1, L2], np.sin(a))))\n",
    },
    "8.4": {
        "terms in another order": PID + "    d = Kd * (e - e_prev) / dt\n    integral += e * dt\n    return (d + Ki * integral + Kp * e, integral)\n",
        "numpy": "import numpy as np\n\n\n" + PID + "    i = np.float64(integral) + e * dt\n    return (np.dot([Kp, Ki, Kd], [e, i, (e - e_prev) / dt]), i)\n",
        "list": PID + "    new = integral + dt * e\n    return [Kp * e + Ki * new + Kd * ((e - e_prev) / dt), new]\n",
    },
    "1.7": {
        "wrap by modulo": [("math.atan2(math.sin(tb - ta), math.cos(tb - ta))", "(tb - ta + math.pi) % (2 * math.pi) - math.pi")],
        "wrap by remainder": [("math.atan2(math.sin(tb - ta), math.cos(tb - ta))", "math.remainder(tb - ta, 2 * math.pi)")],
        "wrap by a loop": [("math.atan2(math.sin(tb - ta), math.cos(tb - ta))", "tb - ta\n    while theta > math.pi:\n        theta -= 2 * math.pi\n"
                                                                                     "    while theta <= -math.pi:\n        theta += 2 * math.pi")],
        "homogeneous matrices": '''import numpy as np


def T(p):
    c, s = np.cos(p[2]), np.sin(p[2])
    return np.array([[c, -s, p[0]], [s, c, p[1]], [0, 0, 1]])


def relative_pose(a, b):
    M = np.linalg.inv(T(a)) @ T(b)
    return (M[0, 2], M[1, 2], np.arctan2(M[1, 0], M[0, 0]))
''',
    },
    "2.8": {
        "numpy": """import numpy as np


def rotate_axis_angle(axis, angle, v):
    k = np.array(axis, dtype=float) / np.linalg.norm(axis)
    q = np.concatenate([[np.cos(angle / 2)], np.sin(angle / 2) * k])
    v = np.array(v, dtype=float)
    t = 2 * np.cross(q[1:], v)
    return (q, v + q[0] * t + np.cross(q[1:], t))
""",
        "Rodrigues": '''import math


def rotate_axis_angle(axis, angle, v):
    n = math.sqrt(sum(a * a for a in axis))
    k = [a / n for a in axis]
    c, s = math.cos(angle), math.sin(angle)
    kv = sum(k[i] * v[i] for i in range(3))
    kxv = (k[1] * v[2] - k[2] * v[1], k[2] * v[0] - k[0] * v[2], k[0] * v[1] - k[1] * v[0])
    h = math.sin(angle / 2)
    q = (math.cos(angle / 2), h * k[0], h * k[1], h * k[2])
    return (q, [v[i] * c + kxv[i] * s + k[i] * kv * (1 - c) for i in range(3)])
''',
        "quaternion products": '''import math


def mul(p, q):
    a1, b1, c1, d1 = p
    a2, b2, c2, d2 = q
    return (a1 * a2 - b1 * b2 - c1 * c2 - d1 * d2, a1 * b2 + b1 * a2 + c1 * d2 - d1 * c2,
            a1 * c2 - b1 * d2 + c1 * a2 + d1 * b2, a1 * d2 + b1 * c2 - c1 * b2 + d1 * a2)


def rotate_axis_angle(axis, angle, v):
    n = math.sqrt(sum(a * a for a in axis))
    s = math.sin(angle / 2)
    q = (math.cos(angle / 2), *(s * a / n for a in axis))
    conj = (q[0], -q[1], -q[2], -q[3])
    return (q, mul(mul(q, (0.0, *v)), conj)[1:])
''',
    },
    "3.10": {
        "numpy": '''import numpy as np


def ekf_predict(x, P, v, omega, dt, Q):
    px, py, th = x
    F = np.array([[1, 0, -v * np.sin(th) * dt], [0, 1, v * np.cos(th) * dt], [0, 0, 1.0]])
    h = (th + omega * dt + np.pi) % (2 * np.pi) - np.pi
    return ([px + v * np.cos(th) * dt, py + v * np.sin(th) * dt, h], F @ np.array(P) @ F.T + np.array(Q))
''',
        "wrap by remainder": [("heading = math.atan2(math.sin(heading), math.cos(heading))", "heading = math.remainder(heading, 2 * math.pi)")],
    },
    "5.8": {
        "numpy solve": '''import numpy as np


def gauss_newton_step(x, edges):
    errors = [z - (x[j] - x[i]) for i, j, z, w in edges]
    H, b = np.zeros((3, 3)), np.zeros(3)
    for (i, j, z, w), e in zip(edges, errors):
        J = np.zeros(3)
        J[i], J[j] = 1.0, -1.0
        H += w * np.outer(J, J)
        b += w * J * e
    if abs(np.linalg.det(H[1:, 1:])) < 1e-12:
        return None
    d = np.linalg.solve(H[1:, 1:], -b[1:])
    return (errors, [x[0], x[1] + d[0], x[2] + d[1]])
''',
        "Cramer in one place": [("    d1 = (-b[1] * h22 + b[2] * h12) / det\n    d2 = (-b[2] * h11 + b[1] * h21) / det\n",
                                 "    r1, r2 = -b[1], -b[2]\n    d1 = (r1 * h22 - h12 * r2) / det\n    d2 = (h11 * r2 - h21 * r1) / det\n")],
    },
    "6.7": {
        "the model": ik(),
        "wrap by modulo": ik(wrap="    t1 = (t1 + math.pi) % (2 * math.pi) - math.pi\n    return (t1, t2)\n"),
        "elbow by atan2 of the sine": ik(angles=(
            "    t2 = math.atan2(math.sqrt(max(0.0, 1 - c2 * c2)), c2)\n"
            "    if elbow_up:\n        t2 = -t2\n"
            "    t1 = math.atan2(y, x) - math.atan2(L2 * math.sin(t2), L1 + L2 * math.cos(t2))\n")),
        "no wrap, remainder": ik(wrap="    return (math.remainder(t1, 2 * math.pi), t2)\n"),
    },
    "7.8": {
        "det from sin theta2": [("det = J[0][0] * J[1][1] - J[0][1] * J[1][0]", "det = L1 * L2 * math.sin(theta2)")],
        "numpy": '''import numpy as np


def jacobian_2link(L1, L2, theta1, theta2):
    a, b = theta1, theta1 + theta2
    J = np.array([[-L1 * np.sin(a) - L2 * np.sin(b), -L2 * np.sin(b)], [L1 * np.cos(a) + L2 * np.cos(b), L2 * np.cos(b)]])
    return (J, bool(abs(np.linalg.det(J)) < 1e-9))
''',
    },
    "8.8": {
        "sign test by product": [("if (u > u_max and e > 0) or (u < u_min and e < 0):",
                                  "if e * (u - min(u_max, max(u_min, u))) > 0:")],
        "integrate only when allowed": '''def pid_step_clamped(e, e_prev, integral, Kp, Ki, Kd, dt, u_min, u_max):
    d = 0.0 if dt == 0 else Kd * (e - e_prev) / dt
    trial = Kp * e + Ki * (integral + e * dt) + d
    winding = (trial > u_max and e > 0) or (trial < u_min and e < 0)
    if not winding:
        integral = integral + e * dt
    u = Kp * e + Ki * integral + d
    return [max(u_min, min(u_max, u)), integral]
''',
    },
    "9.9": {
        "wrap by remainder": [("    return math.atan2(math.sin(a), math.cos(a))", "    return math.remainder(a, 2 * math.pi)")],
        "numpy": '''import math
import numpy as np


def wrap(a):
    return (a + math.pi) % (2 * math.pi) - math.pi


def nav_step(x, P, u, z, landmark, waypoint, dt, Q, R):
    v, w = u
    px, py, th = x
    F = np.array([[1, 0, -v * math.sin(th) * dt], [0, 1, v * math.cos(th) * dt], [0, 0, 1.0]])
    x = np.array([px + v * math.cos(th) * dt, py + v * math.sin(th) * dt, wrap(th + w * dt)])
    P = F @ np.array(P) @ F.T + np.array(Q)
    if z is not None:
        dx, dy = landmark[0] - x[0], landmark[1] - x[1]
        q = dx * dx + dy * dy
        H = np.array([[-dx / math.sqrt(q), -dy / math.sqrt(q), 0], [dy / q, -dx / q, -1]])
        y = np.array([z[0] - math.sqrt(q), wrap(z[1] - (math.atan2(dy, dx) - x[2]))])
        K = P @ H.T @ np.linalg.inv(H @ P @ H.T + np.array(R))
        x = x + K @ y
        x[2] = wrap(x[2])
        P = (np.eye(3) - K @ H) @ P
    e = wrap(math.atan2(waypoint[1] - x[1], waypoint[0] - x[0]) - x[2])
    return (list(x), P.tolist(), (0.5, max(-1.0, min(1.0, 1.5 * e))))
''',
    },
}

WRONG["4.10"], RIGHT["4.10"] = holdout_programs_ekf.WRONG, holdout_programs_ekf.RIGHT
WRONG["5.10"], RIGHT["5.10"] = holdout_programs_se2.WRONG, holdout_programs_se2.RIGHT
WRONG["10.8"], RIGHT["10.8"] = holdout_programs_poses.WRONG, holdout_programs_poses.RIGHT
WRONG["11.8"], RIGHT["11.8"] = holdout_programs_poe.WRONG, holdout_programs_poe.RIGHT
WRONG["12.8"], RIGHT["12.8"] = holdout_programs_particles.WRONG, holdout_programs_particles.RIGHT
WRONG["13.9"], RIGHT["13.9"] = holdout_programs_align.WRONG, holdout_programs_align.RIGHT
