"""Offline: after one visit, the service worker serves every page and runtime
file with the network gone (Derive grading, a Build exercise importing NumPy);
a new deploy is announced by a banner and replaces the old cache as a whole.
Long runs (in the sandbox worker that runs Build code): stopped by
KeyboardInterrupt where the page is cross-origin isolated (the service worker
adds COOP/COEP), by terminating the sandbox where not, and by terminating when
an interrupt is ignored; the grader's own worker is never restarted by them."""

from __future__ import annotations

import base64
import hashlib
import json
import os
import re
import shutil
import time
from pathlib import Path

import pytest
from playwright.sync_api import Page, expect

from conftest import SITE
from helpers import (
    answer_derive,
    exercise,
    feedback,
    keep_to_origin,
    network_is_off,
    open_chapter,
    role,
    run_build,
    set_editor,
    wait_runtime,
)
from site_server import SiteServer

# The offline copy must not lean on the HTTP cache; it needs its service worker.
pytestmark = [pytest.mark.uncached, pytest.mark.browser_context_args(service_workers="allow")]

ROTATE_NUMPY = (
    "import numpy as np\n\n"
    "def rotate_2d(x, y, theta):\n"
    "    R = np.array([[np.cos(theta), -np.sin(theta)], [np.sin(theta), np.cos(theta)]])\n"
    "    return R @ np.array([x, y])\n"
)
ROTATE_OK = "import math\n\ndef rotate_2d(x, y, theta):\n    c, s = math.cos(theta), math.sin(theta)\n    return (c * x - s * y, s * x + c * y)\n"
LOOP = "def rotate_2d(x, y, theta):\n    while True:\n        pass\n"
STUBBORN_LOOP = (  # swallows KeyboardInterrupt: only terminating the worker stops it
    "def rotate_2d(x, y, theta):\n"
    "    while True:\n"
    "        try:\n"
    "            while True:\n"
    "                pass\n"
    "        except BaseException:\n"
    "            pass\n"
)
LONG = 120_000


def wait_offline_ready(page: Page) -> None:
    page.wait_for_function("() => document.documentElement.dataset.workbookOffline === 'ready'", timeout=LONG)


def precache_list(sw_text: str) -> list[list[str]]:
    return json.loads(re.search(r"const FILES = (\[.*?\n\]);", sw_text, re.S).group(1))


def kept_later(sw_text: str) -> list[list[str]]:
    """The files kept when first fetched, not copied with the rest (offline.py's LATER)."""
    return json.loads(re.search(r"const LATER = (\[.*?\]);", sw_text).group(1))


SANDBOX_SNAPSHOT = "assets/vendor/pyodide/sandbox.snapshot.gz"
KEPT = "async (u) => Boolean(await caches.match(new URL(u, window.__workbookBase).href))"


def test_everything_works_offline_after_one_visit(page, context, site_url):
    open_chapter(page, site_url, 0)
    wait_offline_ready(page)
    files = precache_list((SITE / "sw.js").read_text())
    urls = [u for u, *_ in files]
    for needed in ("./", "chapters/00-rotations-2d/", "progress/", "search/search_index.json",
                   "search/search_index.docs.json", "assets/exercises.json",
                   "assets/vendor/pyodide/pyodide.asm.wasm", "assets/vendor/pyodide/pyodide-lock.json",
                   "assets/vendor/pyodide/workbook.snapshot.gz", "assets/vendor/pyodide/python_stdlib.core.zip",
                   "assets/vendor/pyodide/python_stdlib.rest.zip",
                   "assets/vendor/pyodide/python_stdlib.sandbox.zip", "assets/vendor/pyodide/pyodide-lock.sandbox.json",
                   "assets/vendor/katex/katex.min.js", "assets/dist/workbook.js", "assets/dist/worker.js",
                   "assets/workbook.css"):
        assert needed in urls, needed
    assert any(re.match(r"assets/vendor/pyodide/numpy-.*\.whl$", u) for u in urls)
    assert any(re.match(r"assets/vendor/pyodide/robotics_workbook-.*\.whl$", u) for u in urls)
    assert any(u.startswith("assets/dist/chunks/editor-") for u in urls)
    # The sandbox's snapshot is not copied (5 MB a plain start does without): it is kept once the
    # sandbox has started from it online, as the first Build run here does.
    assert [u for u, *_ in kept_later((SITE / "sw.js").read_text())] == [SANDBOX_SNAPSHOT] and SANDBOX_SNAPSHOT not in urls
    build = exercise(page, "0.5")
    set_editor(page, build, ROTATE_NUMPY)
    assert run_build(build, timeout=LONG) == "correct", feedback(build)
    page.wait_for_function(KEPT, arg=SANDBOX_SNAPSHOT, timeout=LONG)

    context.set_offline(True)
    fresh = context.new_page()
    errors: list[str] = []
    fresh.on("pageerror", lambda err: errors.append(str(err)))
    started = time.perf_counter()
    fresh.goto(site_url + "chapters/00-rotations-2d/")
    wait_runtime(fresh, timeout=LONG)
    print(f"\noffline: fresh page load to runtime ready in {time.perf_counter() - started:.1f} s")
    assert network_is_off(fresh)
    # From the cache: the memory snapshot, and the WebAssembly compiled while it was read (worker.js).
    assert fresh.evaluate("[workbook.runtime.startedFrom, workbook.runtime.startStages.wasm]") == ["snapshot", "precompiled"]
    assert answer_derive(exercise(fresh, "0.1"), "3") == "correct"
    build = exercise(fresh, "0.5")
    set_editor(fresh, build, ROTATE_NUMPY)
    started = time.perf_counter()
    assert run_build(build, timeout=LONG) == "correct", feedback(build)
    print(f"offline: first Build run, the sandbox from its kept snapshot, {time.perf_counter() - started:.1f} s")
    assert fresh.evaluate("workbook.sandbox.startStages.from") == "snapshot"  # the sandbox's own, kept too

    # Every precached file is served with the network gone.
    missing = fresh.evaluate("""async (urls) => {
      const bad = [];
      for (const u of urls) {
        try { const r = await fetch(new URL(u, window.__workbookBase)); if (!r.ok) bad.push(u + ' ' + r.status); }
        catch (e) { bad.push(u + ' ' + e); }
      }
      return bad;
    }""", urls)
    assert missing == []
    # The search works too (its index and worker are cached).
    fresh.locator("input.md-search__input").click()
    fresh.locator("input.md-search__input").press_sequentially("quaternion", delay=30)
    expect(fresh.locator(".md-search-result__item").first).to_be_visible(timeout=LONG)
    fresh.keyboard.press("Escape")
    # Another page, and the address without its trailing slash.
    fresh.goto(site_url + "chapters/04-ekf-update")
    assert fresh.url.endswith("chapters/04-ekf-update/")
    exercise(fresh, "4.1").wait_for()
    wait_runtime(fresh, timeout=LONG)
    # A learner whose sandbox never started online: offline, it boots plainly from the copy's files.
    fresh.evaluate("""async (u) => { for (const name of await caches.keys())
      await (await caches.open(name)).delete(new URL(u, window.__workbookBase).href); }""", SANDBOX_SNAPSHOT)
    assert not fresh.evaluate(KEPT, SANDBOX_SNAPSHOT)
    fresh.goto(site_url + "chapters/00-rotations-2d/")
    wait_runtime(fresh, timeout=LONG)
    build = exercise(fresh, "0.5")
    set_editor(fresh, build, ROTATE_NUMPY)
    started = time.perf_counter()
    assert run_build(build, timeout=LONG) == "correct", feedback(build)
    print(f"offline: first Build run, the sandbox booted plainly, {time.perf_counter() - started:.1f} s")
    assert fresh.evaluate("workbook.sandbox.startStages.from") == "boot"
    assert errors == []
    fresh.close()
    context.set_offline(False)


def timed_out(page: Page, ex) -> None:
    page.wait_for_function("el => el.dataset.state === 'error'", arg=ex.element_handle(), timeout=LONG)
    assert ex.get_attribute("data-feedback") == "timeout"
    assert re.search(r"stopped after 5 s", feedback(ex), re.I)


def grades_again(page: Page) -> None:
    assert answer_derive(exercise(page, "0.1"), "3") == "correct"
    build = exercise(page, "0.5")
    set_editor(page, build, ROTATE_OK)
    assert run_build(build, timeout=LONG) == "correct"


def test_interrupt_stops_an_endless_loop_on_an_isolated_page(page, site_url):
    open_chapter(page, site_url, 0)
    wait_offline_ready(page)
    page.reload()  # now served by the service worker, with COOP/COEP
    wait_runtime(page, timeout=LONG)
    assert page.evaluate("crossOriginIsolated") is True
    build = exercise(page, "0.5")
    set_editor(page, build, LOOP)
    build.locator(role("run")).click()
    timed_out(page, build)
    assert page.evaluate("workbook.sandbox.interrupt instanceof Int32Array")
    stops = page.evaluate("[workbook.sandbox.lastStop, workbook.sandbox.interrupts, workbook.sandbox.restarts]")
    assert stops == ["interrupt", 1, 0], f"interrupts sent: {page.evaluate('workbook.sandbox.interruptsSent')}"
    assert page.evaluate("[workbook.runtime.restarts, workbook.runtime.interrupts]") == [0, 0]  # the grader ran no code
    assert page.evaluate("document.documentElement.dataset.workbookRuntime") == "ready"
    grades_again(page)

    # Code that swallows KeyboardInterrupt: a second later, the sandbox is terminated.
    set_editor(page, build, STUBBORN_LOOP)
    build.locator(role("run")).click()
    timed_out(page, build)
    assert page.evaluate("[workbook.sandbox.lastStop, workbook.sandbox.restarts]") == ["terminate", 1]
    assert page.evaluate("workbook.runtime.restarts") == 0
    grades_again(page)


def test_terminate_stops_an_endless_loop_where_not_isolated(page, site_url):
    open_chapter(page, site_url, 0)  # the first visit is never isolated: no service worker yet
    assert page.evaluate("crossOriginIsolated") is False
    build = exercise(page, "0.5")
    set_editor(page, build, LOOP)
    build.locator(role("run")).click()
    timed_out(page, build)
    assert page.evaluate("workbook.sandbox.interrupt") is None
    assert page.evaluate("[workbook.sandbox.lastStop, workbook.sandbox.restarts, workbook.sandbox.interrupts]") == [
        "terminate", 1, 0]
    assert page.evaluate("workbook.runtime.restarts") == 0
    grades_again(page)


# ---- A new deploy ------------------------------------------------------------------
@pytest.fixture
def deploy(tmp_path):
    """A copy of the site (files linked, sw.js and one page real) on a server of its own."""
    root = tmp_path / "site"
    shutil.copytree(SITE, root, copy_function=os.symlink, ignore=shutil.ignore_patterns("sw.js", "related"))
    shutil.copy(SITE / "sw.js", root / "sw.js")
    shutil.copytree(SITE / "related", root / "related")
    with SiteServer(root) as server:
        yield root, server.url


def version_caches(page) -> list[str]:
    """The caches of site versions (not the service worker's small "state" cache: whether the copy is wanted)."""
    return [name for name in page.evaluate("caches.keys()") if not name.endswith(":state")]


def publish_new_version(root: Path) -> None:
    """What a deploy does: one page changes, and sw.js gets a new list and version."""
    page_file = root / "related" / "index.html"
    page_file.write_text(page_file.read_text().replace("<h1", "<h1 data-deploy=\"2\"", 1))
    digest = "sha256-" + base64.b64encode(hashlib.sha256(page_file.read_bytes()).digest()).decode()
    sw = (root / "sw.js").read_text()
    sw = re.sub(r'\["related/", "sha256-[^"]+", \d+\]', f'["related/", "{digest}", {page_file.stat().st_size}]', sw)
    sw = re.sub(r'const VERSION = "[^"]+"', 'const VERSION = "next-deploy"', sw)
    (root / "sw.js").write_text(sw)


def test_a_new_version_is_announced_and_replaces_the_old_cache(browser, deploy):
    root, url = deploy
    context = browser.new_context()
    blocked = keep_to_origin(context, url)
    page = context.new_page()
    errors: list[str] = []
    page.on("pageerror", lambda err: errors.append(str(err)))
    page.goto(url + "related/")
    wait_offline_ready(page)
    page.reload()
    wait_offline_ready(page)
    old_caches = version_caches(page)
    assert len(old_caches) == 1
    assert page.locator("[data-wb-update]").count() == 0

    publish_new_version(root)
    page.evaluate("navigator.serviceWorker.getRegistration().then(r => r.update())")
    banner = page.locator("[data-wb-update]")
    expect(banner).to_be_visible(timeout=LONG)
    expect(banner).to_have_attribute("role", "status")
    # Until the learner reloads, pages still come from the old version, whole.
    assert "data-deploy" not in page.evaluate("fetch('./').then(r => r.text())")

    with page.expect_navigation():
        banner.get_by_role("button", name="Reload").click()
    page.locator("h1[data-deploy='2']").wait_for()
    caches = version_caches(page)
    assert len(caches) == 1 and caches[0].endswith(":next-deploy") and caches != old_caches
    assert page.locator("[data-wb-update]").count() == 0
    assert errors == [] and blocked == []
    context.close()
