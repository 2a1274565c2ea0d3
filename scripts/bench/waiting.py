"""What a learner waits for (issue 28's closing note, issue 29's first Build run).

* ``first_build(page)``: a Build run (0.5, a plain correct solution) clicked the
  moment the grader is ready, on a first visit: click -> verdict, and grader
  ready -> verdict. The sandbox starts when the page is idle after the grader is
  ready (sandbox-client.js), so this is the worst case of a learner who runs code
  at once; first_visit.py makes it on every network profile.
* ``slow_first_visit(b)`` (phase ``waiting``, localhost only): a first visit in a
  new profile through Chromium's own throttling (CDP
  ``Network.emulateNetworkConditions``: 8 Mbps down, 40 ms latency; CPU x4 on the
  page's main thread), with a Check clicked the moment the answer box takes
  input: Check -> verdict, the longest time the loading bar's value and text
  stood still (sampled every 250 ms in the page, js/bar_sampler.js), and then the
  first Build run. CDP's throttling covers the page's and its workers' requests
  (not the service worker's, which copies the site only after ready).
"""

from __future__ import annotations

from workbook.contract import ROLE, STATE

from . import pagejs
from .browser import BenchError, Browsers
from .config import BUILD_ID, BUILD_PLAIN, CH0, DERIVE_INPUT, GRADED, READY_TIMEOUT_MS
from .pagejs import exercise, role

SLOW = {"offline": False, "latency": 40, "downloadThroughput": 8e6 / 8, "uploadThroughput": 8e6 / 8}
CPU_SLOWDOWN = 4
FIRST_BUILD_TIMEOUT_MS = 120_000


def first_build(page) -> dict:
    """Run Build 0.5 once, now: click -> verdict, and the grader's ready -> verdict (page clock)."""
    res = pagejs.run(page, "build_run", {"id": BUILD_ID, "code": BUILD_PLAIN, "timeoutMs": FIRST_BUILD_TIMEOUT_MS})
    if res["state"] != STATE.correct:
        raise BenchError(f"first Build run: exercise {BUILD_ID} ended {res['state']!r}")
    after = page.evaluate("() => performance.now() - window.workbook.runtime.readyAt")
    box = page.evaluate("() => { const s = window.workbook.sandbox; return s ? {from: s.startStages && "
                        "s.startStages.from, spawns: s.spawns} : null; }")
    return {"ms": round(res["ms"], 1), "ready_to_verdict_ms": round(after, 1), "sandbox": box}


ON_TIME_MS = 600  # a longer gap between two samples: the main thread was busy (nothing on the page could move)


def still_stretches(samples: list) -> dict:
    """From the bar's samples while it waited (not after "ready"): the longest time its value and text
    stayed the same (``still_max_ms``, as the learner saw it), the same over samples that came on time
    only (``still_on_time_max_ms``: what the page's updates did, a busy main thread left out), and the
    longest gap between two samples (the main thread was busy: nothing moved)."""
    waiting = [s for s in samples if s[4] != "ready"]
    longest = on_time = gap = 0.0
    if waiting:
        since = since_on_time = waiting[0]
        for before, sample in zip(waiting, waiting[1:]):
            gap = max(gap, sample[0] - before[0])
            if sample[0] - before[0] > ON_TIME_MS:
                since_on_time = sample
            changed = (sample[1], sample[3]) != (since[1], since[3])
            since = sample if changed else since
            longest = longest if changed else max(longest, sample[0] - since[0])
            if (sample[1], sample[3]) != (since_on_time[1], since_on_time[3]):
                since_on_time = sample
            else:
                on_time = max(on_time, sample[0] - since_on_time[0])
    return {"still_max_ms": round(longest), "still_on_time_max_ms": round(on_time), "sample_gap_max_ms": round(gap),
            "samples": len(waiting), "texts": sorted({s[3] for s in waiting})}


def slow_first_visit(b: Browsers) -> dict:
    ctx = b.new_context()
    try:
        ctx.add_init_script(pagejs.init_script("bar_sampler"))
        page = ctx.new_page()
        page.set_default_timeout(30_000)
        page.on("pageerror", lambda err: b.page_errors.append(f"{page.url}: {err}"))
        cdp = ctx.new_cdp_session(page)
        cdp.send("Network.enable")
        cdp.send("Network.emulateNetworkConditions", SLOW)
        cdp.send("Emulation.setCPUThrottlingRate", {"rate": CPU_SLOWDOWN})
        page.goto(b.site + CH0, wait_until="commit", timeout=60_000)
        ex_id = GRADED["derive"][1]
        ex = page.locator(exercise(ex_id))
        ex.locator(role(ROLE.answer)).fill(DERIVE_INPUT, timeout=READY_TIMEOUT_MS)
        res = page.evaluate("""([id, check, timeoutMs]) => { const el = window.__bench.exercise(id);
          return window.__bench.clickAndWait(el, el.querySelector(check), timeoutMs); }""",
                            [ex_id, role(ROLE.check), READY_TIMEOUT_MS * 2])
        if res["state"] not in (STATE.correct, STATE.incorrect):
            raise BenchError(f"slow first visit: the Check ended {res['state']!r}")
        bar = still_stretches(page.evaluate("() => window.__benchBar"))
        build = first_build(page)
        started = page.evaluate("() => window.workbook.runtime.startedFrom")
        page.close()
        return {"check_to_verdict_ms": round(res["ms"]), "bar": bar, "first_build_ms": build["ms"],
                "first_build": build, "started_from": started,
                "conditions": {**SLOW, "cpu_slowdown": CPU_SLOWDOWN}}
    finally:
        ctx.close()
