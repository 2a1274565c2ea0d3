"""10.8 slerp: in space (an oblique view), the frames of q0 and q1 and the frame a fraction t of the
way between them: your quaternion's and the reference's. A frame is drawn as its three axes, the
columns of R(q)."""

from __future__ import annotations

import math

from ...number_format import compact
from ...reference.se3 import angle_between, quat_to_matrix
from ..euler_3d import project
from ..svg import Canvas
from . import Drawn, RunFigure
from .marks import INPUT, REFERENCE, YOURS, finite, inside, key, message, with_message


def _vec(values) -> str:
    return "(" + ", ".join(compact(v) for v in values) + ")"


def _axes(c: Canvas, q, cls: str, length: float, names: str = "") -> None:
    """The three axes of the frame turned by q (normalised first, so any non-zero q can be drawn)."""
    n = math.sqrt(sum(v * v for v in q))
    R = quat_to_matrix([v / n for v in q])
    for k in range(3):
        tip = project([R[i][k] * length for i in range(3)])
        shown = inside(c, tip)
        c.arrow((0, 0), shown, cls)
        if names:
            c.label(shown, names + "xyz"[k], f"wb-fig-label wb-fig-small {cls.split()[0]}", toward=shown)


def frame(d: Drawn) -> tuple[str, str]:
    q0, q1, t = d.args
    want = d.want
    got = d.got if d.got is not None and len(d.got) == 4 and finite(*d.got) else None
    c = Canvas(380, 340, (-1.4, 1.4), (-1.3, 1.3), pad=(12, 12, 12, 20))
    key(c)
    _axes(c, q0, f"{INPUT} wb-fig-thin", 0.7, "0")
    _axes(c, q1, f"{INPUT} wb-fig-thin wb-fig-dash", 0.7, "1")
    _axes(c, want, f"{REFERENCE} wb-fig-thick", 1.0)
    turn = math.degrees(angle_between(q0, q1))
    if got is not None and any(got):
        _axes(c, got, f"{YOURS} wb-fig-thick", 1.0)
        norm = math.sqrt(sum(v * v for v in got))
        yours = f"yours is {_vec(got)}, of length {compact(norm)}"
    else:
        yours = "your function gave no quaternion to draw"
    below = message(c, d.message)
    description = with_message(
        f"{d.label}: from q0 = {_vec(q0)} to q1 = {_vec(q1)}, {compact(turn)}° apart the short way, at "
        f"t = {compact(t)}; the reference's quaternion is {_vec(want)}; {yours}.", d.message)
    return c.svg(f"slerp, {d.label}: the frames of q0, q1 and the blend", extra_height=below), description


RUN = RunFigure(name="slerp", title="Your SLERP, drawn as frames", unit="", frame=frame)
