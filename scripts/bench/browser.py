"""Browsers for the bench: a fresh profile per phase, pages, visits and waits."""

from __future__ import annotations

import functools
import shutil
import tempfile
from typing import Any

from find_browser import find_browser
from workbook.contract import ATTR

from . import pagejs
from .config import (
    BASELINE_PATH,
    BROWSER_UI_FEATURES_OFF,
    CHROMIUM_ARGS,
    DEAD_PROXY,
    READY_TIMEOUT_MS,
    STOCK_PATH,
    SUBPATH,
)
from .cpu_limit import CpuLimit, open_limit
from .records import attribute_long_tasks, net_summary

RUNTIME = f"document.documentElement.getAttribute({ATTR.runtime!r})"


class BenchError(RuntimeError):
    pass


FEATURES_OFF = "--disable-features="


@functools.cache
def launch_args(pw, executable: str) -> tuple[list[str], list[str]]:
    """The browser's flags, and Playwright's defaults to leave out: CHROMIUM_ARGS, with BROWSER_UI_FEATURES_OFF
    added to the features Playwright switches off. Chromium reads only the last --disable-features, so the
    two lists are merged into one flag, in place of Playwright's; its list is read from a browser it
    starts (CDP Browser.getBrowserCommandLine, which needs --enable-automation), so a newer Playwright's list
    is kept too. Once per run: every profile's Browsers shares the answer (callers must not change it)."""
    browser = pw.chromium.launch(executable_path=executable, headless=True,
                                 args=[*CHROMIUM_ARGS, "--enable-automation"])
    try:
        line = browser.new_browser_cdp_session().send("Browser.getBrowserCommandLine")["arguments"]
    finally:
        browser.close()
    theirs = [a for a in line if a.startswith(FEATURES_OFF)]
    off = [f for a in theirs for f in a[len(FEATURES_OFF):].split(",") if f]
    merged = FEATURES_OFF + ",".join(dict.fromkeys([*off, *BROWSER_UI_FEATURES_OFF]))
    return [*CHROMIUM_ARGS, merged], theirs


class Browsers:
    """Launches Chromium (a new profile each time), opens pages, and visits the site."""

    def __init__(self, pw, server, deadline: float, cpu_slowdown: float = 1.0, cpu_share: float | None = None):
        self.pw, self.server = pw, server
        self.site = server.origin + SUBPATH
        self.baseline_url = server.origin + BASELINE_PATH
        self.stock_url = server.origin + STOCK_PATH
        exe = find_browser(shell=False)  # the whole browser, as learners run it (the tests take the lighter shell)
        if not exe:
            raise BenchError("no Chromium found: install Debian's chromium (or `playwright install chromium`)")
        self.executable = exe
        args, ignored = launch_args(pw, exe)
        self.args, self.ignore_default_args = list(args), list(ignored)
        self.version = ""
        self.service_workers = "allow"  # "block" measures the HTTP cache alone
        self.cpu_slowdown = cpu_slowdown  # > 1: CDP Emulation.setCPUThrottlingRate on every page
        # A share of a core for the whole browser (workers included) where a cgroup can be made.
        self.cpu_limit: CpuLimit | None = open_limit(exe, cpu_share) if cpu_share else None
        if self.cpu_limit:
            self.cpu_slowdown = 1.0  # the cgroup slows every thread; CDP on top would slow the main thread twice
        self.cpu_note = (self.cpu_limit.describe() if self.cpu_limit else
                         "CDP Emulation.setCPUThrottlingRate: the page's main thread only (Chromium refuses it for "
                         "workers)" + ("; a CPU cgroup could not be made here" if cpu_share else "")
                         if cpu_slowdown > 1 else None)
        self.external: list[str] = []
        self.page_errors: list[str] = []
        self.deadline = deadline  # time.monotonic(): phases after it are skipped
        self.profiles: list[str] = []  # removed after each phase (their browsers are closed by then)

    def close(self) -> None:
        self.remove_profiles()
        if self.cpu_limit:
            self.cpu_limit.close()

    def remove_profiles(self) -> None:
        while self.profiles:
            shutil.rmtree(self.profiles.pop(), ignore_errors=True)

    def new_context(self):
        """A fresh browser with an empty profile of its own: an on-disk HTTP cache and
        code cache, as a learner's browser has. (Playwright's ``new_context()`` is
        off the record: its in-memory cache refuses entries over ~6 MB, so the 10 MB
        pyodide.asm.wasm would be fetched again on every visit.)"""
        profile = tempfile.mkdtemp(prefix="wb-bench-profile-")
        try:
            ctx = self.pw.chromium.launch_persistent_context(
                profile, executable_path=str(self.cpu_limit.wrapper) if self.cpu_limit else self.executable,
                args=self.args, ignore_default_args=self.ignore_default_args, headless=True, proxy=DEAD_PROXY,
                service_workers=self.service_workers)
        except Exception:
            shutil.rmtree(profile, ignore_errors=True)
            raise
        self.profiles.append(profile)
        if not self.version and ctx.browser:
            self.version = ctx.browser.version
        for page in ctx.pages:  # the persistent context opens with a blank tab
            page.close()
        ctx.add_init_script(pagejs.init_script())
        origin = self.server.origin

        def watch(request):
            url = request.url
            if not url.startswith((origin, "data:", "blob:", "about:", "chrome")):
                self.external.append(url)

        ctx.on("request", watch)
        return ctx

    def new_page(self, ctx):
        page = ctx.new_page()
        page.set_default_timeout(30_000)
        page.on("pageerror", lambda err: self.page_errors.append(f"{page.url}: {err}"))
        if self.cpu_slowdown > 1:
            cdp = ctx.new_cdp_session(page)
            cdp.send("Emulation.setCPUThrottlingRate", {"rate": self.cpu_slowdown})
        return page

    def wait_state(self, page, what: str, expr: str, timeout_ms: int = READY_TIMEOUT_MS):
        try:
            page.wait_for_function(expr, timeout=timeout_ms, polling=50)
        except Exception as err:
            state = page.evaluate(RUNTIME) if not page.is_closed() else "?"
            raise BenchError(f"{what}: not reached within {timeout_ms / 1000:.0f} s at {page.url} "
                             f"(runtime state {state!r}): {str(err).splitlines()[0]}") from None

    def wait_ready(self, page, timeout_ms: int = READY_TIMEOUT_MS):
        self.wait_state(page, "runtime ready", f"() => ['ready','failed'].includes({RUNTIME})", timeout_ms)
        if page.evaluate(RUNTIME) == "failed":
            raise BenchError(f"the runtime failed to start at {page.url}")

    def visit(self, ctx, url: str, baseline: bool = False, timeout_ms: int = READY_TIMEOUT_MS,
              settle: bool = True) -> tuple[Any, dict]:
        """Open `url` in a new page of `ctx`; wait until graded-ready (or the baseline's
        loaded); return the page and a record of time, bytes and long tasks.
        With `settle`, wait a little for late fetches and long tasks first."""
        mark = self.server.mark()
        page = self.new_page(ctx)
        page.goto(url, wait_until="commit", timeout=timeout_ms)
        if baseline:
            self.wait_state(page, "baseline loaded",
                            "() => ['ready','failed'].includes(document.documentElement.dataset.baseline)", timeout_ms)
        else:
            self.wait_ready(page, timeout_ms)
        if settle:
            page.wait_for_timeout(300)  # long tasks right after start-up still count
            self.server.wait_quiet(1.0, 15.0)
        snap = pagejs.run(page, "snapshot")
        if baseline:
            if not snap["baseline"] or "ready" not in snap["baseline"]:
                raise BenchError(f"baseline failed: {snap['baseline']}")
            ready = snap["baseline"]["ready"]
        else:
            ready = next((t for s, t in snap["runtime"] if s == "ready"), None)
        entries = self.server.since(mark)
        rec = {"ready_ms": ready, "net": net_summary(entries), "nav": snap["nav"], "sw": snap["sw"],
               "worker_started_ms": snap["workerStartedAt"],
               "started_from": snap.get("startedFrom"), "worker_stages": snap.get("workerStages"),
               "long_tasks": attribute_long_tasks(snap, (ready or 0) + 300, url)}
        page.bench_mark, page.bench_snapshot = mark, snap  # for the network phase's extra numbers
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
            # The offline copy starts a while after ready: wait for the page to say it is stored
            # (data-workbook-offline), not for a quiet network, or a "warm" visit races the copy.
            try:
                page.wait_for_function(f"() => document.documentElement.getAttribute({ATTR.offline!r}) !== 'caching'",
                                       timeout=60_000, polling=200)
            except Exception:
                pass  # the revisit then shows what a learner who came back too soon gets
            self.server.wait_quiet(2.0, 60.0)
