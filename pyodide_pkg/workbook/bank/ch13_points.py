"""Chapter 13 · Aligning point sets: the centroid of a scan (13.1) and the cross-covariance H of two
paired sets (13.2), worked in checked steps (the two centroids, the first pair's outer product, then H).

13.2's pairs come from :func:`point_sets`: three points of P with whole coordinates, and Q, P turned
about its first point by the turn the odometry reports, rounded to whole coordinates (as a real scan
is noisy), and moved; only draws whose centroids are whole are kept, so every centred coordinate and
every entry of H is a whole number. Its variant 0 is the pair of scans 13.3 and 13.5 start from.

>>> from workbook import bank
>>> P, Q = point_sets(bank.get("13.2").params)
>>> P, Q
([(0, 0), (3, 1), (0, 5)], [(4, 1), (5, 4), (0, 4)])
>>> bank.get("13.2").worked_text()
'[6 3; -13 6]'
"""

from __future__ import annotations

import math

from .. import chains
from ..answer_kinds.matrix import matrix
from ..kinds.derive import Derive
from ..number_format import bmatrix, fmt
from ..reference.alignment import centroid
from ..steps import Step
from ..variants import Choice, Param, Vary
from . import column, grid
from .checks import kept_slips

_P_DEFAULT = ((0, 0), (3, 1), (0, 5))  # with Q (4, 1), (5, 4), (0, 4): H = [6, 3; −13, 6], θ = 53.13°
_Q1_DEFAULT = (4, 1)


def point_params():
    """13.2's parameters: the three points of P, the first point of Q, and the turn the odometry reports."""
    coords = [Param(f"p{i}{a}", _P_DEFAULT[i - 1][k], 0, 5, 1) for i in (1, 2, 3) for k, a in enumerate("xy")]
    return (*coords, Param("q1x", _Q1_DEFAULT[0], -2, 6, 1), Param("q1y", _Q1_DEFAULT[1], -2, 6, 1),
            Choice("turn", 60, (60, 30, 45, 90, 120, 135, 150, -30, -45, -60, -90, -120, -150, 180)))


def point_sets(p) -> tuple[list[tuple[int, int]], list[tuple[int, int]]]:
    """P as drawn; Q: P turned by ``turn`` degrees about its first point and moved to put that point at
    (q1x, q1y), each coordinate rounded to a whole number (as a real scan is noisy); the third point's
    to the nearest whole number that makes Q's centroid whole."""
    P = [(int(p[f"p{i}x"]), int(p[f"p{i}y"])) for i in (1, 2, 3)]
    c, s = math.cos(math.radians(p["turn"])), math.sin(math.radians(p["turn"]))
    x0, y0 = P[0]
    first = (int(p["q1x"]), int(p["q1y"]))
    exact = [(first[0] + c * (x - x0) - s * (y - y0), first[1] + s * (x - x0) + c * (y - y0)) for x, y in P[1:]]
    second = (round(exact[0][0]), round(exact[0][1]))
    third = (_nearest_congruent(exact[1][0], -(first[0] + second[0])),
             _nearest_congruent(exact[1][1], -(first[1] + second[1])))
    return P, [first, second, third]


def _nearest_congruent(v: float, r: int) -> int:
    """The whole number n ≡ r (mod 3) nearest to v (the lower of two as near)."""
    start = math.floor(v) - 2
    return min((n for n in range(start, start + 5) if (n - r) % 3 == 0), key=lambda n: (abs(n - v), n))


def whole_centroids(P, Q) -> bool:
    """Both centroids have whole coordinates (so every centred coordinate and entry of H is whole)."""
    return all(sum(pt[k] for pt in pts) % len(pts) == 0 for pts in (P, Q) for k in (0, 1))


def spread(P) -> bool:
    """Three points not on one line, and no two the same."""
    (ax, ay), (bx, by), (cx, cy) = P
    return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax) != 0


def points_tex(points) -> str:
    """Points as TeX: (0, 0),\\ (3, 0),\\ (3, 3)."""
    return ",\\ ".join(f"({fmt(x)}, {fmt(y)})" for x, y in points)


# ---- 13.1 The centroid of a scan -----------------------------------------------------------------

_SCAN = ((1, 2), (4, 0), (3, 5), (0, 1))


def _scan(p):
    return [(int(p[f"x{i}"]), int(p[f"y{i}"])) for i in (1, 2, 3, 4)]


def _centroid(p):
    """13.1: the centroid of four scan points."""
    pts = _scan(p)
    key = centroid(pts)
    sx, sy = sum(x for x, _ in pts), sum(y for _, y in pts)
    return {
        "key": column(key),
        "slips": kept_slips(column(key), (
            (column((sx / 3, sy / 3)), "That divides the sums by 3. The centroid is the mean over all four points: "
                                      "divide by n = 4.", "divides-sums-centroid-mean"),
            (column((sx, sy)), "Those are the sums of the coordinates. Divide each by the number of points, 4.",
             "sums-coordinates-divide-number"),
            (column(((min(x for x, _ in pts) + max(x for x, _ in pts)) / 2,
                     (min(y for _, y in pts) + max(y for _, y in pts)) / 2)),
             "That is the middle of the box around the points (halfway between the smallest and largest "
             "coordinates). The centroid is the mean of all the points.", "middle-box-around-points"),
        )),
        "values": {
            "xs": " + ".join(f"({fmt(x)})" if x < 0 else fmt(x) for x, _ in pts),
            "ys": " + ".join(f"({fmt(y)})" if y < 0 else fmt(y) for _, y in pts),
            "sumx": fmt(sx), "sumy": fmt(sy),
        },
    }


def _centroid_ok(p):
    made = _centroid(p)
    return len(made["slips"]) >= 2


# ---- 13.2 The cross-covariance H -----------------------------------------------------------------


def _outer(a, b):
    return [[a[0] * b[0], a[0] * b[1]], [a[1] * b[0], a[1] * b[1]]]


def _cross(p, given=None):
    """13.2: H = Σ (pᵢ − p̄)(qᵢ − q̄)ᵀ, from the learner's own centroids and first outer product when given."""
    P, Q = point_sets(p)
    pm_key, qm_key = centroid(P), centroid(Q)
    means_key = ((pm_key[0], qm_key[0]), (pm_key[1], qm_key[1]))
    means = chains.given(given, "means", means_key)
    pm, qm = (means[0][0], means[1][0]), (means[0][1], means[1][1])
    Pc = [(x - pm[0], y - pm[1]) for x, y in P]
    Qc = [(x - qm[0], y - qm[1]) for x, y in Q]
    first_key = grid(_outer(Pc[0], Qc[0]))
    first = chains.given(given, "first", first_key)
    H = [[first[i][j] + sum(_outer(a, b)[i][j] for a, b in zip(Pc[1:], Qc[1:])) for j in range(2)] for i in range(2)]
    Ht = [[H[j][i] for j in range(2)] for i in range(2)]
    raw = [[sum(_outer(a, b)[i][j] for a, b in zip(P, Q)) for j in range(2)] for i in range(2)]
    n = len(P)
    sums = ((sum(x for x, _ in P), sum(x for x, _ in Q)), (sum(y for _, y in P), sum(y for _, y in Q)))
    right_pc = [(x - pm_key[0], y - pm_key[1]) for x, y in P]
    right_qc = [(x - qm_key[0], y - qm_key[1]) for x, y in Q]
    return {
        "key": grid(H),
        "slips": kept_slips(grid(H), (
            (grid(Ht), "That is Σ q′ p′ᵀ, H transposed: in H = Σ p′ q′ᵀ row i comes from P and column j from Q, "
                       "so H₁₂ = Σ p′ₓ q′ᵧ. The transposed H turns the angle's sign round.", "h-transposed"),
            (grid(raw), "That multiplies the points as given, Σ p qᵀ. Subtract the centroids first: H is built "
                        "from the centred points p′ = p − p̄ and q′ = q − q̄.", "uncentred-points"),
            (grid([[v / n for v in row] for row in H]),
             f"That divides the sum by n = {n}. The rotation would come out the same, but this exercise's H is "
             "the sum itself, Σ p′ q′ᵀ.", "divided-by-n"),
        )),
        "steps": {
            "means": {"key": means_key, "slips": kept_slips(means_key, (
                (sums, f"Those are the sums of the coordinates; divide each by n = {n}.", "sums-not-means"),
                (((qm_key[0], pm_key[0]), (qm_key[1], pm_key[1])),
                 "The columns are swapped: p̄ comes first, then q̄.", "columns-swapped-p-comes"),
            ))},
            "first": {"key": first_key, "slips": kept_slips(first_key, (
                (grid(_outer(Qc[0], Pc[0])), "That is q′₁ p′₁ᵀ, transposed: the rows come from p′₁, the "
                                             "columns from q′₁.", "first-product-transposed"),
                (grid(_outer(P[0], Q[0])), "That multiplies p₁ and q₁ as given. Subtract the centroids first: "
                                           "p′₁ = p₁ − p̄ and q′₁ = q₁ − q̄.", "uncentred-first-product"),
            ))},
        },
        "values": {
            "Q": points_tex(Q),
            "Pc": points_tex(right_pc), "Qc": points_tex(right_qc),
            "rest": " + ".join(bmatrix(_outer(a, b)) for a, b in zip(right_pc[1:], right_qc[1:])),
        },
    }


def _cross_ok(p):
    """Whole centroids, three points not on a line, three distinct slips of H, each centroid's two slips,
    and an H that is not symmetric (or the transpose would be right too)."""
    P, Q = point_sets(p)
    if not (whole_centroids(P, Q) and spread(P) and spread(Q)):
        return False
    made = _cross(p)
    H = made["key"]
    return (len(made["slips"]) == 3 and len(made["steps"]["means"]["slips"]) == 2
            and len(made["steps"]["first"]["slips"]) == 2 and H[0][1] != H[1][0])


EXERCISES = (
    Derive(
        id="13.1",
        title="The centroid of a scan",
        spec=matrix(label="p̄ = (x̄, ȳ)ᵀ", names=("x", "y")),
        vary=Vary(_centroid, *(Param(f"{a}{i}", _SCAN[i - 1][k], -3, 6, 1) for i in (1, 2, 3, 4)
                                for k, a in enumerate("xy")), valid=_centroid_ok),
    ),
    Derive(
        id="13.2",
        title="The cross-covariance H",
        spec=matrix(label="H = Σ p′ q′ᵀ"),
        vary=Vary(_cross, *point_params(), valid=_cross_ok),
        steps=(Step("means", "[p̄ q̄]", matrix(label="[p̄ q̄], the two centroids as columns")),
               Step("first", "p′₁ q′₁ᵀ", matrix(label="p′₁ q′₁ᵀ, the first pair's outer product"))),
    ),
)
