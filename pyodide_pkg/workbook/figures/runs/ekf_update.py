"""4.5 ekf_update: on a number line, the estimate before, the measurement, and the estimate after,
yours beside the reference; each bar is the mean ± one standard deviation (the square root of
the variance)."""

from __future__ import annotations

import math

from ...number_format import compact
from ..svg import Canvas
from . import Drawn, RunFigure
from .marks import INPUT, REFERENCE, YOURS, finite, key, message, with_message

ROWS = 4


def _bar(c: Canvas, row: int, mean: float, variance: float, cls: str, name: str) -> str:
    """One estimate as mean ± σ on its row; returns what is wrong with it ("" when nothing)."""
    y = ROWS - row
    c.text((c.xrange[0], y), name, f"wb-fig-label wb-fig-small {cls.split()[0]}", dx=-8, dy=4, anchor="end")
    if not finite(mean, variance):
        return "not a finite number"
    lo, hi = c.xrange
    m = min(max(mean, lo), hi)
    if variance >= 0:
        s = math.sqrt(variance)
        c.line((max(lo, mean - s), y), (min(hi, mean + s), y), f"{cls} wb-fig-thick")
        for end in (mean - s, mean + s):
            if lo <= end <= hi:
                c.line((end, y - 0.15), (end, y + 0.15), cls)
    c.dot((m, y), 5, f"{cls.split()[0]} wb-fig-solid")
    if variance < 0:
        return "a negative variance"
    return "beyond the picture's edge" if m != mean else ""


def frame(d: Drawn) -> tuple[str, str]:
    x, P, z, R = d.args
    want = tuple(d.want)
    got = tuple(d.got) if d.got is not None else None
    spread = [x - math.sqrt(P), x + math.sqrt(P), z - math.sqrt(R), z + math.sqrt(R), want[0]]
    lo, hi = min(spread), max(spread)
    pad = max(0.5, 0.25 * (hi - lo))
    c = Canvas(480, 250, (lo - pad, hi + pad), (0.3, ROWS + 1.4), pad=(128, 12, 12, 26), aspect=False)
    step = 10 ** math.floor(math.log10(max(hi - lo + 2 * pad, 1e-9) / 2))
    k = math.ceil((lo - pad) / step)
    while k * step <= hi + pad:
        c.line((k * step, 0.3), (k * step, ROWS + 0.6), "wb-fig-grid")
        c.text((k * step, 0.3), compact(k * step), "wb-fig-label wb-fig-small wb-fig-muted", dy=16)
        k += 1
    key(c)
    _bar(c, 0, x, P, INPUT, "before (x, P)")
    _bar(c, 1, z, R, "wb-fig-b", "measurement (z, R)")
    _bar(c, 2, want[0], want[1], REFERENCE, "after (reference)")
    said = d.message
    if got is not None:
        wrong = _bar(c, 3, got[0], got[1], YOURS, "after (yours)")
        said = said or (f"your estimate has {wrong}" if wrong else "")
    below = message(c, said)
    yours = (f"yours gives x = {compact(got[0])} with variance {compact(got[1])}" if got is not None
             else "your function gave no estimate to draw")
    description = (f"{d.label}: before the update x = {compact(x)} with variance {compact(P)}; the measurement "
                   f"z = {compact(z)} with variance {compact(R)}; the reference gives x = {compact(want[0])} with "
                   f"variance {compact(want[1])}; {yours}.")
    description = with_message(description, said)
    return c.svg(f"ekf_update, {d.label}: the estimate before and after, yours and the "
                 "reference", extra_height=below), description


RUN = RunFigure(name="ekf-update", title="Your Kalman update, drawn", unit="", frame=frame)
