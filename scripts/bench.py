#!/usr/bin/env python3
"""Measure how fast the workbook starts and grades, next to a baseline.

Run by ``make bench`` (after ``make site``); docs/performance.md explains the
numbers. It serves a copy of ``site/`` on 127.0.0.1 under a sub-path, as GitHub
Pages serves a project site (``Cache-Control: max-age=600``, ``Last-Modified``)
but without gzip, drives headless Chromium with Playwright (the tests' browser
and flags; every request not to 127.0.0.1 fails through a dead proxy), and
writes ``bench-results/latest.json``, a timestamped copy, and a table to stdout.

- Each run starts a fresh browser with an empty profile of its own (cold), then
  revisits in it (warm: HTTP cache, code cache and service worker as a returning
  learner has them). Playwright's off-the-record ``new_context()`` is not used:
  its in-memory cache refuses the 10 MB pyodide.asm.wasm, and its request
  routing would turn the HTTP cache off.
- Times are taken inside the page (``performance.now()``, zero at the navigation
  start; MutationObservers on ``data-workbook-runtime`` and ``data-state``), so
  Playwright's own overhead is not in them. Bytes are counted by the server.
- The BASELINE is a blank page that calls ``loadPyodide()`` on the main thread
  with stock Pyodide 0.27.7 files and the site's lock file, loads the same
  package and imports ``workbook.api``: the way many Pyodide exercise sites start.

    .venv/bin/python scripts/bench.py [--runs N] [--checks 50] [--budget 900]

``BENCH_RUNS`` in the environment sets the default for ``--runs`` (so does
``make bench BENCH_RUNS=7``).
"""

from __future__ import annotations

import argparse
import datetime as dt
import functools
import http.server
import json
import os
import platform
import shutil
import statistics
import subprocess
import sys
import tempfile
import threading
import time
import traceback
from pathlib import Path
from urllib.parse import urlsplit

ROOT = Path(__file__).resolve().parent.parent
SITE = ROOT / "site"
SUBPATH = "/workbook/"
BASELINE_PATH = "/baseline/"
sys.path.insert(0, str(ROOT / "scripts"))

from find_browser import find_browser  # noqa: E402

# The tests' flags (tests/browser/conftest.py).
CHROMIUM_ARGS = ["--no-sandbox", "--disable-gpu", "--disable-background-networking", "--disable-component-update",
                 "--disable-sync", "--no-first-run", "--disable-quic"]
# Nothing listens on port 9 ("discard"): every request that is not to 127.0.0.1 fails.
DEAD_PROXY = {"server": "http://127.0.0.1:9", "bypass": "127.0.0.1"}

CH0, CH1, CH3 = "chapters/00-rotations-2d/", "chapters/01-transforms/", "chapters/03-ekf-predict/"
# One exercise of each checked kind: (page, id).
GRADED = {"derive": (CH0, "0.1"), "trace": (CH0, "0.3"), "debug": (CH3, "3.5"), "design": (CH1, "1.5")}
DERIVE_INPUT = "sqrt(2)/2"  # an expression (exercises the parser), graded incorrect

BUILD_ID = "0.5"
BUILD_PLAIN = (
    "import math\n\n\n"
    "def rotate_2d(x, y, theta):\n"
    "    c, s = math.cos(theta), math.sin(theta)\n"
    "    return (c * x - s * y, s * x + c * y)\n"
)
BUILD_NUMPY = (
    "import numpy as np\n\n\n"
    "def rotate_2d(x, y, theta):\n"
    "    c, s = np.cos(theta), np.sin(theta)\n"
    "    return np.array([[c, -s], [s, c]]) @ np.array([x, y])\n"
)
BUILD_LOOP = "while True:\n    pass\n"

READY_TIMEOUT_MS = 90_000
GRADE_TIMEOUT_MS = 15_000
NUMPY_TIMEOUT_MS = 120_000

# ---------------------------------------------------------------------------
# In-page instrumentation, installed before any of the page's scripts run.
INIT_SCRIPT = r"""
(() => {
  if (window.__bench) return;
  const B = window.__bench = { runtime: [], states: [], clicks: [], longtasks: [], loaf: [] };
  try {
    new PerformanceObserver((list) => {
      for (const e of list.getEntries()) B.longtasks.push({
        start: e.startTime, duration: e.duration, name: e.name,
        attribution: (e.attribution || []).map((a) => ({ name: a.name, containerType: a.containerType,
          containerSrc: a.containerSrc, containerId: a.containerId, containerName: a.containerName })),
      });
    }).observe({ type: "longtask", buffered: true });
  } catch (err) { B.longtaskError = String(err); }
  try {
    new PerformanceObserver((list) => {
      for (const e of list.getEntries()) B.loaf.push({
        start: e.startTime, duration: e.duration, blockingDuration: e.blockingDuration,
        scripts: (e.scripts || []).map((s) => ({ sourceURL: s.sourceURL, sourceFunctionName: s.sourceFunctionName,
          invoker: s.invoker, invokerType: s.invokerType, start: s.startTime, duration: s.duration,
          forcedStyleAndLayoutDuration: s.forcedStyleAndLayoutDuration })),
      });
    }).observe({ type: "long-animation-frame", buffered: true });
  } catch (err) { B.loafError = String(err); }
  new MutationObserver((records) => {
    const t = performance.now();
    for (const r of records) {
      const el = r.target;
      if (r.attributeName === "data-workbook-runtime") B.runtime.push([el.dataset.workbookRuntime, t]);
      else if (r.attributeName === "data-state") B.states.push([el.dataset.exerciseId, el.dataset.state, t]);
      else if (r.attributeName === "data-baseline") B.runtime.push(["baseline-" + el.dataset.baseline, t]);
    }
  }).observe(document, { subtree: true, attributes: true,
                         attributeFilter: ["data-workbook-runtime", "data-state", "data-baseline"] });
  // A Check that submits the form before our script has started reloads the page:
  // the tab's first navigation start and every click survive in sessionStorage.
  B.timeOrigin = performance.timeOrigin;
  try {
    const ss = sessionStorage;
    if (!ss.getItem("__benchOrigin")) ss.setItem("__benchOrigin", String(performance.timeOrigin));
    ss.setItem("__benchDocs", String(Number(ss.getItem("__benchDocs") || 0) + 1));
    B.tabOrigin = Number(ss.getItem("__benchOrigin"));
    B.docs = Number(ss.getItem("__benchDocs"));
  } catch (err) { B.tabOrigin = performance.timeOrigin; B.docs = 1; }
  addEventListener("click", () => {
    const t = performance.now();
    B.clicks.push(t);
    try {
      const all = JSON.parse(sessionStorage.getItem("__benchClicks") || "[]");
      all.push(performance.timeOrigin + t - B.tabOrigin);
      sessionStorage.setItem("__benchClicks", JSON.stringify(all));
    } catch (err) {}
  }, true);
})();
"""

# Clicks a button and resolves when the exercise leaves "pending" (timed in the page).
CLICK_AND_WAIT = r"""
  const clickAndWait = (el, button, timeoutMs) => {
    let mo, timer;
    const done = new Promise((resolve, reject) => {
      mo = new MutationObserver(() => {
        if (el.dataset.state !== "pending") resolve([performance.now(), el.dataset.state]);
      });
      mo.observe(el, { attributes: true, attributeFilter: ["data-state"] });
      timer = setTimeout(() => reject(new Error(`exercise ${el.dataset.exerciseId}: no result within ${timeoutMs} ms`)), timeoutMs);
    });
    const t0 = performance.now();
    button.click();
    return done.then(([t1, state]) => ({ ms: t1 - t0, state })).finally(() => { mo.disconnect(); clearTimeout(timer); });
  };
"""

# Checks an exercise `n` times; each time from the click to the data-state change.
GRADE_LOOP = r"""
async ({ id, n, timeoutMs }) => {""" + CLICK_AND_WAIT + r"""
  const el = document.querySelector(`[data-exercise-id="${id}"]`);
  if (!el) throw new Error(`no exercise ${id} on this page`);
  const button = el.querySelector('[data-role="check"]');
  const times = [], states = [];
  for (let i = 0; i < n; i++) {
    const { ms, state } = await clickAndWait(el, button, timeoutMs);
    times.push(ms); states.push(state);
    await new Promise((r) => setTimeout(r, 5));
  }
  return { times, states };
}
"""

# Runs the Build exercise's tests once: click Run -> data-state change.
BUILD_RUN = r"""
async ({ id, code, timeoutMs }) => {""" + CLICK_AND_WAIT + r"""
  const el = document.querySelector(`[data-exercise-id="${id}"]`);
  const host = el.querySelector('[data-role="editor"]');
  if (code !== null) (await host.wbOpenEditor()).setCode(code);
  const { ms, state } = await clickAndWait(el, el.querySelector('[data-role="run"]'), timeoutMs);
  const passed = [...el.querySelectorAll('[data-role="test-result"]')].map((r) => r.dataset.passed === "true");
  return { ms, state, passed };
}
"""

# Endless loop in the Build editor; the moment its timeout result appears, check a
# Derive exercise and time until that result.
RECOVERY = r"""
async ({ buildId, deriveId, code, answer, timeoutMs }) => {
  const build = document.querySelector(`[data-exercise-id="${buildId}"]`);
  const derive = document.querySelector(`[data-exercise-id="${deriveId}"]`);
  derive.querySelector('[data-role="answer"]').value = answer;
  (await build.querySelector('[data-role="editor"]').wbOpenEditor()).setCode(code);
  const out = {};
  let timer;
  const observers = [];
  const finished = new Promise((resolve, reject) => {
    timer = setTimeout(() => reject(new Error(`no recovery within ${timeoutMs} ms: ${JSON.stringify(out)}`)), timeoutMs);
    const watchDerive = new MutationObserver(() => {
      if (out.fired === undefined || derive.dataset.state === "pending") return;
      out.done = performance.now(); out.deriveState = derive.dataset.state; resolve();
    });
    const watchBuild = new MutationObserver(() => {
      if (build.dataset.state === "pending" || out.fired !== undefined) return;
      out.fired = performance.now(); out.buildState = build.dataset.state;
      out.message = (build.querySelector('[data-role="feedback"]') || {}).textContent || "";
      derive.querySelector('[data-role="check"]').click();
    });
    watchDerive.observe(derive, { attributes: true, attributeFilter: ["data-state"] });
    watchBuild.observe(build, { attributes: true, attributeFilter: ["data-state"] });
    observers.push(watchDerive, watchBuild);
  });
  out.clicked = performance.now();
  build.querySelector('[data-role="run"]').click();
  try { await finished; } finally { clearTimeout(timer); observers.forEach((o) => o.disconnect()); }
  return { ...out, recoveryMs: out.done - out.fired, runToLimitMs: out.fired - out.clicked };
}
"""

SNAPSHOT = r"""
async () => {
  const nav = performance.getEntriesByType("navigation")[0] || {};
  const rt = window.workbook && window.workbook.runtime;
  let sw = { supported: "serviceWorker" in navigator, registrations: 0, controlled: false };
  if (sw.supported) {
    try { sw.registrations = (await navigator.serviceWorker.getRegistrations()).length; } catch (e) {}
    sw.controlled = Boolean(navigator.serviceWorker.controller);
  }
  const B = window.__bench || {};
  return {
    runtime: B.runtime || [], states: B.states || [], clicks: B.clicks || [],
    longtasks: B.longtasks || [], loaf: B.loaf || [], longtaskError: B.longtaskError, loafError: B.loafError,
    nav: { responseStart: nav.responseStart, responseEnd: nav.responseEnd,
           domInteractive: nav.domInteractive, domContentLoaded: nav.domContentLoadedEventEnd,
           load: nav.loadEventEnd, transferSize: nav.transferSize },
    workerStartedAt: rt ? rt.startedAt : null, workerReadyAt: rt ? rt.readyAt : null,
    startedFrom: rt ? rt.startedFrom || null : null, workerStages: rt ? rt.startStages || null : null,
    baseline: window.__baseline || null, sw, now: performance.now(),
    sinceTabStart: (B.timeOrigin || 0) - (B.tabOrigin || 0), docs: B.docs || 1,
    tabClicks: JSON.parse(sessionStorage.getItem("__benchClicks") || "[]"),
  };
}
"""

BASELINE_HTML = """<!doctype html>
<html lang="en"><head><meta charset="utf-8"><title>Baseline: loadPyodide on the main thread</title>
<script src="{base}pyodide.js"></script></head>
<body><p>Baseline: <code>loadPyodide()</code> on the main thread, then the workbook's package.</p>
<script>
(async () => {{
  const root = document.documentElement;
  try {{
    const pyodide = await loadPyodide({{ indexURL: "{base}", packages: ["robotics-workbook"] }});
    pyodide.pyimport("workbook.api");
    window.__baseline = {{ ready: performance.now() }};
    root.dataset.baseline = "ready";
  }} catch (err) {{
    window.__baseline = {{ error: String(err) }};
    root.dataset.baseline = "failed";
  }}
}})();
</script></body></html>
"""


# ---------------------------------------------------------------------------
# The server: site/ under SUBPATH, the baseline page under BASELINE_PATH.
class _CountingWriter:
    def __init__(self, raw, handler):
        self._raw, self._handler = raw, handler

    def write(self, data):
        n = self._raw.write(data)
        self._handler.sent += len(data) if n is None else n
        return n

    def flush(self):
        return self._raw.flush()

    def __getattr__(self, name):
        return getattr(self._raw, name)


class _Handler(http.server.SimpleHTTPRequestHandler):
    extensions_map = {**http.server.SimpleHTTPRequestHandler.extensions_map, ".wasm": "application/wasm",
                      ".js": "text/javascript", ".mjs": "text/javascript", ".json": "application/json",
                      ".whl": "application/octet-stream", ".zip": "application/zip"}
    protocol_version = "HTTP/1.1"  # keep-alive, as a real host

    def __init__(self, *args, bench_server=None, **kwargs):
        self.bench = bench_server
        super().__init__(*args, **kwargs)

    def setup(self):
        super().setup()
        self.sent = 0
        self.wfile = _CountingWriter(self.wfile, self)

    def translate_path(self, path):
        p = urlsplit(path).path
        if p.startswith(SUBPATH):
            return super().translate_path("/" + p[len(SUBPATH):])
        if p.startswith(BASELINE_PATH):
            rel = p[len(BASELINE_PATH):] or "index.html"
            return str(self.bench.baseline_dir / rel.lstrip("/"))
        return str(self.bench.baseline_dir / "__not_found__")

    def end_headers(self):
        self.send_header("Cache-Control", "max-age=600")  # what GitHub Pages sends
        super().end_headers()

    def send_response(self, code, message=None):
        self.status = code
        super().send_response(code, message)

    def handle_one_request(self):
        before, self.status = self.sent, None
        super().handle_one_request()
        if self.status is not None:
            self.bench.record(urlsplit(self.path).path, self.status, self.sent - before)

    def log_message(self, *args):
        pass


class BenchServer:
    def __init__(self, site_dir: Path, baseline_dir: Path):
        self.baseline_dir = baseline_dir
        self.lock = threading.Lock()
        self.log: list[tuple[float, str, int, int]] = []  # (time, path, status, bytes)
        handler = functools.partial(_Handler, directory=str(site_dir), bench_server=self)
        self.httpd = http.server.ThreadingHTTPServer(("127.0.0.1", 0), handler)
        self.httpd.daemon_threads = True
        self.thread = threading.Thread(target=self.httpd.serve_forever, daemon=True)
        self.thread.start()
        self.origin = f"http://127.0.0.1:{self.httpd.server_address[1]}"

    def record(self, path, status, nbytes):
        with self.lock:
            self.log.append((time.monotonic(), path, status, nbytes))

    def mark(self) -> int:
        with self.lock:
            return len(self.log)

    def since(self, mark: int) -> dict:
        with self.lock:
            entries = self.log[mark:]
        by_status: dict[str, int] = {}
        for _, _, status, _ in entries:
            by_status[str(status)] = by_status.get(str(status), 0) + 1
        biggest = sorted(entries, key=lambda e: -e[3])[:8]
        sw_check = sum(e[3] for e in entries if e[1].endswith("/sw.js"))  # the browser's update check
        return {"bytes": sum(e[3] for e in entries), "requests": len(entries), "by_status": by_status,
                "bytes_without_sw_update_check": sum(e[3] for e in entries) - sw_check,
                "largest": [{"path": e[1], "status": e[2], "bytes": e[3]} for e in biggest]}

    def wait_quiet(self, quiet_s: float = 1.0, timeout_s: float = 15.0) -> None:
        """Wait until no request has finished for `quiet_s` (late fetches belong to the phase)."""
        end = time.monotonic() + timeout_s
        while time.monotonic() < end:
            with self.lock:
                last = self.log[-1][0] if self.log else 0.0
            if time.monotonic() - last >= quiet_s:
                return
            time.sleep(0.1)

    def close(self):
        self.httpd.shutdown()
        self.httpd.server_close()


# ---------------------------------------------------------------------------
class BenchError(RuntimeError):
    pass


def summary(values: list[float]) -> dict | None:
    values = [v for v in values if v is not None]
    if not values:
        return None
    return {"median": statistics.median(values), "min": min(values), "max": max(values), "n": len(values),
            "values": [round(v, 3) for v in values]}


def percentile(values: list[float], q: float) -> float:
    """Nearest-rank percentile."""
    s = sorted(values)
    k = max(0, min(len(s) - 1, int(-(-q * len(s) // 100)) - 1))
    return s[k]


OUR_CODE = ("/workbook/assets/dist/", "/workbook/assets/js/", "/workbook/assets/vendor/pyodide/")


def snapshot_info(site: Path) -> dict:
    """Sizes of the memory snapshot the site ships (scripts/build_snapshot.mjs)."""
    path = site / "assets/vendor/pyodide/workbook.snapshot.gz"
    info = {"file": path.name, "gzip_bytes": path.stat().st_size if path.exists() else None}
    meta = ROOT / "build/snapshot.json"
    if meta.exists():
        info.update({k: v for k, v in json.loads(meta.read_text()).items() if k in ("bytes", "sha256", "wheel")})
    return info


def attribute_long_tasks(snap: dict, until_ms: float, page_url: str) -> dict:
    """Long tasks (> 50 ms) before `until_ms`, each with the scripts of the long
    animation frame it falls in (the Long Animation Frames API names the source URL)."""
    tasks = [t for t in snap["longtasks"] if t["start"] <= until_ms]
    out = []
    for t in tasks:
        t_end = t["start"] + t["duration"]
        scripts = []
        for frame in snap["loaf"]:
            for s in frame["scripts"]:
                s_end = s["start"] + s["duration"]
                if s["start"] < t_end and s_end > t["start"] and s["duration"] > 0:
                    scripts.append(s)
        scripts.sort(key=lambda s: -s["duration"])
        top = scripts[0] if scripts else None
        src = (top or {}).get("sourceURL") or ""
        path = urlsplit(src).path
        if top is None:
            owner = "unknown"
        elif path.startswith(OUR_CODE) or (src.split("#")[0] == page_url.split("#")[0] and page_url.startswith("http")):
            owner = "ours"  # our bundle or the inline start-up script in our HTML
        elif path.startswith("/workbook/"):
            owner = "site (theme/vendor)"
        elif not src:
            owner = "no source URL"  # e.g. a browser or bench observer callback
        else:
            owner = "other"
        out.append({"start": round(t["start"], 1), "duration": round(t["duration"], 1), "owner": owner,
                    "top_script": {k: top.get(k) for k in ("sourceURL", "sourceFunctionName", "invoker", "invokerType",
                                                           "duration")} if top else None,
                    "longtask_attribution": t["attribution"]})
    durations = [t["duration"] for t in tasks]
    return {"count": len(tasks), "total_ms": round(sum(durations), 1), "max_ms": round(max(durations, default=0), 1),
            "ours_over_50ms": sum(1 for t in out if t["owner"] == "ours"), "tasks": out,
            "api_errors": [e for e in (snap.get("longtaskError"), snap.get("loafError")) if e]}


class Bench:
    def __init__(self, args, server: BenchServer, pw):
        self.args, self.server, self.pw = args, server, pw
        self.site = server.origin + SUBPATH
        self.baseline_url = server.origin + BASELINE_PATH
        exe = find_browser()
        if not exe:
            raise BenchError("no Chromium found: run `make browser` (or `playwright install chromium`)")
        self.executable = exe
        self.version = ""
        self.service_workers = "allow"  # "block" measures the HTTP cache alone
        self.external: list[str] = []
        self.page_errors: list[str] = []
        self.deadline = time.monotonic() + args.budget
        self.runs: list[dict] = []
        self.profiles: list[str] = []  # removed after each phase (their browsers are closed by then)

    def remove_profiles(self) -> None:
        while self.profiles:
            shutil.rmtree(self.profiles.pop(), ignore_errors=True)

    # -- helpers -----------------------------------------------------------
    def new_context(self):
        """A fresh browser with an empty profile of its own: an on-disk HTTP cache and
        code cache, as a learner's browser has. (Playwright's ``new_context()`` is
        off the record: its in-memory cache refuses entries over ~6 MB, so the 10 MB
        pyodide.asm.wasm would be fetched again on every visit.)"""
        profile = tempfile.mkdtemp(prefix="wb-bench-profile-")
        try:
            ctx = self.pw.chromium.launch_persistent_context(
                profile, executable_path=self.executable, args=CHROMIUM_ARGS, headless=True, proxy=DEAD_PROXY,
                service_workers=self.service_workers)
        except Exception:
            shutil.rmtree(profile, ignore_errors=True)
            raise
        self.profiles.append(profile)
        if not self.version and ctx.browser:
            self.version = ctx.browser.version
        for page in ctx.pages:  # the persistent context opens with a blank tab
            page.close()
        ctx.add_init_script(INIT_SCRIPT)
        origin = self.server.origin

        def watch(request):
            url = request.url
            if not (url.startswith(origin) or url.startswith(("data:", "blob:", "about:", "chrome"))):
                self.external.append(url)

        ctx.on("request", watch)
        return ctx

    def new_page(self, ctx):
        page = ctx.new_page()
        page.set_default_timeout(30_000)
        page.on("pageerror", lambda err: self.page_errors.append(f"{page.url}: {err}"))
        return page

    def wait_state(self, page, what: str, expr: str, timeout_ms: int = READY_TIMEOUT_MS):
        try:
            page.wait_for_function(expr, timeout=timeout_ms, polling=50)
        except Exception as err:
            state = page.evaluate("document.documentElement.dataset.workbookRuntime") if not page.is_closed() else "?"
            raise BenchError(f"{what}: not reached within {timeout_ms / 1000:.0f} s at {page.url} "
                             f"(runtime state {state!r}): {str(err).splitlines()[0]}") from None

    def wait_ready(self, page):
        self.wait_state(page, "runtime ready",
                        "() => ['ready','failed'].includes(document.documentElement.dataset.workbookRuntime)")
        if page.evaluate("document.documentElement.dataset.workbookRuntime") == "failed":
            raise BenchError(f"the runtime failed to start at {page.url}")

    def visit(self, ctx, url: str, baseline: bool = False) -> tuple[object, dict]:
        """Open `url` in a new page of `ctx`; wait until graded-ready (or the baseline's
        loaded); return the page and a record of time, bytes and long tasks."""
        mark = self.server.mark()
        page = self.new_page(ctx)
        page.goto(url, wait_until="commit", timeout=30_000)
        if baseline:
            self.wait_state(page, "baseline loaded",
                            "() => ['ready','failed'].includes(document.documentElement.dataset.baseline)")
        else:
            self.wait_ready(page)
        page.wait_for_timeout(300)  # long tasks right after start-up still count
        self.server.wait_quiet(1.0, 15.0)
        snap = page.evaluate(SNAPSHOT)
        if baseline:
            if not snap["baseline"] or "ready" not in snap["baseline"]:
                raise BenchError(f"baseline failed: {snap['baseline']}")
            ready = snap["baseline"]["ready"]
        else:
            ready = next((t for s, t in snap["runtime"] if s == "ready"), None)
        rec = {"ready_ms": ready, "net": self.server.since(mark), "nav": snap["nav"], "sw": snap["sw"],
               "worker_started_ms": snap["workerStartedAt"],
               "started_from": snap.get("startedFrom"), "worker_stages": snap.get("workerStages"),
               "long_tasks": attribute_long_tasks(snap, (ready or 0) + 300, url)}
        return page, rec

    def settle_sw(self, page) -> None:
        """If the page registered a service worker, let it activate and finish caching."""
        try:
            has = page.evaluate("async () => 'serviceWorker' in navigator && "
                                "(await navigator.serviceWorker.getRegistrations()).length > 0")
        except Exception:
            has = False
        if has:
            page.evaluate("() => Promise.race([navigator.serviceWorker.ready.then(() => true),"
                          " new Promise((r) => setTimeout(() => r(false), 20000))])")
            self.server.wait_quiet(2.0, 60.0)

    # -- phases --------------------------------------------------------------
    def phase_ready(self, run: dict) -> None:
        self.phase_startup(run, ready_only=True)

    def phase_startup(self, run: dict, ready_only: bool = False) -> None:
        """Cold visit (new profile), then a revisit in the same profile (warm); then,
        on the warm page and two more, grading, Build runs and the recovery."""
        ctx = self.new_context()
        try:
            page, cold = self.visit(ctx, self.site + CH0)
            self.settle_sw(page)
            page.close()
            page, warm = self.visit(ctx, self.site + CH0)
            run["cold"], run["warm"] = cold, warm
            if ready_only:
                return
            grading: dict = {}
            self.grade_kinds(page, CH0, grading)
            self.phase_build(page, run)
            self.phase_recovery(page, run)
            page.close()
            for chapter in (CH3, CH1):
                page, _ = self.visit(ctx, self.site + chapter)
                self.grade_kinds(page, chapter, grading)
                page.close()
            run["grading"] = grading
        finally:
            ctx.close()

    def grade_kinds(self, page, chapter: str, grading: dict) -> None:
        for kind, (ch, ex_id) in GRADED.items():
            if ch != chapter:
                continue
            ex = page.locator(f'[data-exercise-id="{ex_id}"]')
            if kind == "derive":
                ex.locator('[data-role="answer"]').fill(DERIVE_INPUT)
            elif kind == "trace":
                ex.locator('[data-role="choice"]').first.check()
            elif kind == "debug":
                ex.locator('[data-role="line"][data-line="1"]').click()
            res = page.evaluate(GRADE_LOOP, {"id": ex_id, "n": self.args.checks, "timeoutMs": GRADE_TIMEOUT_MS})
            bad = [s for s in res["states"] if s not in ("correct", "incorrect")]
            if bad:
                raise BenchError(f"grading {kind} {ex_id}: unexpected states {sorted(set(bad))}")
            times = res["times"]
            grading[kind] = {"exercise": ex_id, "first_ms": times[0], "p50_ms": percentile(times, 50),
                             "p95_ms": percentile(times, 95), "max_ms": max(times), "n": len(times),
                             "outcome": res["states"][0]}

    def phase_build(self, page, run: dict) -> None:
        ex = page.locator(f'[data-exercise-id="{BUILD_ID}"]')
        ex.evaluate("el => el.querySelector('[data-role=editor]').wbOpenEditor()")
        out = {}
        for label, code, first_timeout in (("plain", BUILD_PLAIN, GRADE_TIMEOUT_MS), ("numpy", BUILD_NUMPY, NUMPY_TIMEOUT_MS)):
            mark = self.server.mark()
            results = []
            for i in range(1 + self.args.build_repeats):
                r = page.evaluate(BUILD_RUN, {"id": BUILD_ID, "code": code if i == 0 else None,
                                              "timeoutMs": first_timeout if i == 0 else GRADE_TIMEOUT_MS})
                if r["state"] != "correct" or not r["passed"] or not all(r["passed"]):
                    msg = ex.locator('[data-role="feedback"]').inner_text()
                    raise BenchError(f"build {label} run {i + 1}: state {r['state']}, tests {r['passed']}: {msg[:300]}")
                results.append(r["ms"])
            out[label] = {"first_ms": results[0], "repeat_median_ms": statistics.median(results[1:]),
                          "repeat_ms": results[1:], "bytes": self.server.since(mark)["bytes"]}
        run["build"] = out

    def phase_recovery(self, page, run: dict) -> None:
        res = page.evaluate(RECOVERY, {"buildId": BUILD_ID, "deriveId": GRADED["derive"][1], "code": BUILD_LOOP,
                                       "answer": DERIVE_INPUT, "timeoutMs": 60_000})
        if res.get("deriveState") not in ("correct", "incorrect"):
            raise BenchError(f"recovery: derive exercise ended {res.get('deriveState')!r}")
        run["recovery"] = {"recovery_ms": res["recoveryMs"], "run_to_limit_ms": res["runToLimitMs"],
                           "build_state": res["buildState"], "message": res["message"][:160]}
        page.evaluate("(id) => document.querySelector(`[data-exercise-id=\"${id}\"] [data-role=editor]`)"
                      ".wbEditor.setCode('')", BUILD_ID)

    def phase_first_feedback(self, run: dict) -> None:
        """A learner who types an answer and clicks Check the instant the page opens (cold)."""
        ctx = self.new_context()
        try:
            page = self.new_page(ctx)
            page.goto(self.site + CH0, wait_until="commit", timeout=30_000)
            ex_id = GRADED["derive"][1]
            ex = page.locator(f'[data-exercise-id="{ex_id}"]')
            ex.locator('[data-role="answer"]').fill(DERIVE_INPUT, timeout=30_000)
            ex.locator('[data-role="check"]').click(timeout=30_000)
            expr = ("() => (window.__bench.states || []).some(([id, s]) => id === %s && s !== 'pending' && s !== 'unanswered')"
                    % json.dumps(ex_id))
            try:
                page.wait_for_function(expr, timeout=READY_TIMEOUT_MS, polling=50)
            except Exception as err:
                docs = page.evaluate("() => window.__bench && window.__bench.docs")
                raise BenchError(f"first feedback: no result ({str(err).splitlines()[0]}); documents loaded: {docs}") from None
            snap = page.evaluate(SNAPSHOT)
            shift = snap["sinceTabStart"]  # > 0 when the click reloaded the page
            state, first = next((s, t) for i, s, t in snap["states"] if i == ex_id and s not in ("pending", "unanswered"))
            ready = next((t for s, t in snap["runtime"] if s == "ready"), None)
            run["first_feedback"] = {"feedback_ms": first + shift, "click_ms": (snap["tabClicks"] or [None])[0],
                                     "ready_ms": None if ready is None else ready + shift, "state": state,
                                     "documents": snap["docs"], "reloaded": snap["docs"] > 1}
            page.close()
        finally:
            ctx.close()

    def phase_baseline(self, run: dict) -> None:
        ctx = self.new_context()
        try:
            page, cold = self.visit(ctx, self.baseline_url, baseline=True)
            page.close()
            page, warm = self.visit(ctx, self.baseline_url, baseline=True)
            page.close()
            run["baseline_cold"], run["baseline_warm"] = cold, warm
        finally:
            ctx.close()

    def run_all(self) -> None:
        phases = [(name, fn) for name, fn in (("startup", self.phase_startup),
                                              ("first_feedback", self.phase_first_feedback),
                                              ("baseline", self.phase_baseline),
                                              ("ready", self.phase_ready)) if name in self.args.phases]
        for i in range(self.args.runs):
            run: dict = {"index": i + 1, "errors": {}}
            for name, fn in phases:
                if time.monotonic() > self.deadline:
                    run["errors"][name] = "skipped: time budget spent"
                    continue
                t0 = time.monotonic()
                try:
                    fn(run)
                except Exception as err:  # record and go on: one bad run must not lose the others
                    detail = str(err) if isinstance(err, BenchError) else traceback.format_exc(limit=3)
                    run["errors"][name] = detail
                    print(f"  run {i + 1} {name}: ERROR {detail.splitlines()[0]}", file=sys.stderr)
                run.setdefault("phase_seconds", {})[name] = round(time.monotonic() - t0, 1)
                self.remove_profiles()
            self.runs.append(run)
            print(f"  run {i + 1}/{self.args.runs} done ({sum(run['phase_seconds'].values()):.0f} s)"
                  + (f", errors in {sorted(run['errors'])}" if run["errors"] else ""), file=sys.stderr)


# ---------------------------------------------------------------------------
def collect(runs: list[dict]) -> dict:
    def pick(*path):
        vals = []
        for r in runs:
            v = r
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
        "first_feedback_click_ms": pick("first_feedback", "click_ms"),
        "build_plain_first_ms": pick("build", "plain", "first_ms"),
        "build_plain_ms": pick("build", "plain", "repeat_median_ms"),
        "build_numpy_first_ms": pick("build", "numpy", "first_ms"),
        "build_numpy_ms": pick("build", "numpy", "repeat_median_ms"),
        "numpy_bytes": pick("build", "numpy", "bytes"),
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
    add("cold ready <= 0.8 x baseline cold", rc, 0.8, None if rc is None else rc <= 0.8, "median of per-run ratios")
    p50s = {k: med(f"grade_{k}_p50_ms") for k in GRADED}
    worst = max((v for v in p50s.values() if v is not None), default=None)
    add("grading round trip p50 <= 5 ms (every kind)", worst, 5.0,
        None if worst is None or None in p50s.values() else worst <= 5.0,
        "per kind: " + ", ".join(f"{k} {v:.1f} ms" for k, v in p50s.items() if v is not None))
    b = med("build_plain_ms")
    add("Build run without numpy <= 50 ms", b, 50.0, None if b is None else b <= 50.0,
        "median of the repeat runs; the first run: "
        + ("-" if med("build_plain_first_ms") is None else f"{med('build_plain_first_ms'):.1f} ms"))
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
    return targets


# ---------------------------------------------------------------------------
def fmt(v, unit):
    if v is None:
        return "-"
    if unit == "B":
        return f"{v / 1e6:.2f} MB" if v >= 1e5 else f"{v:.0f} B"
    if unit == "x":
        return f"{v:.2f}x"
    if unit == "n":
        return f"{v:.0f}"
    return f"{v:.0f} ms" if v >= 100 else f"{v:.1f} ms"


TABLE = [
    ("Ready, cold (nav start -> runtime ready)", "ready_cold_ms", "ms"),
    ("Ready, warm (revisit)", "ready_warm_ms", "ms"),
    ("Baseline (main-thread loadPyodide), cold", "baseline_cold_ms", "ms"),
    ("Baseline, warm", "baseline_warm_ms", "ms"),
    ("Ratio cold / baseline cold", "ratio_cold", "x"),
    ("Ratio warm / baseline warm", "ratio_warm", "x"),
    ("First feedback, Check at once (cold)", "first_feedback_ms", "ms"),
    ("Grade round trip Derive p50", "grade_derive_p50_ms", "ms"),
    ("Grade round trip Derive p95", "grade_derive_p95_ms", "ms"),
    ("Grade round trip Trace p50", "grade_trace_p50_ms", "ms"),
    ("Grade round trip Trace p95", "grade_trace_p95_ms", "ms"),
    ("Grade round trip Debug p50", "grade_debug_p50_ms", "ms"),
    ("Grade round trip Debug p95", "grade_debug_p95_ms", "ms"),
    ("Grade round trip Design p50", "grade_design_p50_ms", "ms"),
    ("Grade round trip Design p95", "grade_design_p95_ms", "ms"),
    ("First grade on a fresh page (Derive)", "grade_derive_first_ms", "ms"),
    ("Build 0.5 run, no numpy, first", "build_plain_first_ms", "ms"),
    ("Build 0.5 run, no numpy, repeat", "build_plain_ms", "ms"),
    ("Build 0.5 run, numpy, first (loads numpy)", "build_numpy_first_ms", "ms"),
    ("Build 0.5 run, numpy, repeat", "build_numpy_ms", "ms"),
    ("Recovery: limit fired -> next grade", "recovery_ms", "ms"),
    ("Answer parser, worst input found (native)", "parser_worst_ms", "ms"),
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
    rows = [("Measurement", f"median (n<={runs})", "min", "max")]
    for label, key, unit in TABLE:
        s = metrics.get(key)
        rows.append((label, *(fmt(s[k], unit) if s else "-" for k in ("median", "min", "max"))))
    widths = [max(len(r[i]) for r in rows) for i in range(4)]
    lines = ["| " + " | ".join(c.ljust(w) if i == 0 else c.rjust(w) for i, (c, w) in enumerate(zip(r, widths))) + " |"
             for r in rows]
    lines.insert(1, "|" + "|".join("-" * (w + 2) if i == 0 else "-" * (w + 1) + ":" for i, w in enumerate(widths)) + "|")
    return "\n".join(lines)


def render_targets(targets: list[dict]) -> str:
    lines = []
    for t in targets:
        mark = {True: "met", False: "NOT met", None: "n/a"}[t["met"]]
        v = t["value"]
        vs = "-" if v is None else (f"{v:.2f}" if isinstance(v, float) else str(v))
        lines.append(f"- {t['target']}: {vs} (limit {t['limit']}) -> {mark}" + (f"  [{t['note']}]" if t["note"] else ""))
    return "\n".join(lines)


PYODIDE_CORE = ("pyodide.js", "pyodide.asm.js", "pyodide.asm.wasm", "python_stdlib.zip")


def stage_baseline(site: Path, target: Path) -> dict:
    """The baseline's Pyodide folder: the site's lock file and wheels, with the core
    files as published (node_modules/pyodide, checked against the pinned hashes),
    so that a change to the site's own copies (e.g. a precompiled stdlib) shows
    up against stock Pyodide. Falls back to the site's copies."""
    import hashlib

    shutil.copytree(site / "assets" / "vendor" / "pyodide", target)
    pins = {}
    pin_file = ROOT / "scripts" / "pyodide-0.27.7.sha256"
    if pin_file.exists():
        for line in pin_file.read_text().splitlines():
            if line.strip() and not line.startswith("#"):
                digest, name = line.split()
                pins[name] = digest
    stock = ROOT / "node_modules" / "pyodide"
    source = {}
    for name in PYODIDE_CORE:
        src = stock / name
        if src.exists() and pins.get(name) == hashlib.sha256(src.read_bytes()).hexdigest():
            shutil.copyfile(src, target / name)
            source[name] = "stock pyodide@0.27.7 (npm, hash-checked)"
        else:
            source[name] = "the site's copy"
    return source


def machine_info() -> dict:
    cpu = ""
    try:
        cpu = next((line.split(":", 1)[1].strip() for line in open("/proc/cpuinfo") if line.startswith("model name")), "")
    except OSError:
        cpu = platform.processor()
    mem = None
    try:
        mem = int(next(line.split()[1] for line in open("/proc/meminfo") if line.startswith("MemTotal"))) // 1024
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


def parser_worst_case(repeats: int = 20) -> dict:
    """The Derive answer parser on the most expensive inputs we know, timed natively.

    Its limits (length, nesting, node count, exponent) are checked before any
    evaluation, so no input should take long; this records the worst seen.
    """
    sys.path.insert(0, str(ROOT / "pyodide_pkg"))
    from workbook.answers import MAX_LENGTH, InvalidAnswer, parse_answer

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
    slowest = max(worst, key=worst.get)
    return {"max_ms": worst[slowest], "slowest_input": slowest, "per_input_max_ms": worst}


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
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
    args = ap.parse_args()
    if args.runs < 1 or args.checks < 1 or args.build_repeats < 1:
        ap.error("--runs, --checks and --build-repeats must be at least 1")
    args.phases = [p.strip() for p in args.phases.split(",") if p.strip()]
    unknown = set(args.phases) - {"startup", "first_feedback", "baseline", "ready"}
    if unknown:
        ap.error(f"unknown phase(s): {sorted(unknown)}")
    if not (args.site / "index.html").exists():
        print("site/ is not built: run `make site` (make bench does)", file=sys.stderr)
        return 2

    # A hard stop, whatever happens in the browser.
    watchdog = threading.Timer(args.budget + 300, lambda: (print("bench: hard time limit reached", file=sys.stderr),
                                                           os._exit(3)))
    watchdog.daemon = True
    watchdog.start()

    from playwright.sync_api import sync_playwright

    started = dt.datetime.now(dt.timezone.utc)
    t0 = time.monotonic()
    machine = machine_info()
    work = Path(tempfile.mkdtemp(prefix="wb-bench-"))
    # Serve a copy: a `make site` elsewhere during the run must not change what is measured.
    site_copy = work / "site"
    shutil.copytree(args.site, site_copy)
    baseline_dir = work / "baseline"
    baseline_dir.mkdir()
    baseline_files = stage_baseline(site_copy, baseline_dir / "pyodide")
    (baseline_dir / "index.html").write_text(BASELINE_HTML.format(base=BASELINE_PATH + "pyodide/"))
    server = BenchServer(site_copy, baseline_dir)
    try:
        with sync_playwright() as pw:
            bench = Bench(args, server, pw)
            print(f"bench: {args.runs} run(s), {bench.executable}, site at {bench.site}", file=sys.stderr)
            try:
                bench.run_all()
            finally:
                bench.remove_profiles()
            version = bench.version
    finally:
        server.close()
        shutil.rmtree(work, ignore_errors=True)
    machine["loadavg_end"] = list(os.getloadavg())

    metrics = collect(bench.runs)
    parser = parser_worst_case()
    metrics["parser_worst_ms"] = summary([parser["max_ms"]])
    metrics["parser_worst_case"] = parser
    targets = evaluate_targets(metrics, bench.runs)
    errors = {f"run {r['index']} {k}": v for r in bench.runs for k, v in r["errors"].items()}
    report = {
        "date": started.isoformat(timespec="seconds"),
        "duration_s": round(time.monotonic() - t0, 1),
        "machine": machine,
        "browser": {"name": "chromium", "version": version, "executable": bench.executable, "args": CHROMIUM_ARGS,
                    "headless": True},
        "git": git_info(),
        "config": {"runs": args.runs, "checks": args.checks, "build_repeats": args.build_repeats,
                   "server": "Python ThreadingHTTPServer, HTTP/1.1 keep-alive, Cache-Control: max-age=600, "
                             "Last-Modified/If-Modified-Since, no compression",
                   "baseline_files": baseline_files,
                   "snapshot": snapshot_info(args.site),
                   "pages": {"startup": CH0, "grading": {k: f"{p} {i}" for k, (p, i) in GRADED.items()}}},
        "metrics": metrics,
        "targets": targets,
        "external_requests": sorted(set(bench.external)),
        "page_errors": bench.page_errors,
        "errors": errors,
        "runs": bench.runs,
    }
    args.out.mkdir(parents=True, exist_ok=True)
    stamp = started.strftime("%Y%m%dT%H%M%SZ")
    text = json.dumps(report, indent=2)
    (args.out / f"bench-{stamp}.json").write_text(text)
    (args.out / "latest.json").write_text(text)

    print()
    print(f"Robotics Math Workbook bench, {report['date']}, {machine['nproc']} x {machine['cpu_model']}, "
          f"Chromium {version}, commit {report['git']['commit'][:10]}{' (dirty)' if report['git']['dirty'] else ''}")
    print(render_table(metrics, args.runs))
    print()
    print("Targets:")
    print(render_targets(targets))
    busy = max(machine["loadavg_start"][0], machine["loadavg_end"][0])
    if busy > 0.5 * (machine["nproc"] or 1):
        print(f"\nNOTE: the machine was busy (1-min load average up to {busy:.1f} on {machine['nproc']} CPUs): "
              "times are inflated; rerun on a quiet machine to compare.")
    booted = sorted({r[temp].get("started_from") for r in bench.runs for temp in ("cold", "warm")
                     if isinstance(r.get(temp), dict)} - {"snapshot"}, key=str)
    if booted:
        print(f"\nWARNING: some starts did not use the memory snapshot ({booted}): those times measure the fallback boot.")
    if report["external_requests"]:
        print(f"\nWARNING: {len(report['external_requests'])} request(s) left 127.0.0.1: {report['external_requests'][:5]}")
    if bench.page_errors:
        print(f"\nWARNING: uncaught page errors: {bench.page_errors[:5]}")
    if errors:
        print("\nErrors:")
        for k, v in errors.items():
            print(f"- {k}: {v.splitlines()[0]}")
    print(f"\nwritten: {(args.out / 'latest.json').relative_to(ROOT) if args.out.is_relative_to(ROOT) else args.out / 'latest.json'}"
          f" and bench-{stamp}.json ({report['duration_s']:.0f} s)")
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main())
