"""Chapter 10 · 3-D poses: composing, comparing and interpolating unit quaternions (w, x, y, z),
scalar first as in chapter 2, with the double cover (q and −q are one rotation)."""

from __future__ import annotations

import math

from .. import chains
from ..answer_kinds.matrix import matrix
from ..answer_kinds.number import number
from ..kinds.derive import Derive
from ..number_format import fmt, paren, relation, relation_all, shown
from ..reference.domain import Undefined
from ..reference.rotation3d import quat_from_axis_angle, quat_multiply
from ..reference.se3 import angle_between, quat_dot, to_xyzw
from ..steps import Step
from ..variants import Choice, Param, Vary
from . import column
from .checks import apart, kept_slips

_AXES = {"x": (1, 0, 0), "y": (0, 1, 0), "z": (0, 0, 1)}
SAME_ROTATION = "−q is the same rotation as q (the double cover), so both signs are right."


def _two_lines(terms):
    """A four-term sum in an aligned display, broken after its second term (one line is wider
    than a phone)."""
    return " + ".join(terms[:2]) + " \\\\\n&\\quad + " + " + ".join(terms[2:])


def _q(deg, axis, sign=1):
    """The unit quaternion of ``deg`` degrees about a coordinate axis, times ``sign``, with the
    rounding noise of cos 90° and sin 180° removed (so a component that is 0 is exactly 0)."""
    q = quat_from_axis_angle(_AXES[axis], math.radians(deg))
    return tuple(sign * (0.0 if abs(c) < 1e-12 else c) + 0.0 for c in q)


def _neg(q):
    return tuple(-c for c in q)


def _both_signs(key, candidates):
    """``kept_slips`` over each candidate and its negation (the same rotation, which the answer
    accepts either way), each negation with its candidate's message; a candidate that is the key
    or its negation is no slip."""
    minus = column(_neg([r[0] for r in key]))
    pairs = tuple(pair for value, message, name in candidates
                  if value is not None and apart(value, key) and apart(value, minus)
                  for pair in ((value, message, name), (column(_neg([r[0] for r in value])), message, name)))
    return kept_slips(key, pairs)


def _qtext(q):
    return ",\\ ".join(fmt(c) for c in q)


def _compose(p):
    """10.3: a camera's orientation in the world, q_wc = q_wb ⊗ q_bc, two turns about coordinate axes."""
    q_wb, q_bc = _q(p["a"], p["A"]), _q(p["b"], p["B"])
    key = quat_multiply(q_wb, q_bc)
    u1, u2 = q_wb[1:], q_bc[1:]
    dot = sum(a * b for a, b in zip(u1, u2))
    cross = (u1[1] * u2[2] - u1[2] * u2[1], u1[2] * u2[0] - u1[0] * u2[2], u1[0] * u2[1] - u1[1] * u2[0])
    w1, w2 = q_wb[0], q_bc[0]
    vec = tuple(w1 * b + w2 * a + c for a, b, c in zip(u1, u2, cross))
    # every printed intermediate, from the printed inputs, for the = or ≈ of each line
    s1, s2 = [shown(c) for c in q_wb], [shown(c) for c in q_bc]
    sdot = sum(a * b for a, b in zip(s1[1:], s2[1:]))
    sw = s1[0] * s2[0] - shown(dot)
    return {
        "key": column(key),
        "slips": _both_signs(column(key), (
            (column(quat_multiply(q_bc, q_wb)),
             "That is q_bc ⊗ q_wb, the factors swapped. The chain's names must meet: q_wc = q_wb ⊗ q_bc, "
             "and swapping them flips the sign of the cross term u₁ × u₂.", "q-bc-times-q"),
            (column(to_xyzw(key)),
             "Those are the right numbers in the order (x, y, z, w), scalar last, as ROS and SciPy store "
             "them. This answer asks for (w, x, y, z), scalar first.", "those-right-numbers-order"),
            (column(tuple(a * b for a, b in zip(q_wb, q_bc))),
             "That multiplies component by component. The Hamilton product takes a dot product for the "
             "scalar part and a cross product in the vector part.", "multiplies-component-component-hamilton"),
        )),
        "values": {
            "a": fmt(p["a"]), "A": p["A"], "b": fmt(p["b"]), "B": p["B"],
            "q1": _qtext(q_wb), "q2": _qtext(q_bc), "w1": fmt(w1), "w2": fmt(w2),
            "u1": _qtext(u1), "u2": _qtext(u2),
            "dot_rel": relation(dot, sdot), "dot": fmt(dot), "pdot": paren(dot),
            "cross_rel": relation_all(cross), "cross": _qtext(cross),
            "ww": fmt(w1 * w2), "w_rel": relation(key[0], sw), "w": fmt(key[0]),
            "vec_rel": relation_all(vec), "vec": _qtext(vec),
        },
    }


def _compose_ok(p):
    """Two different axes (so the order matters), and the slips told apart from the key."""
    if p["A"] == p["B"]:
        return False
    made = _compose(p)
    return len(made["slips"]) >= 4


def _angle(p, given=None):
    """10.4: the angle between two orientations, one of them written with its negative sign."""
    q0 = _q(p["a"], "z")
    q1 = _q(p["b"], p["B"], -1)
    d = quat_dot(q0, q1)
    mine = chains.given(given, "dot", d)
    if abs(mine) > 1 + 1e-9:
        raise Undefined(f"a dot product of {fmt(mine)} is larger than 1 in size, and no angle has that cosine: "
                        "the dot product of two unit quaternions lies between −1 and 1")
    half_key = math.degrees(math.acos(min(1.0, abs(mine))))
    half = chains.given(given, "half", half_key)
    key = 2 * half
    long_way = math.degrees(2 * math.acos(max(-1.0, min(1.0, mine))))
    sd = sum(shown(a) * shown(b) for a, b in zip(q0, q1))
    return {
        "key": key,
        "slips": kept_slips(key, (
            (long_way, f"That is 2·arccos({fmt(mine)}) without the absolute value: the long way round, "
                       f"{fmt(long_way)}° = 360° − {fmt(360 - long_way)}°. q₁ and −q₁ are the same orientation, "
                       "so take 2·arccos|q₀ · q₁|.", "2-arccos-without-absolute"),
            (float(half), f"That is arccos|q₀ · q₁| = {fmt(half)}°, half the angle: a quaternion carries θ/2, so "
                          "the angle is twice that.", "arccos-q-q1-half"),
            (float(abs(p["b"] - p["a"])), f"That subtracts the two angles, {fmt(p['b'])}° − {fmt(p['a'])}°, "
                                          "which only works for turns about the same axis. Use the dot product.",
                                              "subtracts-two-angles-which"),
        ), turn=360),
        "steps": {
            "dot": {"key": d, "slips": kept_slips(d, (
                (q0[0] * q1[0] - sum(a * b for a, b in zip(q0[1:], q1[1:])),
                 "That subtracts the vector parts' products, as the scalar part of a Hamilton product does. The "
                 "four-dimensional dot product adds all four: w₀w₁ + x₀x₁ + y₀y₁ + z₀z₁.",
                     "subtracts-vector-parts-products"),
                (abs(d), "The sign is lost: the dot product itself is negative here. The absolute value comes "
                         "afterwards, in the angle.", "sign-lost-dot-product"),
            ))},
            "half": {"key": half_key, "slips": kept_slips(half_key, (
                (long_way / 2, f"That is arccos({fmt(mine)}) without the absolute value: the long way round. "
                               "q₁ and −q₁ are the same orientation, so take arccos|q₀ · q₁|.",
                                   "arccos-without-absolute-value"),
            ), turn=180)},
        },
        "values": {
            "a": fmt(p["a"]), "b": fmt(p["b"]), "B": p["B"], "q0": _qtext(q0), "q1": _qtext(q1),
            "terms": _two_lines([f"{paren(a)} \\cdot {paren(b)}" for a, b in zip(q0, q1)]),
            "dot_rel": relation(d, sd), "abs": fmt(abs(d)),
        },
    }


def _angle_ok(p):
    """A turn of at least 30° between them, not a half turn (where both ways are as long), and the
    slips about the double cover and the half angle told apart from the key."""
    q0, q1 = _q(p["a"], "z"), _q(p["b"], p["B"], -1)
    theta = math.degrees(angle_between(q0, q1))
    if theta < 30 or theta > 170:
        return False
    made = _angle(p)
    return quat_dot(q0, q1) < 0 and len(made["slips"]) >= 2 and len(made["steps"]["dot"]["slips"]) >= 1


def _midpoint(p, given=None):
    """10.5: the SLERP midpoint of two orientations about one axis, the second written with a sign
    that puts it the long way round."""
    axis = p["A"]
    q0, q1 = _q(p["a"], axis), _q(p["b"], axis, -1)
    d = quat_dot(q0, q1)
    mine = chains.given(given, "dot", d)
    if abs(mine) > 1 + 1e-9:
        raise Undefined(f"a dot product of {fmt(mine)} is larger than 1 in size, so no arc Ω has it as its "
                        "cosine: the dot product of two unit quaternions lies between −1 and 1")
    flip = -1.0 if mine < 0 else 1.0
    near = tuple(flip * c for c in q1)
    omega_key = math.degrees(math.acos(min(1.0, abs(mine))))
    omega = math.radians(chains.given(given, "omega", omega_key))
    if math.isclose(math.cos(omega / 2), 0.0, abs_tol=1e-12):
        raise Undefined("an arc of Ω = 180° puts the two quaternions opposite each other, where sin Ω = 0 and "
                        "SLERP's weights divide by zero")
    scale = 1 / (2 * math.cos(omega / 2))
    key = tuple(scale * (a + b) for a, b in zip(q0, near))
    raw = tuple(a + b for a, b in zip(q0, q1))
    n = math.sqrt(sum(c * c for c in raw))
    summed = tuple(a + b for a, b in zip(q0, near))
    return {
        "key": column(key),
        "slips": _both_signs(column(key), (
            (column(tuple(c / n for c in raw)) if flip < 0 and n > 0 else None,
             "That is the midpoint the long way round: q₀ · q₁ is negative, so q₁ must be replaced by −q₁ "
             "(the same orientation) before interpolating, or the path turns by more than 180°.",
             "midpoint-long-way-round"),
            (column(tuple(c / 2 for c in summed)),
             "That is the plain average (q₀ + q₁)/2, which is shorter than 1: not a rotation. SLERP's "
             "weights sin(Ω/2)/sin Ω = 1/(2 cos(Ω/2)) bring it back onto the unit sphere.", "plain-average-q0-q1"),
            (column(to_xyzw(key)),
             "Those are the right numbers in the order (x, y, z, w), scalar last. This answer asks for "
             "(w, x, y, z), scalar first.", "those-right-numbers-order"),
        )),
        "steps": {
            "dot": {"key": d, "slips": kept_slips(d, (
                (q0[0] * q1[0] - sum(a * b for a, b in zip(q0[1:], q1[1:])),
                 "That subtracts the vector parts' products, as the scalar part of a Hamilton product does. The "
                 "four-dimensional dot product adds all four: w₀w₁ + x₀x₁ + y₀y₁ + z₀z₁.",
                     "subtracts-vector-parts-products"),
            ))},
            "omega": {"key": omega_key, "slips": kept_slips(omega_key, (
                (math.degrees(math.acos(max(-1.0, min(1.0, mine)))),
                 f"That is arccos({fmt(mine)}), the arc the long way round. After replacing q₁ by −q₁ the "
                 "cosine is |q₀ · q₁|, and Ω is under 90°.", "arccos-arc-long-way"),
                (2 * omega_key, "That is the angle between the two orientations, twice the arc: on the sphere of "
                                "quaternions the arc Ω is half the turn, cos Ω = |q₀ · q₁|.",
                                    "angle-between-two-orientations"),
            ))},
        },
        "values": {
            "a": fmt(p["a"]), "b": fmt(p["b"]), "A": axis, "q0": _qtext(q0), "q1": _qtext(q1),
            "near": _qtext(near), "halfomega": fmt(math.degrees(omega) / 2),
            "cos_half": fmt(math.cos(omega / 2)), "sum": _qtext(summed), "scale": fmt(scale),
            "mid": fmt((p["a"] + p["b"]) / 2),
            "abs": fmt(abs(d)),
        },
    }


def _midpoint_ok(p):
    q0, q1 = _q(p["a"], p["A"]), _q(p["b"], p["A"], -1)
    d = quat_dot(q0, q1)
    theta = math.degrees(angle_between(q0, q1))
    made = _midpoint(p)
    return d < 0 and 40 <= theta <= 160 and len(made["slips"]) >= 5 and apart(d, -d)


EXERCISES = (
    Derive(
        id="10.3",
        title="Compose two turns as quaternions",
        spec=matrix(label="q_wc = (w, x, y, z)ᵀ", names=("w", "x", "y", "z"), either_sign=SAME_ROTATION),
        vary=Vary(_compose, Param("a", 90, -175, 180, 5, avoid=(0,)), Choice("A", "z", ("x", "y", "z")),
                  Param("b", 90, -175, 180, 5, avoid=(0,)), Choice("B", "x", ("x", "y", "z")), valid=_compose_ok),
    ),
    Derive(
        id="10.4",
        title="The angle between two orientations",
        spec=number(label="θ", unit="°", angle="deg"),
        vary=Vary(_angle, Param("a", 60, 0, 180, 1), Param("b", 120, 0, 179, 1),  # b < 180: w < 0
                  Choice("B", "z", ("x", "y", "z")), valid=_angle_ok),
        steps=(Step("dot", "q₀ · q₁", number(label="q₀ · q₁, the four-dimensional dot product")),
               Step("half", "θ/2", number(label="θ/2 = arccos|q₀ · q₁|", unit="°", angle="deg"))),
    ),
    Derive(
        id="10.5",
        title="A SLERP midpoint, the short way",
        spec=matrix(label="slerp(q₀, q₁, ½) = (w, x, y, z)ᵀ", names=("w", "x", "y", "z"),
                    either_sign=SAME_ROTATION),
        vary=Vary(_midpoint, Param("a", 0, 0, 180, 1), Param("b", 120, 0, 180, 1),
                  Choice("A", "z", ("x", "y", "z")), valid=_midpoint_ok),
        steps=(Step("dot", "q₀ · q₁", number(label="q₀ · q₁, before any flip")),
               Step("omega", "Ω", number(label="Ω, the arc with cos Ω = |q₀ · q₁|", unit="°", angle="deg"))),
    ),
)
