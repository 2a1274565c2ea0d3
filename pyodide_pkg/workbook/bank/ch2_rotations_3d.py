"""Chapter 2 · 3D rotations."""

import math

from ..answer_kinds.base import Slip
from ..answer_kinds.matrix import matrix
from ..answer_kinds.number import number
from ..kinds.derive import Derive
from ..kinds.trace import Option, Trace
from ..number_format import fmt, paren, relation, relation_all, shown
from ..reference.linalg import matvec
from ..reference.rotation3d import quat_axis_angle, quat_from_axis_angle, quat_multiply, quat_norm, rz
from ..variants import Choice, Param, Vary
from . import column
from .checks import slips_apart

_AXES = {"x": (1, 0, 0), "y": (0, 1, 0), "z": (0, 0, 1)}
_SLOT = {"w": 0, "x": 1, "y": 2, "z": 3}  # where each component sits in q = (w, x, y, z)
_QUARTER = math.sqrt(2) / 2


def _axis_text(axis):
    """The unit axis as the text writes it: ``"0, 0, 1"`` for z."""
    return ", ".join(map(str, _AXES[axis]))


def _or_exact(x, value, tex):
    """``tex``, the text's exact form of ``value`` (√2/2, ½), where x is that value; else x as printed."""
    return tex if math.isclose(x, value) else fmt(x)


def _norm_check(q):
    """The squares of q's components as printed, and = or ≈ before the 1 their root is said to be."""
    squares = [c * c for c in q]
    return squares, relation(1.0, math.sqrt(sum(map(shown, squares))))


def _yaw_x_axis(p):
    """2.1: the x unit vector yawed by γ (0° < γ < 180°); asked: its y-component."""
    g = p["gamma"]
    c, s, _ = matvec(rz(math.radians(g)), [1, 0, 0])
    word = "onto" if g == 90 else "towards" if g < 90 else "past"  # where x ends up, seen from y
    return {
        "key": s,
        "title": f"Yaw by {fmt(g)}°",
        "label": f"y-component of Rz({fmt(g)}°)·(1, 0, 0)ᵀ",
        "slips": (Slip(matvec(rz(-math.radians(g)), [1, 0, 0])[1],
                       "That is a clockwise yaw. A positive angle about z turns x towards y (right-hand rule).",
                           name="clockwise-yaw-positive-angle"),),
        "values": {"c": fmt(c), "s": fmt(s), "ms": fmt(-s), "onto": word, "into": "into" if g == 90 else word},
    }


def _quat_w(p):
    """2.3: the unit quaternion of θ about a coordinate axis; asked: its scalar part w."""
    t, axis = p["theta"], p["axis"]
    q = quat_from_axis_angle(_AXES[axis], math.radians(t))
    squares, norm_rel = _norm_check(q)
    return {
        "key": q[0],
        "title": f"Quaternion for {fmt(t)}° about {axis}",
        "slips": (Slip(math.cos(math.radians(t)),
                       f"That is cos {fmt(t)}°, the full angle. A quaternion uses half the angle: "
                       f"w = cos(θ/2) = cos {fmt(t / 2)}°.", name="cos-full-angle-quaternion"),),
        "values": {
            "half": fmt(t / 2), "n": _axis_text(axis),
            "w_surd": "\\tfrac{\\sqrt2}{2} \\approx " if math.isclose(q[0], _QUARTER) else "",
            "w": fmt(q[0]), "v": ", ".join(map(fmt, q[1:])), "q": ",\\ ".join(map(fmt, q)),
            "squares": " + ".join(map(fmt, squares)), "norm_rel": norm_rel,
        },
    }


def _quat_w_ok(p):
    """The full-angle slip cos θ is told apart from w and from −w (which is right too)."""
    made = _quat_w(p)
    return slips_apart(made) and slips_apart({**made, "key": -made["key"]})


def _half_turn_component(p):
    """2.4: the unit quaternion of 180° about one axis; asked: a component off that axis (always 0)."""
    axis, comp = p["axis"], p["comp"]
    q = quat_from_axis_angle(_AXES[axis], math.pi)
    n = _axis_text(axis)
    return {
        "key": q[_SLOT[comp]],
        "title": f"Quaternion for 180° about {axis}",
        "label": comp,
        "slips": (Slip(q[_SLOT[axis]],
                       f"That is the {axis} component. The axis is ({n}), so sin(θ/2) lands in {axis} only; "
                       f"{comp} gets sin(θ/2)·0.", name="component-axis-so-sin"),),
        "values": {"n": n},
    }


def _quat_norm(p):
    """2.5: ‖q‖ of q = (±0.5, ±0.5, ±0.5, ±0.5), always a unit quaternion; and its angle and axis."""
    q = (p["w"], p["x"], p["y"], p["z"])
    axis, angle = quat_axis_angle(q)
    theta = math.degrees(angle)
    return {
        "key": quat_norm(q),
        "slips": (Slip(sum(q), "That is the sum of the components. The norm squares them first: √(4 · 0.5²).",
            name="sum-components-norm-squares"),),
        "values": {
            "pw": paren(q[0]), "px": paren(q[1]), "py": paren(q[2]), "pz": paren(q[3]),
            "half": fmt(theta / 2), "theta": fmt(theta),
            "axis_rel": relation_all(axis), "axis": ", ".join(map(fmt, axis)),
            "signs": ", ".join(fmt(2 * c) for c in q[1:]),
        },
    }


def _yaw_vector(p):
    """2.6: v = (x, y, z) yawed by 90°; asked: the whole rotated vector."""
    v = [p["x"], p["y"], p["z"]]
    turned = matvec(rz(math.pi / 2), v)
    return {
        "key": column(turned),
        "label": "Rz(90°)·({}, {}, {})ᵀ".format(*map(fmt, v)),
        "slips": (
            Slip(column(matvec(rz(-math.pi / 2), v)),
                 "That is Rz(−90°)·v, a clockwise yaw (the same as multiplying by the transpose of Rz(90°)). "
                 "A positive yaw turns x towards y.", name="rz-90-v-clockwise"),
            Slip(column((v[1], v[0], v[2])),
                 "You swapped x and y but lost a sign. A quarter turn about z sends (x, y) to (−y, x).",
                     name="swapped-y-but-lost"),
        ),
        "values": {"px": paren(v[0]), "py": paren(v[1]), "x2": fmt(v[0] ** 2), "y2": fmt(v[1] ** 2),
                   "z2": fmt(v[2] ** 2)},
    }


def _quat_whole(p):
    """2.7: the whole unit quaternion (w, x, y, z) of θ about a coordinate axis."""
    t, axis = p["theta"], p["axis"]
    n, rad = _AXES[axis], math.radians(t)
    q = quat_from_axis_angle(n, rad)
    squares, norm_rel = _norm_check(q)
    view = "seen from above" if axis == "z" else f"seen from the +{axis} side"
    return {
        "key": column(q),
        "title": f"The whole quaternion for {fmt(t)}° about {axis}",
        "slips": (
            Slip(column(quat_from_axis_angle(n, 2 * rad)),
                 f"That is the quaternion of a {fmt(2 * t)}° turn: you used the full angle. A quaternion holds "
                 "half of it: w = cos(θ/2), (x, y, z) = sin(θ/2)·n.", name="quaternion-turn-used-full"),
            Slip(column(q[1:] + q[:1]),
                 "Those are the right numbers in the order (x, y, z, w), scalar last, as some libraries store "
                 "them. This answer asks for (w, x, y, z).", name="those-right-numbers-order"),
            Slip(column(quat_from_axis_angle(n, -rad)),
                 f"That is the conjugate, a turn of −{fmt(t)}° (clockwise {view}). For +{fmt(t)}° about +{axis}, "
                 f"the {axis} part is +sin {fmt(t / 2)}°.", name="conjugate-turn-clockwise-about"),
        ),
        "values": {
            "half": fmt(t / 2), "a": "an" if axis == "x" else "a",  # "an x part", "a z part"
            "n": _axis_text(axis), "nx": str(n[0]), "ny": str(n[1]), "nz": str(n[2]),
            **{f"e{c}": _or_exact(q[_SLOT[c]], _QUARTER, "\\sqrt2/2") for c in "wxyz"},
            "w2": _or_exact(squares[0], 0.5, "\\tfrac12"), "v2": _or_exact(sum(squares[1:]), 0.5, "\\tfrac12"),
            "norm_rel": norm_rel, "back": fmt(360 - t),
        },
    }


def _cross(u, v):
    """u × v, written out as the chapter's prose writes it."""
    return (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])


def _quat_product(p):
    """2.10: the Hamilton product q₁ ⊗ q₂ of two quaternions with small whole components, w first."""
    q1 = (p["w1"], p["x1"], p["y1"], p["z1"])
    q2 = (p["w2"], p["x2"], p["y2"], p["z2"])
    key = quat_multiply(q1, q2)
    u1, u2 = q1[1:], q2[1:]
    dot = sum(a * b for a, b in zip(u1, u2))
    cross = _cross(u1, u2)
    plain = tuple(q1[0] * b + q2[0] * a for a, b in zip(u1, u2))  # w₁u₂ + w₂u₁, the cross term left out
    swapped = quat_multiply(q2, q1)
    pairs = ((1, 2), (2, 0), (0, 1))  # the two factors of each cross component's first term
    return {
        "key": column(key),
        "slips": (
            Slip(column(swapped),
                 "That is q₂ ⊗ q₁: the cross term u₁ × u₂ went in with a minus sign, which is exactly what "
                 "swapping the two factors does. The product does not commute: q₁ ⊗ q₂ adds +u₁ × u₂.",
                     name="q2-q1-cross-term"),
            Slip(column((q1[0] * q2[0] + dot, *key[1:])),
                 f"The scalar part subtracts the dot product: w = w₁w₂ − u₁·u₂ = {fmt(q1[0] * q2[0])} − "
                 f"{paren(dot)}, not w₁w₂ + u₁·u₂.", name="scalar-part-subtracts-dot"),
            Slip(column((key[0], *plain)),
                 "The vector part is missing the cross product: it is w₁u₂ + w₂u₁ + u₁ × u₂. The cross term is "
                 f"({', '.join(map(fmt, cross))}) here.", name="vector-part-missing-cross"),
            Slip(column(tuple(a * b for a, b in zip(q1, q2))),
                 "That multiplies component by component. The Hamilton product mixes them: the scalar part "
                 "takes a dot product and the vector part a cross product.",
                     name="multiplies-component-component-hamilton"),
            Slip(column(key[1:] + key[:1]),
                 "Those are the right numbers in the order (x, y, z, w), scalar last, as some libraries store "
                 "them. This answer asks for (w, x, y, z), scalar first.", name="those-right-numbers-order"),
        ),
        "values": {
            "w1": fmt(q1[0]), "w2": fmt(q2[0]), "u1": ", ".join(map(fmt, u1)), "u2": ", ".join(map(fmt, u2)),
            "dot_terms": " + ".join(f"{paren(a)} \\cdot {paren(b)}" for a, b in zip(u1, u2)),
            "dot": fmt(dot), "pdot": paren(dot), "ww": fmt(q1[0] * q2[0]),
            # one component per line: the three on one line are wider than a phone
            "cross_terms": ", \\\\ &\\qquad ".join(
                f"{paren(u1[i])} \\cdot {paren(u2[j])} - {paren(u1[j])} \\cdot {paren(u2[i])}" for i, j in pairs),
            "cross": ", ".join(map(fmt, cross)),
            "a": ", ".join(fmt(q1[0] * b) for b in u2), "b": ", ".join(fmt(q2[0] * a) for a in u1),
            "w": fmt(key[0]), "v": ", ".join(map(fmt, key[1:])),
            "swapped": ", ".join(map(fmt, swapped)),
        },
    }


def _fair_product(p):
    """2.10's draw is a fair question: the cross term is not zero (so the order matters), the dot
    product is not zero (so its sign does), and the key and every slip are told apart."""
    u1, u2 = (p["x1"], p["y1"], p["z1"]), (p["x2"], p["y2"], p["z2"])
    return any(_cross(u1, u2)) and sum(a * b for a, b in zip(u1, u2)) != 0 and slips_apart(_quat_product(p))


EXERCISES = (
    Derive(
        id="2.1",
        title="Yaw by 90°",
        spec=number(),
        vary=Vary(_yaw_x_axis, Param("gamma", 90, 0.5, 179.5, 0.5, unit="°")),
    ),
    Trace(
        id="2.2",
        title="Where gimbal lock strikes",
        answer="d",
        options=(
            Option("a", "$\\beta = 0°$",
                   "At zero pitch the matrix is $R_z(\\gamma)R_x(\\alpha)$: two different axes, so yaw and roll "
                   "still act independently. This is the best-behaved pitch, not the worst."),
            Option("b", "$\\beta = 45°$",
                   "Nothing special happens at 45°: $\\cos\\beta \\neq 0$, and every rotation near this one "
                   "still has its own yaw, pitch and roll."),
            Option("c", "$\\beta = 180°$",
                   "At 180° the cosine is −1, not 0; the yaw and roll axes stay apart (they only flip sign), so "
                   "no freedom is lost."),
            Option("d", "$\\beta = \\pm 90°$",
                   "Right. Then $\\cos\\beta = 0$, the roll axis is turned onto the yaw axis, and the matrix "
                   "depends on a single combination of yaw and roll ($\\gamma - \\alpha$ at $+90°$, "
                   "$\\gamma + \\alpha$ at $-90°$). One degree of freedom is gone."),
        ),
    ),
    Derive(
        id="2.3",
        title="Quaternion for 90° about z",
        spec=number(
            either_sign="−q is the same rotation as q (by convention w ≥ 0 is written, but both are right).",
            label="w",
        ),
        vary=Vary(_quat_w, Param("theta", 90, 10, 179, 1, unit="°", avoid=(120,)),
                  Choice("axis", "z", ("x", "y", "z")), valid=_quat_w_ok),
    ),
    Derive(
        id="2.4",
        title="Quaternion for 180° about x",
        same_answer="The component off the axis of a half turn is 0 for every axis and component asked.",
        spec=number(label="z"),
        vary=Vary(_half_turn_component, Choice("axis", "x", ("x", "y", "z")), Choice("comp", "z", ("x", "y", "z")),
                  valid=lambda p: p["comp"] != p["axis"]),
    ),
    Derive(
        id="2.5",
        title="The norm of a quaternion",
        same_answer="Every quaternion it draws, with components ±0.5, has norm 1: that is the point of the exercise.",
        spec=number(label="‖q‖"),
        vary=Vary(_quat_norm, *(Param(c, 0.5, -0.5, 0.5, 1) for c in "wxyz"),
                  valid=lambda p: not math.isclose(sum(p.values()), 1.0)),
    ),
    Derive(
        id="2.6",
        title="Yaw a whole vector",
        spec=matrix(names=("x", "y", "z")),
        vary=Vary(_yaw_vector, *(Param(c, d, -5, 5, 1, avoid=(0,)) for c, d in zip("xyz", (2, 1, 3)))),
    ),
    Derive(
        id="2.7",
        title="The whole quaternion for 90° about z",
        spec=matrix(
            label="q = (w, x, y, z)ᵀ",
            names=("w", "x", "y", "z"),
            either_sign="−q is the same rotation as q (by convention w ≥ 0 is written, but both are right).",
        ),
        vary=Vary(_quat_whole, Param("theta", 90, 1, 179, 1, unit="°"), Choice("axis", "z", ("x", "y", "z"))),
    ),
    Derive(
        id="2.10",
        title="Multiply two quaternions",
        spec=matrix(label="q₁ ⊗ q₂ = (w, x, y, z)ᵀ", names=("w", "x", "y", "z")),
        vary=Vary(_quat_product,
                  Param("w1", 1, 1, 3, 1), Param("x1", 2, -2, 2, 1),
                  Param("y1", 0, -2, 2, 1), Param("z1", -1, -2, 2, 1),
                  Param("w2", 2, 1, 3, 1), Param("x2", -1, -2, 2, 1),
                  Param("y2", 1, -2, 2, 1), Param("z2", 0, -2, 2, 1),
                  valid=_fair_product),
    ),
)
