"""``python -m bench`` (from scripts/): options, then the order of the work.

See the package's docstring (``scripts/bench/__init__.py``) for what is measured.
"""

from __future__ import annotations

import argparse
import datetime as dt
import os
import shutil
import sys
import tempfile
import threading
import time
from pathlib import Path

from . import ROOT
from . import __doc__ as PACKAGE_DOC
from .baseline import write_baseline
from .browser import Browsers
from .config import BASELINE_PATH, CACHE_CONTROL, CH0, CHROMIUM_ARGS, GRADED, SITE
from .environment import git_info, machine_info, parser_worst_case, snapshot_info
from .phases import Phases
from .records import summary
from .report import collect, evaluate_targets, print_report, write_results

PHASES = ("startup", "first_feedback", "baseline", "ready")


def parse_args(argv=None) -> argparse.Namespace:
    ap = argparse.ArgumentParser(prog="bench", description=PACKAGE_DOC.split("\n\n")[0])
    ap.add_argument("--runs", type=int, default=int(os.environ.get("BENCH_RUNS", 5)),
                    help="runs of every measurement (default 5, or $BENCH_RUNS)")
    ap.add_argument("--checks", type=int, default=50, help="checks per kind for the grading round trip (default 50)")
    ap.add_argument("--build-repeats", type=int, default=5, help="Build runs after the first, per variant (default 5)")
    ap.add_argument("--budget", type=float, default=900, help="seconds; later runs are skipped after this (default 900)")
    ap.add_argument("--phases", default="startup,first_feedback,baseline",
                    help="comma-separated subset of startup,first_feedback,baseline (default: all); "
                         "'ready' alone measures the cold and warm start-up only (for A/B comparisons)")
    ap.add_argument("--site", type=Path, default=SITE, help="the built site to serve (default site/)")
    ap.add_argument("--out", type=Path, default=ROOT / "bench-results", help="output folder (default bench-results/)")
    args = ap.parse_args(argv)
    if args.runs < 1 or args.checks < 1 or args.build_repeats < 1:
        ap.error("--runs, --checks and --build-repeats must be at least 1")
    args.phases = [p.strip() for p in args.phases.split(",") if p.strip()]
    unknown = set(args.phases) - set(PHASES)
    if unknown:
        ap.error(f"unknown phase(s): {sorted(unknown)}")
    return args


def start_watchdog(seconds: float) -> None:
    """A hard stop, whatever happens in the browser."""
    def stop():
        print("bench: hard time limit reached", file=sys.stderr)
        os._exit(3)

    watchdog = threading.Timer(seconds, stop)
    watchdog.daemon = True
    watchdog.start()


def measure(args, work: Path) -> dict:
    """Serve a copy of the site and the baseline; run the phases; return what was seen."""
    from playwright.sync_api import sync_playwright
    from site_server import SiteServer

    # Serve a copy: a `make site` elsewhere during the run must not change what is measured.
    site_copy = work / "site"
    shutil.copytree(args.site, site_copy)
    baseline_files = write_baseline(site_copy, work / "baseline", BASELINE_PATH)
    with SiteServer(site_copy, mounts={BASELINE_PATH: work / "baseline"}, cache_control=CACHE_CONTROL,
                    keep_alive=True) as server, sync_playwright() as pw:
        browsers = Browsers(pw, server, args.budget)
        print(f"bench: {args.runs} run(s), {browsers.executable}, site at {browsers.site}", file=sys.stderr)
        phases = Phases(browsers, args)
        try:
            phases.run_all(args.phases, args.runs)
        finally:
            browsers.remove_profiles()
    return {"runs": phases.runs, "version": browsers.version, "executable": browsers.executable,
            "external": browsers.external, "page_errors": browsers.page_errors, "baseline_files": baseline_files}


def build_report(args, seen: dict, started: dt.datetime, t0: float, machine: dict) -> dict:
    runs = seen["runs"]
    metrics = collect(runs)
    parser = parser_worst_case()
    metrics["parser_worst_ms"] = summary([parser["max_ms"]])
    metrics["parser_worst_case"] = parser
    return {
        "date": started.isoformat(timespec="seconds"),
        "duration_s": round(time.monotonic() - t0, 1),
        "machine": machine,
        "browser": {"name": "chromium", "version": seen["version"], "executable": seen["executable"],
                    "args": CHROMIUM_ARGS, "headless": True},
        "git": git_info(),
        "config": {"runs": args.runs, "checks": args.checks, "build_repeats": args.build_repeats,
                   "server": "Python ThreadingHTTPServer, HTTP/1.1 keep-alive, Cache-Control: max-age=600, "
                             "Last-Modified/If-Modified-Since, no compression",
                   "baseline_files": seen["baseline_files"],
                   "snapshot": snapshot_info(args.site),
                   "pages": {"startup": CH0, "grading": {k: f"{p} {i}" for k, (p, i) in GRADED.items()}}},
        "metrics": metrics,
        "targets": evaluate_targets(metrics, runs),
        "external_requests": sorted(set(seen["external"])),
        "page_errors": seen["page_errors"],
        "errors": {f"run {r['index']} {k}": v for r in runs for k, v in r["errors"].items()},
        "runs": runs,
    }


def main(argv=None) -> int:
    args = parse_args(argv)
    if not (args.site / "index.html").exists():
        print("site/ is not built: run `make site` (make bench does)", file=sys.stderr)
        return 2
    start_watchdog(args.budget + 300)
    started = dt.datetime.now(dt.timezone.utc)
    t0 = time.monotonic()
    machine = machine_info()
    work = Path(tempfile.mkdtemp(prefix="wb-bench-"))
    try:
        seen = measure(args, work)
    finally:
        shutil.rmtree(work, ignore_errors=True)
    machine["loadavg_end"] = list(os.getloadavg())
    report = build_report(args, seen, started, t0, machine)
    stamp = write_results(report, args.out, started)
    print_report(report, args.out, stamp, args.runs)
    return 1 if report["errors"] else 0


if __name__ == "__main__":
    sys.exit(main())
