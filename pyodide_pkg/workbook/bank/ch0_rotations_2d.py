"""Chapter 0 · 2D rotation matrices."""

import math

from ..answer_kinds.base import Slip
from ..answer_kinds.matrix import matrix
from ..answer_kinds.number import number
from ..kinds.build import Build
from ..kinds.derive import Derive
from ..kinds.trace import Option, Trace
from ..number_format import fmt, paren, relation, shown
from ..reference.linalg import add
from ..reference.rotation2d import compose, det_rot2, rot2, rotate_2d
from ..variants import Choice, Param, Vary
from . import grid

TURNS = {90: ("quarter turn", "y", "-x"), 180: ("half turn", "-x", "-y"), 270: ("three-quarter turn", "-y", "x")}


def _quarter_turn(p):
    """0.1: the point (x, y) turned by +90°; asked: its y-coordinate."""
    x, y = p["x"], p["y"]
    xr, yr = rotate_2d(x, y, math.pi / 2)
    return {
        "key": yr,
        "slips": (Slip(rotate_2d(x, y, -math.pi / 2)[1],
                       "That is a clockwise turn. R(θ) with θ > 0 turns counter-clockwise.",
                           name="clockwise-turn-r-theta"),),
        "values": {"px": paren(x), "py": paren(y), "xr": fmt(xr), "yr": fmt(yr)},
    }


def _composed_entry(p):
    """0.2: the (1,1) entry of R(α)·R(β), which is cos(α + β)."""
    a, b = p["a"], p["b"]
    key = compose(math.radians(a), math.radians(b))[0][0]
    return {
        "key": key,
        "label": f"(1,1) entry of R({fmt(a)}°)·R({fmt(b)}°)",
        "slips": (
            Slip(rot2(math.radians(a))[0][0] * rot2(math.radians(b))[0][0],
                 "You multiplied the two (1,1) entries. A matrix product mixes a row with a column: use R(α)R(β) = "
                 "R(α+β).", name="multiplied-two-1-1"),
            Slip(det_rot2(math.radians(a + b)),
                 "That is the determinant, not the (1,1) entry. The (1,1) entry is cos of the total angle.",
                     name="determinant-1-1-entry"),
        ),
        "values": {"total": fmt(a + b), "c": fmt(key)},
    }


def _diagonal_point(p):
    """0.4: the point (a, a) turned by 45°; asked: its x- or y-coordinate."""
    a, axis = p["a"], p["axis"]
    xr, yr = rotate_2d(a, a, math.pi / 4)
    other = "y" if axis == "x" else "x"
    rules = {"x": "cosθ·x − sinθ·y", "y": "sinθ·x + cosθ·y"}
    tex = {"x": r"\cos\theta\,x - \sin\theta\,y", "y": r"\sin\theta\,x + \cos\theta\,y"}
    r = r"\sqrt2" if a == 1 else rf"{fmt(a)}\sqrt2"
    key, slip = (xr, yr) if axis == "x" else (yr, xr)
    c = shown(math.cos(math.pi / 4))  # the statement's 0.7071, which the derivation multiplies
    return {
        "key": key,
        "title": f"Rotate ({fmt(a)}, {fmt(a)}) by 45°",
        "label": f"{axis}-coordinate of the rotated point",
        "slips": (Slip(slip, f"That is the {other}-coordinate. The {axis}-coordinate is {rules[axis]}.",
            name="coordinate-coordinate"),),
        "values": {"rule": tex[axis], "c": fmt(c), "xr": fmt(xr), "xrel": relation(xr, c * a - c * a), "yr": fmt(yr),
                   "yrel": relation(yr, c * a + c * a), "r": r},
    }


def _rotation_det(p):
    """0.6: det R(θ), which is 1 for every θ."""
    theta = p["theta"]
    return {
        "key": det_rot2(math.radians(theta)),
        "label": f"det R({fmt(theta)}°)",
        "slips": (Slip(-1.0, "A determinant of −1 would be a reflection. Expand cos²θ + sin²θ.",
            name="determinant-1-would-reflection"),),
    }


def _any_turn(total):
    """The words for a turn by ``total``° that is no multiple of 90°: where it sends x and y (TeX)."""
    c, s = math.cos(math.radians(total)), math.sin(math.radians(total))
    return (f"rotation by {fmt(total)}°", rf"{fmt(c)}\,x {'-' if s < 0 else '+'} {fmt(abs(s))}\,y",
            rf"{fmt(-s)}\,x {'-' if c < 0 else '+'} {fmt(abs(c))}\,y")


def _whole_product(p):
    """0.7: the whole matrix R(α)·R(β) = R(α + β) (the workbook's own α + β is a quarter turn)."""
    a, b = p["a"], p["b"]
    total = a + b
    ra, rb = rot2(math.radians(a)), rot2(math.radians(b))
    key = grid(compose(math.radians(a), math.radians(b)))
    turn, x_to, y_to = TURNS.get(total) or _any_turn(total)
    return {
        "key": key,
        "title": f"The whole product R({fmt(a)}°)·R({fmt(b)}°)",
        "label": f"R({fmt(a)}°)·R({fmt(b)}°)",
        "rotation_angle": math.radians(total),
        "slips": (
            Slip(grid([[u * v for u, v in zip(rowa, rowb)] for rowa, rowb in zip(ra, rb)]),
                 "You multiplied entry by entry. A matrix product takes row i of the left matrix against "
                 f"column j of the right one: (1,1) is cos{fmt(a)}°·cos{fmt(b)}° − "
                 f"sin{fmt(a)}°·sin{fmt(b)}°.", name="multiplied-entry-entry-matrix"),
            Slip(grid(add(ra, rb)),
                 f"That is the sum R({fmt(a)}°) + R({fmt(b)}°). Composing rotations multiplies the matrices; "
                 "the angles add, not the matrices.", name="sum-r-r-composing"),
        ),
        "values": {"total": fmt(total), "turn": turn, "x_to": x_to, "y_to": y_to},
    }


EXERCISES = (
    Derive(
        id="0.1",
        title="Rotate a point by 90°",
        spec=number(label="y-coordinate of the rotated point"),
        vary=Vary(_quarter_turn, Param("x", 3, -9.9, 9.9, 0.1, avoid=(0,)), Param("y", 0, -9.9, 9.9, 0.1)),
    ),
    Derive(
        id="0.2",
        title="Compose two rotations",
        spec=number(),
        vary=Vary(_composed_entry, Param("a", 30, 0.5, 179.5, 0.5, unit="°"),
                  Param("b", 60, 0.5, 179.5, 0.5, unit="°")),
    ),
    Trace(
        id="0.3",
        title="Undo a rotation",
        answer="b",
        options=(
            Option("a", "Compute the general inverse $R^{-1}$ by Gaussian elimination",
                   "It gives the right matrix, but it does needless work: for a rotation the inverse is already known, "
                   "it is the transpose."),
            Option("b", "Multiply by the transpose, $R(45°)^\\top = R(-45°)$",
                   "Right. A rotation matrix is orthogonal, so $R^{-1} = R^\\top$, which is the rotation by the "
                   "opposite angle. This holds in every dimension."),
            Option("c", "Rotate by $R(45°)$ a second time",
                   "That turns the point a further 45°, to 90° in all. Undoing a turn means turning the other way."),
            Option("d", "Negate the point's coordinates",
                   "Negating both coordinates is a rotation by 180°, not the undoing of a 45° turn."),
        ),
    ),
    Derive(
        id="0.4",
        title="Rotate (1, 1) by 45°",
        spec=number(),
        # x' of (a, a) is 0 for every a: the variants ask y' = a√2, which tells students apart
        vary=Vary(_diagonal_point, Param("a", 1, 0.05, 9.95, 0.05), Choice("axis", "x", ("y",))),
    ),
    Build(
        id="0.5",
        title="Implement rotate_2d",
        function="rotate_2d",
        params=("x", "y", "theta"),
        starter=(
            "import math\n\n\n"
            "def rotate_2d(x, y, theta):\n"
            '    """Rotate (x, y) counter-clockwise by theta radians; return (x\', y\')."""\n'
            "    # Your code here: apply R(theta) to the point.\n"
            "    return (x, y)\n"
        ),
        solution=(
            "import math\n\n\n"
            "def rotate_2d(x, y, theta):\n"
            '    """Rotate (x, y) counter-clockwise by theta radians; return (x\', y\')."""\n'
            "    c, s = math.cos(theta), math.sin(theta)\n"
            "    return (c * x - s * y, s * x + c * y)\n"
        ),
        reference=rotate_2d,
        run_figure="rotate",
        examples=((3, 0, math.pi / 2), (1, 1, math.pi / 4), (2, -1, 0.0), (1, 0, math.pi)),
        random_args=lambda rng: (rng.uniform(-5, 5), rng.uniform(-5, 5), rng.uniform(-math.pi, math.pi)),
    ),
    Derive(
        id="0.6",
        title="The determinant of a rotation",
        same_answer="det R(θ) is 1 for every angle θ: that is the point of the exercise.",
        spec=number(),
        vary=Vary(_rotation_det, Param("theta", 37, 5, 355, 5, unit="°", avoid=(90, 180, 270))),
    ),
    Derive(
        id="0.7",
        title="The whole product R(30°)·R(60°)",
        spec=matrix(),
        vary=Vary(_whole_product, Param("a", 30, 1, 179, 1, unit="°"), Param("b", 60, 1, 179, 1, unit="°")),
    ),
)
