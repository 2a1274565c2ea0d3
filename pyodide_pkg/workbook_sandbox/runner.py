"""Run a learner's code on the cases of a job and report what came back, as plain JSON.

A *job* comes from the grader (``workbook.kinds.build``)::

    {"function": "rotate_2d", "harness": "call", "cases": [[3, 0, 1.5707963267948966], ...],
     "figure": {"harness": "pid_loop", "cases": [[8, 3, 1.5, 0.1, 60]]}}

``figure`` is optional: the runs a run figure draws besides the tests (a
closed-loop driver's trajectories), made after the tests and reported as
``"figure": [CASE, ...]`` in the same form.

:func:`run` compiles the code under the file name ``<your code>`` (so that
tracebacks can be cut down to the learner's own frames), executes it in a fresh
namespace, finds the function, and drives it through the job's harness once per
case, each with its own copy of the arguments. ``print`` output is captured and
capped. What the code changed in loaded modules is put back when the run ends
(:class:`~workbook_sandbox.restore.Restore`). The report::

    {"load": null | ERROR, "missing": false, "cases": [CASE, ...],
     "stdout": "...", "cut": false, "stopped": null | "interrupt" | "memory"}

with ``CASE`` = ``{"value": VALUE}`` or ``{"error": ERROR}`` (plus ``"partial": VALUE``,
what a closed-loop driver had when the function failed), or ``{"skipped": true}``
after a run was stopped, ``VALUE`` what :func:`~workbook_sandbox.values.encode`
makes of the returned value, and ``ERROR`` = ``{"type", "message", "line",
"traceback"}``. Nothing in it is a verdict: the grader compares the values with
its own and decides.

Every failure of the learner's code is reported, never raised: any exception,
``SystemExit`` (``exit()``), ``KeyboardInterrupt`` (raised by the code, or the
page's interrupt at the time limit: the run stops there), ``MemoryError`` (the
run stops there too), numbers too large for a float, values whose ``repr``
fails.

>>> report = run({"function": "f", "harness": "call", "cases": [[2], [0]]},
...              "def f(x):\\n    return (1 / x, x)\\n")
>>> [c.get("value", c.get("error"))["text" if "value" in c else "type"] for c in report["cases"]]
['(0.5, 2)', 'ZeroDivisionError']
"""

from __future__ import annotations

import ast
import contextlib
import copy
import importlib
import io
import json
import traceback
from collections.abc import Callable
from typing import Any

from . import harness
from .restore import PLAIN_HOMES, STDLIB_HOMES, Restore
from .values import clip, encode

FILENAME = "<your code>"
STDOUT_CAP = 4000
MESSAGE_CAP = 300
TRACEBACK_CAP = 2000


class _CappedIO(io.StringIO):
    def write(self, s: str) -> int:
        text = str(s)
        room = STDOUT_CAP - self.tell()
        if room > 0:
            super().write(text[:room])
        self.cut = getattr(self, "cut", False) or len(text) > room
        return len(text)


def error_info(err: BaseException, source_lines: list[str]) -> dict[str, Any]:
    """The error's type, message, the learner's last line and a traceback of the learner's frames only."""
    if isinstance(err, SyntaxError) and err.filename == FILENAME:
        text = (err.text or "").rstrip()
        line = f"line {err.lineno}: {text}"
        return {"type": "SyntaxError", "message": clip(str(err.msg), MESSAGE_CAP), "line": err.lineno,
                "traceback": clip(f"{line}\nSyntaxError: {err.msg}", TRACEBACK_CAP)}
    lines: list[str] = []
    last_line = None
    for frame in traceback.extract_tb(err.__traceback__):
        if frame.filename == FILENAME:
            last_line = frame.lineno
            code = source_lines[frame.lineno - 1].strip() if frame.lineno and frame.lineno <= len(source_lines) else ""
            lines.append(f"line {frame.lineno}, in {frame.name}: {clip(code, 200)}")
    message = _message(err)
    if len(lines) > 6:  # deep recursion: its first and last frames
        lines = lines[:3] + ["..."] + lines[-3:]
    lines.append(f"{type(err).__name__}: {message}" if message else type(err).__name__)
    return {"type": clip(type(err).__name__, 60), "message": message, "line": last_line,
            "traceback": clip("\n".join(lines), TRACEBACK_CAP)}


UNSHOWN = "(its message cannot be shown)"


def _message(err: BaseException) -> str:
    """The error's message; when its ``__str__`` fails (raises, even MemoryError, or returns no
    string), a note saying so: that is the learner's code, not the sandbox, failing. Only an
    interrupt goes on (the page's, at the time limit, or the code's own), to stop the run."""
    try:
        return clip(str(err), MESSAGE_CAP)
    except KeyboardInterrupt:
        raise
    except BaseException:
        return UNSHOWN


class _Stop(Exception):
    """The run stops: the page's interrupt (or the code's own KeyboardInterrupt), or memory ran out."""

    def __init__(self, why: str, info: dict[str, Any]) -> None:
        self.why, self.info = why, info


class Run:
    """One run of a learner's code on one job."""

    def __init__(self, job: dict[str, Any], code: str) -> None:
        self.function = str(job["function"])
        self.drive = harness.driver(job.get("harness", "call"))
        self.cases = [tuple(args) for args in job["cases"]]
        figure = job.get("figure") or {}
        self.figure_drive = harness.driver(figure.get("harness", "call"))
        self.figure_cases = [tuple(args) for args in figure.get("cases", ())]
        self.code = code
        self.lines = code.split("\n")
        self.out = _CappedIO()
        self.report: dict[str, Any] = {"load": None, "missing": False, "cases": [], "stopped": None}

    def info(self, err: BaseException) -> dict[str, Any]:
        """:func:`error_info`; an interrupt while the error's message is made stops the run."""
        try:
            return error_info(err, self.lines)
        except KeyboardInterrupt:
            name = clip(type(err).__name__, 60)
            raise _Stop("interrupt", {"type": name, "message": UNSHOWN, "line": None,
                                      "traceback": f"{name}: {UNSHOWN}"}) from None

    def guarded(self, action: Callable[[], Any]) -> tuple[bool, Any]:
        """Run ``action``: (True, its result), or (False, the error's info). Stops the run on an interrupt
        or when memory runs out."""
        try:
            return True, action()
        except harness.Partial as stop:  # a closed-loop driver stopped: the function's own error, and the trajectory
            return True, stop
        except MemoryError as err:
            raise _Stop("memory", self.info(err)) from None
        except KeyboardInterrupt as err:
            raise _Stop("interrupt", self.info(err)) from None
        except BaseException as err:  # SystemExit, GeneratorExit and the learner's own BaseException subclasses too
            return False, self.info(err)

    def load(self) -> Callable[..., Any] | None:
        try:
            compiled = compile(self.code, FILENAME, "exec")
        except (SyntaxError, ValueError) as err:  # ValueError: a NUL byte in the source
            if not isinstance(err, SyntaxError):
                err = SyntaxError(str(err), (FILENAME, 1, 0, self.lines[0] if self.lines else ""))
            self.report["load"] = {**error_info(err, self.lines), "phase": "syntax"}
            return None
        namespace: dict[str, Any] = {"__name__": "__learner__"}
        ok, info = self.guarded(lambda: exec(compiled, namespace))
        if not ok:
            self.report["load"] = {**info, "phase": "load"}
            return None
        fn = namespace.get(self.function)
        if not callable(fn):
            self.report["missing"] = True
            return None
        return fn

    def case(self, fn: Callable[..., Any], args: tuple, drive: Callable[..., Any] | None = None) -> dict[str, Any]:
        drive = drive or self.drive
        ok, got = self.guarded(lambda: drive(fn, *copy.deepcopy(args)))
        if not ok:
            return {"error": got}
        if isinstance(got, harness.Partial):
            return self.partial(got)
        ok, value = self.guarded(lambda: encode(got))
        return {"value": value} if ok else {"error": value}

    def partial(self, stop: harness.Partial) -> dict[str, Any]:
        """What a closed-loop driver had when the function failed, and the function's error."""
        cause = stop.__cause__ if stop.__cause__ is not None else stop  # drivers let interrupts through
        out: dict[str, Any] = {"error": self.info(cause)}
        ok, value = self.guarded(lambda: encode(stop.so_far))
        if ok:
            out["partial"] = value
        return out

    def preimport(self) -> None:
        """Import, before the restore notes the interpreter, the watched modules the code imports
        (a first ``import numpy`` would otherwise come after the snapshot, and what the run
        changed in NumPy would stay)."""
        try:
            tree = ast.parse(self.code)
        except (SyntaxError, ValueError, RecursionError, MemoryError):
            return
        names = {alias.name for node in ast.walk(tree) if isinstance(node, ast.Import) for alias in node.names}
        names |= {node.module for node in ast.walk(tree) if isinstance(node, ast.ImportFrom) and node.level == 0
                  and node.module}
        for name in sorted(names):
            if name.split(".")[0] in PLAIN_HOMES:
                with contextlib.suppress(Exception, KeyboardInterrupt):
                    importlib.import_module(name)

    def run(self, restore: Restore) -> dict[str, Any]:
        cases = self.report["cases"]
        self.preimport()
        # The restore outside the redirection: it notes (and puts back) the real stdout, not this run's.
        with restore, contextlib.redirect_stdout(self.out):
            fn = None
            try:
                fn = self.load()
                for args in self.cases if fn is not None else ():
                    cases.append(self.case(fn, args))  # type: ignore[arg-type]  # (runs only when fn is not None)
                if fn is not None and self.figure_cases:
                    figure: list[Any] = []
                    self.report["figure"] = figure
                    cases = figure  # a stop from here on is the figure's runs' to report
                    for args in self.figure_cases:
                        figure.append(self.case(fn, args, self.figure_drive))
            except _Stop as stop:
                self.report["stopped"] = stop.why
                if fn is None:
                    self.report["load"] = {**stop.info, "phase": "load"}
                else:
                    total = len(self.cases) if cases is self.report["cases"] else len(self.figure_cases)
                    cases.append({"error": stop.info})
                    cases += [{"skipped": True}] * (total - len(cases))
        self.report["stdout"] = self.out.getvalue()
        self.report["cut"] = bool(getattr(self.out, "cut", False))
        return self.report


def run(job: dict[str, Any], code: str, restore: Restore | None = None) -> dict[str, Any]:
    """The report of running ``code`` on ``job`` (see the module's docstring). ``restore``: what is put
    back after the run (by default what :data:`~workbook_sandbox.restore.STDLIB_HOMES` names)."""
    return Run(job, code).run(restore or Restore(STDLIB_HOMES))


def run_json(job: str, code: str, restore: Restore | None = None) -> str:
    """:func:`run` with the job and the report as JSON text (what the sandbox passes on)."""
    return json.dumps(run(json.loads(job), str(code), restore))


# The sandbox's runs share one restore: its notes serve every run before which the interpreter
# still binds what they say (Restore._notes_hold), and are taken again otherwise.
_SANDBOX_RESTORE = Restore(STDLIB_HOMES)


def run_in_sandbox(job: str, code: str) -> tuple[str, bool]:
    """The sandbox worker's call: the report as JSON text, and whether the sandbox should be
    replaced now (the run was stopped by an interrupt or by running out of memory)."""
    report = run(json.loads(job), str(code), _SANDBOX_RESTORE)
    return json.dumps(report), report["stopped"] is not None
