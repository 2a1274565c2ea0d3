"""Chapter 4 · EKF update step."""

import math

from .. import chains
from ..answer_kinds.base import Slip
from ..answer_kinds.matrix import matrix
from ..answer_kinds.number import number
from ..chains import Uses
from ..kinds.build import Build
from ..kinds.derive import Derive
from ..kinds.trace import Option, Trace
from ..number_format import fixed, fmt, paren, relation, shown
from ..reference.domain import bearing_of
from ..reference.ekf import ekf_update, innovation, measurement_jacobian, range_bearing  # noqa: F401 (the doctests)
from ..steps import Step
from ..variants import Param, Vary
from . import column
from .checks import apart, kept_slips, slips_apart

_POSE = (0, 0, 0)
_LANDMARK = (3, 4)
_H_PRED = range_bearing(_POSE, _LANDMARK)

# 4.1 to 4.3 and 4.7: a robot facing east (θ = 0) at (x, y) sights a landmark at (lx, ly).
# Positions in steps of 0.1 m: offsets, ranges and bearings differ from one student to the next.
_SIGHTING = (Param("x", 0, -2, 2, 0.1), Param("y", 0, -2, 2, 0.1), Param("lx", 3, -5, 5, 0.1),
             Param("ly", 4, -5, 5, 0.1))


def _exact(v):
    """A difference or sum of the grid's decimals without float noise (3 stays the whole number 3)."""
    v = round(v, 10)
    return int(v) if v == int(v) else v


def _offsets(p):
    """The landmark's offset (dx, dy) from the robot, without float noise."""
    return _exact(p["lx"] - p["x"]), _exact(p["ly"] - p["y"])


def _sighting(p):
    """The offsets and distances of a sighting, and the strings every derivation of it prints."""
    pose, landmark = (p["x"], p["y"], 0), (p["lx"], p["ly"])
    dx, dy = _offsets(p)
    q = _exact(dx * dx + dy * dy)
    whole = isinstance(q, int) and math.isqrt(q) ** 2 == q  # √q is a whole number
    r = range_bearing(pose, landmark)[0]
    return {
        "pose": pose, "landmark": landmark, "dx": dx, "dy": dy, "q": q, "r": r, "whole": whole,
        "rq_plain": fmt(r) if whole else f"√{fmt(q)} ≈ {fmt(r)}",  # √q in a slip's words
        "values": {
            "px": paren(p["x"]), "py": paren(p["y"]), "dx": fmt(dx), "dy": fmt(dy),
            "dx2": fmt(dx * dx), "dy2": fmt(dy * dy), "q": fmt(q), "r": fmt(r),
            "rq": fmt(r) if whole else f"\\sqrt{{{fmt(q)}}}",  # √q in TeX: exact
            "req": relation(r),
        },
    }


# ---- the steps of a sighting (4.1 to 4.3, 4.7): the offset d = (dx, dy), then q (4.1), the bearing (4.2),
# ---- ∂r/∂dx (4.3, below) or H's bearing row (4.7, ch4_jacobian.py)
OFFSET = Step("d", "(dx, dy)", matrix(label="(dx, dy) = (lx − x, ly − y)", names=("dx", "dy"), unit="m"))
SQUARED = Step("q", "q = dx² + dy²", number(label="q = dx² + dy²"))
ANGLE = Step("phi", "atan2(dy, dx) in radians", number(label="atan2(dy, dx)", unit="rad", angle="rad", periodic=True))


def _offset(p, s, given):
    """Step d: the landmark's offset from the robot, the learner's own when ``given`` has it.
    Returns (dx, dy) and the step (its key and the slips made at it)."""
    key = column((s["dx"], s["dy"]))
    dx, dy = (row[0] for row in chains.given(given, "d", key))
    slips = [Slip(column((-s["dx"], -s["dy"])), "That is the robot's position minus the landmark's: the offset is "
                                                "the landmark minus the robot, dx = lx − x and dy = ly − y.",
                                                    name="robot-s-position-minus")]
    if apart(key, column(s["landmark"]), slips[0].value):
        slips.append(Slip(column(s["landmark"]), "That is where the landmark is. Its offset from the robot "
                                                 f"subtracts the robot's position ({fmt(p['x'])}, {fmt(p['y'])}).",
                                                     name="where-landmark-offset-robot"))
    return (dx, dy), {"key": key, "slips": tuple(slips)}


def _squared(d, given):
    """Step q = dx² + dy² from the learner's own offset ``d``; the learner's own q when ``given`` has it."""
    dx, dy = d
    key = dx * dx + dy * dy
    slips = [Slip((dx + dy) ** 2, "That is (dx + dy)², the square of the sum. Square each offset on its own, "
                                  "then add: q = dx² + dy².", name="dx-dy-2-square")]
    signed = dx * abs(dx) + dy * abs(dy)  # a negative offset squared as −(d²)
    if (dx < 0 or dy < 0) and apart(key, slips[0].value, signed):
        slips.append(Slip(signed, "A negative offset squared gives a positive number: (−a)² = a², so every "
                                  "term of q = dx² + dy² adds.", name="negative-offset-squared-gives"))
    return chains.given(given, "q", key), {"key": key, "slips": tuple(slips)}


def _jacobian_of(d, q):
    """H from the offset ``d`` and ``q`` (the learner's own steps, or the printed ones). With
    q = dx² + dy² it is the reference's measurement Jacobian:

    >>> _jacobian_of((3, 4), 25) == measurement_jacobian((0, 0, 0), (3, 4))
    True
    """
    dx, dy = d
    r = math.sqrt(q)
    return [[-dx / r, -dy / r, 0.0], [dy / q, -dx / q, -1.0]]


def _predicted_range(p, given=None):
    """4.1: the range from the robot at (x, y) to the landmark (lx, ly), in steps d and q."""
    s = _sighting(p)
    d, offset = _offset(p, s, given)
    q, squared = _squared(d, given)
    r = math.sqrt(q)
    a, b = sorted((abs(s["dx"]), abs(s["dy"])))
    if (a, b) == (3, 4):
        remark = "The familiar 3-4-5 right triangle."
    elif s["whole"]:
        remark = f"A {a}-{b}-{fmt(s['r'])} right triangle: the range comes out whole."
    else:
        remark = f"A right triangle with legs {fmt(a)} m and {fmt(b)} m: the range is its hypotenuse."
    return {
        "key": r,
        "slips": (Slip(float(q), "That is q = dx² + dy², the squared range. Take its square root.",
            name="q-dx2-dy2-squared"),),
        "steps": {"d": offset, "q": squared},
        "values": {**s["values"], "remark": remark,
                   "next41": ("Exercise 4.4 compares this range with a measurement." if s["r"] == _H_PRED[0]
                              and (p["x"], p["y"], p["lx"], p["ly"]) == (0, 0, *_LANDMARK)
                              else "Exercise 4.4 compares the range of this exercise's first numbers with a "
                                   "measurement.")},
    }


def _predicted_bearing(p, given=None):
    """4.2: the bearing of the landmark (lx, ly) from the robot at (x, y) facing east, in degrees,
    in steps d and atan2(dy, dx) in radians."""
    s = _sighting(p)
    (dx, dy), offset = _offset(p, s, given)
    phi = bearing_of(dx, dy)  # the learner's own offset may be (0, 0): then no bearing is defined
    turn = 2 * math.pi
    slips = [Slip(math.atan2(dx, dy), "The arguments are swapped. atan2 takes (dy, dx): the angle is measured "
                                      "from the x-axis.", name="phi-arguments-swapped")]
    if dx < 0 and apart(phi, slips[0].value, math.atan(dy / dx), turn=turn):
        slips.append(Slip(math.atan(dy / dx), "That is atan(dy/dx), which cannot tell a landmark behind the robot "
                                              "(dx < 0) from one ahead of it: it is off by π. atan2(dy, dx) looks at "
                                              "both signs.", name="atan-dy-dx-which"))
    rad = chains.given(given, "phi", phi)
    deg = math.degrees(rad)
    return {
        "key": deg,
        "slips": (
            Slip(math.degrees(math.atan2(dx, dy)),
                 f"The arguments are swapped. atan2 takes (dy, dx): atan2({fmt(dy)}, {fmt(dx)}), measured from the "
                 "x-axis.", name="arguments-swapped"),
        ),
        "steps": {"d": offset, "phi": {"key": phi, "slips": tuple(slips)}},
        "values": {**s["values"], "rad_rel": relation(phi), "deg": fmt(deg),
                   "deg_rel": relation(deg, math.degrees(shown(phi)))},
    }


SLOPE = Step("drdx", "∂r/∂dx", number(label="∂r/∂dx, the range's derivative by dx"))


def _range_slope(p, given=None):
    """4.3: H(1,1) = −dx/√q, how fast the range changes as the robot steps along x, in steps: the
    offset d, then ∂r/∂dx = dx/√q (the derivative of √q), which the chain rule's ∂dx/∂x = −1 turns
    into H(1,1) (each the learner's own when ``given`` has it)."""
    s = _sighting(p)
    d, offset = _offset(p, s, given)
    dx, dy = d
    root = math.sqrt(dx * dx + dy * dy)
    slope = dx / root
    mine = chains.given(given, "drdx", slope)
    h11 = _jacobian_of((s["dx"], s["dy"]), s["q"])[0][0]  # the printed H(1,1), from the printed offset
    deg = math.degrees(range_bearing(s["pose"], s["landmark"])[1])
    return {
        "key": -mine,
        "slips": (
            Slip(-dy / root, "That is H(1,2) = −dy/√q, the derivative with respect to y. H(1,1) uses dx.",
                name="h-1-2-dy"),
            Slip(slope, "The sign is flipped: that is ∂r/∂dx = dx/√q. The robot's x enters through dx = lx − x, "
                        "so the chain rule multiplies by ∂dx/∂x = −1: H(1,1) = −dx/√q.", name="sign-flipped-r-dx"),
            Slip(-dx / (root * root), f"You divided by q. The range row divides by √q = {s['rq_plain']}; "
                                      "it is the bearing row that divides by q.", name="divided-q-range-row"),
        ),
        "steps": {"d": offset, "drdx": {"key": slope, "slips": kept_slips(slope, (
            (dx / (root * root), "That divides by q. The range is √q, and the derivative of √q by dx is "
                                 "(1/(2√q))·2dx = dx/√q.", "divides-q-range-q"),
            (dy / root, "That is ∂r/∂dy = dy/√q. The derivative by dx has dx on top.", "r-dy-dy-q"),
            (-slope, "That already has the minus of ∂dx/∂x = −1: that is H(1,1) itself. This step is the "
                     "derivative by dx alone, dx/√q.", "already-has-minus-dx"),
        ))}},
        "values": {**s["values"], "h11": fmt(h11), "size": fmt(abs(h11)), "drel": relation(h11),
                   "cos_rel": relation(abs(h11), math.cos(math.radians(shown(deg)))),
                   "phi": f"{fmt(deg)}°" if deg >= 0 else f"({fmt(deg)}°)"},
    }


def _range_innovation(p, given=None):
    """4.4: the range innovation z_r − h_r between measured (zr, zphi) and predicted (hr, hphi);
    ``given`` holds the learner's own range from exercise 4.1 in place of hr, where hr is 4.1's."""
    hr = chains.given(given, "hr", p["hr"])
    y = innovation((p["zr"], p["zphi"]), (hr, p["hphi"]))
    closer = y[0] < 0
    places = 1 if round(p["zr"], 1) == p["zr"] else 2  # the ranges as the sensor gives them: 4.8, or 4.83
    return {
        "key": y[0],
        "slips": (
            Slip(innovation((hr,), (p["zr"],))[0],
                 "The sign is flipped. The innovation is z − h(x): measured minus predicted.",
                     name="sign-flipped-innovation-z"),
            Slip(y[1], "That is the bearing innovation, the second component. The range is the first.",
                name="bearing-innovation-second-component"),
        ),
        "values": {"zr1": fixed(p["zr"], places), "hr1": fixed(hr, places), "yr": fmt(y[0]), "gap": fmt(abs(y[0])),
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


def _ahead(p):
    return _offsets(p)[0] > 0


def _off_both_axes(p):
    """A real right triangle: the landmark is at least 0.5 m off the robot's x and y lines."""
    return all(abs(d) >= 0.5 for d in _offsets(p))


def _range_ok(p):
    """4.1: a real right triangle, and the range told apart from q (they meet at r = 1)."""
    return _off_both_axes(p) and slips_apart(_predicted_range(p))


EXERCISES = (
    Derive(
        id="4.1",
        title="Predicted range",
        spec=number(label="r", unit="m"),
        vary=Vary(_predicted_range, *_SIGHTING, valid=_range_ok),
        steps=(OFFSET, SQUARED),
    ),
    Derive(
        id="4.2",
        title="Predicted bearing",
        spec=number(label="φ", unit="°", angle="deg", periodic=True),
        vary=Vary(_predicted_bearing, *_SIGHTING,
                  valid=lambda p: _off_both_axes(p) and _offsets(p)[0] != _offsets(p)[1]),
        steps=(OFFSET, ANGLE),
    ),
    Derive(
        id="4.3",
        title="An entry of H",
        spec=number(label="H(1,1)"),
        vary=Vary(_range_slope, *_SIGHTING,
                  valid=lambda p: _ahead(p) and _off_both_axes(p) and abs(_offsets(p)[0]) != abs(_offsets(p)[1])),
        steps=(OFFSET, SLOPE),
    ),
    Derive(
        id="4.4",
        title="The innovation",
        spec=number(label="range innovation", unit="m"),
        vary=Vary(_range_innovation,
                  Param("hr", 5, 3, 7, 0.1, unit=" m"), Param("hphi", _H_PRED[1], 0.2273, 1.4273, 0.1, unit=" rad"),
                  Param("zr", 4.8, 2.5, 7.5, 0.01, unit=" m"), Param("zphi", 0.95, 0.05, 1.6, 0.01, unit=" rad"),
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
        random_args=lambda rng: (rng.uniform(-10, 10), rng.uniform(0.01, 5),
                                 rng.uniform(-10, 10), rng.uniform(0.01, 5)),
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
)
