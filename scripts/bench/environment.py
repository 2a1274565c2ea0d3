"""Where the bench ran: machine, git commit, the site's snapshot, and the
native worst case of the answer parser."""

from __future__ import annotations

import json
import os
import platform
import subprocess
import time
from pathlib import Path

from . import ROOT


def machine_info() -> dict:
    cpu = ""
    try:
        cpu = next((line.split(":", 1)[1].strip() for line in Path("/proc/cpuinfo").read_text().splitlines()
                    if line.startswith("model name")), "")
    except OSError:
        cpu = platform.processor()
    mem = None
    try:
        mem = int(next(line.split()[1] for line in Path("/proc/meminfo").read_text().splitlines()
                       if line.startswith("MemTotal"))) // 1024
    except (OSError, StopIteration):
        pass
    return {"nproc": os.cpu_count(), "cpu_model": cpu, "mem_mb": mem, "platform": platform.platform(),
            "python": platform.python_version(), "loadavg_start": list(os.getloadavg())}


def git_info() -> dict:
    def git(*a):
        try:
            return subprocess.run(["git", *a], cwd=ROOT, capture_output=True, text=True, timeout=10).stdout.strip()
        except (OSError, subprocess.SubprocessError):
            return ""
    return {"commit": git("rev-parse", "HEAD"), "dirty": bool(git("status", "--porcelain", "--untracked-files=no"))}


def snapshot_info(site: Path) -> dict:
    """Sizes of the memory snapshot the site ships (scripts/build_snapshot.mjs)."""
    path = site / "assets/vendor/pyodide/workbook.snapshot.gz"
    info = {"file": path.name, "gzip_bytes": path.stat().st_size if path.exists() else None}
    meta = ROOT / "build/snapshot.json"
    if meta.exists():
        info.update({k: v for k, v in json.loads(meta.read_text()).items() if k in ("bytes", "sha256", "wheel")})
    return info


def parser_worst_case(repeats: int = 20) -> dict:
    """The Derive answer parser on the most expensive inputs we know, timed natively.

    Its limits (length, nesting, node count, exponent) are checked before any
    evaluation, so no input should take long; this records the worst seen.
    """
    from workbook.expr import MAX_LENGTH, InvalidAnswer, parse_answer

    half = MAX_LENGTH // 2
    cases = {
        "longest sum": "+".join(["1"] * half)[:MAX_LENGTH],
        "deepest nesting": "(" * 12 + "1" + ")" * 12,
        "nested functions": "sqrt(" * 12 + "2" + ")" * 12,
        "power tower": "9**9**9",
        "largest allowed power": "2**1000",
        "many unicode roots": "√" * MAX_LENGTH,
        "10 000 digits": "9" * 10_000,
        "10 000 parentheses": "(" * 5_000 + ")" * 5_000,
        "10 000 mixed": ("sqrt(2)/2+" * 1_000)[:10_000],
    }
    worst = {}
    for name, text in cases.items():
        times = []
        for _ in range(repeats):
            t = time.perf_counter()
            try:
                parse_answer(text)
            except InvalidAnswer:
                pass
            times.append((time.perf_counter() - t) * 1000)
        worst[name] = round(max(times), 3)
    slowest = max(worst, key=lambda name: worst[name])
    return {"max_ms": worst[slowest], "slowest_input": slowest, "per_input_max_ms": worst}


def run_figure_times(repeats: int = 50) -> dict:
    """Drawing each Build exercise's run figure (workbook.figures.runs), natively: p50 over ``repeats``
    draws of the figure of a wrong run (the starter code: every case off, the worst ones drawn too)."""
    import json
    import statistics

    from workbook import bank
    from workbook.build_judge import read_report
    from workbook.figures import runs
    from workbook.kinds.build import Build
    from workbook_sandbox import runner

    per = {}
    for ex in bank.all_exercises():
        if not isinstance(ex, Build) or not getattr(ex, "run_figure", ""):
            continue
        arguments, trace = ex.arguments(), runs.trace_job(ex)
        report = read_report(runner.run(json.loads(ex.job()), ex.starter), len(arguments),
                             len(trace["cases"]) if trace else 0)
        cases = ex.cases(arguments)
        times = []
        for _ in range(repeats):
            t = time.perf_counter()
            runs.draw_run(ex, report, cases, arguments)
            times.append((time.perf_counter() - t) * 1000)
        per[ex.id] = round(statistics.median(times), 3)
    slowest = max(per, key=lambda name: per[name]) if per else None
    return {
        "max_p50_ms": per[slowest] if slowest else None,
        "slowest": slowest,
        "per_exercise_p50_ms": per,
        "repeats": repeats,
    }
