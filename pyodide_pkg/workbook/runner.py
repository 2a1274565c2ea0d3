"""Run a learner's Build code against its tests.

The code is compiled under the file name ``<your code>`` so tracebacks can be cut
down to the learner's own frames and line numbers. ``print`` output is captured
(and capped). Time limits are enforced by the caller: the page stops the worker.
"""

from __future__ import annotations

import contextlib
import io
import math
import random
import traceback
from typing import Any

from .exercises import Build
from .result import Result

FILENAME = "<your code>"
STDOUT_CAP = 4000


class _CappedIO(io.StringIO):
    def write(self, s: str) -> int:
        room = STDOUT_CAP - self.tell()
        if room > 0:
            super().write(s[:room])
        return len(s)


def _short(value: Any) -> str:
    if isinstance(value, float):
        return repr(round(value, 6))
    if isinstance(value, (list, tuple)):
        inner = ", ".join(_short(v) for v in value)
        return f"({inner})" if isinstance(value, tuple) else f"[{inner}]"
    text = repr(value)
    return text if len(text) <= 80 else text[:77] + "..."


def _call_text(ex: Build, args: tuple) -> str:
    return f"{ex.function}({', '.join(_short(a) for a in args)})"


def _error_info(err: BaseException, source_lines: list[str]) -> dict[str, Any]:
    """A short traceback holding only the learner's frames."""
    lines: list[str] = []
    last_line = None
    if isinstance(err, SyntaxError) and err.filename == FILENAME:
        last_line = err.lineno
        lines.append(f"line {err.lineno}: {(err.text or '').rstrip()}")
        return {"type": "SyntaxError", "message": err.msg, "line": last_line,
                "traceback": "\n".join(lines + [f"SyntaxError: {err.msg}"])}
    for frame in traceback.extract_tb(err.__traceback__):
        if frame.filename == FILENAME:
            last_line = frame.lineno
            code = source_lines[frame.lineno - 1].strip() if frame.lineno and frame.lineno <= len(source_lines) else ""
            lines.append(f"line {frame.lineno}, in {frame.name}: {code}")
    summary = f"{type(err).__name__}: {err}"
    return {"type": type(err).__name__, "message": str(err), "line": last_line,
            "traceback": "\n".join(lines + [summary])}


def _as_pair(value: Any, size: int) -> list[float]:
    """Turn a list, tuple or NumPy array of ``size`` numbers into floats."""
    if isinstance(value, (str, bytes, dict)) or not hasattr(value, "__iter__"):
        raise TypeError(f"expected a sequence of {size} numbers, got {type(value).__name__} {_short(value)}")
    items = list(value)
    if len(items) != size:
        raise TypeError(f"expected {size} numbers, got {len(items)}: {_short(value)}")
    out = []
    for item in items:
        if isinstance(item, (str, bytes)) or hasattr(item, "__len__"):
            raise TypeError(f"expected plain numbers, got {type(item).__name__} {_short(item)} inside the result")
        out.append(float(item))
    return out


def _agrees(ex: Build, got: list[float], want: list[float]) -> bool:
    return all(math.isclose(g, w, rel_tol=ex.rel_tol, abs_tol=max(ex.abs_tol, 1e-9)) for g, w in zip(got, want))


def hidden_cases(ex: Build) -> list[tuple]:
    rng = random.Random(f"hidden:{ex.id}")
    return [ex.random_args(rng) for _ in range(ex.hidden_count)]


def run_build(ex: Build, code: str) -> Result:
    source_lines = code.split("\n")
    out = _CappedIO()
    rows: list[dict[str, Any]] = []

    def finish(status: str, message: str, tag: str = "", error: dict | None = None) -> Result:
        text = out.getvalue()
        if out.tell() >= STDOUT_CAP:
            text += "\n… (output cut)"
        return Result(status, message, tag=tag, data={"tests": rows, "stdout": text, "error": error})

    try:
        compiled = compile(code, FILENAME, "exec")
    except SyntaxError as err:
        info = _error_info(err, source_lines)
        return finish("incorrect", f"Syntax error on line {info['line']}: {err.msg}.", "syntax", info)
    namespace: dict[str, Any] = {"__name__": "__learner__"}
    with contextlib.redirect_stdout(out):
        try:
            exec(compiled, namespace)
        except MemoryError:
            return finish("error", "Your code ran out of memory. The Python runtime was restarted; your code is kept.", "memory")
        except Exception as err:
            info = _error_info(err, source_lines)
            return finish("incorrect", f"Your code raised {info['type']} while loading.", "exception", info)
        fn = namespace.get(ex.function)
        if not callable(fn):
            return finish("incorrect", f"Define a function named {ex.signature}.", "missing")

        def one(args: tuple) -> tuple[bool, dict[str, Any]]:
            want = [float(v) for v in ex.reference(*args)]
            row: dict[str, Any] = {"input": _call_text(ex, args), "expected": _short(tuple(round(w, 6) for w in want))}
            try:
                got_raw = fn(*args)
            except MemoryError:
                raise
            except Exception as err:
                info = _error_info(err, source_lines)
                row.update(actual=f"raised {info['type']}", passed=False, message=info["traceback"], line=info["line"])
                return False, row
            row["actual"] = _short(got_raw)
            try:
                got = _as_pair(got_raw, len(want))
            except (TypeError, ValueError) as err:
                row.update(passed=False, message=str(err))
                return False, row
            row["actual"] = _short(tuple(round(g, 6) for g in got))
            ok = _agrees(ex, got, want)
            row.update(passed=ok, message="" if ok else "values differ")
            return ok, row

        try:
            for args in ex.examples:
                ok, row = one(args)
                row["name"] = "example"
                rows.append(row)
            hidden = hidden_cases(ex)
            failed = None
            for args in hidden:
                ok, row = one(args)
                if not ok:
                    failed = row
                    break
            summary = {"name": f"{len(hidden)} hidden random cases", "passed": failed is None}
            if failed is None:
                summary.update(input=f"{len(hidden)} random inputs", expected="reference values", actual="all agree", message="")
            else:
                summary.update({k: failed[k] for k in ("input", "expected", "actual", "message")})
                if failed.get("line"):
                    summary["line"] = failed["line"]
            rows.append(summary)
        except MemoryError:
            return finish("error", "Your code ran out of memory. The Python runtime was restarted; your code is kept.", "memory")

    passed = sum(1 for r in rows if r["passed"])
    error = next(({"line": r["line"], "traceback": r["message"]} for r in rows if r.get("line")), None)
    if passed == len(rows):
        return finish("correct", f"All {len(rows)} tests pass.")
    return finish("incorrect", f"{passed} of {len(rows)} tests pass.", "exception" if error else "", error)
