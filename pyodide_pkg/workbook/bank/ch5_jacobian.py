"""Chapter 5 · the SE(2) edge Jacobian: one entry of ∂e/∂xᵢ's heading column (5.9), worked in steps:
the offset tⱼ − tᵢ, then R′(θᵢ)ᵀ(tⱼ − tᵢ) (the derivative of the turn, where the signs go wrong), then the entry."""

import math

from .. import chains
from ..answer_kinds.matrix import matrix
from ..answer_kinds.number import number
from ..kinds.derive import Derive
from ..number_format import fmt, paren, relation
from ..number_format import shown as shown_value
from ..reference.pose_graph_jacobian import rotation_transpose, rotation_transpose_derivative
from ..steps import Step
from ..variants import Choice, Param, Vary
from . import column
from .checks import kept_slips

OFFSET = Step("d", "tⱼ − tᵢ", matrix(label="tⱼ − tᵢ = (xⱼ − xᵢ, yⱼ − yᵢ)", names=("dx", "dy"), unit="m"))
TURNED = Step("turned", "R′(θᵢ)ᵀ(tⱼ − tᵢ)", matrix(label="R′(θᵢ)ᵀ(tⱼ − tᵢ), a column of two", unit="m"))
_ANGLES = (60, 30, 45, 90, 120, 135, 150, -30, -45, -60, -90, -120, -135, -150)
_SUB = {"x": "_x", "y": "_y"}


def _times(M, d):
    """The 2×2 matrix M times the offset d."""
    return [M[r][0] * d[0] + M[r][1] * d[1] for r in range(2)]


def _offset_step(p, given):
    """Step d: pose j's position minus pose i's, the learner's own when ``given`` has it."""
    dx, dy = p["xj"] - p["xi"], p["yj"] - p["yi"]
    key = column((dx, dy))
    slips = kept_slips(key, (
        (column((-dx, -dy)), "That is tᵢ − tⱼ. The offset of pose j from pose i is tⱼ − tᵢ = (xⱼ − xᵢ, yⱼ − yᵢ).",
            "t-t-offset-pose"),
        (column((p["xj"], p["yj"])), "That is where pose j is. Its offset from pose i subtracts pose i's position "
                                     f"({fmt(p['xi'])}, {fmt(p['yi'])}).", "where-pose-j-offset"),
    ))
    d = [row[0] for row in chains.given(given, "d", key)]
    return d, {"key": key, "slips": slips}


def _turned_step(theta, d, given):
    """Step turned: R′(θᵢ)ᵀ times the learner's own offset ``d``, where the derivative's signs go wrong;
    the learner's own column when ``given`` has it."""
    c, s = math.cos(theta), math.sin(theta)
    key = column(_times(rotation_transpose_derivative(theta), d))
    slips = kept_slips(key, (
        (column(_times([[-s, -c], [c, -s]], d)),
         "That uses the derivative of R(θᵢ), not of its transpose. h turns the offset into pose i's frame with "
         "R(θᵢ)ᵀ = [cos θ, sin θ; −sin θ, cos θ]: differentiate that one.", "uses-derivative-r-theta"),
        (column(_times(rotation_transpose(theta), d)),
         "That is R(θᵢ)ᵀ(tⱼ − tᵢ) = h itself. Differentiate each entry of R(θᵢ)ᵀ by θ first: cos θ becomes "
         "−sin θ and sin θ becomes cos θ.", "r-theta-t-t"),
        (column([-v for v in _times(rotation_transpose_derivative(theta), d)]),
         "Every sign is flipped: that is −R′(θᵢ)ᵀ(tⱼ − tᵢ). Either a derivative's sign slipped (cos θ gives "
         "−sin θ, sin θ gives +cos θ) or the minus of e = z − h came in early; this step is the product before "
         "that minus.", "every-sign-flipped-rp"),
    ))
    return [row[0] for row in chains.given(given, "turned", key)], {"key": key, "slips": slips}


def _printed_column_relation(values, printed_inputs):
    """= when every entry of the column, worked from the printed inputs, prints as it is; else ≈."""
    return "=" if all(relation(v, w) == "=" for v, w in zip(values, printed_inputs)) else "\\approx"


def _heading_entry(p, given=None):
    """5.9: ∂e_x/∂θᵢ or ∂e_y/∂θᵢ of e = z − (xᵢ⁻¹ ⊕ xⱼ), in steps: the offset, then R′(θᵢ)ᵀ times it
    (each the learner's own when ``given`` has it)."""
    theta = math.radians(p["ti"])
    row = 0 if p["entry"] == "x" else 1
    sub = _SUB[p["entry"]]
    d, offset = _offset_step(p, given)
    g, turned = _turned_step(theta, d, given)
    h = _times(rotation_transpose(theta), d)
    key = -g[row]
    flipped = (g[row], "The sign is flipped: that is a row of ∂h/∂θᵢ = R′(θᵢ)ᵀ(tⱼ − tᵢ). The error is e = z − h, "
                       "so its derivative is minus h's.", "sign-flipped-row-of-dh")
    if row == 0:
        slips = kept_slips(key, (
            flipped,
            (-g[1], "That is the other row, ∂e_y/∂θᵢ. The entry asked is in row 1 of −R′(θᵢ)ᵀ(tⱼ − tᵢ).",
                "other-row-e-y"),
            (-h[0], "That multiplies by R(θᵢ)ᵀ, not by its derivative: it is −h_x itself. The entry is the change "
                    "of e as θᵢ changes, so it needs R′(θᵢ)ᵀ.", "multiplies-r-theta-t"),
        ))
    else:  # row 1 of R(θ)ᵀ is minus row 0 of R′(θ)ᵀ, so −h_y is both slips below: one message names both
        slips = kept_slips(key, (
            flipped,
            (-g[0], "That is the other row's entry, ∂e_x/∂θᵢ (the same number as −h_y, which multiplying by "
                    "R(θᵢ)ᵀ instead of its derivative would give). The entry asked is ∂e_y/∂θᵢ, row 2 of "
                    "−R′(θᵢ)ᵀ(tⱼ − tᵢ).", "other-row-s-entry"),
        ))
    # what the derivation prints: the draw's own numbers, never the learner's
    true_d = (p["xj"] - p["xi"], p["yj"] - p["yi"])
    M = rotation_transpose_derivative(theta)
    true_g = _times(M, true_d)
    true_h = _times(rotation_transpose(theta), true_d)
    shown = [[shown_value(v) for v in r] for r in M]
    return {
        "key": key,
        "label": f"∂e{sub}/∂θᵢ",
        "slips": slips,
        "steps": {"d": offset, "turned": turned},
        "values": {
            "sub": sub, "row": str(row + 1), "pxi": paren(p["xi"]), "pyi": paren(p["yi"]),
            "m00": fmt(M[0][0]), "m01": fmt(M[0][1]), "m10": fmt(M[1][0]), "m11": fmt(M[1][1]),
            "pm00": paren(M[0][0]), "pm01": paren(M[0][1]), "pm10": paren(M[1][0]), "pm11": paren(M[1][1]),
            "pd0": paren(true_d[0]), "pd1": paren(true_d[1]),
            "turned_rel": _printed_column_relation(true_g, _times(shown, true_d)),
            "g_row": paren(true_g[row]),
            "hx": fmt(true_h[0]), "hy": fmt(true_h[1]),
            "h_named": "-h_y" if row == 0 else "h_x",
            "h_value": fmt(-true_g[row]),
        },
    }


def _fair(p):
    """Pose j is off both of pose i's axes-aligned lines (each offset term counts), the entry is not
    near zero (so its sign matters), and every slip of the draw is kept."""
    if p["xj"] == p["xi"] or p["yj"] == p["yi"]:
        return False
    made = _heading_entry(p)
    wanted = 3 if p["entry"] == "x" else 2
    return abs(made["key"]) >= 0.5 and len(made["slips"]) == wanted and all(
        len(step["slips"]) >= 2 for step in made["steps"].values())


EXERCISES = (
    Derive(
        id="5.9",
        title="An entry of the edge Jacobian ∂e/∂xᵢ",
        spec=number(label="∂e_x/∂θᵢ"),
        vary=Vary(_heading_entry,
                  Param("xi", 1, -2, 2, 0.5), Param("yi", 1, -2, 2, 0.5), Choice("ti", 60, _ANGLES),
                  Param("xj", 4, -3, 4, 0.5), Param("yj", 2, -3, 4, 0.5), Param("tj", 80, -170, 170, 10),
                  Choice("entry", "x", ("x", "y")),
                  valid=_fair),
        steps=(OFFSET, TURNED),
    ),
)
