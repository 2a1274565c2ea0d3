"""7.7's table: each entry of the arm's Jacobian J as a formula in θ1, θ2, L1, L2, with its answer, its TeX,
what it equals in words, and the slips a learner makes on it (each with its stable name). Kept apart from
``ch7_jacobians.py`` so that neither file grows past 400 lines."""

from __future__ import annotations

import math

from ..reference.arm import jacobian_2link


def entry_of(r: int, c: int):
    """J(r+1, c+1) as a function of the formula's variables."""
    return lambda theta1, theta2, L1, L2: jacobian_2link(L1, L2, theta1, theta2)[r][c]


# Each entry of J as a formula: its answer, its TeX, the slips a learner makes on it.
FORMULAS = {
    (1, 1): ("-L1*sin(theta1) - L2*sin(theta1 + "
             "theta2)", "-L_1\\sin\\theta_1 - L_2\\sin(\\theta_1{s}+{s}\\theta_2)", "-y", (
        (lambda theta1, theta2, L1, L2: -jacobian_2link(L1, L2, theta1, theta2)[0][0],
         "The sign is flipped: the derivative of cos is −sin.", "sign-flipped-derivative-cos"),
        (lambda theta1, theta2, L1, L2: -L1 * math.sin(theta1),
         "Link 2 moves with θ1 too: its term L2 cos(θ1 + θ2) also depends on θ1, and contributes "
         "−L2 sin(θ1 + θ2).", "link-2-moves-theta1"),
        (entry_of(0, 1), "That is J(1,2) = ∂x/∂θ2: only link 2 depends on θ2. J(1,1) differentiates by θ1, which "
         "moves both links.", "gave-j12"),
        (entry_of(1, 0), "That is J(2,1) = ∂y/∂θ1, from the sines of y. J(1,1) differentiates x, the cosines.",
        "gave-j21"),
    )),
    (1, 2): ("-L2*sin(theta1 + theta2)", "-L_2\\sin(\\theta_1{s}+{s}\\theta_2)", "-(y - L_1\\sin\\theta_1)", (
        (lambda theta1, theta2, L1, L2: -jacobian_2link(L1, L2, theta1, theta2)[0][1],
         "The sign is flipped: the derivative of cos is −sin.", "sign-flipped-derivative-cos"),
        (entry_of(0, 0), "That is J(1,1) = ∂x/∂θ1: joint 1 moves both links. J(1,2) differentiates by θ2, which "
         "moves link 2 only.", "gave-j11"),
        (entry_of(1, 1), "That is J(2,2) = ∂y/∂θ2, from the sines of y. J(1,2) differentiates x, the cosines.",
        "gave-j22"),
    )),
    (2, 1): ("L1*cos(theta1) + L2*cos(theta1 + "
             "theta2)", "L_1\\cos\\theta_1 + L_2\\cos(\\theta_1{s}+{s}\\theta_2)", "x", (
        (lambda theta1, theta2, L1, L2: -jacobian_2link(L1, L2, theta1, theta2)[1][0],
         "The sign is flipped: the derivative of sin is +cos.", "sign-flipped-derivative-sin"),
        (lambda theta1, theta2, L1, L2: L1 * math.cos(theta1),
         "Link 2 moves with θ1 too: its term L2 sin(θ1 + θ2) also depends on θ1, and contributes "
         "L2 cos(θ1 + θ2).", "link-2-moves-theta1"),
        (entry_of(1, 1), "That is J(2,2) = ∂y/∂θ2: only link 2 depends on θ2. J(2,1) differentiates by θ1, which "
         "moves both links.", "gave-j22"),
        (entry_of(0, 0), "That is J(1,1) = ∂x/∂θ1, from the cosines of x. J(2,1) differentiates y, the sines.",
        "gave-j11"),
    )),
    (2, 2): ("L2*cos(theta1 + theta2)", "L_2\\cos(\\theta_1{s}+{s}\\theta_2)", "x - L_1\\cos\\theta_1", (
        (lambda theta1, theta2, L1, L2: -jacobian_2link(L1, L2, theta1, theta2)[1][1],
         "The sign is flipped: the derivative of sin is +cos.", "sign-flipped-derivative-sin"),
        (entry_of(1, 0), "That is J(2,1) = ∂y/∂θ1: joint 1 moves both links. J(2,2) differentiates by θ2, which "
         "moves link 2 only.", "gave-j21"),
        (entry_of(0, 1), "That is J(1,2) = ∂x/∂θ2, from the cosines of x. J(2,2) differentiates y, the sines.",
        "gave-j12"),
    )),
}
