"""The checkers: one per exercise kind, each returning a :class:`Result`."""

from __future__ import annotations

import math

from .answers import InvalidAnswer, parse_answer
from .exercises import Build, Debug, Derive, Design, Exercise, Trace
from .result import Result

CLOSE_FRACTION = 0.02


def fmt(x: float) -> str:
    """A number as the workbook prints it: up to 4 decimals, no trailing zeros.

    >>> fmt(0.70710678), fmt(3.0), fmt(-0.0)
    ('0.7071', '3', '0')
    """
    s = f"{x:.4f}".rstrip("0").rstrip(".")
    return "0" if s in ("-0", "") else s


def within(ex: Derive, value: float, target: float) -> bool:
    return abs(value - target) <= max(ex.rel_tol * abs(target), ex.abs_tol)


def check_derive(ex: Derive, text: object) -> Result:
    try:
        answer = parse_answer(text)
    except InvalidAnswer as err:
        return Result("invalid", str(err))
    value, key = answer.value, ex.key
    if answer.unit and not ex.angle:
        return Result("invalid", "This answer is not an angle: type it without a degree or radian unit.")
    if ex.angle == "deg" and answer.unit == "rad":
        value = math.degrees(value)
    elif ex.angle == "rad" and answer.unit == "deg":
        value = math.radians(value)

    if within(ex, value, key):
        return Result("correct", f"Correct: {fmt(key)}{ex.unit if ex.unit == '°' else ''}.")
    for slip in ex.slips:
        if within(ex, value, slip.value):
            return Result("incorrect", slip.message, tag="slip")
    if answer.unit is None and ex.angle == "deg" and within(ex, math.degrees(value), key):
        return Result("incorrect", "That looks like radians. This answer is in degrees: multiply by 180/π, or type the unit, e.g. 0.9273 rad.", tag="radians")
    if answer.unit is None and ex.angle == "rad" and within(ex, math.radians(value), key):
        return Result("incorrect", "That looks like degrees. This answer is in radians: multiply by π/180, or type the unit, e.g. 90°.", tag="degrees")
    if key != 0 and within(ex, -value, key):
        return Result("incorrect", "The size is right but the sign is wrong. Check which way the quantity points.", tag="sign")
    if abs(value - key) <= CLOSE_FRACTION * max(abs(key), 1e-9) or (key == 0 and abs(value) <= CLOSE_FRACTION):
        return Result("incorrect", "Close, but not within tolerance. Carry more digits through the intermediate steps.", tag="close")
    return Result("incorrect", "Not quite. Try the hint, or work the derivation one line at a time.")


def check_trace(ex: Trace, choice: object) -> Result:
    options = {o.key: o for o in ex.options}
    if choice not in options:
        return Result("invalid", "Choose one of the options first.")
    why = options[choice].why
    return Result("correct" if choice == ex.answer else "incorrect", why, tag="why")


def check_debug(ex: Debug, line: object) -> Result:
    count = len(ex.lines)
    try:
        n = int(line)  # type: ignore[arg-type]
    except (TypeError, ValueError):
        return Result("invalid", "Click the line you think holds the bug, then check.")
    if not 1 <= n <= count:
        return Result("invalid", f"Pick a line between 1 and {count}.")
    if n == ex.bug_line:
        return Result("correct", ex.bug, data={"line": n})
    note = ex.notes.get(n, "This line does what it should.")
    note = note if note.rstrip().endswith((".", "!", "?")) else note.rstrip() + "."
    return Result("incorrect", f"Line {n} is fine: {note} The bug is on another line.", data={"line": n})


def check_design(ex: Design, order: object) -> Result:
    solution = ex.solution
    if not isinstance(order, (list, tuple)) or sorted(map(str, order)) != sorted(solution):
        return Result("invalid", "Arrange all the steps, each once, then check.")
    order = [str(k) for k in order]
    in_place = sum(a == b for a, b in zip(order, solution))
    if in_place == len(solution):
        return Result("correct", "Correct: every step is in place.", data={"in_place": in_place})
    first = next(i for i, (a, b) in enumerate(zip(order, solution)) if a != b)
    text = {s.key: s.text for s in ex.steps}[order[first]]
    return Result(
        "incorrect",
        f"{in_place} of {len(solution)} steps are in place. The first one out of place is step {first + 1}, “{text}”.",
        data={"in_place": in_place, "first_wrong": first + 1},
    )


def check(ex: Exercise, answer: object) -> Result:
    """Grade ``answer`` for any non-Build exercise."""
    if isinstance(ex, Derive):
        return check_derive(ex, answer)
    if isinstance(ex, Trace):
        return check_trace(ex, answer)
    if isinstance(ex, Debug):
        return check_debug(ex, answer)
    if isinstance(ex, Design):
        return check_design(ex, answer)
    if isinstance(ex, Build):
        from .runner import run_build

        return run_build(ex, str(answer))
    raise TypeError(f"unknown exercise type {type(ex).__name__}")
