"""0.5 rotate_2d: each tested point, where your function turns it, and where it belongs."""

from __future__ import annotations

import math

from ...number_format import compact
from ..svg import Canvas
from . import Drawn, RunFigure
from .marks import INPUT, REFERENCE, YOURS, finite, inside, key, message, off_picture, with_message


def frame(d: Drawn) -> tuple[str, str]:
    x, y, theta = d.args
    want = tuple(d.want)
    got = tuple(d.got) if d.got is not None and finite(*d.got) else None
    reach = max(1.0, math.hypot(x, y), math.hypot(*want)) * 1.3
    c = Canvas(360, 320, (-reach, reach), (-reach, reach), pad=(12, 12, 12, 24))
    c.grid(10 ** math.floor(math.log10(reach)), labels=False)
    key(c)
    c.arrow((0, 0), (x, y), f"{INPUT} wb-fig-thin")
    c.dot((x, y), 4, f"{INPUT} wb-fig-solid")
    c.label((x, y), "p", f"wb-fig-label wb-fig-small {INPUT}", toward=(x, y))
    c.arrow((0, 0), want, f"{REFERENCE} wb-fig-thin")
    c.dot(want, 6, "wb-fig-c")
    said = d.message
    if got is not None:
        shown = inside(c, got)
        if off_picture(c, got):
            said = said or "your point lies beyond the picture's edge"
        c.line(want, shown, "wb-fig-bad wb-fig-thin")
        c.arrow((0, 0), shown, f"{YOURS} wb-fig-thick")
        c.dot(shown, 4, f"{YOURS} wb-fig-solid")
        c.label(shown, "yours", f"wb-fig-label wb-fig-small {YOURS}", toward=shown)
    below = message(c, said)
    turn = f"p = ({compact(x)}, {compact(y)}) turned by {compact(math.degrees(theta))}°"
    where = (f"your function puts it at ({compact(got[0])}, {compact(got[1])})" if got is not None
             else "your function gave no point to draw")
    description = f"{d.label}: {turn}; the reference puts it at ({compact(want[0])}, {compact(want[1])}); {where}."
    description = with_message(description, said)
    return c.svg(f"rotate_2d, {d.label}: yours and the reference", extra_height=below), description


RUN = RunFigure(name="rotate", title="Your rotate_2d, drawn", unit="", frame=frame, points=True)
