"""2.8 rotate_axis_angle: in space (an oblique view), the axis, the vector v, and v turned about the
axis: by your quaternion and by the reference's."""

from __future__ import annotations

import math

from ...number_format import compact
from ..euler_3d import project
from ..svg import Canvas
from . import Drawn, RunFigure
from .marks import INPUT, REFERENCE, YOURS, finite, inside, key, message, with_message


def _vec(values) -> str:
    return "(" + ", ".join(compact(v) for v in values) + ")"


def frame(d: Drawn) -> tuple[str, str]:
    axis, angle, v = d.args
    q, turned = d.want
    got = d.got if d.got is not None and finite(*d.got[0], *d.got[1]) else None
    size = max(1.0, math.sqrt(sum(x * x for x in v)) * 1.25)
    c = Canvas(380, 340, (-size, size), (-size, size), pad=(12, 12, 12, 20))
    key(c)
    for k, name in enumerate("xyz"):
        tip = [0.0, 0.0, 0.0]
        tip[k] = size * 0.85
        c.arrow((0, 0), project(tip), f"{INPUT} wb-fig-thin")
        c.label(project(tip), name, f"wb-fig-label wb-fig-small {INPUT}", toward=project(tip))
    n = math.sqrt(sum(a * a for a in axis)) or 1.0
    unit = [a / n * size for a in axis]
    c.line(project([-u for u in unit]), project(unit), "wb-fig-b wb-fig-dash wb-fig-thin")
    c.label(project(unit), "axis", "wb-fig-label wb-fig-small wb-fig-b", toward=project(unit))
    c.arrow((0, 0), project(v), f"{INPUT} wb-fig-thick")
    c.label(project(v), "v", f"wb-fig-label wb-fig-small {INPUT}", toward=project(v))
    c.arrow((0, 0), project(turned), f"{REFERENCE} wb-fig-thick")
    if got is not None:
        shown = inside(c, project(got[1]))
        c.arrow((0, 0), shown, f"{YOURS} wb-fig-thick")
        c.label(shown, "yours", f"wb-fig-label wb-fig-small {YOURS}", toward=shown)
        yours = f"your quaternion is {_vec(got[0])} and turns v to {_vec(got[1])}"
    else:
        yours = "your function gave no vector to draw"
    below = message(c, d.message)
    description = with_message(
        f"{d.label}: v = {_vec(v)} turned {compact(math.degrees(angle))}° about the axis {_vec(axis)}; the "
        f"reference's quaternion is {_vec(q)} and turns v to {_vec(turned)}; {yours}.", d.message)
    return c.svg(f"rotate_axis_angle, {d.label}: v turned about the axis", extra_height=below), description


RUN = RunFigure(name="axis-angle", title="Your axis-angle rotation, drawn", unit="", frame=frame)
