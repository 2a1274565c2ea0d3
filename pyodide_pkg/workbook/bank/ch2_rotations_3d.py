"""Chapter 2 · 3D rotations."""

import math

from ..answer_kinds.matrix import MatrixDerive
from ..kinds.derive import Derive, Slip
from ..kinds.trace import Option, Trace
from ..reference.linalg import matvec
from ..reference.rotation3d import quat_from_axis_angle, quat_norm, rz
from . import column

_V = (2, 1, 3)
_Q90Z = quat_from_axis_angle((0, 0, 1), math.pi / 2)  # (w, x, y, z)

EXERCISES = (
    Derive(
        id="2.1",
        title="Yaw by 90°",
        key=matvec(rz(math.pi / 2), [1, 0, 0])[1],
        label="y-component of Rz(90°)·(1, 0, 0)ᵀ",
        slips=(
            Slip(matvec(rz(-math.pi / 2), [1, 0, 0])[1],
                 "That is a clockwise yaw. A positive angle about z turns x towards y (right-hand rule)."),
        ),
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
        key=quat_from_axis_angle((0, 0, 1), math.pi / 2)[0],
        either_sign="−q is the same rotation as q (by convention w ≥ 0 is written, but both are right).",
        label="w",
        slips=(
            Slip(math.cos(math.pi / 2),
                 "That is cos 90°, the full angle. A quaternion uses half the angle: w = cos(θ/2) = cos 45°."),
        ),
    ),
    Derive(
        id="2.4",
        title="Quaternion for 180° about x",
        key=quat_from_axis_angle((1, 0, 0), math.pi)[3],
        label="z",
        slips=(
            Slip(quat_from_axis_angle((1, 0, 0), math.pi)[1],
                 "That is the x component. The axis is (1, 0, 0), so sin(θ/2) lands in x only; z gets sin(θ/2)·0."),
        ),
    ),
    Derive(
        id="2.5",
        title="The norm of a quaternion",
        key=quat_norm((0.5, 0.5, 0.5, 0.5)),
        label="‖q‖",
        slips=(
            Slip(2.0, "That is the sum of the components. The norm squares them first: √(4 · 0.5²)."),
        ),
    ),
    MatrixDerive(
        id="2.6",
        title="Yaw a whole vector",
        key=column(matvec(rz(math.pi / 2), list(_V))),
        label="Rz(90°)·(2, 1, 3)ᵀ",
        slips=(
            Slip(column(matvec(rz(-math.pi / 2), list(_V))),
                 "That is Rz(−90°)·v, a clockwise yaw (the same as multiplying by the transpose of Rz(90°)). "
                 "A positive yaw turns x towards y."),
            Slip(column((_V[1], _V[0], _V[2])),
                 "You swapped x and y but lost a sign. A quarter turn about z sends (x, y) to (−y, x)."),
        ),
    ),
    MatrixDerive(
        id="2.7",
        title="The whole quaternion for 90° about z",
        key=column(_Q90Z),
        label="q = (w, x, y, z)ᵀ",
        either_sign="−q is the same rotation as q (by convention w ≥ 0 is written, but both are right).",
        slips=(
            Slip(column(quat_from_axis_angle((0, 0, 1), math.pi)),
                 "That is the quaternion of a 180° turn: you used the full angle. A quaternion holds half of it: "
                 "w = cos(θ/2), (x, y, z) = sin(θ/2)·n."),
            Slip(column(_Q90Z[1:] + _Q90Z[:1]),
                 "Those are the right numbers in the order (x, y, z, w), scalar last, as some libraries store "
                 "them. This answer asks for (w, x, y, z)."),
            Slip(column(quat_from_axis_angle((0, 0, 1), -math.pi / 2)),
                 "That is the conjugate, a turn of −90° (clockwise seen from above). For +90° about +z, "
                 "the z part is +sin 45°."),
        ),
    ),
)
