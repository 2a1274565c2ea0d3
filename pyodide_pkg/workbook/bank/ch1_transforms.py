"""Chapter 1 · Homogeneous transforms."""

import math

from .. import chains
from ..answer_kinds.base import Slip
from ..answer_kinds.matrix import matrix
from ..answer_kinds.number import number
from ..kinds.derive import Derive
from ..kinds.design import Design, Step
from ..kinds.trace import Option, Trace
from ..number_format import fmt, paren, relation_all, shown, signed
from ..reference.linalg import matvec, transpose
from ..reference.transform2d import apply, chain, transform2d
from ..steps import Step as WorkStep
from ..variants import Param, Vary
from . import column, grid
from .checks import apart, kept_slips, slips_apart


def _with(rot, t):
    """[[rot, t], [0, 1]] as a 3×3 key."""
    return grid([[*rot[0], t[0]], [*rot[1], t[1]], [0.0, 0.0, 1.0]])


def _terms(coefs, xs, const=None):
    r"""A dot product written out in TeX, as the derivations print it: ``0 \cdot 2 + 1 \cdot 1 - 1``,
    and its value computed from the numbers as printed.

    >>> _terms((-1, 0), (2, -2), 2)
    ('-1 \\cdot 2 + 0 \\cdot (-2) + 2', 0.0)
    """
    parts = [f"{fmt(c) if k == 0 else signed(c)} \\cdot {paren(x)}" for k, (c, x) in enumerate(zip(coefs, xs))]
    value = sum(shown(c) * shown(x) for c, x in zip(coefs, xs)) + (shown(const) if const is not None else 0.0)
    return " ".join(parts + ([signed(const)] if const is not None else [])), value


def _pure_translation(p):
    """1.1: a point (px, py) of a robot at (tx, ty) with heading 0; asked: its world x."""
    tx, ty, px, py = p["tx"], p["ty"], p["px"], p["py"]
    T = transform2d(tx, ty, 0)
    wx, wy = apply(T, px, py)
    ahead = f"The point is {fmt(px)} m ahead of it" if py == 0 and px > 0 else \
        f"The point sits at ({fmt(px)}, {fmt(py)}) in its frame"
    return {
        "key": wx,
        "slips": (
            Slip(apply(transform2d(0, 0, 0), px, py)[0],
                 f"That is the point in the robot frame. The robot sits at ({fmt(tx)}, {fmt(ty)}), so add its "
                 "position.", name="point-robot-frame-robot"),
            Slip(apply(T, 0, 0)[0], f"That is the robot's own x. {ahead}: add the point too.", name="robot-s-own-add"),
        ),
        "values": {"stx": signed(tx), "sty": signed(ty), "wx": fmt(wx), "wy": fmt(wy)},
    }


def _turn_and_shift(p):
    """1.2: the point d ahead of a robot at (tx, ty) facing 90°; asked: its world y."""
    tx, ty, d = p["tx"], p["ty"], p["d"]
    wx, wy = apply(transform2d(tx, ty, math.pi / 2), d, 0)
    turned = apply(transform2d(0, 0, math.pi / 2), d, 0)
    shifted = apply(transform2d(tx, ty, 0), d, 0)
    left_out: tuple[Slip, ...]
    if not apart(turned[1], shifted[1]):
        left_out = (Slip(turned[1], f"You left something out: turning ({fmt(d)}, 0) by 90° alone gives y = "
                                    f"{fmt(turned[1])}, "
                                    f"and shifting it by ({fmt(tx)}, {fmt(ty)}) without turning also gives "
                                    f"y = {fmt(shifted[1])}. T rotates first, then adds t.",
                                        name="left-something-out-turning"),)
    else:
        left_out = (Slip(turned[1], f"You left something out: turning ({fmt(d)}, 0) by 90° alone gives "
                                    f"y = {fmt(turned[1])}. T rotates first, then adds t = ({fmt(tx)}, {fmt(ty)}).",
                                        name="left-something-out-turning"),
                    Slip(shifted[1], f"You left something out: shifting ({fmt(d)}, 0) by ({fmt(tx)}, {fmt(ty)}) "
                                     f"without turning gives y = {fmt(shifted[1])}. T rotates first, then adds t.",
                                         name="left-something-out-shifting"))
    distance = "one metre" if d == 1 else f"{fmt(d)} metres"
    return {
        "key": wy,
        "slips": left_out + (
            Slip(apply(transform2d(tx, ty, -math.pi / 2), d, 0)[1],
                 "That is a clockwise turn. A heading of +90° turns the robot's x-axis onto the world's +y.",
                     name="clockwise-turn-heading-90"),
        ),
        "values": {"distance": distance, "Distance": distance[0].upper() + distance[1:], "stx": signed(tx),
                   "sty": signed(ty), "wx": fmt(wx), "wy": fmt(wy), "ty_turn": fmt(turned[1]), "sx": fmt(shifted[0])},
    }


def _tool_point(p):
    """1.3: a point d along a tool frame (at (ux, uy) in the base, turned 90°) of a base at (bx, by); asked: world x."""
    bx, by, ux, uy, d = p["bx"], p["by"], p["ux"], p["uy"], p["d"]
    T_world_base, T_base_tool = transform2d(bx, by, 0), transform2d(ux, uy, math.pi / 2)
    in_base = apply(T_base_tool, d, 0)
    wx, wy = apply(chain(T_world_base, T_base_tool), d, 0)
    verb = "lifts" if bx == 0 and by > 0 else "lowers" if bx == 0 else "shifts"
    return {
        "key": wx,
        "slips": (
            Slip(apply(chain(T_base_tool, T_world_base), d, 0)[0],
                 "The order is reversed. Apply the tool-to-base transform to the point first, then base-to-world.",
                     name="order-reversed-apply-tool"),
            Slip(apply(chain(T_world_base, transform2d(ux, uy, 0)), d, 0)[0],
                 f"You added the offsets but skipped the tool frame's 90° turn: ({fmt(d)}, 0) in the tool frame "
                 "points along the base's y-axis.", name="added-offsets-but-skipped"),
        ),
        "values": {"bpx": fmt(in_base[0]), "bpy": fmt(in_base[1]), "wx": fmt(wx), "wy": fmt(wy), "verb": verb},
    }


def _tool_point_ok(p):
    """The base is offset (else the chain is one transform), and the slips differ from the key and each other."""
    b_plus_u = p["bx"] + p["ux"]
    reversed_x, unturned_x = p["ux"] - p["by"], b_plus_u + p["d"]
    return ((p["bx"], p["by"]) != (0, 0) and apart(reversed_x, b_plus_u, unturned_x)
            and slips_apart(_tool_point(p)))


def _inverse_steps(R, t, given):
    """1.6's steps: Rᵀ, then −Rᵀt from the learner's own Rᵀ (each the learner's own when ``given``
    has it), and the slips made at each. Returns (Rᵀ, −Rᵀt) and the steps."""
    RT = [list(r) for r in chains.given(given, "RT", grid(transpose(R)))]
    back = [-v for v in matvec(RT, t)]
    tinv = [r[0] for r in chains.given(given, "tinv", column(back))]
    return (RT, tinv), {
        "RT": {"key": grid(transpose(R)), "slips": kept_slips(grid(transpose(R)), (
            (grid(R), "That is R itself. Undoing the turn takes the transpose Rᵀ: swap the two entries off the "
                      "diagonal, so the sine changes sign.", "r-itself-undoing-turn"),))},
        "tinv": {"key": column(back), "slips": kept_slips(column(back), (
            (column([-v for v in t]), "That is −t, the robot's position negated in world axes. T⁻¹ needs it in "
                                      "the robot's own axes: multiply by Rᵀ as well, −Rᵀt.", "t-robot-s-position"),
            (column(matvec(RT, t)), "That is Rᵀt, without the minus: the translation of T⁻¹ is −Rᵀt. Check with "
                                    f"the robot's own position: T⁻¹ must send ({fmt(t[0])}, {fmt(t[1])}) to the "
                                    "origin.", "rtt-without-minus-translation"),
            (column([-v for v in matvec(transpose(RT), t)]),
             "That multiplies t by R, the turn forwards (or takes the columns of Rᵀ for its rows). −Rᵀt takes "
             "each row of Rᵀ times t.", "multiplies-t-r-turn"),
        ))},
    }


def _inverse_pose(p, given=None):
    """1.6: T⁻¹ for a robot at (tx, ty) with heading θ, in steps: Rᵀ, then −Rᵀt (the learner's own
    when ``given`` has them)."""
    tx, ty, theta = p["tx"], p["ty"], p["theta"]
    T = transform2d(tx, ty, math.radians(theta))
    R = [row[:2] for row in T[:2]]
    RT = transpose(R)
    RT_t = matvec(RT, [tx, ty])
    (mine, tinv), worked = _inverse_steps(R, [tx, ty], given)
    key = _with(mine, tinv)
    wx, wy = apply(T, 1, 0)  # the point 1 m ahead of the robot, in the world
    (c, s_), (ns, _) = RT
    default = (tx, ty, theta) == (2, 1, 90)
    rt = [_terms(row, (tx, ty)) for row in RT]  # R^T t written out, and its value from the printed entries
    printed = _with(RT, [-v for v in RT_t])
    chk = [_terms(row[:2], (wx, wy), row[2]) for row in printed[:2]]  # T^-1 applied to the point ahead
    return {
        "key": key,
        "slips": (
            Slip(_with(RT, [-tx, -ty]),
                 "The rotation block is right, but the translation is −t, the robot's position negated in world "
                 "axes. T⁻¹ needs it in the robot's own axes: −Rᵀt.", name="rotation-block-right-but"),
            Slip(_with(RT, RT_t),
                 "The translation has the wrong sign: it is −Rᵀt. Check with the robot's own position: "
                 f"T⁻¹ must send ({fmt(tx)}, {fmt(ty)}) to the origin.", name="translation-has-wrong-sign"),
            Slip(_with(R, [-tx, -ty]),
                 "Negating the translation is not enough: the turn must be undone too, so the rotation block is "
                 "Rᵀ, and the translation becomes −Rᵀt.", name="negating-translation-enough-turn"),
            Slip(grid(T), "That is T itself, the robot's pose. The question asks for the transform that undoes it.",
                name="t-itself-robot-s"),
        ),
        "steps": worked,
        "values": {
            "whose": "Exercise 1.2's robot, with the workbook's numbers," if default else "A robot",
            "check_on": "exercise 1.2's answer with the workbook's numbers" if default
                        else "the point one metre straight ahead of the robot",
            **{f"t{i}{j}": fmt(T[i - 1][j - 1]) for i in (1, 2) for j in (1, 2)},
            "r11": fmt(c), "r12": fmt(s_), "r21": fmt(ns),
            "rt1_terms": rt[0][0], "rt2_terms": rt[1][0],
            "rt_rel": relation_all(RT_t, [v for _, v in rt]), "rt1": fmt(RT_t[0]), "rt2": fmt(RT_t[1]),
            "k13": fmt(printed[0][2]), "k23": fmt(printed[1][2]), "wx": fmt(wx), "wy": fmt(wy),
            "chk1": chk[0][0], "chk2": chk[1][0], "chk_rel": relation_all((1, 0), [v for _, v in chk]),
        },
    }


def _inverse_pose_ok(p):
    """Not a pure rotation or a half turn (where slips coincide with the key or each other), and no entry
    of −Rᵀt so near zero that the 4-decimal entries of T cannot give it within the tolerance."""
    if (p["tx"], p["ty"]) == (0, 0) or p["theta"] % 180 == 0:
        return False
    c, s = math.cos(math.radians(p["theta"])), math.sin(math.radians(p["theta"]))
    return all(abs(v) < 1e-9 or abs(v) >= 0.5 for v in (c * p["tx"] + s * p["ty"], -s * p["tx"] + c * p["ty"]))


EXERCISES = (
    Derive(
        id="1.1",
        title="Pure translation",
        spec=number(label="x-coordinate in the world frame"),
        vary=Vary(_pure_translation, Param("tx", 3, -9.9, 9.9, 0.1, avoid=(0,)), Param("ty", 4, -9.9, 9.9, 0.1),
                  Param("px", 1, -9.9, 9.9, 0.1, avoid=(0,)), Param("py", 0, -9.9, 9.9, 0.1),
                  valid=lambda p: p["px"] != p["tx"] and slips_apart(_pure_translation(p))),
    ),
    Derive(
        id="1.2",
        title="Rotation plus translation",
        spec=number(label="y-coordinate in the world frame"),
        vary=Vary(_turn_and_shift, Param("tx", 2, -9.9, 9.9, 0.1), Param("ty", 1, -9.9, 9.9, 0.1, avoid=(0,)),
                  Param("d", 1, 0.5, 3, 0.5, unit=" m"),
                  valid=lambda p: not math.isclose(p["ty"], 2 * p["d"]) and slips_apart(_turn_and_shift(p))),
    ),
    Derive(
        id="1.3",
        title="Chain two transforms",
        spec=number(label="x-coordinate in the world frame"),
        vary=Vary(_tool_point, Param("bx", 0, -9.9, 9.9, 0.1), Param("by", 1, -5, 5, 0.1),
                  Param("ux", 2, -9.9, 9.9, 0.1), Param("uy", 0, -5, 5, 0.1), Param("d", 1, 1, 3, 1),
                  valid=_tool_point_ok),
    ),
    Trace(
        id="1.4",
        title="Invert a transform",
        answer="c",
        options=(
            Option("a", "Multiply the world point by $T^\\top$",
                   "The transpose undoes a pure rotation only. $T^\\top$ moves the translation into the bottom row, "
                   "so it is not even a valid transform."),
            Option("b", "Subtract the robot's position $t$ from the point",
                   "That undoes the shift but not the turn: the difference is still expressed along the world "
                   "axes, not the robot's."),
            Option("c", "Multiply by $T^{-1} = \\begin{bmatrix} R^\\top & -R^\\top t \\\\ 0 & 1 \\end{bmatrix}$",
                   "Right. Undo the shift, then the turn: $R^\\top(p - t) = R^\\top p - R^\\top t$. It costs a "
                   "transpose and one matrix–vector product, no general inversion."),
            Option("d", "Multiply by $T$ a second time",
                   "That moves the point one more robot pose further away from the robot frame, rather than back."),
        ),
    ),
    Design(
        id="1.5",
        title="A LiDAR-to-world pipeline",
        steps=(
            Step("lidar", "The pedestrian in the LiDAR frame, ${}^{\\text{lidar}}p$"),
            Step("car", "Apply ${}^{\\text{car}}T_{\\text{lidar}}$ (LiDAR to car)"),
            Step("world", "Apply ${}^{\\text{world}}T_{\\text{car}}$ (car to world)"),
            Step("out", "The pedestrian in the world (GPS) frame, ${}^{\\text{world}}p$"),
        ),
        shown=("world", "out", "lidar", "car"),
    ),
    Derive(
        id="1.6",
        title="The inverse transform, whole",
        spec=matrix(label="T⁻¹"),
        vary=Vary(_inverse_pose, Param("tx", 2, -5, 5, 1), Param("ty", 1, -5, 5, 1),
                  Param("theta", 90, -175, 180, 5, unit="°"), valid=_inverse_pose_ok),
        steps=(WorkStep("RT", "Rᵀ", matrix(label="Rᵀ, the rotation block of T⁻¹")),
               WorkStep("tinv", "−Rᵀt", matrix(label="−Rᵀt, the translation of T⁻¹", names=("x", "y")))),
    ),
)
