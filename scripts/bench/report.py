"""From the runs' records to metrics, targets, the table, and bench-results/."""

from __future__ import annotations

import datetime as dt
import json
from pathlib import Path

from . import ROOT
from .config import GRADED
from .network_report import render_network
from .records import fmt, summary


def collect(runs: list[dict]) -> dict:
    def pick(*path):
        vals: list[float] = []
        for r in runs:
            v: object = r
            for key in path:
                v = v.get(key) if isinstance(v, dict) else None
            if isinstance(v, (int, float)):
                vals.append(float(v))
        return summary(vals)

    m = {
        "ready_cold_ms": pick("cold", "ready_ms"),
        "ready_warm_ms": pick("warm", "ready_ms"),
        "baseline_cold_ms": pick("baseline_cold", "ready_ms"),
        "baseline_warm_ms": pick("baseline_warm", "ready_ms"),
        "worker_created_cold_ms": pick("cold", "worker_started_ms"),
        "dom_content_loaded_cold_ms": pick("cold", "nav", "domContentLoaded"),
        "first_feedback_ms": pick("first_feedback", "feedback_ms"),
        "class_page_ms": pick("class_page", "total_ms"),
        "class_stats_ms": pick("class_page", "stats_ms"),
        "class_longest_task_ms": pick("class_page", "longest_task_ms"),
        "first_feedback_click_ms": pick("first_feedback", "click_ms"),
        "build_plain_first_ms": pick("build", "plain", "first_ms"),
        "build_plain_ms": pick("build", "plain", "repeat_median_ms"),
        "build_new_first_ms": pick("build_new", "first_ms"),
        "build_new_ms": pick("build_new", "repeat_median_ms"),
        "build_heavy_first_ms": pick("build_heavy", "first_ms"),
        "build_heavy_ms": pick("build_heavy", "repeat_median_ms"),
        "build_numpy_first_ms": pick("build", "numpy", "first_ms"),
        "build_numpy_ms": pick("build", "numpy", "repeat_median_ms"),
        "numpy_bytes": pick("build", "numpy", "bytes"),
        "sandbox_start_ms": pick("build", "sandbox", "start_ms"),
        "slow_check_to_verdict_ms": pick("waiting", "check_to_verdict_ms"),
        "slow_bar_still_max_ms": pick("waiting", "bar", "still_max_ms"),
        "slow_bar_still_on_time_max_ms": pick("waiting", "bar", "still_on_time_max_ms"),
        "slow_bar_sample_gap_max_ms": pick("waiting", "bar", "sample_gap_max_ms"),
        "slow_first_build_ms": pick("waiting", "first_build_ms"),
        "sandbox_wasm_bytes": pick("build", "sandbox", "wasm_bytes"),
        "recovery_ms": pick("recovery", "recovery_ms"),
        "bytes_first_visit": pick("cold", "net", "bytes"),
        "bytes_revisit": pick("warm", "net", "bytes"),
        "bytes_revisit_without_sw_check": pick("warm", "net", "bytes_without_sw_update_check"),
        "requests_revisit": pick("warm", "net", "requests"),
        "baseline_bytes_first_visit": pick("baseline_cold", "net", "bytes"),
        "longtasks_cold_count": pick("cold", "long_tasks", "count"),
        "longtasks_cold_total_ms": pick("cold", "long_tasks", "total_ms"),
        "longtasks_cold_max_ms": pick("cold", "long_tasks", "max_ms"),
        "longtasks_warm_count": pick("warm", "long_tasks", "count"),
        "longtasks_warm_max_ms": pick("warm", "long_tasks", "max_ms"),
        "longtasks_ours": pick("cold", "long_tasks", "ours_over_50ms"),
        "baseline_longtasks_cold_total_ms": pick("baseline_cold", "long_tasks", "total_ms"),
        "baseline_longtasks_cold_max_ms": pick("baseline_cold", "long_tasks", "max_ms"),
    }
    m["draw_p50_ms"] = pick("draw", "p50_ms")
    m["draw_p95_ms"] = pick("draw", "p95_ms")
    for kind in GRADED:
        m[f"grade_{kind}_p50_ms"] = pick("grading", kind, "p50_ms")
        m[f"grade_{kind}_p95_ms"] = pick("grading", kind, "p95_ms")
        m[f"grade_{kind}_first_ms"] = pick("grading", kind, "first_ms")
    # ratios per run (same run, same conditions), then summarised
    for temp in ("cold", "warm"):
        ratios = [r[temp]["ready_ms"] / r[f"baseline_{temp}"]["ready_ms"] for r in runs
                  if r.get(temp, {}).get("ready_ms") and r.get(f"baseline_{temp}", {}).get("ready_ms")]
        m[f"ratio_{temp}"] = summary(ratios)
    return m


def evaluate_targets(m: dict, runs: list[dict]) -> list[dict]:
    def med(key):
        return (m.get(key) or {}).get("median")

    targets = []

    def add(name, value, limit, met, note=""):
        targets.append({"target": name, "value": value, "limit": limit,
                        "met": met, "note": note})

    rw, rc = med("ratio_warm"), med("ratio_cold")
    add("warm ready <= 0.5 x baseline warm", rw, 0.5, None if rw is None else rw <= 0.5, "median of per-run ratios")
    warm, cold = med("ready_warm_ms"), med("ready_cold_ms")
    both = bool(warm and cold)
    add("warm ready never slower than a cold start (ours, warm / cold)", warm / cold if both else None, 1.0,
        warm <= cold if both else None, "medians (issue 29)")
    add("localhost: cold ready <= 0.6 x baseline cold", rc, 0.6, None if rc is None else rc <= 0.6,
        "median of per-run ratios (issue 14; was 0.8)")
    p50s = {k: med(f"grade_{k}_p50_ms") for k in GRADED}
    worst = max((v for v in p50s.values() if v is not None), default=None)
    add("grading round trip p50 <= 5 ms (every kind)", worst, 5.0,
        None if worst is None or None in p50s.values() else worst <= 5.0,
        "per kind: " + ", ".join(f"{k} {v:.1f} ms" for k, v in p50s.items() if v is not None))
    d = med("draw_p50_ms")
    add("New numbers (draw) p50 <= 30 ms", d, 30.0, None if d is None else d <= 30.0,
        "worker draw + DOM + KaTeX, every Derive exercise of chapter 0 (issue 13)")
    b = med("build_plain_ms")
    add("Build run without numpy <= 50 ms", b, 50.0, None if b is None else b <= 50.0,
        "median of the repeat runs; the first run: "
        + ("-" if med("build_plain_first_ms") is None else f"{med('build_plain_first_ms'):.1f} ms"))
    f = med("run_figure_p50_ms")
    add("Run figure drawn <= 30 ms (native p50)", f, 30.0, None if f is None else f <= 30.0,
        "the slowest Build exercise's figure, of a wrong run (workbook.figures.runs)")
    b = med("build_new_ms")
    add("Build 1.7 run (Code the robot) without numpy <= 50 ms", b, 50.0, None if b is None else b <= 50.0,
        "median of the repeat runs; the closed-loop 9.9: "
        + ("-" if med("build_heavy_ms") is None else f"{med('build_heavy_ms'):.1f} ms (no target)"))
    ours = [r["cold"]["long_tasks"]["ours_over_50ms"] + r["warm"]["long_tasks"]["ours_over_50ms"]
            for r in runs if "cold" in r and "warm" in r]
    unknown = sum(1 for r in runs for w in ("cold", "warm") if w in r
                  for t in r[w]["long_tasks"]["tasks"] if t["owner"] == "unknown")
    add("no main-thread long task > 50 ms caused by our code (start-up)", sum(ours) if ours else None, 0,
        None if not ours else sum(ours) == 0,
        f"count over {2 * len(ours)} page loads (cold and warm)"
        + (f"; {unknown} long task(s) without script attribution" if unknown else ""))
    sw_runs = [r for r in runs if "warm" in r]
    controlled = [r["warm"]["sw"]["controlled"] for r in sw_runs]
    revisit = med("bytes_revisit")
    other = (m.get("bytes_revisit_without_sw_check") or {}).get("max")
    if sw_runs and all(controlled):
        add("revisit transfers 0 bytes once the service worker holds the site", revisit, 0,
            revisit == 0 or other == 0,
            "" if revisit == 0 else f"only the browser's service-worker update check (sw.js, {revisit:.0f} B) "
            "went to the network" if other == 0 else f"{other:.0f} B besides the sw.js update check")
    else:
        add("revisit transfers 0 bytes once the service worker holds the site", revisit, 0, None,
            "no service worker controlled the revisit: not measurable yet")
    c, cs, ct = med("class_page_ms"), med("class_stats_ms"), med("class_longest_task_ms")
    files = next((r["class_page"]["files"] for r in runs if "class_page" in r), None)
    add("class page: 1,000 hand-ins re-graded <= 60 s", c, 60_000.0,
        None if c is None or files != 1000 else c <= 60_000.0,
        f"{files} files (18 answers and 1 Build run each)" if files else "")
    add("class page: statistics <= 2 s", cs, 2000.0, None if cs is None else cs <= 2000.0, "after the grading")
    add("class page: no main-thread task > 200 ms", ct, 200.0, None if ct is None else ct <= 200.0,
        "from the files given to the statistics shown")
    still = med("slow_bar_still_max_ms")
    add("the loading bar never stands still > 1 s (slow first visit, CDP 8 Mbps / 40 ms / CPU x4)", still, 1000.0,
        None if still is None else still <= 1000.0, "median over runs of the longest stretch per run (250 ms samples)")
    return targets


# ---------------------------------------------------------------------------
TABLE = [
    ("Ready, cold (nav start -> runtime ready)", "ready_cold_ms", "ms"),
    ("Ready, warm (revisit)", "ready_warm_ms", "ms"),
    ("Baseline (main-thread loadPyodide), cold", "baseline_cold_ms", "ms"),
    ("Baseline, warm", "baseline_warm_ms", "ms"),
    ("Ratio cold / baseline cold", "ratio_cold", "x"),
    ("Ratio warm / baseline warm", "ratio_warm", "x"),
    ("First feedback, Check at once (cold)", "first_feedback_ms", "ms"),
    ("Class page: hand-ins read and re-graded (--class-files, 1,000 by default)", "class_page_ms", "ms"),
    ("Class page: statistics after the grading", "class_stats_ms", "ms"),
    ("Class page: longest main-thread task meanwhile", "class_longest_task_ms", "ms"),
    ("Grade round trip Derive p50", "grade_derive_p50_ms", "ms"),
    ("Grade round trip Derive p95", "grade_derive_p95_ms", "ms"),
    ("Grade round trip Trace p50", "grade_trace_p50_ms", "ms"),
    ("Grade round trip Trace p95", "grade_trace_p95_ms", "ms"),
    ("Grade round trip Debug p50", "grade_debug_p50_ms", "ms"),
    ("Grade round trip Debug p95", "grade_debug_p95_ms", "ms"),
    ("Grade round trip Design p50", "grade_design_p50_ms", "ms"),
    ("Grade round trip Design p95", "grade_design_p95_ms", "ms"),
    ("Grade round trip 3×3 matrix p50", "grade_matrix_p50_ms", "ms"),
    ("Grade round trip formula p50", "grade_formula_p50_ms", "ms"),
    ("First grade on a fresh page (Derive)", "grade_derive_first_ms", "ms"),
    ("New numbers (draw, DOM, KaTeX) p50", "draw_p50_ms", "ms"),
    ("New numbers (draw, DOM, KaTeX) p95", "draw_p95_ms", "ms"),
    ("Build 0.5 run, no numpy, first", "build_plain_first_ms", "ms"),
    ("Build 0.5 run, no numpy, repeat", "build_plain_ms", "ms"),
    ("Build 1.7 run (Code the robot), no numpy, first", "build_new_first_ms", "ms"),
    ("Build 1.7 run (Code the robot), no numpy, repeat", "build_new_ms", "ms"),
    ("Build 9.9 run (closed loop, the heaviest), no numpy, first", "build_heavy_first_ms", "ms"),
    ("Build 9.9 run (closed loop, the heaviest), no numpy, repeat", "build_heavy_ms", "ms"),
    ("Build 0.5 run, numpy, first (loads numpy)", "build_numpy_first_ms", "ms"),
    ("Build 0.5 run, numpy, repeat", "build_numpy_ms", "ms"),
    ("Sandbox start (spawn -> ready)", "sandbox_start_ms", "ms"),
    ("Slow first visit (8 Mbps, 40 ms, CPU x4): Check -> verdict", "slow_check_to_verdict_ms", "ms"),
    ("Slow first visit: loading bar stood still, longest", "slow_bar_still_max_ms", "ms"),
    ("Slow first visit: the same, busy main thread left out", "slow_bar_still_on_time_max_ms", "ms"),
    ("Slow first visit: longest gap between bar samples (busy main thread)", "slow_bar_sample_gap_max_ms", "ms"),
    ("Slow first visit: first Build run (click -> verdict)", "slow_first_build_ms", "ms"),
    ("Sandbox interpreter memory at start", "sandbox_wasm_bytes", "B"),
    ("Recovery: limit fired -> next grade", "recovery_ms", "ms"),
    ("Answer parser, worst input found (native)", "parser_worst_ms", "ms"),
    ("Run figure drawn, p50 of 50, slowest exercise (native)", "run_figure_p50_ms", "ms"),
    ("Bytes, first visit", "bytes_first_visit", "B"),
    ("Bytes, revisit", "bytes_revisit", "B"),
    ("Bytes, revisit, besides the sw.js update check", "bytes_revisit_without_sw_check", "B"),
    ("Bytes, baseline first visit", "baseline_bytes_first_visit", "B"),
    ("Bytes, loading numpy", "numpy_bytes", "B"),
    ("Long tasks at start-up, cold (count)", "longtasks_cold_count", "n"),
    ("Long tasks at start-up, cold (total)", "longtasks_cold_total_ms", "ms"),
    ("Long tasks at start-up, cold (max)", "longtasks_cold_max_ms", "ms"),
    ("Long tasks at start-up, warm (max)", "longtasks_warm_max_ms", "ms"),
    ("Long tasks caused by our code", "longtasks_ours", "n"),
    ("Baseline long tasks, cold (total)", "baseline_longtasks_cold_total_ms", "ms"),
    ("Baseline long tasks, cold (max)", "baseline_longtasks_cold_max_ms", "ms"),
]


def render_table(metrics: dict, runs: int) -> str:
    rows: list[tuple[str, ...]] = [("Measurement", f"median (n<={runs})", "min", "max")]
    for label, key, unit in TABLE:
        s = metrics.get(key)
        rows.append((label, *(fmt(s[k], unit) if s else "-" for k in ("median", "min", "max"))))
    widths = [max(len(r[i]) for r in rows) for i in range(4)]
    lines = ["| " + " | ".join(c.ljust(w) if i == 0 else c.rjust(w) for i, (c, w) in enumerate(zip(r, widths))) + " |"
             for r in rows]
    lines.insert(
        1, "|" + "|".join("-" * (w + 2) if i == 0 else "-" * (w + 1) + ":" for i, w in enumerate(widths)) + "|"
    )
    return "\n".join(lines)


def render_targets(targets: list[dict]) -> str:
    lines = []
    for t in targets:
        mark = {True: "met", False: "NOT met", None: "n/a"}[t["met"]]
        v = t["value"]
        vs = "-" if v is None else (f"{v:.2f}" if isinstance(v, float) else str(v))
        lines.append(f"- {t['target']}: {vs} (limit {t['limit']}) -> "
                     f"{mark}" + (f"  [{t['note']}]" if t["note"] else ""))
    return "\n".join(lines)



# ---------------------------------------------------------------------------
def write_results(report: dict, out: Path, started: dt.datetime) -> str:
    """bench-results/latest.json and a timestamped copy; returns the stamp."""
    out.mkdir(parents=True, exist_ok=True)
    stamp = started.strftime("%Y%m%dT%H%M%SZ")
    text = json.dumps(report, indent=2)
    (out / f"bench-{stamp}.json").write_text(text)
    (out / "latest.json").write_text(text)
    return stamp


def print_report(report: dict, out: Path, stamp: str, runs: int) -> None:
    machine, version = report["machine"], report["browser"]["version"]
    print()
    print(f"Robotics Math Workbook bench, {report['date']}, {machine['nproc']} x {machine['cpu_model']}, "
          f"Chromium {version}, commit {report['git']['commit'][:10]}{' (dirty)' if report['git']['dirty'] else ''}")
    if runs:
        print(render_table(report["metrics"], runs))
    if report.get("network"):

        print()
        print("First visit per network profile (medians):")
        print(render_network(report["network"]))
    print()
    print("Targets:")
    print(render_targets(report["targets"]))
    busy = max(machine["loadavg_start"][0], machine["loadavg_end"][0])
    if busy > 0.5 * (machine["nproc"] or 1):
        print(f"\nNOTE: the machine was busy (1-min load average up to {busy:.1f} on {machine['nproc']} CPUs): "
              "times are inflated; rerun on a quiet machine to compare.")
    booted = sorted({r[temp].get("started_from") for r in report["runs"] for temp in ("cold", "warm")
                     if isinstance(r.get(temp), dict)} - {"snapshot"}, key=str)
    if booted:
        print(f"\nWARNING: some starts did not use the memory snapshot ({booted}): those times measure the fallback "
              "boot.")
    if report["external_requests"]:
        print(f"\nWARNING: {len(report['external_requests'])} request(s) left 127.0.0.1: "
              f"{report['external_requests'][:5]}")
    if report["page_errors"]:
        print(f"\nWARNING: uncaught page errors: {report['page_errors'][:5]}")
    if report["errors"]:
        print("\nErrors:")
        for k, v in report["errors"].items():
            print(f"- {k}: {v.splitlines()[0]}")
    latest = out / "latest.json"
    print(f"\nwritten: {latest.relative_to(ROOT) if latest.is_relative_to(ROOT) else latest}"
          f" and bench-{stamp}.json ({report['duration_s']:.0f} s)")
