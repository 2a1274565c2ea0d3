"""The bug hunts from real robots (Debug 0.8, 2.9, 3.11, 3.12, 4.9, 6.8, 7.9, 8.9, 10.9, 10.10) and Build's fresh hidden cases.

test_bank.py proves for every Debug exercise that the program fails its cases, agrees
with the reference once its marked line is fixed, and that every other line has a note.
Here each bug's symptom is asserted concretely (what it does to the robot), the fix is
shown to remove it, and the numbers the explanation quotes are the ones the code gives.
"""

from __future__ import annotations

import math
import re
from html import escape
from pathlib import Path

import pytest

from holdout_programs_debug import HALF_FIXES
from workbook import bank
from workbook.api import dispatch
from workbook.bank import ch10_bugs
from workbook.contract import ATTR, REVIEW_KINDS, ROLE
from workbook.figures import symptoms
from workbook.kinds.base import PlainPage
from workbook.number_format import fmt, prose
from workbook.reference.arm import forward_kinematics_2link
from workbook.reference.pid import simulate_saturated
from workbook.reference.rotation3d import quat_norm
from workbook.reference.se3 import compose, invert, transform_point

HUNTS = ("0.8", "2.9", "3.11", "3.12", "4.9", "6.8", "7.9", "8.9", "10.9", "10.10")


def programs(exercise_id: str):
    """The exercise and its program, buggy and fixed, as functions."""
    ex = bank.get(exercise_id)
    lines = ex.lines
    fixed_lines = [*lines[: ex.bug_line - 1], ex.fixed_line, *lines[ex.bug_line:]]
    return ex, load(ex.code, ex.function), load("\n".join(fixed_lines), ex.function)


def load(code: str, name: str):
    namespace: dict = {}
    exec(compile(code, "<debug>", "exec"), namespace)  # our own program, not a learner's
    return namespace[name]


def flat(v) -> list[float]:
    return [x for item in v for x in (flat(item) if isinstance(item, (list, tuple)) else [float(item)])]


def close(a, b, tol=1e-9) -> bool:
    a, b = flat(a), flat(b)
    return len(a) == len(b) and all(math.isclose(x, y, rel_tol=tol, abs_tol=tol) for x, y in zip(a, b))


@pytest.mark.parametrize("exercise_id", HUNTS)
def test_each_hunt_is_a_short_debug_program_with_one_marked_line(exercise_id):
    ex, _buggy, fixed = programs(exercise_id)
    assert ex.kind == "debug"
    assert 6 <= len(ex.lines) <= 14
    assert all(line.strip() for line in ex.lines), "a blank line would need a note of its own"
    assert ex.check(ex.bug_line).status == "correct" and ex.check(ex.bug_line).message == ex.bug
    for n in ex.notes:
        verdict = ex.check(n)
        note = ex.notes[n].rstrip(".").removeprefix("correct: ")
        assert verdict.status == "incorrect" and note in verdict.message
    for args in ex.cases:
        assert close(fixed(*args), ex.reference(*args))  # the fix agrees with the reference
    assert "Fix:" in ex.bug and ex.fixed_line.strip()[:12] in ex.bug


def test_atan_sends_the_arm_to_the_opposite_quadrant():
    ex, buggy, fixed = programs("6.8")
    L1, L2, x, y = 1.0, 1.0, -1.2, 0.8
    tip_bug = forward_kinematics_2link(L1, L2, *buggy(L1, L2, x, y))
    tip_fixed = forward_kinematics_2link(L1, L2, *fixed(L1, L2, x, y))
    assert close(tip_fixed, (x, y))
    assert tip_bug[0] > 0 and tip_bug[1] < 0  # the target is in the second quadrant, the tip in the fourth
    assert close(tip_bug, (-x, -y))
    assert f"({prose(tip_bug[0])}, {prose(tip_bug[1])})" in ex.bug
    with pytest.raises(ZeroDivisionError):
        buggy(L1, L2, 0.0, 1.5)
    assert close(forward_kinematics_2link(L1, L2, *fixed(L1, L2, 0.0, 1.5)), (0.0, 1.5))


def test_degrees_in_cos_scatter_the_lidar_points():
    ex, buggy, fixed = programs("0.8")
    right, wrong = fixed(0.0, 0.0, 0.0, 2.0, 90.0), buggy(0.0, 0.0, 0.0, 2.0, 90.0)
    assert close(right, (0.0, 2.0))  # 2 m to the left of a robot facing east
    assert math.dist(right, wrong) > 0.5
    assert math.isclose(math.hypot(*wrong), 2.0)  # the range is right, the direction is not
    assert f"({prose(wrong[0])}, {prose(wrong[1])})" in ex.bug


def test_an_unwrapped_bearing_innovation_is_nearly_a_full_turn():
    ex, buggy, fixed = programs("4.9")
    seen = ex.cases[0]
    nu_bug, nu_fixed = buggy(*seen)[1], fixed(*seen)[1]
    assert abs(nu_bug) > math.pi and abs(nu_fixed) < 0.1
    assert math.isclose(abs(nu_bug - nu_fixed), 2 * math.pi)
    assert prose(nu_bug) in ex.bug and prose(nu_fixed) in ex.bug


def test_the_quaternion_norm_drifts_without_renormalising():
    ex, buggy, fixed = programs("2.9")
    start, rate, dt = (1.0, 0.0, 0.0, 0.0), (0.0, 0.0, 5.0), 0.01
    assert quat_norm(buggy(start, *rate, dt, 1000)) > 1.3
    assert abs(quat_norm(fixed(start, *rate, dt, 1000)) - 1) < 1e-12
    norms = [quat_norm(buggy(start, *rate, dt, n)) for n in range(60)]
    first = next(n for n, v in enumerate(norms) if v > 1.01)
    facts = symptoms.gyro_facts()
    assert first == facts["first_over"] and f"after {first} steps" in ex.bug
    assert fmt(facts["final"]) in ex.bug and math.isclose(facts["final"], quat_norm(buggy(start, *rate, dt, 1000)))


def test_swapped_factors_hide_the_sideways_uncertainty():
    ex, buggy, fixed = programs("3.11")
    F, P, Q = ex.cases[0]
    wrong, right = buggy(F, P, Q), fixed(F, P, Q)
    assert right[1][1] > 5 * wrong[1][1]  # the heading's doubt belongs in y; the bug leaves y's variance small
    assert math.isclose(wrong[1][1], P[1][1] + Q[1][1])
    assert fmt(right[1][1]) in ex.bug and fmt(wrong[1][1]) in ex.bug


def test_milliseconds_make_the_robot_drive_a_thousand_times_too_far():
    ex, buggy, fixed = programs("3.12")
    args = ex.cases[0]
    assert math.isclose(buggy(*args)[0], 1000 * fixed(*args)[0])
    assert fmt(buggy(*args)[0]) in ex.bug and fmt(fixed(*args)[0]) in ex.bug


def test_the_sign_error_calls_the_sweeping_arm_still():
    _ex, buggy, fixed = programs("7.9")
    straight = (1.0, 1.0, 0.0, 0.0, 1.0, 0.0)
    assert buggy(*straight)[1] == 0.0
    assert math.isclose(fixed(*straight)[1], 2.0)  # (L1 + L2)·ω1


def test_the_mount_used_backwards_misplaces_the_detection():
    """10.9: with T_cam_base where T_base_cam belongs, the floor point 1 m ahead of the camera leaves the
    floor and lands where the explanation says; the fix puts it where the reference does."""
    ex, buggy, fixed = programs("10.9")
    T_world_base, T_cam_base, p_cam = ex.cases[0]
    right, wrong = fixed(T_world_base, T_cam_base, p_cam), buggy(T_world_base, T_cam_base, p_cam)
    assert close(right, ex.reference(T_world_base, T_cam_base, p_cam))
    assert abs(right[2]) < 1e-12 and abs(wrong[2]) > 0.05  # on the floor; the bug lifts it off
    assert math.dist(right, wrong) > 0.3
    for value in (*right, *wrong, math.dist(right, wrong)):
        assert fmt(value) in ex.bug
    for args in ex.cases:
        assert close(fixed(*args), ex.reference(*args)) and not close(buggy(*args), ex.reference(*args))


def test_scalar_first_reads_the_identity_as_a_half_turn():
    """10.10: the identity as ROS writes it, (0, 0, 0, 1), read scalar first is a half turn about z:
    the bug reports 180°, the fix 0°, and both numbers are the explanation's."""
    ex, buggy, fixed = programs("10.10")
    assert math.isclose(abs(buggy((0.0, 0.0, 0.0, 1.0))[2]), math.pi)
    assert fixed((0.0, 0.0, 0.0, 1.0)) == (1.0, 0.0, 0.0)
    assert "facing 180° instead of 0°" in ex.bug
    for args in ex.cases:
        assert close(fixed(*args), ex.reference(*args))


CH10 = (Path(__file__).resolve().parents[2] / "docs" / "chapters" / "10-poses-3d.md").read_text(encoding="utf-8")


def _statement(exercise_id: str) -> str:
    """An exercise's statement in chapter 10, its lines joined (up to its hint)."""
    start = CH10.index(f"::: exercise {exercise_id} |")
    return " ".join(CH10[start:CH10.index("::: hint", start)].split())


def test_10_9_says_where_the_bug_puts_a_detection_straight_ahead():
    """10.9's statement: nearer or farther, higher or lower, by tilt; in the case the explanation quotes
    (30° down) the point lands 0.31 m nearer and only 0.083 m low, so "higher or lower" alone is not it."""
    text = _statement("10.9")
    assert "nearer or farther and higher or lower than they are" in text and "tilt" in text
    T_world_base = bank.get("10.9").cases[0][0]
    seen = set()
    for pitch in (5, 10, 20, 30, 45, 60, 80):
        T_cam_base = ch10_bugs._mount(pitch, 0.3, 0.5)
        right = transform_point(compose(T_world_base, invert(T_cam_base)), (1.0, 0.0, 0.0))
        wrong = transform_point(compose(T_world_base, T_cam_base), (1.0, 0.0, 0.0))
        camera = transform_point(compose(T_world_base, invert(T_cam_base)), (0.0, 0.0, 0.0))
        nearer = math.dist(right[:2], camera[:2]) - math.dist(wrong[:2], camera[:2])
        seen |= {"nearer" if nearer > 0 else "farther", "lower" if wrong[2] < right[2] else "higher"}
        if pitch == 30:
            assert math.isclose(nearer, 0.3098, abs_tol=1e-4) and math.isclose(wrong[2] - right[2], -0.0830, abs_tol=1e-4)
    assert seen == {"nearer", "farther", "lower", "higher"}


def test_10_10_says_a_ground_robot_always_hears_180_degrees():
    """10.10's statement: for a robot on the floor (a turn about z only), the bug reports 180° whatever the yaw,
    so it is right only when the robot really faces 180°; not "every heading it reports is wrong"."""
    text = _statement("10.10")
    assert "every heading it reports is wrong" not in text and "keeps reporting 180°, whichever way it turns" in text
    _ex, buggy, fixed = programs("10.10")
    for yaw_deg in range(-179, 181, 7):
        half = math.radians(yaw_deg) / 2
        q_msg = (0.0, 0.0, math.sin(half), math.cos(half))
        assert math.isclose(abs(math.degrees(buggy(q_msg)[2])), 180.0)
        assert math.isclose(math.degrees(fixed(q_msg)[2]), yaw_deg, abs_tol=1e-9)


def test_chapter_10_says_where_slerp_s_division_fails():
    """The unguarded SLERP formula is right to rounding down to Ω = 1e-7 rad; it fails (0/0) only when the dot
    product rounds to 1, as the chapter now says (it said the division "loses all precision" near 0)."""
    prose = " ".join(CH10.split("## Two traps")[0].split())
    assert "loses all precision" not in prose and "down to $\\Omega = 10^{-7}$ rad" in prose

    def unguarded(q0, q1, t):
        omega = math.acos(min(sum(a * b for a, b in zip(q0, q1)), 1.0))
        a, b = math.sin((1 - t) * omega) / math.sin(omega), math.sin(t * omega) / math.sin(omega)
        return [a * x + b * y for x, y in zip(q0, q1)]

    for exponent in range(1, 8):
        for t in (0.1, 0.3, 0.75):
            q1 = (math.cos(10.0 ** -exponent), 0.0, 0.6 * math.sin(10.0 ** -exponent), 0.8 * math.sin(10.0 ** -exponent))
            half = math.atan2(math.hypot(q1[2], q1[3]), q1[0])  # the arc these rounded numbers really span
            want = (math.cos(t * half), 0.0, 0.6 * math.sin(t * half), 0.8 * math.sin(t * half))
            assert close(unguarded((1.0, 0.0, 0.0, 0.0), q1, t), want, tol=3e-16)
    with pytest.raises(ZeroDivisionError):
        unguarded((1.0, 0.0, 0.0, 0.0), (math.cos(1e-8), 0.0, math.sin(1e-8), 0.0), 0.5)


@pytest.mark.parametrize("exercise_id,name", [(i, n) for i in HALF_FIXES for n in HALF_FIXES[i]])
def test_a_repair_that_only_half_fixes_the_bug_disagrees_on_a_case(exercise_id, name):
    ex = bank.get(exercise_id)
    code = ex.code
    for old, new in HALF_FIXES[exercise_id][name]:
        assert old in code, old
        code = code.replace(old, new)
    half = load(code, ex.function)
    assert any(not close(half(*args), ex.reference(*args)) for args in ex.cases), name


@pytest.mark.parametrize("exercise_id", HUNTS)
def test_a_fine_line_s_note_reads_as_a_sentence(exercise_id):
    ex = bank.get(exercise_id)
    for n in range(1, len(ex.lines) + 1):
        if n == ex.bug_line:
            continue
        message = ex.check(n).message
        assert message.startswith(f"Line {n} is ") and message.endswith(" The bug is on another line.")
        assert "fine: correct" not in message and ": correct" not in message and ".." not in message
        first = message.split(": ", 1)[1] if " is fine: " in message else ""
        assert not first.startswith(("takes ", "returns ", "imports ", "unpacks ", "clamps ", "adds ", "computes ")), message


def _as_8_8(lines: list[str]) -> str:
    """8.9's program as 8.8's function: limits [u_min, u_max] where 8.9 has ±u_max, and dt = 0 as 8.8 asks."""
    code = "\n".join(lines).replace("pid_step_limited(e, e_prev, integral, Kp, Ki, Kd, dt, u_max)",
                                    "pid_step_clamped(e, e_prev, integral, Kp, Ki, Kd, dt, u_min, u_max)")
    code = code.replace("(e - e_prev) / dt", "((e - e_prev) / dt if dt > 0 else 0.0)")
    return code.replace("u < -u_max", "u < u_min").replace("max(-u_max,", "max(u_min,") + "\n"


def test_8_8_and_8_9_teach_one_anti_windup_rule():
    """Chapter 8 teaches one anti-windup rule, conditional integration. 8.9's fixed program, written as
    8.8's function, passes 8.8; 8.8's model solution, asked 8.9's question, agrees with 8.9's reference
    everywhere; 8.9's buggy program and the rule 'hold whenever saturated' fail 8.8, as the chapter says."""
    import random

    ex88, ex89 = bank.get("8.8"), bank.get("8.9")
    _, _buggy, fixed = programs("8.9")
    fixed_lines = [*ex89.lines[: ex89.bug_line - 1], ex89.fixed_line, *ex89.lines[ex89.bug_line:]]
    assert ex88.check(_as_8_8(fixed_lines)).status == "correct"
    assert ex88.check(_as_8_8(ex89.lines)).status == "incorrect"
    frozen = [*ex89.lines[: ex89.bug_line - 1], "    integral = integral if u != max(-u_max, min(u_max, u)) else candidate",
              *ex89.lines[ex89.bug_line:]]
    verdict = ex88.check(_as_8_8(frozen))
    assert verdict.status == "incorrect" and not verdict.data["tests"][-1]["passed"]
    model: dict = {}
    exec(ex88.solution, model)
    rng = random.Random(89)
    for _ in range(3000):
        args = (rng.uniform(-10, 10), rng.uniform(-10, 10), rng.uniform(-20, 20), rng.uniform(0, 5),
                rng.uniform(0, 2), rng.uniform(0, 2), rng.uniform(0.01, 1))
        u_max = rng.uniform(0.5, 10)
        want = ex89.reference(*args, u_max)
        assert close(model["pid_step_clamped"](*args, -u_max, u_max), want)
        assert close(fixed(*args, u_max), want)
    assert "8.8" in ex89.bug and "conditional integration" in ex89.bug


def test_windup_overshoots_more_than_the_fixed_controller():
    _ex, buggy, fixed = programs("8.9")
    gains, limit = symptoms.WINDUP_GAINS, symptoms.WINDUP_LIMIT
    peaks = {name: max(simulate_saturated(step, *gains, limit)[1]) for name, step in (("bug", buggy), ("fixed", fixed))}
    assert peaks["bug"] - 1 > 0.3 and peaks["fixed"] - 1 < 0.05
    facts = symptoms.windup_facts()
    assert math.isclose(100 * (peaks["bug"] - 1), facts["overshoot"]["bug"])
    assert math.isclose(100 * (peaks["fixed"] - 1), facts["overshoot"]["fixed"])


@pytest.mark.parametrize("exercise_id", [i for i in HUNTS if bank.get(i).symptom])
def test_a_symptom_is_drawn_hidden_in_the_widget_with_its_description(exercise_id):
    ex = bank.get(exercise_id)
    html = ex.widget("ex-x", PlainPage())
    figure = re.search(rf'<figure [^>]*{ATTR.role}="{ROLE.symptom}"[^>]*>(.*?)</figure>', html, re.S)
    assert figure and " hidden" in figure.group(0).split(">")[0]
    svg, text = symptoms.render(ex.symptom)
    assert svg in figure.group(1) and "<title>" in svg
    assert "<figcaption>" in figure.group(1) and escape(text) in figure.group(1)


def test_exercises_without_a_symptom_draw_none():
    assert ROLE.symptom not in bank.get("3.5").widget("ex-3-5", PlainPage())


def test_debug_and_build_join_the_review_queue():
    assert set(REVIEW_KINDS) == {"derive", "build", "debug"}


# ---- Build: a seed carried in the request draws fresh hidden cases --------------------
BUILDS = [ex for ex in bank.all_exercises() if ex.kind == "build"]


@pytest.mark.parametrize("ex", BUILDS, ids=lambda e: e.id)
def test_build_hidden_cases_follow_the_seed_and_the_examples_stay(ex):
    own, a, a_again, b = ex.variant(0), ex.variant(17), bank.variant(ex.id, 17), ex.variant(18)
    assert own is ex
    assert a.hidden_cases() == a_again.hidden_cases() == ex.variant(17).hidden_cases()
    assert a.hidden_cases() != b.hidden_cases() != ex.hidden_cases()
    assert a.hidden_cases() != ex.hidden_cases()
    for drawn in (a, b):
        assert drawn.arguments()[: len(ex.examples)] == ex.arguments()[: len(ex.examples)]
        assert len(drawn.arguments()) == len(ex.arguments())
    assert a.check(ex.solution).status == "correct"


def test_a_review_s_cases_and_judgement_use_the_same_fresh_cases():
    ex = bank.get("0.5")
    fresh = dispatch({"op": "cases", "exercise": "0.5", "code": ex.solution, "variant": 4321})
    own = dispatch({"op": "cases", "exercise": "0.5", "code": ex.solution})
    assert fresh["ok"] and own["ok"] and fresh["value"]["job"] != own["value"]["job"]
    assert fresh["value"]["job"] == dispatch({"op": "cases", "exercise": "0.5", "code": "", "variant": 4321})["value"]["job"]
    ran = dispatch({"op": "run", "exercise": "0.5", "code": ex.solution, "variant": 4321})
    assert ran["ok"] and ran["value"]["status"] == "correct"
    bad = dispatch({"op": "cases", "exercise": "0.5", "code": "", "variant": -3})
    assert not bad["ok"] and bad["error"]["kind"] == "bad-request"
