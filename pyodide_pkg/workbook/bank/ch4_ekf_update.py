"""Chapter 4 · EKF update step."""

import math

from ..kinds.build import Build
from ..answer_kinds.base import Slip
from ..answer_kinds.number import number
from ..answer_kinds.matrix import matrix
from ..answer_kinds.expression import formula
from ..kinds.derive import Derive
from ..kinds.trace import Option, Trace
from ..number_format import fixed, fmt, paren, relation, shown
from ..reference.ekf import ekf_update, innovation, measurement_jacobian, range_bearing
from ..variants import Choice, Param, Vary
from .. import chains
from ..chains import Uses
from . import grid

_POSE = (0, 0, 0)
_LANDMARK = (3, 4)
_H_PRED = range_bearing(_POSE, _LANDMARK)

# 4.1 to 4.3 and 4.7: a robot facing east (θ = 0) at (x, y) sights a landmark at (lx, ly).
_SIGHTING = (Param("x", 0, -2, 2, 1), Param("y", 0, -2, 2, 1), Param("lx", 3, -5, 5, 1), Param("ly", 4, -5, 5, 1))


def _sighting(p):
    """The offsets and distances of a sighting, and the strings every derivation of it prints."""
    pose, landmark = (p["x"], p["y"], 0), (p["lx"], p["ly"])
    dx, dy = p["lx"] - p["x"], p["ly"] - p["y"]
    q = dx * dx + dy * dy
    root = math.isqrt(q)
    whole = root * root == q  # √q is a whole number
    r = range_bearing(pose, landmark)[0]
    return {
        "pose": pose, "landmark": landmark, "dx": dx, "dy": dy, "q": q, "r": r, "whole": whole,
        "rq_plain": fmt(r) if whole else f"√{fmt(q)} ≈ {fmt(r)}",  # √q in a slip's words
        "values": {
            "px": paren(p["x"]), "py": paren(p["y"]), "dx": fmt(dx), "dy": fmt(dy),
            "dx2": fmt(dx * dx), "dy2": fmt(dy * dy), "q": fmt(q), "r": fmt(r),
            "rq": fmt(r) if whole else f"\\sqrt{{{q}}}",  # √q in TeX: exact
            "req": relation(r),
        },
    }


def _predicted_range(p):
    """4.1: the range from the robot at (x, y) to the landmark (lx, ly)."""
    s = _sighting(p)
    a, b = sorted((abs(s["dx"]), abs(s["dy"])))
    if (a, b) == (3, 4):
        remark = "The familiar 3-4-5 right triangle."
    elif s["whole"]:
        remark = f"A {a}-{b}-{fmt(s['r'])} right triangle: the range comes out whole."
    else:
        remark = f"A right triangle with legs {a} m and {b} m: the range is its hypotenuse."
    return {
        "key": s["r"],
        "slips": (Slip(float(s["q"]), "That is q = dx² + dy², the squared range. Take its square root."),),
        "values": {**s["values"], "remark": remark,
                   "next41": ("Exercise 4.4 compares this range with a measurement." if s["r"] == _H_PRED[0]
                              and (p["x"], p["y"], p["lx"], p["ly"]) == (0, 0, *_LANDMARK)
                              else "Exercise 4.4 compares the range of this exercise's first numbers with a measurement.")},
    }


def _predicted_bearing(p):
    """4.2: the bearing of the landmark (lx, ly) from the robot at (x, y) facing east, in degrees."""
    s = _sighting(p)
    phi = range_bearing(s["pose"], s["landmark"])[1]
    deg = math.degrees(phi)
    dx, dy = fmt(s["dx"]), fmt(s["dy"])
    return {
        "key": deg,
        "slips": (
            Slip(math.degrees(math.atan2(s["dx"], s["dy"])),
                 f"The arguments are swapped. atan2 takes (dy, dx): atan2({dy}, {dx}), measured from the x-axis."),
        ),
        "values": {**s["values"], "rad": fmt(phi), "rad_rel": relation(phi), "deg": fmt(deg),
                   "deg_rel": relation(deg, math.degrees(shown(phi)))},
    }


def _range_slope(p):
    """4.3: H(1,1) = −dx/√q, how fast the range changes as the robot steps along x."""
    s = _sighting(p)
    H = measurement_jacobian(s["pose"], s["landmark"])
    deg = math.degrees(range_bearing(s["pose"], s["landmark"])[1])
    return {
        "key": H[0][0],
        "slips": (
            Slip(H[0][1], "That is H(1,2) = −dy/√q, the derivative with respect to y. H(1,1) uses dx."),
            Slip(-s["dx"] / s["q"], f"You divided by q. The range row divides by √q = {s['rq_plain']}; "
                                    "it is the bearing row that divides by q."),
        ),
        "values": {**s["values"], "h11": fmt(H[0][0]), "size": fmt(abs(H[0][0])),
                   "cos_rel": relation(abs(H[0][0]), math.cos(math.radians(shown(deg)))),
                   "phi": f"{fmt(deg)}°" if deg >= 0 else f"({fmt(deg)}°)"},
    }


def _range_innovation(p, given=None):
    """4.4: the range innovation z_r − h_r between measured (zr, zphi) and predicted (hr, hphi);
    ``given`` holds the learner's own range from exercise 4.1 in place of hr, where hr is 4.1's."""
    hr = chains.given(given, "hr", p["hr"])
    y = innovation((p["zr"], p["zphi"]), (hr, p["hphi"]))
    closer = y[0] < 0
    return {
        "key": y[0],
        "slips": (
            Slip(innovation((hr,), (p["zr"],))[0],
                 "The sign is flipped. The innovation is z − h(x): measured minus predicted."),
            Slip(y[1], "That is the bearing innovation, the second component. The range is the first."),
        ),
        "values": {"zr1": fixed(p["zr"], 1), "hr1": fixed(hr, 1), "yr": fmt(y[0]), "gap": fmt(abs(y[0])),
                   "from41": "(its range is exercise 4.1's)" if _range_of_41(p) is not None else "",
                   "closer": "closer" if closer else "farther", "pull": "pull" if closer else "push",
                   "towards": "towards" if closer else "away from"},
    }


def _range_of_41(p):
    """4.4's predicted range is exercise 4.1's answer (variant 0) when it is that number: then 0, else None."""
    return 0 if p["hr"] == _H_PRED[0] else None


def _innovation_is_a_surprise(p):
    """A range surprise of 0.1 to 1 m and a bearing one of at most 0.2 rad, in numbers that are not 4.4's own."""
    dr, dphi = round(abs(p["zr"] - p["hr"]), 6), abs(p["zphi"] - p["hphi"])
    shown = (p["hr"], p["zr"], round(p["hphi"], 4), p["zphi"])
    return 0 < dr <= 1 and dphi <= 0.2 and shown != (5, 4.8, 0.9273, 0.95)


def _whole_jacobian(p):
    """4.7: the measurement Jacobian H of a landmark ahead and to the left of the robot."""
    s = _sighting(p)
    H = measurement_jacobian(s["pose"], s["landmark"])
    dx, dy, q = s["dx"], s["dy"], s["q"]
    return {
        "key": grid(H),
        "slips": (
            Slip(grid([[h / q ** 0.5 for h in H[0]], H[1]]),
                 "The range row divides by q. Differentiating √q gives 1/(2√q) times the derivative of q, so "
                 f"the range row divides by √q = {s['rq_plain']} (only the bearing row divides by q)."),
            Slip(grid([H[0], [dy / q ** 0.5, -dx / q ** 0.5, -1.0]]),
                 f"The bearing row divides by √q. The derivative of atan2(dy, dx) divides by q = dx² + dy² = {fmt(q)}."),
            Slip(grid([H[0], [H[1][0], H[1][1], 0.0]]),
                 "H(2,3) is not 0: the bearing is φ = atan2(dy, dx) − θ, so turning the robot by δθ changes "
                 "it by −δθ."),
            Slip(grid([[-h for h in H[0]], [-H[1][0], -H[1][1], H[1][2]]]),
                 "The x and y columns have the wrong sign: you differentiated by the landmark's position. "
                 "dx = lx − x, so moving the robot by +δx shrinks dx."),
        ),
        "values": {**s["values"],
                   "away": fmt(s["r"]) if s["whole"] else f"\\sqrt{{{q}}} {relation(s['r'])} {fmt(s['r'])}"},
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
_ENTRIES = {
    "2,1": ("dy", 1, "past a landmark on its left", "dy > 0",
            "swings the landmark further round to the left, so the bearing grows", "dy", (
                (_over_q(-1, "dy"), "The sign is flipped. dx = lx − x, so ∂dx/∂x = −1, and that minus cancels the one in "
                                    "∂atan2(dy, dx)/∂dx = −dy/q."),
                (_over_root_q(1, "dy"), "That divides by √q, as the range row does. The derivative of atan2 divides by "
                                        "q = dx² + dy²."),
                (_over_q(-1, "dx"), "That is H(2,2) = ∂φ/∂y. The x-derivative has dy on top."),
                (_over_root_q(-1, "dx"), "That is H(1,1) = ∂r/∂x, from the range row. The bearing row is the second one."),
            )),
    "2,2": ("dx", -1, "past a landmark ahead of it", "dx > 0",
            "swings the landmark round to the right, so the bearing falls", "-dx", (
                (_over_q(1, "dx"), "The sign is flipped. dy = ly − y, so ∂dy/∂y = −1: multiply "
                                   "∂atan2(dy, dx)/∂dy = dx/q by it."),
                (_over_root_q(-1, "dx"), "That divides by √q, as the range row does: it is H(1,1) = ∂r/∂x. The "
                                         "derivative of atan2 divides by q = dx² + dy²."),
                (_over_q(1, "dy"), "That is H(2,1) = ∂φ/∂x. The y-derivative has dx on top."),
                (_over_root_q(-1, "dy"), "That is H(1,2) = ∂r/∂y, from the range row. The bearing row is the second one."),
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
        "slips": tuple(Slip(f, message) for f, message in slips),
        "values": {
            "ij": f"{i + 1}{j + 1}", "fn": f_tex, "var": var, "dvar": dvar,
            "what": "range" if i == 0 else "bearing", "fdef": f_def, "fop": f_of, "inner": inner,
            "inner_frac": inner_frac, "result": f"{minus}\\frac{{{top}}}{{{den_tex}}}",
            "ahead": fmt(_LANDMARK[0]), "left": fmt(_LANDMARK[1]),
            "example": shown_as, "example_rel": relation(example), "example_value": fmt(example),
            "move": f"+{var}", "where": where, "condition": condition, "effect": effect, "follows": follows,
        },
    }


def _ahead(p):
    return p["lx"] > p["x"]


def _off_both_axes(p):
    """A real right triangle: the landmark is not straight along x or y from the robot."""
    return p["lx"] != p["x"] and p["ly"] != p["y"]


EXERCISES = (
    Derive(
        id="4.1",
        title="Predicted range",
        answer=number(label="r", unit="m"),
        vary=Vary(_predicted_range, *_SIGHTING, valid=_off_both_axes),
    ),
    Derive(
        id="4.2",
        title="Predicted bearing",
        answer=number(label="φ", unit="°", angle="deg", periodic=True),
        vary=Vary(_predicted_bearing, *_SIGHTING,
                  valid=lambda p: _off_both_axes(p) and p["lx"] - p["x"] != p["ly"] - p["y"]),
    ),
    Derive(
        id="4.3",
        title="An entry of H",
        answer=number(label="H(1,1)"),
        vary=Vary(_range_slope, *_SIGHTING,
                  valid=lambda p: _ahead(p) and _off_both_axes(p) and abs(p["lx"] - p["x"]) != abs(p["ly"] - p["y"])),
    ),
    Derive(
        id="4.4",
        title="The innovation",
        answer=number(label="range innovation", unit="m"),
        vary=Vary(_range_innovation,
                  Param("hr", 5, 3, 7, 0.1, unit=" m"), Param("hphi", _H_PRED[1], 0.2273, 1.4273, 0.1, unit=" rad"),
                  Param("zr", 4.8, 2.5, 7.5, 0.1, unit=" m"), Param("zphi", 0.95, 0.05, 1.6, 0.01, unit=" rad"),
                  valid=_innovation_is_a_surprise),
        uses=(Uses("4.1", "hr", "range r", variant=_range_of_41),),
    ),
    Build(
        id="4.5",
        title="Implement ekf_update",
        function="ekf_update",
        params=("x", "P", "z", "R"),
        starter=(
            "def ekf_update(x, P, z, R):\n"
            '    """Scalar Kalman update with h(x) = x; return (x_new, P_new)."""\n'
            "    # Your code here: the gain K, then the new state and covariance.\n"
            "    return (x, P)\n"
        ),
        solution=(
            "def ekf_update(x, P, z, R):\n"
            '    """Scalar Kalman update with h(x) = x; return (x_new, P_new)."""\n'
            "    K = P / (P + R)\n"
            "    return (x + K * (z - x), (1 - K) * P)\n"
        ),
        reference=ekf_update,
        run_figure="ekf-update",
        examples=((5.866, 0.5, 5.7, 0.2), (0.0, 1.0, 1.0, 1.0), (2.0, 1.0, 3.0, 0.0), (10.0, 0.1, 12.0, 2.0)),
        random_args=lambda rng: (rng.uniform(-10, 10), rng.uniform(0.01, 5), rng.uniform(-10, 10), rng.uniform(0.01, 5)),
    ),
    Trace(
        id="4.6",
        title="The gain at the extremes",
        answer="a",
        options=(
            Option("a", "$K \\to 1$: the update returns the measurement, $x^+ = z$",
                   "Right. $K = P/(P+R) \\to P/P = 1$, so $x^+ = x^- + (z - x^-) = z$: a perfect sensor overrides "
                   "the prediction. At the other end, $R \\to \\infty$ gives $K \\to 0$."),
            Option("b", "$K \\to 0$: the measurement is ignored",
                   "That is the opposite extreme, $R \\to \\infty$: a useless sensor. With $R \\to 0$ the "
                   "denominator shrinks to $P$."),
            Option("c", "$K \\to 0.5$: prediction and measurement are averaged",
                   "An even split happens when $P = R$, when both are equally trusted, not when the sensor "
                   "is perfect."),
            Option("d", "$K$ grows without bound",
                   "$K = P/(P+R)$ never exceeds 1 while $P, R \\ge 0$; at $R = 0$ it is exactly 1."),
        ),
    ),
    Derive(
        id="4.7",
        title="The whole measurement Jacobian H",
        answer=matrix(label="H"),
        vary=Vary(_whole_jacobian, *_SIGHTING, valid=lambda p: _ahead(p) and p["ly"] > p["y"]),
    ),
    Derive(
        id="4.8",
        title="H(2,1) as a formula",
        answer=formula(variables=("dx", "dy"), domain={"dx": (0.5, 5.0), "dy": (0.5, 5.0)}),
        vary=Vary(_jacobian_entry_formula, Choice("entry", "2,1", ("1,1", "1,2", "2,1", "2,2"))),
    ),
)
