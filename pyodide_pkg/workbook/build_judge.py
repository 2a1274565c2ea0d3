"""The grader's side of a Build run: read the sandbox's report, compare, write the verdict.

The report (``workbook_sandbox.runner``) says what the learner's function
returned on each case, or what it raised. It comes from the sandbox, where the
learner's code ran, so it is data, never a verdict: every field is checked for
its type and cut to its size here, a value counts only as the numbers it
carries, and the expected values are computed by the grader itself. A forged
report can at most claim outputs for the learner's own function.

>>> want = [[0.0, 3.0]]
>>> report = {"cases": [{"value": {"type": "tuple", "length": 2, "text": "(0.0, 3.0)",
...     "items": [{"type": "float", "number": 0.0, "text": "0.0"}, {"type": "float", "number": 3.0, "text": "3.0"}]}}]}
>>> rows = compare(read_report(report, 1), [Case("example", "rotate_2d(3, 0, 1.570796)", want[0])], 1e-6, 1e-9)
>>> rows[0]["passed"], rows[0]["actual"]
(True, '(0.0, 3.0)')
"""

from __future__ import annotations

import json
import math
import re
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

from workbook_sandbox.runner import MESSAGE_CAP, STDOUT_CAP, TRACEBACK_CAP
from workbook_sandbox.values import DEPTH_CAP, ITEMS_CAP, TEXT_CAP, clip, show

from .contract import TAG
from .verdict import GradingError, Verdict

REPORT_CAP = 1_000_000  # characters of a report the grader reads at all
UNREADABLE = "The sandbox's report on this run could not be read; run it again."


@dataclass
class Case:
    """One test as the grader knows it: how it is shown and the expected value (numbers, maybe nested).
    ``diagnose``, when the exercise has one, names what is wrong with a value that disagrees (the learner's
    numbers, shaped as ``want``) in a sentence, or gives "" when it cannot say (``Build.diagnose``)."""

    name: str
    input: str
    want: Any
    diagnose: Callable[[Any], str] | None = field(default=None, compare=False, repr=False)

    @property
    def expected(self) -> str:
        return show(_rounded(self.want))


def _rounded(value: Any) -> Any:
    if value is None or isinstance(value, bool):
        return value
    if isinstance(value, (list, tuple)):
        return tuple(_rounded(v) for v in value)
    return round(value, 6) if math.isfinite(value) else value


# ---- Reading the report ----------------------------------------------------------------


def _text(value: Any, cap: int) -> str:
    return clip(value, cap) if isinstance(value, str) else ""


def _error(raw: Any) -> dict[str, Any]:
    raw = raw if isinstance(raw, dict) else {}
    line = raw.get("line")
    return {"type": _text(raw.get("type"), 60) or "Exception", "message": _text(raw.get("message"), MESSAGE_CAP),
            "line": line if type(line) is int and 0 < line < 10_000_000 else None,
            "traceback": _text(raw.get("traceback"), TRACEBACK_CAP)}


def _value(raw: Any, depth: int = 0) -> dict[str, Any]:
    """An encoded value, reduced to what the grader uses: type, text, number or items."""
    raw = raw if isinstance(raw, dict) else {}
    out: dict[str, Any] = {"type": _text(raw.get("type"), 40) or "object", "text": _text(raw.get("text"), TEXT_CAP)}
    number = raw.get("number")
    if type(number) in (int, float) and not isinstance(number, bool):
        try:
            out["number"] = float(number)
        except OverflowError:
            pass
    length, items = raw.get("length"), raw.get("items")
    if type(length) is int and length >= 0 and isinstance(items, list) and depth <= DEPTH_CAP:
        out["length"] = length
        out["items"] = [_value(item, depth + 1) for item in items[:ITEMS_CAP]]
    return out


@dataclass
class Report:
    load: dict[str, Any] | None
    missing: bool
    cases: list[dict[str, Any]]
    stdout: str
    stopped: str | None
    figure: list[dict[str, Any]] = field(default_factory=list)  # the run figure's own runs (closed-loop drivers)


def _case(case: Any) -> dict[str, Any]:
    """One case of a report: its value, or its error (and what a closed-loop driver had so far)."""
    case = case if isinstance(case, dict) else {}
    if "error" in case:
        out = {"error": _error(case["error"])}
        if "partial" in case:
            out["partial"] = _value(case["partial"])
        return out
    if "value" in case:
        return {"value": _value(case["value"])}
    return {"skipped": True}


def read_report(raw: Any, count: int, figure_count: int = 0) -> Report:
    """The sandbox's report (a dict, or its JSON text) checked and cut to size; ``count`` cases at most
    (and ``figure_count`` runs of a run figure).
    Raises GradingError("bad-request") when it is not a report at all."""
    if isinstance(raw, str):
        if len(raw) > REPORT_CAP:
            raise GradingError("bad-request", UNREADABLE)
        try:
            raw = json.loads(raw)
        except (ValueError, RecursionError):
            raise GradingError("bad-request", UNREADABLE) from None
    if not isinstance(raw, dict) or not isinstance(raw.get("cases", []), list):
        raise GradingError("bad-request", UNREADABLE)
    load = raw.get("load")
    cases = [_case(case) for case in raw.get("cases", [])[:count]]
    figure = drawn if isinstance(drawn := raw.get("figure"), list) else []
    stdout = _text(raw.get("stdout"), STDOUT_CAP)
    if raw.get("cut") is True or (isinstance(raw.get("stdout"), str) and len(raw["stdout"]) > STDOUT_CAP):
        stdout += "\n… (output cut)"
    stopped = raw.get("stopped") if raw.get("stopped") in ("interrupt", "memory") else None
    return Report({**_error(load), "phase": "syntax" if load.get("phase") == "syntax" else "load"}
                  if isinstance(load, dict) else None, raw.get("missing") is True, cases, stdout, stopped,
                  [_case(case) for case in figure[:figure_count]])


# ---- Comparing ---------------------------------------------------------------------------


class Mismatch(Exception):
    """A value of the wrong shape or type: the message for its test row."""


def _what(value: dict[str, Any]) -> str:
    """A value named in a message: its type and text ("int 5"), or just the text of an int too large to show."""
    return value["text"] if value["type"] == "int" and "number" not in value else f"{value['type']} {value['text']}"


def numbers(value: dict[str, Any], want: Any) -> Any:
    """The numbers ``value`` carries, shaped as ``want`` (a number or a sequence of them, maybe nested;
    None where the reference refuses); Mismatch when it has another shape."""
    if want is None:
        if value["type"] != "NoneType":
            raise Mismatch(f"expected None (the reference refuses this input), got {_what(value)}")
        return None
    if not isinstance(want, (list, tuple)):
        if isinstance(want, bool) and value["type"] in ("bool", "bool_") and value.get("number") is not None:
            return bool(value["number"])  # a yes/no answer is shown as one (False, not 0.0)
        if "number" not in value:
            if value["type"] == "int":
                raise Mismatch(f"expected plain numbers, got a number too large for a float ({value['text']})")
            raise Mismatch(f"expected plain numbers, got {value['type']} {value['text']} inside the result")
        return value["number"]
    if "length" not in value:
        raise Mismatch(f"expected a sequence of {len(want)} numbers, got {_what(value)}")
    if value["length"] != len(want):
        raise Mismatch(f"expected {len(want)} numbers, got {value['length']}: {value['text']}")
    if len(value["items"]) != len(want):
        raise Mismatch(f"expected {len(want)} numbers: {value['text']}")
    out = []
    for item, w in zip(value["items"], want):
        if not isinstance(w, (list, tuple)) and "length" in item:
            raise Mismatch(f"expected plain numbers, got {item['type']} {item['text']} inside the result")
        out.append(numbers(item, w))
    return out


def angle_at(at: str, angles: tuple[str, ...]) -> bool:
    """Whether the entry at index path ``at`` is an angle: a pattern such as ``[0][2]``, ``*`` any index."""
    return any(re.fullmatch(re.escape(p).replace(r"\*", r"\d+"), at) for p in angles)


def _same_angle(got: float, want: float, tol: float) -> bool:
    """Two angles in [−π, π] that name the same direction: an exact half-turn may come out as π or −π
    (``math.atan2(math.sin(a), math.cos(a))`` gives −π at a = −π), and both are right.

    >>> _same_angle(-math.pi, math.pi, 1e-9), _same_angle(3 * math.pi, math.pi, 1e-9)
    (True, False)
    """
    if not (math.isfinite(got) and math.isfinite(want)) or abs(got) > math.pi + tol:
        return False  # an angle outside [−π, π] was not brought into the range the statement asks for
    return abs(math.remainder(got - want, 2 * math.pi)) <= tol


def first_difference(got: Any, want: Any, rel_tol: float, abs_tol: float, at: str = "",
                     angles: tuple[str, ...] = ()) -> tuple | None:
    """Where ``got`` first disagrees with ``want`` (same shape): ``(index path, got, want)``, or None.
    Entries whose path matches one of ``angles`` are compared as angles (π and −π agree).

    >>> first_difference([[1.0, 2.0], [3.0, 4.5]], [[1.0, 2.0], [3.0, 4.0]], 1e-6, 1e-9)
    ('[1][1]', 4.5, 4.0)
    >>> first_difference([1.0, -math.pi], [1.0, math.pi], 1e-6, 1e-9, angles=("[1]",)) is None
    True
    """
    if want is None or got is None:
        return None if got is want else (at, got, want)
    if isinstance(want, (list, tuple)):
        for i, (g, w) in enumerate(zip(got, want)):
            found = first_difference(g, w, rel_tol, abs_tol, f"{at}[{i}]", angles)
            if found is not None:
                return found
        return None
    tol = max(rel_tol * abs(want), abs_tol, 1e-9)
    if angles and not isinstance(want, bool) and angle_at(at, angles):
        return None if _same_angle(got, want, tol) else (at, got, want)
    return None if math.isclose(got, want, rel_tol=rel_tol, abs_tol=max(abs_tol, 1e-9)) else (at, got, want)


def row(case: Case, outcome: dict[str, Any], rel_tol: float, abs_tol: float,
        angles: tuple[str, ...] = ()) -> dict[str, Any]:
    """One test row: the case, what the learner's function gave, and whether it agrees."""
    out: dict[str, Any] = {"name": case.name, "input": case.input, "expected": case.expected}
    if "error" in outcome:
        error = outcome["error"]
        return {**out, "actual": f"raised {error['type']}", "passed": False,
                "message": error["traceback"] or f"{error['type']}: {error['message']}", "line": error["line"]}
    if "value" not in outcome:
        return {**out, "actual": "not run", "passed": False, "message": "The run stopped before this test."}
    value = outcome["value"]
    try:
        got = numbers(value, case.want)
    except Mismatch as err:
        return {**out, "actual": value["text"], "passed": False, "message": str(err)}
    found = first_difference(got, case.want, rel_tol, abs_tol, angles=angles)
    message = "" if found is None or not found[0] else (
        f"first difference at {found[0]}: expected {show(_rounded(found[2]))}, got {show(_rounded(found[1]))}")
    said = _diagnosis(case, got) if found is not None else ""
    if said:
        message = said + (f" ({message})" if message else "")
    return {**out, "actual": show(_rounded(got)), "passed": found is None, "message": message}


def _diagnosis(case: Case, got: Any) -> str:
    """What the exercise's own diagnosis names about a disagreeing value ("" when it names nothing, or fails:
    a fault of the diagnosis must never cost the learner the row)."""
    if case.diagnose is None:
        return ""
    try:
        said = case.diagnose(got)
    except Exception:
        return ""
    return said if isinstance(said, str) else ""


def compare(report: Report, cases: list[Case], rel_tol: float, abs_tol: float,
            angles: tuple[str, ...] = ()) -> list[dict[str, Any]]:
    """A row per case, in order (a case the report lacks was not run)."""
    outcomes = report.cases + [{"skipped": True}] * (len(cases) - len(report.cases))
    return [row(case, outcome, rel_tol, abs_tol, angles) for case, outcome in zip(cases, outcomes)]


def hidden_summary(rows: list[dict[str, Any]]) -> dict[str, Any]:
    """One row for all the hidden cases (edge cases, then random ones): the first that fails, or 'all agree'."""
    summary = {"name": f"{len(rows)} hidden cases"}
    for r in rows:
        if not r["passed"]:
            return {**r, **summary}
    return {**summary, "input": f"{len(rows)} hidden inputs", "expected": "reference values",
            "actual": "all agree", "passed": True, "message": ""}


# ---- The verdict ---------------------------------------------------------------------------


def judge(report: Report, cases: list[Case], signature: str, shown: int, rel_tol: float, abs_tol: float,
          angles: tuple[str, ...] = ()) -> Verdict:
    """The verdict on a run: a load error, a missing function, or the ``shown`` example rows and one
    row for the hidden cases (``signature`` names the function the learner must define)."""
    def verdict(status: str, message: str, tag: str = "", error: dict | None = None, rows: list | None = None):
        return Verdict(status, message, tag=tag, data={"tests": rows or [], "stdout": report.stdout, "error": error})

    load = report.load
    if load is not None and load["phase"] == "syntax":
        return verdict("incorrect", f"Syntax error on line {load['line']}: {load['message']}.", TAG.syntax,
                       _error_data(load))
    if load is not None:
        what = "ran out of memory" if report.stopped == "memory" else f"raised {load['type']}"
        return verdict("incorrect", f"Your code {what} while loading.", TAG.exception, _error_data(load))
    if report.missing:
        return verdict("incorrect", f"Define a function named {signature}.", TAG.missing)
    rows = compare(report, cases, rel_tol, abs_tol, angles)
    rows = rows[:shown] + [hidden_summary(rows[shown:])]
    passed = sum(1 for r in rows if r["passed"])
    if passed == len(rows):
        return verdict("correct", f"All {len(rows)} tests pass.", rows=rows)
    failing = next((r for r in rows if r.get("line")), None)
    error = {"line": failing["line"], "traceback": failing["message"]} if failing else None
    message = f"{passed} of {len(rows)} tests pass."
    if report.stopped == "memory":
        stop = next((r["input"] for r in rows if r["actual"] == "raised MemoryError"), "a test")
        message = f"Your code ran out of memory on {stop}; the sandbox was restarted. {message}"
    return verdict("incorrect", message, TAG.exception if error else TAG.failed, error, rows)


def _error_data(error: dict[str, Any]) -> dict[str, Any]:
    return {key: error[key] for key in ("type", "message", "line", "traceback")}
