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
from .config import (
    BASELINE_PATH,
    CACHE_CONTROL,
    CH0,
    CHROMIUM_ARGS,
    DEFAULT_PROFILES,
    GRADED,
    PROFILES,
    SITE,
    STOCK_PATH,
)
from .environment import git_info, machine_info, parser_worst_case, run_figure_times, snapshot_info
from .network_report import collect_network, network_targets
from .phases import LOCAL_PHASES, Phases
from .records import summary
from .report import collect, evaluate_targets, print_report, write_results
from .stock_page import build_stock


def parse_args(argv=None) -> argparse.Namespace:
    ap = argparse.ArgumentParser(prog="bench", description=PACKAGE_DOC.split("\n\n")[0])
    ap.add_argument("--runs", type=int, default=int(os.environ.get("BENCH_RUNS", 5)),
                    help="runs of every measurement (default 5, or $BENCH_RUNS)")
    ap.add_argument("--draws", type=int, default=10, help="rounds of New numbers over a page's Derive exercises "
                                                          "(default 10)")
    ap.add_argument("--checks", type=int, default=50, help="checks per kind for the grading round trip (default 50)")
    ap.add_argument("--build-repeats", type=int, default=5, help="Build runs after the first, per variant (default 5)")
    ap.add_argument("--budget", type=float, default=2400,
                    help="seconds for all profiles; later runs are skipped after this (default 2400)")
    ap.add_argument("--profiles", default=DEFAULT_PROFILES,
                    help="comma-separated network profiles, each NAME or NAME:RUNS, of "
                         f"{', '.join(PROFILES)} (default {DEFAULT_PROFILES}: localhost --runs times, "
                         + ", ".join(f"{p.name} {p.runs}" for p in PROFILES.values() if p.runs) + " times at most)")
    ap.add_argument("--phases", default="startup,first_feedback,baseline,class_page,waiting",
                    help="comma-separated subset of startup,first_feedback,baseline,class_page,waiting (default: all); "
                         "'ready' alone measures the cold and warm start-up only (for A/B comparisons)")
    ap.add_argument("--class-files", type=int, default=1000,
                    help="hand-in files the class page re-grades (default 1000)")
    ap.add_argument("--site", type=Path, default=SITE, help="the built site to serve (default site/)")
    ap.add_argument("--out", type=Path, default=ROOT / "bench-results", help="output folder (default bench-results/)")
    args = ap.parse_args(argv)
    if args.runs < 1 or args.checks < 1 or args.build_repeats < 1 or args.class_files < 1:
        ap.error("--runs, --checks, --build-repeats and --class-files must be at least 1")
    args.phases = [p.strip() for p in args.phases.split(",") if p.strip()]
    unknown = set(args.phases) - set(LOCAL_PHASES)
    if unknown:
        ap.error(f"unknown phase(s): {sorted(unknown)}")
    args.profiles = parse_profiles(ap, args.profiles, args.runs)
    return args


def parse_profiles(ap, text: str, runs: int) -> dict[str, int]:
    """``"localhost,phone:1"`` -> {"localhost": runs, "phone": 1}."""
    out = {}
    for item in (p.strip() for p in text.split(",") if p.strip()):
        name, _, count = item.partition(":")
        if name not in PROFILES:
            ap.error(f"unknown profile {name!r}: choose from {', '.join(PROFILES)}")
        if count and not (count.isdigit() and int(count) >= 1):
            ap.error(f"profile {item!r}: the run count must be a whole number >= 1")
        default = min(runs, cap) if (cap := PROFILES[name].runs) else runs
        out[name] = int(count) if count else default
    if not out:
        ap.error("--profiles: name at least one profile")
    return out


def start_watchdog(seconds: float) -> None:
    """A hard stop, whatever happens in the browser."""
    def stop():
        print("bench: hard time limit reached", file=sys.stderr)
        os._exit(3)

    watchdog = threading.Timer(seconds, stop)
    watchdog.daemon = True
    watchdog.start()


def measure(args, work: Path, deadline: float) -> dict:
    """Serve a copy of the site and the baseline; run each profile's phases; return what was seen."""
    from playwright.sync_api import sync_playwright

    # Serve a copy: a `make site` elsewhere during the run must not change what is measured.
    site_copy = work / "site"
    shutil.copytree(args.site, site_copy)
    baseline_files = write_baseline(site_copy, work / "baseline", BASELINE_PATH)
    mounts = {BASELINE_PATH: work / "baseline", STOCK_PATH: build_stock(work / "stock")}
    seen = {"profiles": {}, "version": "", "executable": "", "external": [], "page_errors": [],
            "baseline_files": baseline_files, "cpu_notes": {}}
    with sync_playwright() as pw:
        for name, runs in args.profiles.items():
            measure_profile(args, pw, PROFILES[name], runs, site_copy, mounts, deadline, seen)
    return seen


def measure_profile(args, pw, profile, runs: int, site: Path, mounts: dict, deadline: float, seen: dict) -> None:
    """One profile: its own server (link) and browsers (CPU); localhost runs the phases of today too."""
    from site_server import SiteServer

    with SiteServer(site, mounts=mounts, cache_control=CACHE_CONTROL, keep_alive=True,
                    link=profile.link) as server:
        if profile.link and profile.link.gzip:
            server.precompress()  # before the clock runs, as a real host has it ready
        browsers = Browsers(pw, server, deadline, profile.cpu_slowdown, profile.cpu_share)
        seen["cpu_notes"][profile.name] = browsers.cpu_note
        link = "no emulation" if not profile.link else \
            f"{profile.link.bandwidth_bps / 1e6:g} Mbps, {profile.link.rtt_ms:g} ms RTT, gzip"
        print(f"bench: {profile.name} ({link}, CPU x{profile.cpu_slowdown:g}): {runs} run(s), "
              f"{browsers.executable}, site at {browsers.site}", file=sys.stderr)
        phases = Phases(browsers, args, profile)
        try:
            phases.run_all(args.phases if profile.name == "localhost" else [], runs)
        finally:
            browsers.close()
    seen["profiles"][profile.name] = phases.runs
    seen["version"] = seen["version"] or browsers.version
    seen["executable"] = browsers.executable
    seen["args"] = browsers.args
    seen["external"] += browsers.external
    seen["page_errors"] += browsers.page_errors


def build_report(args, seen: dict, started: dt.datetime, t0: float, machine: dict) -> dict:
    runs = seen["profiles"].get("localhost", [])
    metrics = collect(runs)
    network = collect_network(seen["profiles"])
    parser = parser_worst_case()
    metrics["parser_worst_ms"] = summary([parser["max_ms"]])
    metrics["parser_worst_case"] = parser
    drawn = run_figure_times()
    metrics["run_figure_p50_ms"] = summary([drawn["max_p50_ms"]])
    metrics["run_figure_times"] = drawn
    return {
        "date": started.isoformat(timespec="seconds"),
        "duration_s": round(time.monotonic() - t0, 1),
        "machine": machine,
        "browser": {"name": "chromium", "version": seen["version"], "executable": seen["executable"],
                    "args": seen.get("args", CHROMIUM_ARGS), "headless": True},
        "git": git_info(),
        "config": {"runs": args.runs, "checks": args.checks, "build_repeats": args.build_repeats,
                   "server": "Python ThreadingHTTPServer, HTTP/1.1 keep-alive, Cache-Control: max-age=600, "
                             "Last-Modified/If-Modified-Since, no compression (localhost profile)",
                   "profiles": {name: profile_config(name, n, seen["cpu_notes"].get(name))
                                for name, n in args.profiles.items()},
                   "baseline_files": seen["baseline_files"],
                   "snapshot": snapshot_info(args.site),
                   "pages": {"startup": CH0, "grading": {k: f"{p} {i}" for k, (p, i) in GRADED.items()}}},
        "metrics": metrics,
        "targets": (evaluate_targets(metrics, runs) if runs else []) + network_targets(network),
        "network": network,
        "external_requests": sorted(set(seen["external"])),
        "page_errors": seen["page_errors"],
        "errors": {f"{'' if name == 'localhost' else name + ' '}run {r['index']} {k}": v
                   for name, prs in seen["profiles"].items() for r in prs for k, v in r["errors"].items()},
        "runs": runs,
        "profile_runs": {name: prs for name, prs in seen["profiles"].items() if name != "localhost"},
    }


def profile_config(name: str, runs: int, cpu_note: str | None) -> dict:
    p = PROFILES[name]
    link = None if p.link is None else {
        "bandwidth_mbps": p.link.bandwidth_bps / 1e6, "rtt_ms": p.link.rtt_ms, "gzip": p.link.gzip,
        "model": "one token bucket shared by every connection (16 KiB writes), one RTT before each response"}
    return {"runs": runs, "link": link, "cpu_slowdown": p.cpu_slowdown, "cpu_note": cpu_note,
            "ready_timeout_ms": p.ready_timeout_ms, "precache_timeout_ms": p.precache_timeout_ms}


def main(argv=None) -> int:
    args = parse_args(argv)
    if not (args.site / "index.html").exists():
        print("site/ is not built: run `make site` (make bench does)", file=sys.stderr)
        return 2
    start_watchdog(args.budget + 1200)  # a phase begun before the budget ran out may take long
    started = dt.datetime.now(dt.UTC)
    t0 = time.monotonic()
    machine = machine_info()
    work = Path(tempfile.mkdtemp(prefix="wb-bench-"))
    try:
        seen = measure(args, work, t0 + args.budget)
    finally:
        shutil.rmtree(work, ignore_errors=True)
    machine["loadavg_end"] = list(os.getloadavg())
    report = build_report(args, seen, started, t0, machine)
    stamp = write_results(report, args.out, started)
    print_report(report, args.out, stamp, args.profiles.get("localhost", 0))
    return 1 if report["errors"] else 0


if __name__ == "__main__":
    sys.exit(main())
