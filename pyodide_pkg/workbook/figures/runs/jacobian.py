"""7.8 jacobian_2link: the arm at the tested angles and, at its tip, the velocity ellipse of your
Jacobian (where unit joint speeds can move the tip) over the reference's; a singular pose flattens
it to a line, and the figure says whether each of you called it singular."""

from __future__ import annotations

import math

from ...number_format import compact
from . import Drawn, RunFigure
from .arm import draw_arm, workspace
from .marks import REFERENCE, YOURS, finite, message, with_message


def velocity_ellipse(J, scale: float, tip, n: int = 48) -> list[tuple[float, float]]:
    """The tip moved by J·(cos t, sin t) for t around the circle, scaled by ``scale``.

    >>> [tuple(round(v, 6) + 0.0 for v in p) for p in velocity_ellipse([[1, 0], [0, 2]], 1, (0, 0), n=3)][:2]
    [(1.0, 0.0), (-0.5, 1.732051)]
    """
    return [(tip[0] + scale * (J[0][0] * math.cos(t) + J[0][1] * math.sin(t)),
             tip[1] + scale * (J[1][0] * math.cos(t) + J[1][1] * math.sin(t)))
            for t in (2 * math.pi * k / n for k in range(n + 1))]


def _said(singular) -> str:
    return "singular" if singular else "not singular"


def frame(d: Drawn) -> tuple[str, str]:
    L1, L2, t1, t2 = d.args
    elbow = (L1 * math.cos(t1), L1 * math.sin(t1))
    tip = (elbow[0] + L2 * math.cos(t1 + t2), elbow[1] + L2 * math.sin(t1 + t2))
    c = workspace(L1, L2)
    draw_arm(c, elbow, tip, "wb-fig-muted")
    J, singular = d.want
    size = max(1e-9, max(abs(v) for row in J for v in row))
    scale = 0.35 * (abs(L1) + abs(L2)) / size
    c.polyline(velocity_ellipse(J, scale, tip), f"{REFERENCE}")
    said = d.message
    got = d.got
    if got is not None and finite(*[v for row in got[0] for v in row], got[1]):
        c.polyline(velocity_ellipse(got[0], scale, tip), f"{YOURS} wb-fig-thick")
        yours = f"your function says {_said(got[1] >= 0.5)}"
    else:
        yours = "your function gave no Jacobian to draw"
    if singular:
        c.label(tip, "singular", "wb-fig-label wb-fig-small wb-fig-bad", toward=tip)
    below = message(c, said)
    description = with_message(
        f"{d.label}: links {compact(L1)} and {compact(L2)} at θ1 = {compact(math.degrees(t1))}°, "
        f"θ2 = {compact(math.degrees(t2))}°; the reference's velocity ellipse is drawn dashed, and the pose is "
        f"{_said(singular)}; {yours}.", said)
    return c.svg(f"jacobian_2link, {d.label}: velocity ellipses at the tip", extra_height=below), description


RUN = RunFigure(name="jacobian", title="Your Jacobian, drawn", unit="", frame=frame)
