"""Chapter 0 · 2D rotation matrices."""

import math

from ..answer_kinds.matrix import MatrixDerive
from ..kinds.build import Build
from ..kinds.derive import Derive, Slip
from ..kinds.trace import Option, Trace
from ..reference.linalg import add
from ..reference.rotation2d import compose, det_rot2, rot2, rotate_2d
from ..variants import Param, Vary, num, paren
from . import grid

_R30, _R60 = rot2(math.radians(30)), rot2(math.radians(60))


def _quarter_turn(p):
    """0.1: the point (x, y) turned by +90°; asked: its y-coordinate."""
    x, y = p["x"], p["y"]
    xr, yr = rotate_2d(x, y, math.pi / 2)
    return {
        "key": yr,
        "slips": (Slip(rotate_2d(x, y, -math.pi / 2)[1],
                       "That is a clockwise turn. R(θ) with θ > 0 turns counter-clockwise."),),
        "values": {"px": paren(x), "py": paren(y), "xr": num(xr), "yr": num(yr)},
    }

EXERCISES = (
    Derive(
        id="0.1",
        title="Rotate a point by 90°",
        label="y-coordinate of the rotated point",
        vary=Vary(_quarter_turn, Param("x", 3, -5, 5, 1, avoid=(0,)), Param("y", 0, -5, 5, 1)),
    ),
    Derive(
        id="0.2",
        title="Compose two rotations",
        key=compose(math.radians(30), math.radians(60))[0][0],
        label="(1,1) entry of R(30°)·R(60°)",
        slips=(
            Slip(math.cos(math.radians(30)) * math.cos(math.radians(60)),
                 "You multiplied the two (1,1) entries. A matrix product mixes a row with a column: use R(α)R(β) = R(α+β)."),
            Slip(1.0, "That is the determinant, not the (1,1) entry. The (1,1) entry is cos of the total angle."),
        ),
    ),
    Trace(
        id="0.3",
        title="Undo a rotation",
        answer="b",
        options=(
            Option("a", "Compute the general inverse $R^{-1}$ by Gaussian elimination",
                   "It gives the right matrix, but it does needless work: for a rotation the inverse is already known, it is the transpose."),
            Option("b", "Multiply by the transpose, $R(45°)^\\top = R(-45°)$",
                   "Right. A rotation matrix is orthogonal, so $R^{-1} = R^\\top$, which is the rotation by the opposite angle. This holds in every dimension."),
            Option("c", "Rotate by $R(45°)$ a second time",
                   "That turns the point a further 45°, to 90° in all. Undoing a turn means turning the other way."),
            Option("d", "Negate the point's coordinates",
                   "Negating both coordinates is a rotation by 180°, not the undoing of a 45° turn."),
        ),
    ),
    Derive(
        id="0.4",
        title="Rotate (1, 1) by 45°",
        key=rotate_2d(1, 1, math.pi / 4)[0],
        label="x-coordinate of the rotated point",
        slips=(Slip(rotate_2d(1, 1, math.pi / 4)[1], "That is the y-coordinate. The x-coordinate is cosθ·x − sinθ·y."),),
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
        examples=((3, 0, math.pi / 2), (1, 1, math.pi / 4), (2, -1, 0.0), (1, 0, math.pi)),
        random_args=lambda rng: (rng.uniform(-5, 5), rng.uniform(-5, 5), rng.uniform(-math.pi, math.pi)),
    ),
    Derive(
        id="0.6",
        title="The determinant of a rotation",
        key=det_rot2(math.radians(37)),
        label="det R(37°)",
        slips=(Slip(-1.0, "A determinant of −1 would be a reflection. Expand cos²θ + sin²θ."),),
    ),
    MatrixDerive(
        id="0.7",
        title="The whole product R(30°)·R(60°)",
        key=grid(compose(math.radians(30), math.radians(60))),
        label="R(30°)·R(60°)",
        rotation_angle=math.radians(90),
        slips=(
            Slip(grid([[a * b for a, b in zip(ra, rb)] for ra, rb in zip(_R30, _R60)]),
                 "You multiplied entry by entry. A matrix product takes row i of the left matrix against "
                 "column j of the right one: (1,1) is cos30°·cos60° − sin30°·sin60°."),
            Slip(grid(add(_R30, _R60)),
                 "That is the sum R(30°) + R(60°). Composing rotations multiplies the matrices; the angles add, "
                 "not the matrices."),
        ),
    ),
)
