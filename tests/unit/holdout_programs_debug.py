"""Repairs of Debug exercises that only half fix the bug (tests/unit/test_bug_hunts.py): each is a list
of (old, new) changes to the buggy program, and each must disagree with the reference on one of the
exercise's cases, so that the cases hold the repair the explanation names to its word."""

from __future__ import annotations

HALF_FIXES: dict[str, dict[str, list[tuple[str, str]]]] = {
    "6.8": {
        "atan2 for the target, atan(k2/k1) for the elbow term": [
            ("    t1 = math.atan(y / x) - math.atan2(k2, k1)", "    t1 = math.atan2(y, x) - math.atan(k2 / k1)")],
    },
    "8.9": {
        "frozen whenever saturated, whatever the sign of e": [
            ("    integral = candidate", "    integral = integral if u > u_max or u < -u_max else candidate")],
        "the integral kept, the output from the candidate": [
            ("    integral = candidate", "    integral = integral if winding else candidate"),
            ("    u = Kp * e + Ki * integral + Kd * derivative\n", "")],
    },
}
