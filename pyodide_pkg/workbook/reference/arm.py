"""The two-link planar arm: forward and inverse kinematics, Jacobian, singularities.

Angles are in radians; θ2 is the elbow angle measured from the first link.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import NamedTuple

from .linalg import Matrix, Vector, det2, matvec
from .pose_graph import wrap_angle


def forward_kinematics_2link(L1: float, L2: float, theta1: float, theta2: float) -> tuple[float, float]:
    """Where the tip of the arm is: x = L1 cosθ1 + L2 cos(θ1+θ2), y likewise with sin.

    Exercise 6.1: the straight arm reaches (2, 0).

    >>> forward_kinematics_2link(1, 1, 0, 0)
    (2.0, 0.0)

    Exercise 6.2: θ1 = 30°, θ2 = 45°; the second link points at 75°.

    >>> [round(v, 4) for v in forward_kinematics_2link(1, 1, math.radians(30), math.radians(45))]
    [1.1248, 1.4659]
    """
    x = L1 * math.cos(theta1) + L2 * math.cos(theta1 + theta2)
    y = L1 * math.sin(theta1) + L2 * math.sin(theta1 + theta2)
    return (x, y)


def is_reachable(L1: float, L2: float, x: float, y: float, tol: float = 1e-9) -> bool:
    """True when |L1 − L2| ≤ √(x² + y²) ≤ L1 + L2: the target lies in the annulus.

    Exercise 6.4, with L1 = 2, L2 = 1: (3, 1) is √10 ≈ 3.16 away, beyond reach 3.

    >>> is_reachable(2, 1, 3, 1), is_reachable(2, 1, 3, 0), is_reachable(2, 1, 0.5, 0)
    (False, True, False)
    """
    r = math.hypot(x, y)
    return abs(L1 - L2) - tol <= r <= L1 + L2 + tol


def cos_elbow(L1: float, L2: float, x: float, y: float) -> float:
    """cos θ2 = (x² + y² − L1² − L2²) / (2 L1 L2), from the law of cosines.

    Exercise 6.3: the target (1, 1) with unit links gives cos θ2 = 0.

    >>> cos_elbow(1, 1, 1, 1)
    0.0

    A link of length 0 leaves no elbow angle to find:

    >>> cos_elbow(1, 0, 1, 0)
    Traceback (most recent call last):
    ...
    ValueError: L2 must be non-zero: cos θ2 divides by 2·L1·L2 (got L1=1, L2=0)
    """
    if L1 == 0 or L2 == 0:
        bad = "L1" if L1 == 0 else "L2"
        raise ValueError(f"{bad} must be non-zero: cos θ2 divides by 2·L1·L2 (got L1={L1:g}, L2={L2:g})")
    return (x * x + y * y - L1 * L1 - L2 * L2) / (2 * L1 * L2)


class IKSolutions(NamedTuple):
    """Both answers of the inverse kinematics, each a pair (θ1, θ2) in radians."""

    elbow_up: tuple[float, float]
    elbow_down: tuple[float, float]


def inverse_kinematics_2link(L1: float, L2: float, x: float, y: float) -> IKSolutions:
    """Joint angles that put the tip at (x, y), both elbow solutions.

    θ2 = ±acos(cos θ2) and θ1 = atan2(y, x) − atan2(L2 sin θ2, L1 + L2 cos θ2).
    ``elbow_down`` takes θ2 ≥ 0 and ``elbow_up`` θ2 ≤ 0: seen from the base
    looking at the target, the elbow then sits to the right, respectively the
    left, of the line to the target (so elbow-up is above that line for a target
    to the right of the base, x > 0). At the edge of the workspace the two coincide.

    Raises ``ValueError`` when the target is out of reach.

    Exercise 6.3: unit links, target (1, 1): θ2 = ±90°.

    >>> sol = inverse_kinematics_2link(1, 1, 1, 1)
    >>> [round(math.degrees(a), 6) + 0.0 for a in sol.elbow_down]
    [0.0, 90.0]
    >>> [round(math.degrees(a), 6) + 0.0 for a in sol.elbow_up]
    [90.0, -90.0]
    >>> inverse_kinematics_2link(2, 1, 3, 1)
    Traceback (most recent call last):
    ...
    ValueError: target (3, 1) is out of reach: its distance 3.1623 is outside [1, 3]
    """
    if not is_reachable(L1, L2, x, y):
        raise ValueError(
            f"target ({x:g}, {y:g}) is out of reach: its distance {math.hypot(x, y):.4f} "
            f"is outside [{abs(L1 - L2):g}, {L1 + L2:g}]")
    c2 = max(-1.0, min(1.0, cos_elbow(L1, L2, x, y)))
    base = math.atan2(y, x)

    def solve(theta2: float) -> tuple[float, float]:
        return (base - math.atan2(L2 * math.sin(theta2), L1 + L2 * math.cos(theta2)), theta2)

    t2 = math.acos(c2)
    return IKSolutions(elbow_up=solve(-t2), elbow_down=solve(t2))


def jacobian_2link(L1: float, L2: float, theta1: float, theta2: float) -> Matrix:
    """J = ∂(x, y)/∂(θ1, θ2) = [[−L1 s1 − L2 s12, −L2 s12], [L1 c1 + L2 c12, L2 c12]].

    Exercise 7.1: unit links at θ = (0, 90°).

    >>> [[round(v, 12) + 0.0 for v in row] for row in jacobian_2link(1, 1, 0, math.pi / 2)]
    [[-1.0, -1.0], [1.0, 0.0]]
    """
    s1, c1 = math.sin(theta1), math.cos(theta1)
    s12, c12 = math.sin(theta1 + theta2), math.cos(theta1 + theta2)
    return [[-L1 * s1 - L2 * s12, -L2 * s12],
            [L1 * c1 + L2 * c12, L2 * c12]]


def jacobian_det(L1: float, L2: float, theta1: float, theta2: float) -> float:
    """det J, which works out to L1 L2 sin θ2 (θ1 drops out).

    Exercise 7.3: the straight arm (θ2 = 0) is singular.

    >>> jacobian_det(1, 1, 0, 0)
    0.0
    >>> round(jacobian_det(1, 1, 0.3, math.pi / 2), 12)
    1.0
    """
    return det2(jacobian_2link(L1, L2, theta1, theta2))


def manipulability(J: Matrix) -> float:
    """w = |det J| for a square Jacobian: how much area of velocities the arm can reach.

    >>> manipulability([[-1, -1], [1, 0]])
    1
    """
    return abs(det2(J))


def velocity_ratio(J: Matrix) -> float:
    """How many times more easily the tip moves in its best direction than in its worst:
    the ratio of J's singular values, σmax/σmin (the square roots of JᵀJ's eigenvalues).

    Exercise 7.4: at θ = (0, 90°) with unit links, about 2.6 (exactly (3 + √5)/2).

    >>> round(velocity_ratio([[-1, -1], [1, 0]]), 4)
    2.618
    >>> velocity_ratio([[-1, -1], [2, 2]])
    inf
    """
    a, b = J[0][0] ** 2 + J[1][0] ** 2, J[0][1] ** 2 + J[1][1] ** 2  # JᵀJ's diagonal
    c = J[0][0] * J[0][1] + J[1][0] * J[1][1]  # and its off-diagonal entry
    mid, half = (a + b) / 2, math.hypot((a - b) / 2, c)
    low = mid - half
    return math.inf if low <= 1e-12 * mid else math.sqrt((mid + half) / low)


def most_manipulable_theta2(L1: float, L2: float, samples: int = 3601) -> float:
    """The elbow angle in [0, π] (radians) where |det J| peaks, found by a scan.

    Exercise 7.4: the peak is at a right-angled elbow.

    >>> round(math.degrees(most_manipulable_theta2(1, 1)), 6)
    90.0
    """
    grid = [math.pi * k / (samples - 1) for k in range(samples)]
    return max(grid, key=lambda t2: manipulability(jacobian_2link(L1, L2, 0.0, t2)))


def end_effector_velocity(J: Matrix, qdot: Sequence[float]) -> Vector:
    """(ẋ, ẏ) = J · (θ̇1, θ̇2).

    Exercise 7.2: joint 1 turning at 1 rad/s with J from exercise 7.1.

    >>> end_effector_velocity([[-1, -1], [1, 0]], [1, 0])
    [-1, 1]
    """
    return matvec(J, list(qdot))


def ik_2link(L1: float, L2: float, x: float, y: float, elbow_up: bool):
    """Exercise 6.7: the joint angles (θ1, θ2) for one elbow, θ1 brought into (−π, π];
    None when the target is out of reach (the refusal a caller can test for).

    >>> [round(math.degrees(a), 6) + 0.0 for a in ik_2link(1, 1, 1, 1, True)]
    [90.0, -90.0]
    >>> ik_2link(2, 1, 3, 1, False) is None
    True
    """
    if not is_reachable(L1, L2, x, y):
        return None
    sol = inverse_kinematics_2link(L1, L2, x, y)
    theta1, theta2 = sol.elbow_up if elbow_up else sol.elbow_down
    return wrap_angle(theta1), theta2


SINGULAR_DET = 1e-9  # |det J| below this counts as singular (a float at θ2 = π is about 1e-16, not 0)


def jacobian_singular(L1: float, L2: float, theta1: float, theta2: float) -> tuple[Matrix, bool]:
    """Exercise 7.8: the Jacobian and whether the arm is at a singularity (|det J| < SINGULAR_DET).

    >>> J, singular = jacobian_singular(1, 1, 0, math.pi)
    >>> singular, round(jacobian_det(1, 1, 0, math.pi), 12) + 0.0
    (True, 0.0)
    >>> jacobian_singular(1, 1, 0, math.pi / 2)[1]
    False
    """
    return jacobian_2link(L1, L2, theta1, theta2), abs(jacobian_det(L1, L2, theta1, theta2)) < SINGULAR_DET
