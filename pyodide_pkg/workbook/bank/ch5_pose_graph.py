"""Chapter 5 · Pose-graph SLAM."""

import math

from .. import chains
from ..answer_kinds.base import Slip
from ..answer_kinds.matrix import matrix
from ..answer_kinds.number import number
from ..kinds.derive import Derive
from ..kinds.trace import Option, Trace
from ..number_format import fmt, paren, relation, relation_all
from ..reference.linalg import det2
from ..reference.pose_graph import (
    edge_error,
    edge_error_relative,
    edge_error_simple,
    gauss_newton_size,
    information_matrix,
    pose_graph_variables,
    relative_pose,
)
from ..steps import Step
from ..variants import Param, Vary
from . import column, grid
from .checks import apart, slips_apart

_X1 = (0.0, 0.0, 0.0)
_Z12 = (1.0, 0.0, 0.0)
# Exercise 5.6: pose 1 sits at (2, 1) facing north; the prose turns the motion with R(90°).
_XI = (2.0, 1.0, math.pi / 2)
_WORDS = ["zero", "one", "two", "three", "four", "five", "six", "seven", "eight", "nine", "ten", "eleven", "twelve",
          "thirteen", "fourteen", "fifteen", "sixteen", "seventeen", "eighteen", "nineteen"]
_TENS = ["twenty", "thirty", "forty", "fifty", "sixty", "seventy", "eighty", "ninety"]


def _times(r: float) -> str:
    """A ratio in words: ``ten`` for 10, ``twenty-five`` for 25, ``12.5`` when not whole."""
    k = round(r)
    if abs(r - k) > 1e-9 or not 0 <= k < 100:
        return fmt(r)
    if k < 20:
        return _WORDS[k]
    tens, ones = divmod(k, 10)
    return _TENS[tens - 2] + (f"-{_WORDS[ones]}" if ones else "")


def _pose_count(p):
    """5.1: the unknowns of a planar pose graph of n poses."""
    n = p["n"]
    return {
        "key": pose_graph_variables(n, pose_dof=3),
        "slips": (
            Slip(n, "That counts poses, not numbers. Each planar pose carries three unknowns: x, y and θ.",
                name="counts-poses-numbers-each"),
            Slip(pose_graph_variables(n, pose_dof=6),
                 "Six per pose is the 3D case. A planar pose has only x, y and θ.", name="six-per-pose-3d"),
        ),
        "values": {"unknowns": fmt(pose_graph_variables(n, pose_dof=3)),
                   "unknowns3d": fmt(pose_graph_variables(n, pose_dof=6))},
    }


def _odometry_error(p, given=None):
    """5.2: e = z₁₂ − (x₂ − x₁) for pose 1 at the origin; asked: its x-component. In steps: the
    pose difference d = x₂ − x₁, then the whole e (each the learner's own when ``given`` has it)."""
    x2 = (p["x2"], p["y2"], p["t2"])
    diff = column(b - a for a, b in zip(_X1, x2))
    d = [row[0] for row in chains.given(given, "d", diff)]
    e = [row[0] for row in chains.given(given, "e", column(edge_error_simple((0.0, 0.0, 0.0), d, _Z12)))]
    exact = edge_error(_X1, x2, _Z12)[0]
    change = abs(exact - e[0]) / abs(e[0]) if e[0] else 0.0
    again = [Slip(column(d), "That is x₂ − x₁ again, from step 1. Subtract it from the odometry reading "
                             "z₁₂ = (1, 0, 0).", name="x2-x1-again-step")]
    return {
        "key": e[0],
        "slips": (
            Slip(-e[0], "The sign is flipped: you computed (x₂ − x₁) − z₁₂. The error is measurement minus "
                        "prediction.", name="sign-flipped-computed-x2"),
            Slip(d[0], "That is the pose difference x₂ − x₁ alone. Subtract it from the odometry reading z₁₂.",
                name="pose-difference-x2-x1"),
        ),
        "steps": {
            "d": {"key": diff, "slips": (
                Slip(column(a - b for a, b in zip(_X1, x2)), "That is x₁ − x₂, the difference the wrong way round: "
                                                             "the motion runs from pose 1 to pose 2, x₂ − x₁.",
                                                                 name="x1-x2-difference-wrong"),)},
            "e": {"key": column(e), "slips": (
                Slip(column(-v for v in e), "The sign is flipped: that is (x₂ − x₁) − z₁₂. The error is the "
                                            "measurement minus the prediction, z₁₂ − (x₂ − x₁).",
                                                name="sign-flipped-x2-x1"),
                *(again if apart(e, d) else ())),
            },
        },
        "values": {
            "sign": "negative" if e[0] < 0 else "positive",
            "gap": fmt(abs(e[0])),
            "apart": "further apart" if e[0] < 0 else "closer together",
            "exact": fmt(exact),
            "heading": fmt(x2[2]),
            "changes": "barely changes it" if change < 0.01 else f"changes it by about {round(100 * change)} %",
        },
    }


def _information_diagonal(p):
    """5.3: Ω = Σ⁻¹ for a diagonal Σ = diag(s, s, t); asked: Ω(1,1)."""
    s, t = p["s"], p["t"]
    omega = information_matrix([[s, 0, 0], [0, s, 0], [0, 0, t]])
    return {
        "key": omega[0][0],
        "slips": (
            Slip(s, "That is Σ(1,1), the covariance itself. The information matrix is its inverse, Ω = Σ⁻¹.",
                name="1-1-covariance-itself"),
            Slip(omega[2][2], "That is Ω(3,3), the heading entry. The (1,1) entry belongs to x.",
                name="omega-3-3-heading"),
        ),
        "values": {"wxy": fmt(omega[0][0]), "wt": fmt(omega[2][2]), "times": _times(omega[2][2] / omega[0][0])},
    }


def _hessian_size(p):
    """5.5: the side of H for n poses of 6 DOF and m landmarks of 3 DOF."""
    n, m = p["n"], p["m"]
    size = gauss_newton_size(n, 6, m, 3)
    million, rest = divmod(size * size, 10**6)
    return {
        "key": size,
        "slips": (
            Slip(gauss_newton_size(n, 6),
                 f"That counts the poses only. In full SLAM the {m} landmarks are unknowns too, 3 numbers each.",
                     name="counts-poses-only-full"),
            Slip(gauss_newton_size(n, 3, m, 3),
                 "A 3D pose has 6 degrees of freedom (x, y, z, roll, pitch, yaw), not 3.", name="3d-pose-has-6"),
            Slip(size ** 2,
                 "That is the number of entries of H. The question asks for its side: one row per unknown.",
                     name="number-entries-h-question"),
            Slip(gauss_newton_size(0, 6, m, 3), f"That counts the landmarks only. Add the {n} poses, 6 numbers each.",
                name="counts-landmarks-only-add"),
        ),
        "values": {"poses": fmt(gauss_newton_size(n, 6)), "marks": fmt(gauss_newton_size(0, 6, m, 3)),
                   "size": fmt(size), "entries": f"{'over' if rest else 'exactly'} {million} million"},
    }


def _distinct_sizes(p):
    """5.5: no slip count equals another (3n + 3m = 6n when m = n; 6n = 3m when m = 2n)."""
    return p["m"] != p["n"] and p["m"] != 2 * p["n"]


def _turned_edge_error(p, given=None):
    """5.6: e = z₁₂ − x₁⁻¹ ⊕ x₂ with pose 1 at (2, 1) facing north, as a column, in steps: the world
    difference d, then h = x₁⁻¹ ⊕ x₂ (each the learner's own when ``given`` has it). h is d seen
    from a pose at the origin with pose 1's heading, and e is the error of an edge from the origin
    to h, so the reference's own error agrees:

    >>> made = _turned_edge_error({"x2": 1.95, "y2": 2.1, "t2": 0.02})
    >>> ref = edge_error_relative(_XI, (1.95, 2.1, math.pi / 2 + 0.02), _Z12)
    >>> all(math.isclose(a, b, abs_tol=1e-12) for (a,), b in zip(made["key"], ref))
    True
    """
    xj = (p["x2"], p["y2"], math.pi / 2 + p["t2"])
    dx, dy = xj[0] - _XI[0], xj[1] - _XI[1]
    d = [row[0] for row in chains.given(given, "d", column((dx, dy)))]
    h = chains.given(given, "h", column(relative_pose((0.0, 0.0, _XI[2]), (d[0], d[1], xj[2]))))
    h = [row[0] for row in h]
    e = edge_error_relative((0.0, 0.0, 0.0), h, _Z12)
    world = edge_error_simple(_XI, xj, _Z12)
    turn = h[2]
    return {
        "key": column(e),
        "slips": (
            Slip(column(world),
                 "You subtracted the poses in world axes. Odometry measures the motion in pose 1's frame, and "
                 "pose 1 faces north: turn x₂ − x₁ into that frame first (its forward axis is the world's +y).",
                     name="subtracted-poses-world-axes"),
            Slip(column([-v for v in e]),
                 "The sign is flipped: that is prediction minus measurement. The error is z₁₂ − h, measured "
                 "minus predicted.", name="sign-flipped-prediction-minus"),
            Slip(column(h),
                 "That is h, the motion the poses imply, seen from pose 1. The error subtracts it from the "
                 "odometry reading z₁₂.", name="h-motion-poses-imply"),
        ),
        "steps": {
            "d": {"key": column((dx, dy)), "slips": (
                Slip(column((-dx, -dy)), "That is x₁ − x₂, the wrong way round: the difference runs from pose 1 "
                                         "to pose 2, x₂ − x₁.", name="x1-x2-wrong-way"),
                Slip(column(xj[:2]), "That is where pose 2 is. Subtract pose 1's position (2, 1) from it.",
                    name="where-pose-2-subtract")),
            },
            "h": {"key": column(h), "slips": (
                Slip(column((d[0], d[1], turn)),
                     "That is the world difference as it is. Turn it into pose 1's frame with R(90°)ᵀ: facing "
                     "north, pose 1's forward axis is the world's +y.", name="world-difference-turn-into"),
                Slip(column((*relative_pose((0.0, 0.0, -_XI[2]), (d[0], d[1], 0.0))[:2], turn)),
                     "That turns the difference by R(90°), the wrong way. Into pose 1's frame it is R(θ₁)ᵀ, the "
                     "transpose: the world's +y becomes pose 1's forward axis.", name="turns-difference-r-90"),
                Slip(column((h[0], h[1], xj[2])),
                     "The third entry is pose 2's heading. h holds the turn from pose 1 to pose 2: θ₂ − θ₁.",
                         name="third-entry-pose-2")),
            },
        },
        "values": {
            "pdx": paren(dx), "pdy": paren(dy),
            "hx": fmt(h[0]), "hy": fmt(h[1]), "ht": fmt(h[2]),
            "wx": fmt(world[0]), "wy": fmt(world[1]), "wt": fmt(world[2]),
        },
    }


def _xy_block(p):
    """5.7's Σ: x and y variances s, their covariance b, the heading variance t."""
    s, b, t = p["s"], p["b"], p["t"]
    return [[s, b, 0], [b, s, 0], [0, 0, t]]


def _inverse_block(s, b, det):
    """The x–y block's inverse, (1/det)·[[s, −b], [−b, s]], with ``det`` the learner's own or
    the printed one. With det = s² − b² it is the reference's inverse:

    >>> Omega = information_matrix(_xy_block({"s": 0.02, "b": 0.01, "t": 0.001}))
    >>> all(math.isclose(a, b) for a, b in zip(sum(_inverse_block(0.02, 0.01, 0.02 ** 2 - 0.01 ** 2), []),
    ...                                        [Omega[0][0], Omega[0][1], Omega[1][0], Omega[1][1]]))
    True
    """
    return [[s / det, -b / det], [-b / det, s / det]]


def _correlated_information(p, given=None):
    """5.7: Ω = Σ⁻¹ for a Σ whose x and y errors are correlated, in steps: the x–y block's
    determinant, then its inverse (each the learner's own when ``given`` has it)."""
    sigma = _xy_block(p)
    s, b = p["s"], p["b"]
    omega_ref = information_matrix(sigma)
    det = chains.given(given, "det", det2([row[:2] for row in sigma[:2]]))
    block = [list(r) for r in chains.given(given, "block", _inverse_block(s, b, det))]
    omega = [block[0] + [0.0], block[1] + [0.0], [0.0, 0.0, omega_ref[2][2]]]
    return {
        "key": grid(omega),
        "slips": (
            Slip(grid([[1 / sigma[i][i] if i == j else 0.0 for j in range(3)] for i in range(3)]),
                 f"You inverted the diagonal alone. With the correlation {fmt(b)} between x and y, the 2×2 block has "
                 "to be inverted as a whole: 1/det times [[d, −b], [−c, a]].",
                     name="inverted-diagonal-alone-correlation"),
            Slip(grid([[1 / v if v else 0.0 for v in row] for row in sigma]),
                 "You took the reciprocal of each entry. The inverse of a matrix is not entry by entry: invert "
                 "the x–y block as a whole, then the θ entry on its own.", name="took-reciprocal-each-entry"),
            Slip(grid([[v / det if i < 2 and j < 2 else (1 / v if i == j else 0.0)
                        for j, v in enumerate(row)] for i, row in enumerate(sigma)]),
                 "The off-diagonal entries have the wrong sign. The inverse of [[a, b], [c, d]] is "
                 "[[d, −b], [−c, a]] / (ad − bc): swap the diagonal and negate the off-diagonal.",
                     name="off-diagonal-entries-have"),
        ),
        "steps": {
            "det": {"key": det2([row[:2] for row in sigma[:2]]), "slips": (
                Slip(s * s + b * b, "That adds b·c. The determinant of [[a, b], [c, d]] is ad − bc: subtract the "
                                    "product of the off-diagonal entries.", name="adds-b-c-determinant"),
                Slip(s * s, "That is the product of the diagonal alone. The correlation takes b·c = "
                            f"{fmt(b * b)} off it: det = ad − bc.", name="product-diagonal-alone-correlation")),
            },
            "block": {"key": grid(block), "slips": (
                Slip(grid([[s, -b], [-b, s]]), "That is the swapped and negated matrix before dividing: multiply it "
                                               f"by 1/det = 1/{fmt(det)}.", name="swapped-negated-matrix-before"),
                Slip(grid([[s / det, b / det], [b / det, s / det]]),
                     "The off-diagonal entries keep their sign here. The inverse negates them: [[d, −b], [−c, a]] / "
                     "det.", name="off-diagonal-entries-keep"),
                Slip(grid([[1 / s, 0.0], [0.0, 1 / s]]),
                     "That inverts the diagonal alone, as if x and y were not correlated. The block is inverted as "
                     "a whole, with its determinant.", name="inverts-diagonal-alone-if")),
            },
        },
        "values": {
            "mb": fmt(-b), "wt": fmt(omega_ref[2][2]), "inv_s": fmt(1 / s),
            "w11": fmt(omega[0][0]), "w11_rel": relation(omega[0][0]), "block_rel": relation_all(block),
        },
    }


def _two_places_suffice(p):
    """5.7: Σ is positive definite and every non-zero entry of Ω is at least 10, so the
    statement's "decimals to two places are fine" stays within the grading tolerance."""
    s, b = p["s"], p["b"]
    if b >= s:
        return False
    omega = information_matrix(_xy_block(p))
    return all(abs(v) >= 10 for row in omega for v in row if abs(v) > 1e-9)


EXERCISES = (
    Derive(
        id="5.1",
        title="Count the unknowns",
        spec=number(label="number of optimisation variables", unit="variables"),
        vary=Vary(_pose_count, Param("n", 100, 10, 999, 1)),
    ),
    Derive(
        id="5.2",
        title="Odometry edge error",
        spec=number(label="x-component of e = z₁₂ − (x₂ − x₁)", unit="m"),
        vary=Vary(_odometry_error, Param("x2", 1.1, 0.5, 1.5, 0.005, unit=" m", avoid=(1,)),
                  Param("y2", 0.05, -0.1, 0.1, 0.05, unit=" m"),
                  Param("t2", 0.02, -0.05, 0.05, 0.01, unit=" rad", avoid=(0,)),
                  valid=lambda p: slips_apart(_odometry_error(p))),
        steps=(Step("d", "x₂ − x₁", matrix(label="x₂ − x₁", names=("dx|x", "dy|y", "dθ|θ"), units=("m", "m", "rad"))),
               Step("e", "e = z₁₂ − (x₂ − x₁)", matrix(label="e = z₁₂ − (x₂ − x₁)", names=("e_x|x", "e_y|y", "e_θ|θ"),
                                                      units=("m", "m", "rad")))),
    ),
    Derive(
        id="5.3",
        title="Information matrix",
        spec=number(label="Ω(1,1), the (1,1) entry of Σ⁻¹"),
        vary=Vary(_information_diagonal, Param("s", 0.01, 0.01, 0.1, 0.0005, avoid=(0.03,)),
                  Param("t", 0.001, 0.001, 0.005, 0.001, avoid=(0.003,))),
    ),
    Trace(
        id="5.4",
        title="What a loop closure does",
        answer="c",
        options=(
            Option("a", "Pose $x_{50}$ jumps onto $x_1$; every other pose stays where it was",
                   "That satisfies the new edge but tears the odometry edge between $x_{49}$ and $x_{50}$ wide open. "
                   "The optimiser minimises the cost of all edges, so one large error is not what it settles on."),
            Option("b", "Only $x_1$ and $x_{50}$ move, meeting halfway",
                   "The two end poses are tied to their neighbours by odometry edges; moving them alone would load "
                   "all the error onto those two edges. The neighbours follow, and their neighbours too."),
            Option("c", "Every pose from $x_1$ to $x_{50}$ shifts a little, spreading the accumulated drift",
                   "Right. Gauss–Newton solves for all poses at once; the drift the loop closure reveals is shared "
                   "out along the chain, so each odometry edge takes a small error instead of one edge taking a huge "
                   "one."),
            Option("d", "Nothing: the new edge contradicts 49 odometry edges and is outvoted",
                   "Edges are not votes. The loop-closure edge adds its own term to the cost, and the optimum balances "
                   "it against the odometry terms according to their information matrices."),
        ),
    ),
    Derive(
        id="5.5",
        title="Size of the Gauss–Newton system",
        spec=number(label="rows (= columns) of H"),
        vary=Vary(_hessian_size, Param("n", 1000, 500, 3000, 10), Param("m", 500, 100, 1000, 10),
                  valid=_distinct_sizes),
    ),
    Derive(
        id="5.6",
        title="Edge error from a turned pose",
        spec=matrix(label="e₁₂ = (eₓ, e_y, e_θ)ᵀ", names=("e_x|x", "e_y|y", "e_θ|θ"), units=("m", "m", "rad")),
        vary=Vary(_turned_edge_error, Param("x2", 1.95, 1.9, 2.1, 0.05, unit=" m"),
                  Param("y2", 2.1, 1.7, 2.4, 0.1, unit=" m"), Param("t2", 0.02, 0.01, 0.05, 0.01, unit=" rad")),
        steps=(Step("d", "x₂ − x₁ in world axes", matrix(label="(x₂ − x₁, y₂ − y₁)", names=("dx", "dy"), unit="m")),
               Step("h", "h = x₁⁻¹ ⊕ x₂", matrix(label="h = x₁⁻¹ ⊕ x₂", names=("h_x|x", "h_y|y", "h_θ|θ"),
                                                 units=("m", "m", "rad")))),
    ),
    Derive(
        id="5.7",
        title="Information from a correlated covariance",
        spec=matrix(label="Ω = Σ⁻¹"),
        vary=Vary(_correlated_information, Param("s", 0.02, 0.01, 0.05, 0.001, avoid=(0.03,)),
                  Param("b", 0.01, 0.005, 0.045, 0.001), Param("t", 0.001, 0.001, 0.005, 0.001, avoid=(0.003,)),
                  valid=_two_places_suffice),
        steps=(Step("det", "determinant of the x–y block", number(label="det = ad − bc of the x–y block")),
               Step("block", "inverse of the x–y block", matrix(label="the x–y block of Ω"))),
    ),
)
