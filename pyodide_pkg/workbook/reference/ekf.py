"""The extended Kalman filter for a planar robot: predict with the motion
model (one Euler step of the unicycle), update with a range-and-bearing landmark sighting.

The state is the pose ``(x, y, theta)``; matrices are lists of rows.
"""

from __future__ import annotations

import math

from .linalg import Matrix, add, identity, inverse, matmul, matvec, sub, transpose
from .pose_graph import wrap_angle


def motion_model(state, v: float, omega: float, dt: float) -> tuple[float, float, float]:
    """Drive for ``dt`` seconds at speed ``v`` and turn rate ``omega``.

    x' = x + v cosθ dt,  y' = y + v sinθ dt,  θ' = θ + ω dt.

    Exercise 3.1: from the origin facing east, 1 m/s for 1 s.

    >>> motion_model((0, 0, 0), 1, 0, 1)
    (1.0, 0.0, 0)

    Exercise 3.2: facing 45°, 2 m/s for 0.5 s.

    >>> [round(s, 4) for s in motion_model((0, 0, math.pi / 4), 2, 0, 0.5)]
    [0.7071, 0.7071, 0.7854]
    """
    x, y, theta = state
    return (x + v * math.cos(theta) * dt,
            y + v * math.sin(theta) * dt,
            theta + omega * dt)


def motion_model_arc(state, v: float, omega: float, dt: float) -> tuple[float, float, float]:
    """The exact motion for constant ``v`` and ``omega``: a circular arc of radius v/ω
    (Probabilistic Robotics' velocity motion model), a straight line when ω = 0.

    :func:`motion_model` is its first-order (Euler) step: they agree to first order in
    ``dt``, the Euler end lying about v·ω·dt²/2 to the outside of the turn.

    >>> motion_model_arc((0, 0, 0), 1, 0, 1) == motion_model((0, 0, 0), 1, 0, 1)
    True
    >>> [round(s, 4) for s in motion_model_arc((0, 0, 0), 1, math.pi / 2, 1)]  # a quarter circle of radius 2/π
    [0.6366, 0.6366, 1.5708]
    """
    x, y, theta = state
    if omega == 0:
        return motion_model(state, v, omega, dt)
    r, turned = v / omega, theta + omega * dt
    return (x + r * (math.sin(turned) - math.sin(theta)),
            y - r * (math.cos(turned) - math.cos(theta)),
            turned)


def motion_jacobian(state, v: float, omega: float, dt: float) -> Matrix:
    """F = ∂f/∂x of the motion model at ``state``.

    Only the heading column differs from the identity.

    Exercise 3.3: facing north, v = 1, dt = 0.5 gives F(1,3) = −0.5.

    >>> round(motion_jacobian((0, 0, math.pi / 2), 1, 0, 0.5)[0][2], 12)
    -0.5
    >>> motion_jacobian((0, 0, 0), 1, 0, 1)
    [[1.0, 0.0, -0.0], [0.0, 1.0, 1.0], [0.0, 0.0, 1.0]]
    """
    _, _, theta = state
    return [[1.0, 0.0, -v * math.sin(theta) * dt],
            [0.0, 1.0, v * math.cos(theta) * dt],
            [0.0, 0.0, 1.0]]


def ekf_predict(state, P: Matrix, v: float, omega: float, dt: float, Q: Matrix):
    """The predict step: move the pose, then P⁻ = F P Fᵀ + Q.

    Returns ``(state', P')``; F is taken at the *old* state.

    Exercise 3.4: P⁻(1,1) = 1.01 and P⁻(2,2) = 1.11.

    >>> P = [[1, 0, 0], [0, 1, 0], [0, 0, 0.1]]
    >>> Q = [[0.01, 0, 0], [0, 0.01, 0], [0, 0, 0.001]]
    >>> s, Pm = ekf_predict((0, 0, 0), P, 1, 0, 1, Q)
    >>> s
    (1.0, 0.0, 0)
    >>> [[round(p, 4) + 0.0 for p in row] for row in Pm]
    [[1.01, 0.0, 0.0], [0.0, 1.11, 0.1], [0.0, 0.1, 0.101]]
    """
    F = motion_jacobian(state, v, omega, dt)
    P_pred = add(matmul(matmul(F, P), transpose(F)), Q)
    return motion_model(state, v, omega, dt), P_pred


def ekf_predict_wrapped(state, P: Matrix, v: float, omega: float, dt: float, Q: Matrix):
    """Exercise 3.10: :func:`ekf_predict` with the heading brought back into (−π, π].

    >>> s, _ = ekf_predict_wrapped((0, 0, 3), [[0] * 3] * 3, 0, 1, 0.5, [[0] * 3] * 3)
    >>> round(s[2], 4)
    -2.7832
    """
    (x, y, theta), P_pred = ekf_predict(state, P, v, omega, dt, Q)
    return (x, y, wrap_angle(theta)), P_pred


def range_bearing(state, landmark) -> tuple[float, float]:
    """h(x): the range and bearing from the pose to a landmark at (lx, ly).

    φ = atan2(dy, dx) − θ, in radians (not wrapped).

    Exercises 4.1 and 4.2: from the origin facing east, the landmark (3, 4)
    is 5 m away at 53.13°.

    >>> r, phi = range_bearing((0, 0, 0), (3, 4))
    >>> r, round(math.degrees(phi), 2)
    (5.0, 53.13)
    """
    x, y, theta = state
    dx, dy = landmark[0] - x, landmark[1] - y
    return math.hypot(dx, dy), math.atan2(dy, dx) - theta


def measurement_jacobian(state, landmark) -> Matrix:
    """H = ∂h/∂x of the range-bearing model (2×3).

    With dx = lx − x, dy = ly − y, q = dx² + dy²:
    H = [[−dx/√q, −dy/√q, 0], [dy/q, −dx/q, −1]].

    Exercise 4.3: H(1,1) = −3/5 for the landmark (3, 4) seen from the origin.

    >>> [[round(h, 4) for h in row] for row in measurement_jacobian((0, 0, 0), (3, 4))]
    [[-0.6, -0.8, 0.0], [0.16, -0.12, -1.0]]
    >>> measurement_jacobian((3, 4, 0), (3, 4))
    Traceback (most recent call last):
    ...
    ValueError: landmark (3, 4) is at the robot's position: its bearing is undefined
    """
    x, y, _ = state
    dx, dy = landmark[0] - x, landmark[1] - y
    q = dx * dx + dy * dy
    if q == 0:
        raise ValueError(f"landmark ({landmark[0]:g}, {landmark[1]:g}) is at the robot's position: its bearing is "
                         "undefined")
    r = math.sqrt(q)
    return [[-dx / r, -dy / r, 0.0],
            [dy / q, -dx / q, -1.0]]


def ekf_update(x: float, P: float, z: float, R: float) -> tuple[float, float]:
    """The scalar update with h(x) = x (so H = 1): K = P/(P+R).

    Returns ``(x + K(z − x), (1 − K) P)``.

    Exercise 4.5, with the numbers of chapter 9: K = 0.5/0.7 ≈ 0.714.

    >>> [round(v, 4) for v in ekf_update(5.866, 0.5, 5.7, 0.2)]
    [5.7474, 0.1429]

    A perfect sensor (R = 0) hands over the measurement (exercise 4.6).

    >>> ekf_update(2.0, 1.0, 3.0, 0.0)
    (3.0, 0.0)

    With P = R = 0 the innovation covariance S = P + R is zero and the gain
    is undefined:

    >>> ekf_update(2.0, 0.0, 3.0, 0.0)
    Traceback (most recent call last):
    ...
    ValueError: P + R must be positive: the innovation covariance S = P + R is 0 (P=0, R=0)
    """
    if not P + R > 0:
        raise ValueError(f"P + R must be positive: the innovation covariance S = P + R is {P + R:g} (P={P:g}, R={R:g})")
    K = P / (P + R)
    return x + K * (z - x), (1 - K) * P


def innovation(z, h) -> list[float]:
    """y = z − h(x⁻): what the sensor says that the prediction did not (measured minus predicted).

    Exercise 4.4: predicted (5, 0.9273), measured (4.8, 0.95); the range
    innovation is −0.2 m (the landmark looks closer than predicted).

    >>> [round(v, 4) for v in innovation((4.8, 0.95), (5, 0.9273))]
    [-0.2, 0.0227]
    """
    return [zi - hi for zi, hi in zip(z, h)]


def innovation_wrapped(z, h) -> list[float]:
    """The innovation of a (range, bearing) sighting, the bearing brought into (−π, π].

    Two bearings either side of ±π point almost the same way, but their plain
    difference is nearly 2π (the bug of exercise 4.9); wrapped, it is the
    small angle between them.

    >>> [round(v, 4) for v in innovation((4.8, -3.1), (5, 3.1))]
    [-0.2, -6.2]
    >>> [round(v, 4) for v in innovation_wrapped((4.8, -3.1), (5, 3.1))]
    [-0.2, 0.0832]
    """
    nu = innovation(z, h)
    return [nu[0], wrap_angle(nu[1]), *nu[2:]]


def ekf_update_matrix(x, P: Matrix, z, h, H: Matrix, R: Matrix):
    """The general update, given the predicted measurement ``h`` = h(x⁻).

    y = z − h,  S = H P Hᵀ + R,  K = P Hᵀ S⁻¹,  x⁺ = x + K y,  P⁺ = (I − K H) P.
    Returns ``(x_new, P_new)`` with ``x_new`` a list.

    Exercise 4.4's numbers: h = (5, 0.9273), z = (4.8, 0.95), so the range
    innovation is −0.2 and the update pulls the robot toward the landmark
    at (3, 4) (its x and y grow).

    >>> x0 = [0.0, 0.0, 0.0]
    >>> P0 = [[1, 0, 0], [0, 1, 0], [0, 0, 0.1]]
    >>> H = measurement_jacobian(x0, (3, 4))
    >>> R = [[0.1, 0], [0, 0.01]]
    >>> xn, Pn = ekf_update_matrix(x0, P0, [4.8, 0.95], [5, 0.9273], H, R)
    >>> [round(v, 4) for v in xn]
    [0.1333, 0.1273, -0.0151]
    >>> round(Pn[0][0], 4) < 1
    True

    With one state and H = 1 it is :func:`ekf_update`.

    >>> xn, Pn = ekf_update_matrix([5.866], [[0.5]], [5.7], [5.866], [[1]], [[0.2]])
    >>> round(xn[0], 4), round(Pn[0][0], 4)
    (5.7474, 0.1429)
    """
    y = innovation(z, h)
    K = kalman_gain(P, H, R)
    x_new = [xi + di for xi, di in zip(x, matvec(K, y))]
    P_new = matmul(sub(identity(len(x)), matmul(K, H)), P)
    return x_new, P_new


def ekf_update_range_bearing(x, P: Matrix, z, landmark, R: Matrix):
    """Exercise 4.10: one EKF update of the pose ``x`` = (x, y, θ) on a range–bearing sighting ``z`` = (r, φ)
    of a mapped landmark, in the simple form P⁺ = (I − K H) P.

    h and H at the prediction, the innovation with its bearing wrapped into (−π, π], then S, K, and
    x⁺ = x + K y with the heading wrapped. Returns ``(x_new, P_new)`` (lists), or None when the
    landmark sits at the robot's position (its bearing, so H, is undefined there).

    Exercise 4.4's sighting, as :func:`ekf_update_matrix` works it:

    >>> xn, Pn = ekf_update_range_bearing([0, 0, 0], [[1, 0, 0], [0, 1, 0], [0, 0, 0.1]], (4.8, 0.95), (3, 4),
    ...                                   [[0.1, 0], [0, 0.01]])
    >>> [round(v, 4) for v in xn]
    [0.1333, 0.1273, -0.0151]

    A landmark behind the robot, predicted at a bearing just under π and seen just past −π: the wrapped
    innovation is 0.0366 rad, and the pose moves by a few centimetres (unwrapped, −6.25 rad would swing
    the heading by 5.5 rad and throw y 2.7 m off).

    >>> x, P, z, R = [0, 0, 0], [[0.1, 0, 0], [0, 0.1, 0], [0, 0, 0.05]], (4.0, -3.13), [[0.01, 0], [0, 0.001]]
    >>> [round(v, 3) + 0.0 for v in ekf_update_range_bearing(x, P, z, (-4, 0.1), R)[0]]
    [-0.001, 0.016, -0.032]
    >>> h, H = range_bearing(x, (-4, 0.1)), measurement_jacobian(x, (-4, 0.1))
    >>> [round(v, 3) + 0.0 for v in ekf_update_matrix(x, P, z, h, H, R)[0]]
    [-0.069, -2.726, 5.456]
    >>> ekf_update_range_bearing([1, 2, 0], [[1, 0, 0], [0, 1, 0], [0, 0, 1]], (1, 0), (1, 2), [[1, 0], [0, 1]]) is None
    True
    """
    if (landmark[0] - x[0], landmark[1] - x[1]) == (0, 0):
        return None
    H = measurement_jacobian(x, landmark)
    y = innovation_wrapped(z, range_bearing(x, landmark))
    K = kalman_gain(P, H, R)
    moved = [xi + di for xi, di in zip(x, matvec(K, y))]
    x_new = [moved[0], moved[1], wrap_angle(moved[2])]
    P_new = matmul(sub(identity(len(x)), matmul(K, H)), P)
    return x_new, P_new


def kalman_gain(P: Matrix, H: Matrix, R: Matrix) -> Matrix:
    """K = P Hᵀ S⁻¹ with S = H P Hᵀ + R: how far the update trusts each measurement.

    Scalar case of exercise 4.5 (P = 0.5, R = 0.2): K = 0.5 / 0.7.

    >>> round(kalman_gain([[0.5]], [[1]], [[0.2]])[0][0], 4)
    0.7143

    A perfect sensor (R = 0) gets the full gain (exercise 4.6).

    >>> kalman_gain([[1.0]], [[1]], [[0.0]])
    [[1.0]]

    P = R = 0 leaves nothing to weigh:

    >>> kalman_gain([[0.0]], [[1]], [[0.0]])  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    ValueError: the innovation covariance S = H P Hᵀ + R is singular (P and R are both zero ...): matrix is singular ...
    """
    Ht = transpose(H)
    S = add(matmul(matmul(H, P), Ht), R)
    try:
        S_inv = inverse(S)
    except ValueError as err:
        raise ValueError(f"the innovation covariance S = H P Hᵀ + R is singular "
                         f"(P and R are both zero along some measurement): {err}") from None
    return matmul(matmul(P, Ht), S_inv)


def covariance_ellipse(P: Matrix, n_sigma: float = 1.0) -> tuple[float, float, float]:
    """The x–y uncertainty ellipse of a covariance: ``(a, b, angle)``.

    Uses the top-left 2×2 block [[pxx, pxy], [pxy, pyy]] of ``P``. ``a`` ≥ ``b``
    are the semi-axes, ``n_sigma`` standard deviations long (the square roots of
    the block's eigenvalues, scaled), and ``angle`` (radians) is the direction of
    the major axis, measured from the x-axis.

    Exercise 3.4's P⁻ = diag(1.01, 1.11, …) is widest along y.

    >>> a, b, angle = covariance_ellipse([[1.01, 0, 0], [0, 1.11, 0.1], [0, 0.1, 0.101]])
    >>> round(a, 4), round(b, 4), round(math.degrees(angle), 1)
    (1.0536, 1.005, 90.0)

    A correlated block tilts the ellipse: here by 45°.

    >>> [round(v, 4) for v in covariance_ellipse([[2, 1], [1, 2]], n_sigma=2)[:2]]
    [3.4641, 2.0]
    >>> round(math.degrees(covariance_ellipse([[2, 1], [1, 2]])[2]), 1)
    45.0
    """
    pxx, pxy, pyy = P[0][0], P[0][1], P[1][1]
    mean = (pxx + pyy) / 2
    spread = math.hypot((pxx - pyy) / 2, pxy)
    big, small = mean + spread, max(0.0, mean - spread)
    angle = 0.5 * math.atan2(2 * pxy, pxx - pyy)
    return n_sigma * math.sqrt(big), n_sigma * math.sqrt(small), angle
