"""Chapter 10's bug hunts: a camera mount used the wrong way round (T_cam_base where T_base_cam is
needed), and a ROS orientation, stored scalar last, unpacked scalar first."""

from __future__ import annotations

import math

from ..kinds.debug import Debug
from ..number_format import fmt
from ..reference.rotation3d import ry
from ..reference.se3 import compose, from_xyzw, invert, pose, quat_to_matrix, transform_point

_MOUNT = """\
def detection_in_world(T_world_base, T_cam_base, p_cam):
    def mul(A, B):
        return [[sum(A[i][k] * B[k][j] for k in range(4)) for j in range(4)] for i in range(4)]
    def invert(T):
        Rt = [[T[j][i] for j in range(3)] for i in range(3)]
        t = [-sum(Rt[i][k] * T[k][3] for k in range(3)) for i in range(3)]
        return [Rt[i] + [t[i]] for i in range(3)] + [[0.0, 0.0, 0.0, 1.0]]
    T_base_cam = invert(T_cam_base)
    T_world_cam = mul(T_world_base, T_cam_base)
    p = list(p_cam) + [1.0]
    return [sum(T_world_cam[i][k] * p[k] for k in range(4)) for i in range(3)]
"""


def _in_world(T_world_base, T_cam_base, p_cam):
    return transform_point(compose(T_world_base, invert(T_cam_base)), p_cam)


def mount_facts() -> dict:
    """The first case: a robot at (2, 1, 0) facing 90°, a camera 0.3 m ahead of the base and 0.5 m up,
    pitched 30° down; a detection on the floor, 1 m straight ahead of the camera. Where it is, and where
    the bug puts it."""
    T_world_base, T_cam_base, p_cam = _MOUNT_CASES[0]
    right = _in_world(T_world_base, T_cam_base, p_cam)
    wrong = transform_point(compose(T_world_base, T_cam_base), p_cam)
    return {"right": right, "wrong": wrong, "off": math.dist(right, wrong)}


def _mount(pitch_deg, ahead, up):
    """T_cam_base from calibration: the base seen from a camera mounted ``ahead`` and ``up`` on it and
    pitched ``pitch_deg`` down about the base's y-axis."""
    return [list(r) for r in invert(pose(ry(math.radians(pitch_deg)), (ahead, 0.0, up)))]


_YAW90 = [[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]]
_MOUNT_CASES = (
    ([list(r) for r in pose(_YAW90, (2.0, 1.0, 0.0))], _mount(30, 0.3, 0.5), (1.0, 0.0, 0.0)),
    ([list(r) for r in pose(quat_to_matrix((0.5, 0.5, 0.5, 0.5)), (0.0, -1.0, 0.2))], _mount(10, 0.1, 0.4),
     (1.0, 0.5, -0.2)),
    ([list(r) for r in pose([[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]], (0.0, 0.0, 0.0))],
     _mount(45, 0.2, 0.8), (3.0, 0.0, 1.0)),
)


def _mount_bug() -> str:
    f = mount_facts()
    return ("Line 9 multiplies T_world_base by T_cam_base, the base seen from the camera: the inner names "
            "(base, cam) do not meet, so the product is not the camera's pose. Line 8 has already inverted the "
            "calibration into T_base_cam, and that is the one the chain needs: T_world_base · T_base_cam = "
            "T_world_cam. With the robot at (2, 1) facing 90°, the camera 0.3 m ahead and 0.5 m up, pitched 30° "
            "down, an object on the floor 1 m in front of the camera is at ("
            + ", ".join(fmt(v) for v in f["right"]) + ") in the world; the bug puts it at ("
            + ", ".join(fmt(v) for v in f["wrong"]) + f"), {fmt(f['off'])} m away. "
            "Fix: T_world_cam = mul(T_world_base, T_base_cam).")


_YAW_MSG = """\
import math
def facing(q_msg):
    # q_msg: the orientation field of a ROS pose message
    w, x, y, z = q_msg
    fx = 1 - 2 * (y * y + z * z)
    fy = 2 * (x * y + w * z)
    return (fx, fy, math.atan2(fy, fx))
"""


def _facing(q_msg):
    """The robot's forward axis in the world (the first column of R(q)) and its heading, from an
    orientation stored (x, y, z, w)."""
    R = quat_to_matrix(from_xyzw(q_msg))
    return (R[0][0], R[1][0], math.atan2(R[1][0], R[0][0]))


def facing_facts() -> dict:
    """The identity orientation as ROS writes it, (0, 0, 0, 1), read by the bug and by the fix."""
    x, y, z, w = 0.0, 0.0, 0.0, 1.0
    bug_w, bug_x, bug_y, bug_z = x, y, z, w  # what line 4 reads
    heading = math.atan2(2 * (bug_x * bug_y + bug_w * bug_z), 1 - 2 * (bug_y * bug_y + bug_z * bug_z))
    return {"bug_heading": math.degrees(heading), "right_heading": math.degrees(_facing((x, y, z, w))[2])}


def _facing_bug() -> str:
    f = facing_facts()
    return ("Line 4 unpacks the message as (w, x, y, z), but a ROS orientation is stored (x, y, z, w), scalar "
            "last. Every component lands in the wrong slot, and the formula still gives a rotation, just "
            "the wrong one: a robot standing still with the identity orientation, (0, 0, 0, 1) in the "
            f"message, is read as w = 0, z = 1, a half turn about z, so it is reported facing "
            f"{fmt(f['bug_heading'])}° instead of {fmt(f['right_heading'])}°. Nothing fails or warns. "
            "Fix: x, y, z, w = q_msg (and name such variables by their order, q_xyzw).")


EXERCISES = (
    Debug(
        id="10.9",
        title="Find the bug in the camera-to-world chain",
        code=_MOUNT,
        bug_line=9,
        fixed_line="    T_world_cam = mul(T_world_base, T_base_cam)",
        bug=_mount_bug(),
        notes={
            1: "takes the robot's pose, the camera calibration (the base seen from the camera) and a detection",
            2: "correct: a 4 × 4 matrix product",
            3: "correct: row i of A times column j of B",
            4: "correct: the inverse of a pose",
            5: "correct: Rᵀ, the rotation undone",
            6: "correct: −Rᵀt, the old origin in the new frame's axes",
            7: "correct: [Rᵀ −Rᵀt; 0 1]",
            8: "correct: the calibration inverted, so the names read base from camera",
            10: "correct: the detection with a fourth coordinate of 1",
            11: "correct: the first three rows of T_world_cam times the point",
        },
        function="detection_in_world",
        reference=_in_world,
        cases=_MOUNT_CASES,
    ),
    Debug(
        id="10.10",
        title="Find the bug in the heading from a ROS pose",
        code=_YAW_MSG,
        bug_line=4,
        fixed_line="    x, y, z, w = q_msg",
        bug=_facing_bug(),
        notes={
            1: "imports math for atan2",
            2: "takes the orientation of a pose message",
            3: "correct: a comment that says where the numbers come from",
            5: "correct: the x part of the robot's forward axis, R₁₁ = 1 − 2(y² + z²)",
            6: "correct: the y part of the forward axis, R₂₁ = 2(xy + wz)",
            7: "returns the forward axis and the heading it points along",
        },
        function="facing",
        reference=_facing,
        cases=(((0.0, 0.0, 0.0, 1.0),),
               ((0.0, 0.0, math.sin(math.radians(30)), math.cos(math.radians(30))),),
               ((0.1, -0.2, 0.6, math.sqrt(0.59)),),
               ((0.5, 0.5, 0.5, 0.5),)),
    ),
)
