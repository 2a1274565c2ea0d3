"""What a Debug exercise's bug does to the robot, drawn once at build time.

Each symptom has ``facts()`` (the numbers of one scenario, from the reference
implementations: the bank quotes them in the bug's explanation) and a drawing of
the buggy behaviour beside the fixed one. :func:`render` gives the SVG and a
sentence describing it (the figure's caption, and its accessible description).
The Debug widget holds the figure hidden and shows it with the explanation once
the bug is found (``docs/assets/js/kinds/debug.js``).

>>> sorted(SYMPTOMS)
['ik-quadrant', 'quaternion-norm', 'windup']
>>> svg, text = render("windup")
>>> svg.startswith("<svg") and "overshoot" in text
True
"""

from __future__ import annotations

import math
from collections.abc import Callable
from functools import cache, partial

from ..number_format import fixed, fmt, prose
from ..reference.arm import forward_kinematics_2link, inverse_kinematics_2link
from ..reference.pid import pid_step_saturated, simulate_saturated
from ..reference.rotation3d import quat_integrate, quat_norm
from .svg import Canvas

MUTED = "wb-fig-label wb-fig-small wb-fig-muted"


# ---- 6.8: atan instead of atan2 ---------------------------------------------------
IK_LINKS, IK_TARGET = (1.0, 1.0), (-1.2, 0.8)


@cache
def ik_facts() -> dict:
    """The arm asked to reach a target behind it: the right joint angles and atan's."""
    (L1, L2), (x, y) = IK_LINKS, IK_TARGET
    t1, t2 = inverse_kinematics_2link(L1, L2, x, y).elbow_down
    t1_bug = math.atan(y / x) - (math.atan2(y, x) - t1)  # the same elbow, the base angle from atan
    tip = forward_kinematics_2link(L1, L2, t1_bug, t2)
    return {"links": IK_LINKS, "target": IK_TARGET, "t1": t1, "t2": t2, "t1_bug": t1_bug, "tip_bug": tip,
            "miss": math.hypot(tip[0] - x, tip[1] - y)}


def _ik_draw(f: dict) -> str:
    (L1, _), (x, y) = f["links"], f["target"]
    c = Canvas(360, 260, (-2.2, 2.2), (-1.6, 1.6), pad=14)
    c.grid(1.0)
    c.dot((x, y), 7, "wb-fig-b")
    for t1, cls in ((f["t1"], "wb-fig-c"), (f["t1_bug"], "wb-fig-bad wb-fig-dash")):
        elbow = (L1 * math.cos(t1), L1 * math.sin(t1))
        tip = forward_kinematics_2link(f["links"][0], f["links"][1], t1, f["t2"])
        c.polyline([(0, 0), elbow, tip], f"{cls} wb-fig-thick")
        c.dot(tip, 4, f"{cls} wb-fig-solid")
    c.text((x, y), "target: the tip with atan2", "wb-fig-label wb-fig-small wb-fig-c", dy=26)
    tip = f["tip_bug"]
    c.text(tip, "the tip with atan", "wb-fig-label wb-fig-small wb-fig-bad", dx=-20, dy=24, anchor="start")
    c.dot((0, 0), 4, "wb-fig-solid")
    return c.svg(_ik_text(f))


def _ik_text(f: dict) -> str:
    (x, y), tip = f["target"], f["tip_bug"]
    return (f"The arm asked to reach ({prose(x)}, {prose(y)}), behind the base: with atan2 its tip lands on the "
            f"target; with atan the whole arm is turned half a turn and the tip lands at ({prose(tip[0])}, "
            f"{prose(tip[1])}), {fmt(f['miss'])} m away.")


# ---- 2.9: the quaternion is never renormalised -------------------------------------
GYRO_RATE, GYRO_DT, GYRO_STEPS = (0.0, 0.0, 5.0), 0.01, 1000


@cache
def gyro_facts() -> dict:
    """‖q‖ step by step, integrating a 5 rad/s yaw rate for 10 s, without and with the division by ‖q‖."""
    def norms(renormalise: bool) -> list[float]:
        q, out = (1.0, 0.0, 0.0, 0.0), [1.0]
        for _ in range(GYRO_STEPS):
            q = quat_integrate(q, GYRO_RATE, GYRO_DT, 1, renormalise=renormalise)
            out.append(quat_norm(q))
        return out

    bug = norms(False)
    first = next(k for k, n in enumerate(bug) if n > 1.01)
    return {"rate": GYRO_RATE[2], "dt": GYRO_DT, "steps": GYRO_STEPS, "bug": bug, "fixed": norms(True),
            "first_over": first, "final": bug[-1], "stretch": bug[-1] ** 2}


def _chart(width: float, height: float, duration: float, yrange: tuple[float, float], yticks, xlabel) -> Canvas:
    c = Canvas(width, height, (0.0, duration), yrange, pad=(44, 14, 14, 32), aspect=False)
    for v in yticks:
        c.line((0, v), (duration, v), "wb-fig-grid")
        c.text((0, v), fmt(v), MUTED, dx=-6, dy=4, anchor="end")
    step = 2 if duration >= 4 else 1
    for t in range(0, int(duration) + 1, step):
        c.line((t, yrange[0]), (t, yrange[1]), "wb-fig-grid")
        c.text((t, yrange[0]), xlabel(t), MUTED, dy=18)
    return c


def _gyro_draw(f: dict) -> str:
    duration = f["steps"] * f["dt"]
    c = _chart(420, 240, duration, (0.9, 1.45), (1.0, 1.1, 1.2, 1.3, 1.4), lambda t: f"{t} s")
    ts = [k * f["dt"] for k in range(f["steps"] + 1)]
    c.polyline(list(zip(ts, f["fixed"]))[::10], "wb-fig-c wb-fig-thick")
    c.polyline(list(zip(ts, f["bug"]))[::10], "wb-fig-bad wb-fig-thick wb-fig-dash")
    c.text((duration, f["final"]), "never renormalised", "wb-fig-label wb-fig-small "
                                                         "wb-fig-bad", dx=-4, dy=-8, anchor="end")
    c.text((duration, 1.0), "divided by ‖q‖", "wb-fig-label wb-fig-small wb-fig-c", dx=-4, dy=-8, anchor="end")
    return c.svg(_gyro_text(f))


def _gyro_text(f: dict) -> str:
    return (f"The norm ‖q‖ while a gyroscope's {fmt(f['rate'])} rad/s yaw rate is integrated every "
            f"{fmt(f['dt'])} s: divided by ‖q‖ it stays 1; never renormalised it passes 1.01 after "
            f"{f['first_over']} steps and reaches {fmt(f['final'])} after {f['steps']}.")


# ---- 8.9: integral windup -------------------------------------------------------
WINDUP_GAINS, WINDUP_LIMIT, WINDUP_TIME = (6.0, 4.0, 1.0), 2.5, 10.0


@cache
def windup_facts() -> dict:
    """The step response with a saturating actuator, with and without anti-windup."""
    runs = {}
    for name, clamp in (("fixed", True), ("bug", False)):
        step = partial(pid_step_saturated, anti_windup=clamp)
        runs[name] = simulate_saturated(step, *WINDUP_GAINS, WINDUP_LIMIT, duration=WINDUP_TIME)
    peak = {name: max(ys) for name, (_, ys) in runs.items()}
    return {"gains": WINDUP_GAINS, "u_max": WINDUP_LIMIT, "runs": runs,
            "overshoot": {name: 100 * (p - 1.0) for name, p in peak.items()}}


def _windup_draw(f: dict) -> str:
    c = _chart(420, 250, WINDUP_TIME, (-0.1, 1.5), (0.0, 0.5, 1.0, 1.5), lambda t: f"{t} s")
    c.line((0, 1), (WINDUP_TIME, 1), "wb-fig-b wb-fig-dash")
    for name, cls in (("fixed", "wb-fig-c"), ("bug", "wb-fig-bad wb-fig-dash")):
        ts, ys = f["runs"][name]
        c.polyline(list(zip(ts, ys))[::5], f"{cls} wb-fig-thick")
    ts, ys = f["runs"]["bug"]
    k = max(range(len(ys)), key=ys.__getitem__)
    c.text((ts[k], ys[k]), "integral winds up", "wb-fig-label wb-fig-small wb-fig-bad", dx=14, dy=-4, anchor="start")
    c.text((WINDUP_TIME / 2, 0.75), "integral held while it would wind "
                                    "up", "wb-fig-label wb-fig-small wb-fig-c", anchor="start")
    return c.svg(_windup_text(f))


def _windup_text(f: dict) -> str:
    kp, ki, kd = f["gains"]
    o = f["overshoot"]
    return (f"A PID controller (Kp = {fmt(kp)}, Ki = {fmt(ki)}, Kd = {fmt(kd)}) whose push saturates at "
            f"{fmt(f['u_max'])} moves a mass on a spring and damper from 0 to 1: when the integral keeps growing "
            f"while the output is saturated, the response overshoots by {fixed(o['bug'], 1)} %; held, by "
            f"{fixed(o['fixed'], 1)} %.")


SYMPTOMS: dict[str, tuple[Callable[[], dict], Callable[[dict], str], Callable[[dict], str]]] = {
    "ik-quadrant": (ik_facts, _ik_draw, _ik_text),
    "quaternion-norm": (gyro_facts, _gyro_draw, _gyro_text),
    "windup": (windup_facts, _windup_draw, _windup_text),
}


def render(name: str) -> tuple[str, str]:
    """The symptom ``name`` as ``(svg, description)``."""
    facts, draw, text = SYMPTOMS[name]
    f = facts()
    return draw(f), text(f)
