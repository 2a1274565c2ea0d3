"""Chapter 4 · the measurement Jacobian H: the whole of it at a sighting (4.7, worked in steps: the
offset d, as in 4.1 to 4.3, then H's bearing row, where the chain rule goes wrong) and one entry of
its position columns as a formula (4.8)."""

import math

from .. import chains
from ..answer_kinds.base import Slip
from ..answer_kinds.expression import formula
from ..answer_kinds.matrix import matrix
from ..kinds.derive import Derive
from ..number_format import fmt, relation, relation_all
from ..reference.ekf import measurement_jacobian
from ..steps import Step
from ..variants import Choice, Vary
from . import grid
from .ch4_ekf_update import (  # the chapter's sighting and its first step
    _LANDMARK,
    _SIGHTING,
    OFFSET,
    _ahead,
    _jacobian_of,
    _offset,
    _offsets,
    _sighting,
)
from .checks import kept_slips

BEARING_ROW = Step("bearing", "H's bearing row (∂φ/∂x, ∂φ/∂y, ∂φ/∂θ)",
                   matrix(label="the bearing row of H: ∂φ/∂x, ∂φ/∂y, ∂φ/∂θ"))


def _bearing_row(d, given):
    """Step 2 of 4.7: H's bearing row from the learner's own offset ``d``, (dy/q, −dx/q, −1) with
    q = dx² + dy², and the slips made at it; the learner's own row when ``given`` has it."""
    dx, dy = d
    q = dx * dx + dy * dy
    root = math.sqrt(q)
    key = ((dy / q, -dx / q, -1.0),)
    slips = kept_slips(key, (
        (((dy / root, -dx / root, -1.0),), "That divides by √q, as the range row does. The derivative of "
                                           f"atan2(dy, dx) divides by q = dx² + dy² = {fmt(q)} itself.",
                                               "divides-q-range-row"),
        (((-dy / q, dx / q, -1.0),), "The x and y entries have the wrong sign: (−dy/q, dx/q) is atan2's "
                                     "derivative by (dx, dy). The robot's x and y enter through dx = lx − x and "
                                     "dy = ly − y, so the chain rule multiplies each by −1.", "y-entries-have-wrong"),
        (((dy / q, -dx / q, 0.0),), "∂φ/∂θ is not 0: the bearing is φ = atan2(dy, dx) − θ, so turning the robot "
                                    "by δθ changes it by −δθ.", "phi-theta-0-bearing"),
        (((-dx / q, -dy / q, -1.0),), "That follows the range row's pattern (−dx, −dy). The bearing turns, it "
                                      "does not stretch: ∂φ/∂x = dy/q and ∂φ/∂y = −dx/q, dx and dy crossed over.",
                                          "follows-range-row-s"),
    ))
    return chains.given(given, "bearing", key)[0], {"key": key, "slips": slips}


def _whole_jacobian(p, given=None):
    """4.7: the measurement Jacobian H of a landmark ahead and to the left of the robot, in steps:
    the offset d, then H's bearing row (the learner's own when ``given`` has them)."""
    s = _sighting(p)
    d, offset = _offset(p, s, given)
    dx, dy = d
    q = dx * dx + dy * dy
    bearing, row = _bearing_row(d, given)
    H = [_jacobian_of(d, q)[0], list(bearing)]
    root = math.sqrt(q)
    printed = _jacobian_of((s["dx"], s["dy"]), s["q"])[1]
    return {
        "key": grid(H),
        "slips": (
            Slip(grid([[h / root for h in H[0]], H[1]]),
                 "The range row divides by q. Differentiating √q gives 1/(2√q) times the derivative of q, so "
                 f"the range row divides by √q = {s['rq_plain']} (only the bearing row divides by q).",
                     name="range-row-divides-q"),
            Slip(grid([H[0], [dy / root, -dx / root, -1.0]]),
                 "The bearing row divides by √q. The derivative of atan2(dy, dx) divides by q = dx² + dy² = "
                 f"{fmt(s['q'])}.", name="bearing-row-divides-q"),
            Slip(grid([H[0], [H[1][0], H[1][1], 0.0]]),
                 "H(2,3) is not 0: the bearing is φ = atan2(dy, dx) − θ, so turning the robot by δθ changes "
                 "it by −δθ.", name="h-2-3-0"),
            Slip(grid([[-h for h in H[0]], [-H[1][0], -H[1][1], H[1][2]]]),
                 "The x and y columns have the wrong sign: you differentiated by the landmark's position. "
                 "dx = lx − x, so moving the robot by +δx shrinks dx.", name="y-columns-have-wrong"),
        ),
        "steps": {"d": offset, "bearing": row},
        "values": {**s["values"], "brel": relation_all(printed),
                   "away": fmt(s["r"]) if s["whole"] else f"\\sqrt{{{fmt(s['q'])}}} {relation(s['r'])} {fmt(s['r'])}"},
    }


def _over_q(sign, top):
    """±dx/q or ±dy/q, with q = dx² + dy² (the bearing row's denominator)."""
    if top == "dx":
        return lambda dx, dy: sign * dx / (dx * dx + dy * dy)
    return lambda dx, dy: sign * dy / (dx * dx + dy * dy)


def _over_root_q(sign, top):
    """±dx/√q or ±dy/√q (the range row's denominator)."""
    if top == "dx":
        return lambda dx, dy: sign * dx / (dx * dx + dy * dy) ** 0.5
    return lambda dx, dy: sign * dy / (dx * dx + dy * dy) ** 0.5


# 4.8: each entry of H's position columns, (row, column) -> (numerator, its sign, what it says in words,
# and its slips: the chain rule's sign, the other row's denominator, the neighbouring entries).
# each entry's four slips, in this order: the sign, the range row's √q for the bearing's q (or the reverse),
# the other column's derivative, the other row's entry
_ENTRY_SLIPS = ("sign-flipped", "wrong-denominator", "other-column", "other-row")
_ENTRIES = {
    "2,1": ("dy", 1, "past a landmark on its left", "dy > 0",
            "swings the landmark further round to the left, so the bearing grows", "dy", (
                (_over_q(-1, "dy"), "The sign is flipped. dx = lx − x, so ∂dx/∂x = −1, and that minus cancels the one "
                                    "in "
                                    "∂atan2(dy, dx)/∂dx = −dy/q."),
                (_over_root_q(1, "dy"), "That divides by √q, as the range row does. The derivative of atan2 divides by "
                                        "q = dx² + dy²."),
                (_over_q(-1, "dx"), "That is H(2,2) = ∂φ/∂y. The x-derivative has dy on top."),
                (_over_root_q(-1, "dx"), "That is H(1,1) = ∂r/∂x, from the range row. The bearing row is the second "
                                         "one."),
            )),
    "2,2": ("dx", -1, "past a landmark ahead of it", "dx > 0",
            "swings the landmark round to the right, so the bearing falls", "-dx", (
                (_over_q(1, "dx"), "The sign is flipped. dy = ly − y, so ∂dy/∂y = −1: multiply "
                                   "∂atan2(dy, dx)/∂dy = dx/q by it."),
                (_over_root_q(-1, "dx"), "That divides by √q, as the range row does: it is H(1,1) = ∂r/∂x. The "
                                         "derivative of atan2 divides by q = dx² + dy²."),
                (_over_q(1, "dy"), "That is H(2,1) = ∂φ/∂x. The y-derivative has dx on top."),
                (_over_root_q(-1, "dy"), "That is H(1,2) = ∂r/∂y, from the range row. The bearing row is the second "
                                         "one."),
            )),
    "1,1": ("dx", -1, "towards a landmark ahead of it", "dx > 0",
            "brings it closer, so the range falls", "-dx", (
                (_over_root_q(1, "dx"), "The sign is flipped. dx = lx − x, so ∂dx/∂x = −1: multiply "
                                        "∂√q/∂dx = dx/√q by it."),
                (_over_q(-1, "dx"), "That divides by q, as the bearing row does: it is H(2,2) = ∂φ/∂y. "
                                    "Differentiating √q gives dx/√q: the range row divides by √q."),
                (_over_root_q(-1, "dy"), "That is H(1,2) = ∂r/∂y. The x-derivative has dx on top."),
                (_over_q(1, "dy"), "That is H(2,1) = ∂φ/∂x, from the bearing row. The range row is the first one."),
            )),
    "1,2": ("dy", -1, "towards a landmark on its left", "dy > 0",
            "brings it closer, so the range falls", "-dy", (
                (_over_root_q(1, "dy"), "The sign is flipped. dy = ly − y, so ∂dy/∂y = −1: multiply "
                                        "∂√q/∂dy = dy/√q by it."),
                (_over_q(-1, "dy"), "That divides by q, as the bearing row does. Differentiating √q gives dy/√q: "
                                    "the range row divides by √q."),
                (_over_root_q(-1, "dx"), "That is H(1,1) = ∂r/∂x. The y-derivative has dy on top."),
                (_over_q(-1, "dx"), "That is H(2,2) = ∂φ/∂y, from the bearing row. The range row is the first one."),
            )),
}
_ATAN2 = r"\operatorname{atan2}(dy, dx)"
_SQRT_Q = r"\sqrt{dx^2 + dy^2}"


def _jacobian_entry_formula(p):
    """4.8: one entry of H's position columns as a formula in dx and dy (which one is the draw)."""
    entry = p["entry"]
    i, j = (int(k) - 1 for k in entry.split(","))
    top, sign, where, condition, effect, follows, slips = _ENTRIES[entry]
    var, dvar = ("x", "dx") if j == 0 else ("y", "dy")
    minus = "-" if sign < 0 else ""
    if i == 0:  # the range row: r = √q, ∂r/∂d = d/√q
        den, den_tex = "sqrt(dx^2 + dy^2)", _SQRT_Q
        f_tex, f_def, f_of = " r", f"r = {_SQRT_Q}", _SQRT_Q
        inner = f"{dvar}/{_SQRT_Q}"
        inner_frac = f"\\frac{{{dvar}}}{{{_SQRT_Q}}}"
    else:  # the bearing row: φ = atan2(dy, dx) − θ, ∂atan2/∂dx = −dy/q, ∂atan2/∂dy = dx/q
        den, den_tex = "(dx^2 + dy^2)", "dx^2 + dy^2"
        f_tex, f_def, f_of = r"\phi", f"\\phi = {_ATAN2} - \\theta", _ATAN2
        inner = "-dy/(dx^2 + dy^2)" if j == 0 else "dx/(dx^2 + dy^2)"
        inner_frac = "\\frac{-dy}{dx^2 + dy^2}" if j == 0 else "\\frac{dx}{dx^2 + dy^2}"
    example = measurement_jacobian((0.0, 0.0, 0.0), _LANDMARK)[i][j]  # dx = 3, dy = 4
    q0 = _LANDMARK[0] ** 2 + _LANDMARK[1] ** 2
    shown_as = f"{minus}{_LANDMARK[0] if top == 'dx' else _LANDMARK[1]}/{math.isqrt(q0) if i == 0 else q0}"
    return {
        "key": lambda dx, dy: measurement_jacobian((0.0, 0.0, 0.0), (dx, dy))[i][j],
        "answer_text": f"{minus}{top}/{den}",
        "label": f"H({entry}) = ∂{'r' if i == 0 else 'φ'}/∂{var}",
        "slips": tuple(Slip(f, message, name=name) for (f, message), name in zip(slips, _ENTRY_SLIPS, strict=True)),
        "values": {
            "ij": f"{i + 1}{j + 1}", "fn": f_tex, "var": var, "dvar": dvar,
            "what": "range" if i == 0 else "bearing", "fdef": f_def, "fop": f_of, "inner": inner,
            "inner_frac": inner_frac, "result": f"{minus}\\frac{{{top}}}{{{den_tex}}}",
            "ahead": fmt(_LANDMARK[0]), "left": fmt(_LANDMARK[1]),
            "example": shown_as, "example_rel": relation(example), "example_value": fmt(example),
            "move": f"+{var}", "where": where, "condition": condition, "effect": effect, "follows": follows,
        },
    }


EXERCISES = (
    Derive(
        id="4.7",
        title="The whole measurement Jacobian H",
        spec=matrix(label="H"),
        vary=Vary(_whole_jacobian, *_SIGHTING, valid=lambda p: _ahead(p) and _offsets(p)[1] > 0),
        steps=(OFFSET, BEARING_ROW),
    ),
    Derive(
        id="4.8",
        title="H(2,1) as a formula",
        same_answer="A formula in dx and dy: students differ only in which of four entries they are asked.",
        spec=formula(variables=("dx", "dy"), domain={"dx": (0.5, 5.0), "dy": (0.5, 5.0)}),
        vary=Vary(_jacobian_entry_formula, Choice("entry", "2,1", ("1,1", "1,2", "2,1", "2,2"))),
    ),
)
