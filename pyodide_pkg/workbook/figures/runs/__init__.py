"""Run figures: after a Build run, the learner's function drawn beside the reference.

A Build exercise names one (``Build.run_figure``); after judging, the grader
draws it from what the learner's function returned (the sandbox's report, read
as data by ``workbook.build_judge``) and from its own reference, run by the
grader itself, through the same harness driver, after the learner's code has
finished. The learner's code never touches the reference drawn: in the page it
ran in another worker, and natively its changes were put back before judging.

Each figure module defines ``RUN``, a :class:`RunFigure`: how one case is drawn
(``frame``), the unit of its error, and, for a figure that needs a trajectory,
a :class:`Trace` (a closed-loop driver of ``workbook_sandbox.harness`` and the
arguments of each run). :func:`draw_run` returns::

    {"name", "title", "readout": "Largest error 0.003 m at test 4",
     "frames": [{"label", "svg", "description", "readout"}, ...], "start": 3}

one frame per drawn case (the visible tests, the worst hidden case when one
fails, or each trajectory run), ``start`` the frame to show first (the worst).
Nothing here raises on what a learner's function returned: ``None``, text, a
wrong shape, NaN, an exception part-way through a trajectory all become a
message on the frame, drawn as far as the numbers go.
"""

from __future__ import annotations

import copy
import math
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

from workbook_sandbox import harness

from ...build_judge import Mismatch, angle_at, numbers
from ...number_format import compact
from ...registry import RUN_FIGURES

TRACE_CAP = 64  # samples of a trajectory the report carries (workbook_sandbox.values.ITEMS_CAP)


@dataclass(frozen=True)
class Trace:
    """Closed-loop runs: the driver (``workbook_sandbox.harness``) and each run's arguments."""

    harness: str
    cases: tuple[tuple, ...]
    names: tuple[str, ...] = ()


@dataclass
class Drawn:
    """One case as a figure draws it: the reference's numbers and the learner's, as far as they go."""

    label: str
    args: tuple
    want: Any
    got: Any = None  # shaped as ``want`` (a trajectory: the learner's samples, maybe fewer)
    message: str = ""  # what went wrong, for people ("" when the numbers are all there)
    error: float | None = None  # the largest difference from the reference (None: nothing to compare)
    raw: list[float] | None = None  # the learner's plain numbers when they do not have the reference's shape


@dataclass(frozen=True)
class RunFigure:
    name: str
    title: str
    unit: str
    frame: Callable[[Drawn], tuple[str, str]]  # the case's SVG and a sentence describing it
    trace: Trace | None = None
    points: bool = False  # the output is a point (x, y): its error is the distance, not the largest difference
    width: int | None = None  # a trajectory: 0, of numbers; n, of rows of n numbers (None: one call's value)
    with_start: bool = True  # a trajectory's first sample is where it starts (not a step's outcome)


def get(name: str) -> RunFigure:
    """The run figure called ``name`` (:data:`workbook.registry.RUN_FIGURES`: one module each)."""
    return RUN_FIGURES.get(name)


def names() -> list[str]:
    return RUN_FIGURES.names()


# ---- the learner's numbers -------------------------------------------------------------


def flat(value: Any) -> list[float]:
    """Every number in a (nested) value, in order (None, a refusal, holds none).

    >>> flat([1, [2.5, None, True]])
    [1.0, 2.5, 1.0]
    """
    if value is None:
        return []
    if isinstance(value, (list, tuple)):
        return [x for v in value for x in flat(v)]
    return [float(value)]


def largest_gap(got: Any, want: Any) -> float:
    """The largest absolute difference between matching numbers (NaN when one is not finite).

    >>> largest_gap([1.0, 2.0], [1.0, 2.5])
    0.5
    """
    pairs = list(zip(flat(got), flat(want)))
    if any(not math.isfinite(g) for g, _ in pairs):
        return math.nan
    return max((abs(g - w) for g, w in pairs), default=0.0)


def distance(got: Any, want: Any) -> float:
    """How far the point ``got`` is from ``want`` (NaN when it is not finite).

    >>> distance([3.0, 4.0], [0.0, 0.0])
    5.0
    """
    g, w = flat(got), flat(want)
    if len(g) != 2 or len(w) != 2:
        return largest_gap(got, want)
    return math.hypot(g[0] - w[0], g[1] - w[1])


def _sample(item: dict[str, Any], width: int) -> float | list[float] | str:
    """One sample of a trajectory: a number (``width`` 0) or a row of ``width`` numbers; or why it is not."""
    if width == 0:
        x = item.get("number")
        if x is None:
            return f"{item.get('type', 'object')} {item.get('text', '')}, not a number"
        return x if math.isfinite(x) else f"{compact(x)}"
    row = item.get("items")
    if row is None or len(row) != width or item.get("length") != width:
        return f"{item.get('type', 'object')} {item.get('text', '')}, not {width} numbers"
    out = [_sample(v, 0) for v in row]
    bad = next((v for v in out if isinstance(v, str)), None)
    return out if bad is None else bad  # type: ignore[return-value]  # (out holds only numbers when bad is None)


def series(value: dict[str, Any], width: int = 0) -> tuple[list, str]:
    """A trajectory from a reported value: its samples (numbers, or rows of ``width`` numbers) up to the
    first that is not finite, and why it stops there ("" when it does not).

    >>> series({"items": [{"number": 1.0}, {"number": float("nan")}]})
    ([1.0], 'sample 1 is NaN')
    """
    items = value.get("items")
    if items is None:
        return [], f"expected a list, got {value.get('type', 'object')} {value.get('text', '')}"
    out: list = []
    for k, item in enumerate(items):
        sample = _sample(item, width)
        if isinstance(sample, str):
            return out, f"sample {k} is {sample}"
        out.append(sample)
    return out, ""


def _failure(outcome: dict[str, Any]) -> str:
    error = outcome["error"]
    return f"raised {error['type']}" + (f": {error['message']}" if error["message"] else "")


def _plain(value: dict[str, Any]) -> list[float] | None:
    """The numbers of a flat sequence of numbers (a pair where the reference refuses), else None."""
    items = value.get("items")
    if items is None or value.get("length") != len(items):
        return None
    out = [item.get("number") for item in items]
    return out if all(isinstance(x, float) and math.isfinite(x) for x in out) else None


def _call_case(label: str, args: tuple, want: Any, outcome: dict[str, Any], points: bool,
               angles: tuple[str, ...] = ()) -> Drawn:
    drawn = Drawn(label, args, want)
    if "error" in outcome:
        drawn.message = f"Your function {_failure(outcome)}."
    elif "value" not in outcome:
        drawn.message = "The run stopped before this case."
    else:
        try:
            drawn.got = numbers(outcome["value"], want)
        except Mismatch as err:
            drawn.message = f"Your function returned something else: {err}."
            drawn.raw = _plain(outcome["value"])
        else:
            drawn.error = (distance if points else largest_gap)(as_angles(drawn.got, want, angles), want)
            if not math.isfinite(drawn.error):
                drawn.message = "Your function returned a number that is not finite (NaN or infinity)."
                drawn.error = None
    return drawn


def as_angles(got: Any, want: Any, angles: tuple[str, ...], at: str = "") -> Any:
    """``got`` with each angle entry (``Build.angles``) in [−π, π] written as the turn nearest ``want``'s
    (−π for π: the same half-turn, which the tests accept), for measuring errors.

    >>> as_angles([1.0, -math.pi], [1.0, math.pi], ("[1]",))
    [1.0, 3.141592653589793]
    """
    if not angles or got is None or want is None:
        return got
    if isinstance(got, (list, tuple)) and isinstance(want, (list, tuple)):
        return [as_angles(g, w, angles, f"{at}[{i}]") for i, (g, w) in enumerate(zip(got, want))] + list(
            got[len(want) :]
        )
    if isinstance(got, float) and math.isfinite(got) and abs(got) <= math.pi + 1e-9 and angle_at(at, angles):
        return want + math.remainder(got - want, 2 * math.pi)
    return got


def _trace_case(label: str, args: tuple, want: list, outcome: dict[str, Any], width: int, start: int,
                angles: tuple[str, ...] = ()) -> Drawn:
    drawn = Drawn(label, args, want, got=[])
    value = outcome.get("value", outcome.get("partial"))
    if value is not None:
        drawn.got, why = series(value, width)
        if why:
            drawn.message = f"Stopped: {why}."
    if "error" in outcome:
        drawn.message = f"Stopped after {max(0, len(drawn.got) - start)} steps: your function {_failure(outcome)}."
    elif value is None:
        drawn.message = "The run stopped before this case."
    if len(drawn.got) > start:  # a start alone compares nothing
        common = min(len(drawn.got), len(want))
        drawn.error = largest_gap(as_angles(drawn.got[:common], want[:common], angles), want[:common])
    return drawn


def _reference(fn: Callable[..., Any], drive: Callable[..., Any], args: tuple) -> list:
    """The reference through the driver (the grader's own run; it keeps at most TRACE_CAP samples)."""
    try:
        out = drive(fn, *copy.deepcopy(args))
    except harness.Partial as stop:  # the reference never fails on the cases chosen; be safe anyway
        out = stop.so_far
    return [float(y) if not isinstance(y, (list, tuple)) else [float(v) for v in y] for y in out][:TRACE_CAP]


# ---- the figure --------------------------------------------------------------------------


def _items(fig: RunFigure, ex: Any, report: Any, cases: list, arguments: list[list]) -> tuple[list[Drawn], list[Drawn]]:
    """What is drawn, and every case compared: each trajectory run; or the visible tests, then the
    hidden case with the largest error and the first that failed outright (when there are such)."""
    if fig.trace is not None:
        drive = harness.driver(fig.trace.harness)
        outcomes = report.figure + [{"skipped": True}] * (len(fig.trace.cases) - len(report.figure))
        labels = fig.trace.names or tuple(f"run {k + 1}" for k in range(len(fig.trace.cases)))
        runs = [_trace_case(label, args, _reference(ex.reference, drive, args), outcome, fig.width or 0,
                            int(fig.with_start)) for label, args, outcome in zip(labels, fig.trace.cases, outcomes)]
        return runs, runs
    outcomes = report.cases + [{"skipped": True}] * (len(cases) - len(report.cases))
    shown = len(ex.examples)
    def one(label: str, args: tuple, want: Any, outcome: dict[str, Any]) -> Drawn:
        if fig.width is None:
            return _call_case(label, args, want, outcome, fig.points, getattr(ex, "angles", ()))
        return _trace_case(label, args, want, outcome, fig.width, int(fig.with_start), getattr(ex, "angles", ()))
    items = [one(f"test {k + 1}" if k < shown else f"hidden case {k - shown + 1}", tuple(args), case.want, outcome)
             for k, (args, case, outcome) in enumerate(zip(arguments, cases, outcomes))]
    hidden = items[shown:]
    off = [d for d in hidden if d.error is not None and d.error > max(ex.abs_tol, 1e-9)
           + ex.rel_tol * max(map(abs, flat(d.want)), default=0.0)]
    extra = [max(off, key=lambda d: d.error or 0.0)] if off else []  # (off: errors that are numbers)
    failed = next((d for d in hidden if d.message), None)
    if failed is not None:
        extra.append(failed)
    return items[:shown] + extra, items


def _readout(fig: RunFigure, items: list[Drawn]) -> str:
    """The largest error and its case, and the first case that went wrong."""
    errors = [d for d in items if d.error is not None]
    failed = next((d for d in items if d.message), None)
    parts = []
    if errors:
        worst = max(errors, key=lambda d: d.error or 0.0)  # (errors: numbers)
        unit = f" {fig.unit}" if fig.unit else ""
        if compact(worst.error or 0.0) == "0":
            where = "on every case" if failed is None else "as far as its numbers go"
            parts.append(f"largest error 0{unit}: yours agrees with the reference {where}")
        else:
            parts.append(f"largest error {compact(worst.error or 0.0)}{unit} at {worst.label}")
    if failed is not None:
        parts.append(f"{failed.label}: {failed.message}")
    text = "; ".join(parts) or "nothing to compare"
    return text[0].upper() + text[1:]


def _frame(fig: RunFigure, drawn: Drawn) -> dict[str, str]:
    unit = f" {fig.unit}" if fig.unit else ""
    readout = f"error {compact(drawn.error)}{unit}" if drawn.error is not None else "no error to measure"
    if drawn.message:
        readout += f". {drawn.message}"
    svg, description = fig.frame(drawn)
    return {"label": drawn.label, "svg": svg, "description": description, "readout": f"{drawn.label}: {readout}"}


def draw_run(ex: Any, report: Any, cases: list, arguments: list[list]) -> dict[str, Any]:
    """The run figure of a judged run (see the module's docstring). ``cases`` are the grader's
    (``Build.cases``: the reference's values), ``report`` the sandbox's, read (``build_judge.Report``)."""
    fig = get(ex.run_figure)
    drawn, every = _items(fig, ex, report, cases, arguments)
    frames = [_frame(fig, d) for d in drawn]
    return {"name": fig.name, "title": fig.title, "readout": _readout(fig, every), "frames": frames,
            "start": _start(drawn, every)}


def _start(drawn: list[Drawn], every: list[Drawn]) -> int:
    """The frame to open on: the case the readout names first (the largest error, when it is not 0),
    else the first that went wrong, else the worst."""
    errors = [d for d in every if d.error is not None]
    worst = max(errors, key=lambda d: d.error or 0.0) if errors else None
    at = next((k for k, d in enumerate(drawn) if d is worst), None)
    if worst is not None and worst.error is not None and compact(worst.error) != "0" and at is not None:
        return at
    badness = [math.inf if d.message else (d.error or 0.0) for d in drawn]
    return badness.index(max(badness)) if badness else 0


def trace_job(ex: Any) -> dict[str, Any] | None:
    """What the sandbox runs for the figure besides the tests (``job["figure"]``), if anything."""
    if not getattr(ex, "run_figure", ""):
        return None
    trace = get(ex.run_figure).trace
    return None if trace is None else {"harness": trace.harness, "cases": [list(args) for args in trace.cases]}
