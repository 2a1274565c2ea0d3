"""Build: write a Python function; tests compare it with the reference implementation.

The learner's code is compiled under the file name ``<your code>`` so tracebacks
can be cut down to the learner's own frames and line numbers; ``print`` output
is captured (and capped). Time limits are enforced by the page (it interrupts or
replaces the worker).

A run is isolated from the grader: every expected value is computed before the
learner's code starts, each call gets its own copy of the arguments, and
whatever the code rebinds in a loaded module (``workbook.*``, ``math``,
``random``, builtins, ...) or in the grader's classes is put back when the run
ends (see :class:`Isolation`).
"""

from __future__ import annotations

import contextlib
import copy
import io
import math
import random
import sys
import traceback
from dataclasses import dataclass
from typing import Any, Callable, ClassVar

from ..contract import ROLE, TAG
from ..verdict import GradingError, Verdict
from .base import ATTR, Exercise, Page, escape, role_attr

FILENAME = "<your code>"
STDOUT_CAP = 4000
OUT_OF_MEMORY = "Your code ran out of memory. The Python runtime was restarted; your code is kept."


@dataclass(frozen=True)
class Build(Exercise):
    """``examples`` are the visible cases (argument tuples, usually the workbook's
    own numbers); ``random_args`` draws the hidden cases from a seeded RNG.
    """

    function: str = ""
    params: tuple[str, ...] = ()
    starter: str = ""
    solution: str = ""
    reference: Callable[..., Any] | None = None
    examples: tuple[tuple, ...] = ()
    random_args: Callable[[random.Random], tuple] | None = None
    hidden_count: int = 20
    rel_tol: float = 1e-6
    abs_tol: float = 1e-9
    time_limit: float = 5.0
    kind: ClassVar[str] = "build"
    op: ClassVar[str] = "run"
    reveal_label: ClassVar[str] = "Show solution"

    @property
    def signature(self) -> str:
        return f"{self.function}({', '.join(self.params)})"

    def hidden_cases(self) -> list[tuple]:
        rng = random.Random(f"hidden:{self.id}")
        return [self.random_args(rng) for _ in range(self.hidden_count)]

    def check(self, code: object) -> Verdict:
        return run(self, str(code))

    def widget(self, base: str, page: Page) -> str:
        return (
            f'<div class="wb-build">'
            f'<p class="wb-label" id="{base}-editor-label">Your code: define <code>{escape(self.signature)}</code>. '
            f"<kbd>Ctrl</kbd>+<kbd>Enter</kbd> runs the tests.</p>"
            f'<div class="wb-editor" {role_attr(ROLE.editor)} data-time-limit="{self.time_limit:g}" '
            f'aria-labelledby="{base}-editor-label">'
            f'<pre class="wb-starter" {role_attr(ROLE.code)}><code>{escape(self.starter)}</code></pre></div>'
            f'<div class="wb-build-actions">'
            f'<button type="button" class="md-button md-button--primary" {role_attr(ROLE.run)}>Run tests</button>'
            f'<button type="button" class="md-button" {role_attr(ROLE.reset)}>Reset to starter</button></div>'
            f'<div class="wb-tests" {role_attr(ROLE.tests)} hidden></div>'
            f'<pre class="wb-stdout" {role_attr(ROLE.stdout)} hidden></pre>'
            f"</div>"
        )


EXERCISE = Build
_ = ATTR  # the widget's attributes all come from the contract


# ---- Isolation -------------------------------------------------------------------


class Isolation:
    """Put back, when a run ends, whatever the learner's code rebound.

    On entry it records the namespace of every loaded module, the attributes of
    the classes defined in the grader's modules and those it relies on
    (``CLASS_HOMES``), and the fields of every loaded exercise; on exit it
    restores them (names the run added are removed) and reseeds ``random``. Modules the run imported stay
    loaded (NumPy is slow to load), with their state reset to before the run only
    where they existed before it.
    """

    def __enter__(self) -> "Isolation":
        self.modules = {name: (mod, dict(vars(mod))) for name, mod in list(sys.modules.items())
                        if mod is not None and hasattr(mod, "__dict__")}
        self.classes = [(cls, dict(vars(cls))) for cls in _grader_classes()]
        self.objects = [(obj, dict(vars(obj))) for obj in _grader_objects()]
        return self

    def __exit__(self, *exc: object) -> None:
        for mod, saved in self.modules.values():
            space = vars(mod)
            if not _same(space, saved):
                space.clear()
                space.update(saved)
        for obj, saved in self.objects:
            if not _same(vars(obj), saved):
                vars(obj).clear()
                vars(obj).update(saved)
        for cls, saved in self.classes:
            for name in set(vars(cls)) - set(saved):
                with contextlib.suppress(AttributeError, TypeError):
                    delattr(cls, name)
            for name, value in saved.items():
                if vars(cls).get(name, _MISSING) is not value:
                    with contextlib.suppress(AttributeError, TypeError):
                        setattr(cls, name, value)
        random.seed()


_MISSING = object()


def _same(space: dict, saved: dict) -> bool:
    """True when no name was added, removed or rebound (by identity: values may be arrays)."""
    return len(space) == len(saved) and all(space.get(k, _MISSING) is v for k, v in saved.items())


def _grader_objects() -> list[object]:
    """The exercises of the chapters loaded so far (their fields hold keys and references)."""
    out: list[object] = []
    for name, mod in list(sys.modules.items()):
        if name.startswith("workbook.bank.ch"):
            out += [ex for ex in getattr(mod, "EXERCISES", ()) if hasattr(ex, "__dict__")]
    return out


# Modules whose classes' attributes are restored too (every module's own names always are).
CLASS_HOMES = ("workbook", "random", "math", "copy", "json", "io", "contextlib", "traceback", "dataclasses")


def _grader_classes() -> list[type]:
    out = []
    for name, mod in list(sys.modules.items()):
        if name.split(".")[0] in CLASS_HOMES:
            out += [v for v in vars(mod).values() if isinstance(v, type) and v.__module__ == name]
    return out


# ---- Running -------------------------------------------------------------------


class _CappedIO(io.StringIO):
    def write(self, s: str) -> int:
        room = STDOUT_CAP - self.tell()
        if room > 0:
            super().write(s[:room])
        return len(s)


def short(value: Any) -> str:
    """A value as a test row shows it.

    >>> short(0.1234567891), short((1, [2.0, 'x'])), len(short("y" * 100))
    ('0.123457', "(1, [2.0, 'x'])", 80)
    """
    if isinstance(value, float):
        return repr(round(value, 6))
    if isinstance(value, (list, tuple)):
        inner = ", ".join(short(v) for v in value)
        return f"({inner})" if isinstance(value, tuple) else f"[{inner}]"
    text = repr(value)
    return text if len(text) <= 80 else text[:77] + "..."


def error_info(err: BaseException, source_lines: list[str]) -> dict[str, Any]:
    """A short traceback that holds only the learner's frames."""
    if isinstance(err, SyntaxError) and err.filename == FILENAME:
        line = f"line {err.lineno}: {(err.text or '').rstrip()}"
        return {"type": "SyntaxError", "message": err.msg, "line": err.lineno,
                "traceback": f"{line}\nSyntaxError: {err.msg}"}
    lines: list[str] = []
    last_line = None
    for frame in traceback.extract_tb(err.__traceback__):
        if frame.filename == FILENAME:
            last_line = frame.lineno
            code = source_lines[frame.lineno - 1].strip() if frame.lineno and frame.lineno <= len(source_lines) else ""
            lines.append(f"line {frame.lineno}, in {frame.name}: {code}")
    lines.append(f"{type(err).__name__}: {err}")
    return {"type": type(err).__name__, "message": str(err), "line": last_line, "traceback": "\n".join(lines)}


def as_numbers(value: Any, size: int) -> list[float]:
    """A list, tuple or NumPy array of ``size`` plain numbers, as floats."""
    if isinstance(value, (str, bytes, dict)) or not hasattr(value, "__iter__"):
        raise TypeError(f"expected a sequence of {size} numbers, got {type(value).__name__} {short(value)}")
    items = list(value)
    if len(items) != size:
        raise TypeError(f"expected {size} numbers, got {len(items)}: {short(value)}")
    out = []
    for item in items:
        if isinstance(item, (str, bytes)) or hasattr(item, "__len__"):
            raise TypeError(f"expected plain numbers, got {type(item).__name__} {short(item)} inside the result")
        out.append(float(item))
    return out


@dataclass
class Case:
    """One test: its arguments, the reference's answer and how both are shown, all
    computed before any learner code runs."""

    name: str
    args: tuple
    want: list[float]
    input: str
    expected: str


def cases_for(ex: Build) -> tuple[list[Case], list[Case]]:
    def case(name: str, args: tuple) -> Case:
        want = [float(v) for v in ex.reference(*copy.deepcopy(args))]
        return Case(name, args, want, f"{ex.function}({', '.join(short(a) for a in args)})",
                    short(tuple(round(w, 6) for w in want)))

    return [case("example", a) for a in ex.examples], [case("hidden", a) for a in ex.hidden_cases()]


class _Run:
    """One run of a learner's code against an exercise's tests."""

    def __init__(self, ex: Build, code: str) -> None:
        self.ex, self.code = ex, code
        self.lines = code.split("\n")
        self.out = _CappedIO()
        self.rows: list[dict[str, Any]] = []
        self.isclose = math.isclose  # bound now: the learner's code may rebind math.isclose

    def verdict(self, status: str, message: str, tag: str = "", error: dict | None = None) -> Verdict:
        text = self.out.getvalue()
        if self.out.tell() >= STDOUT_CAP:
            text += "\n… (output cut)"
        return Verdict(status, message, tag=tag, data={"tests": self.rows, "stdout": text, "error": error})

    def load(self) -> Callable[..., Any] | Verdict:
        """Compile and execute the code; the learner's function, or a verdict on why there is none."""
        try:
            compiled = compile(self.code, FILENAME, "exec")
        except SyntaxError as err:
            info = error_info(err, self.lines)
            return self.verdict("incorrect", f"Syntax error on line {info['line']}: {err.msg}.", TAG.syntax, info)
        namespace: dict[str, Any] = {"__name__": "__learner__"}
        try:
            exec(compiled, namespace)
        except MemoryError:
            raise
        except Exception as err:
            info = error_info(err, self.lines)
            return self.verdict("incorrect", f"Your code raised {info['type']} while loading.", TAG.exception, info)
        fn = namespace.get(self.ex.function)
        if not callable(fn):
            return self.verdict("incorrect", f"Define a function named {self.ex.signature}.", TAG.missing)
        return fn

    def test(self, fn: Callable[..., Any], case: Case) -> dict[str, Any]:
        ex = self.ex
        row: dict[str, Any] = {"name": case.name, "input": case.input, "expected": case.expected}
        try:
            got_raw = fn(*copy.deepcopy(case.args))
        except MemoryError:
            raise
        except Exception as err:
            info = error_info(err, self.lines)
            return {**row, "actual": f"raised {info['type']}", "passed": False, "message": info["traceback"],
                    "line": info["line"]}
        try:
            got = as_numbers(got_raw, len(case.want))
        except (TypeError, ValueError) as err:
            return {**row, "actual": short(got_raw), "passed": False, "message": str(err)}
        ok = all(self.isclose(g, w, rel_tol=ex.rel_tol, abs_tol=max(ex.abs_tol, 1e-9)) for g, w in zip(got, case.want))
        return {**row, "actual": short(tuple(round(g, 6) for g in got)), "passed": ok, "message": ""}

    def hidden_summary(self, fn: Callable[..., Any], hidden: list[Case]) -> dict[str, Any]:
        """One row for all the hidden cases: the first that fails, or 'all agree'."""
        summary = {"name": f"{len(hidden)} hidden random cases"}
        for case in hidden:
            row = self.test(fn, case)
            if not row["passed"]:
                return {**row, **summary}
        return {**summary, "input": f"{len(hidden)} random inputs", "expected": "reference values",
                "actual": "all agree", "passed": True, "message": ""}

    def grade(self) -> Verdict:
        examples, hidden = cases_for(self.ex)
        with contextlib.redirect_stdout(self.out), Isolation():
            loaded = self.load()
            if isinstance(loaded, Verdict):
                return loaded
            self.rows = [self.test(loaded, case) for case in examples]
            self.rows.append(self.hidden_summary(loaded, hidden))
        passed = sum(1 for r in self.rows if r["passed"])
        if passed == len(self.rows):
            return self.verdict("correct", f"All {len(self.rows)} tests pass.")
        error = next(({"line": r["line"], "traceback": r["message"]} for r in self.rows if r.get("line")), None)
        return self.verdict("incorrect", f"{passed} of {len(self.rows)} tests pass.",
                            TAG.exception if error else TAG.failed, error)


def run(ex: Build, code: str) -> Verdict:
    """Run ``code`` against the tests of ``ex``; raises GradingError("memory") when it runs out of memory."""
    try:
        return _Run(ex, code).grade()
    except MemoryError:
        raise GradingError("memory", OUT_OF_MEMORY) from None
