"""A learner's first visit on a network profile, next to the baseline's.

Ours: open chapter 0 in a new profile, wait until the runtime is ready, grade
one Derive answer at once (the first grade right after ready), run one Build
exercise at once (the first Build run right after ready: waiting.py), then wait
(bounded) until the service worker has stored the site for offline use and the
link is quiet. The baseline: open its page, wait until ``workbook.api`` is
imported, then until the link is quiet. Both: time to ready, bytes on the wire
before ready and in all, files sent more than once, LCP and total blocking time.
"""

from __future__ import annotations

from workbook.contract import ATTR, DATA, ROLE, STATE

from . import pagejs, waiting
from .browser import BenchError, Browsers
from .config import CH0, DERIVE_INPUT, GRADE_TIMEOUT_MS, GRADED, Profile
from .pagejs import exercise, role
from .records import bytes_before, fetched_twice, largest_contentful_paint, net_summary, total_blocking_time
from .stock_page import SETTLE_MS

OFFLINE = f"document.documentElement.getAttribute({ATTR.offline!r})"
OFFLINE_DONE = tuple(s for s in DATA["offlineStates"] if s != "caching")  # stored, or cannot be


def _numbers(b: Browsers, page, mark: int, rec: dict) -> dict:
    """What the server and the page saw since `mark` (the navigation)."""
    snap = page.bench_snapshot  # taken the moment ready was seen
    entries = b.server.since(mark)
    ready = rec["ready_ms"]
    before = bytes_before(entries, (snap["timeOrigin"] + ready) / 1000) if ready is not None else None
    twice = fetched_twice(entries)
    return {"ready_ms": ready, "bytes_before_ready": before, "bytes_first_visit": sum(e["bytes"] for e in entries),
            "requests": len(entries), "revalidated_304": sum(1 for e in entries if e["status"] == 304),
            "fetched_twice": twice, "fetched_twice_count": len(twice),
            "lcp_ms": largest_contentful_paint(snap), "tbt_ms": total_blocking_time(snap, ready or 0),
            "long_tasks_to_ready": sum(1 for t in snap["longtasks"] if t["start"] <= (ready or 0)),
            "net": net_summary(entries), "started_from": rec.get("started_from"),
            # the server's clock against the page's: the navigation request's arrival after
            # the page's time origin (a few ms; large values would mean the clocks disagree)
            "clock_check_ms": round(entries[0]["start"] * 1000 - snap["timeOrigin"], 1) if entries else None,
            "api_errors": [e for e in (snap.get("longtaskError"), snap.get("lcpError")) if e]}


def ours(b: Browsers, profile: Profile) -> dict:
    ctx = b.new_context()
    try:
        mark = b.server.mark()
        page, rec = b.visit(ctx, b.site + CH0, timeout_ms=profile.ready_timeout_ms, settle=False)
        first_grade = grade_once(page)
        first_build = waiting.first_build(page)
        offline = wait_offline(page, profile.precache_timeout_ms)
        quiet = b.server.wait_quiet(2.0, 60.0)
        out = _numbers(b, page, mark, rec)
        out["tbt_load5_ms"] = tbt_to_load_plus(page)
        out.update(first_grade_ms=first_grade["ms"], first_grade_state=first_grade["state"],
                   first_build_ms=first_build["ms"], first_build_after_ready_ms=first_build["ready_to_verdict_ms"],
                   first_build_sandbox=first_build["sandbox"],
                   offline=offline, quiet=quiet, sw=pagejs.run(page, "snapshot")["sw"])
        page.close()
        return out
    finally:
        ctx.close()


def baseline(b: Browsers, profile: Profile) -> dict:
    ctx = b.new_context()
    try:
        mark = b.server.mark()
        page, rec = b.visit(ctx, b.baseline_url, baseline=True, timeout_ms=profile.ready_timeout_ms, settle=False)
        quiet = b.server.wait_quiet(2.0, 60.0)
        out = _numbers(b, page, mark, rec)
        out["quiet"] = quiet
        page.close()
        return out
    finally:
        ctx.close()


def tbt_to_load_plus(page) -> float | None:
    """Total blocking time from the navigation to the load event + SETTLE_MS (the stock page's window)."""
    snap = pagejs.run(page, "snapshot")
    load = (snap.get("nav") or {}).get("load")
    if not load:
        return None
    return total_blocking_time(snap, load + SETTLE_MS)


def stock(b: Browsers, profile: Profile) -> dict:
    """The stock theme's page (stock_page.py): the theme's own blocking, to load + SETTLE_MS."""
    ctx = b.new_context()
    try:
        page = b.new_page(ctx)
        page.goto(b.stock_url, wait_until="load", timeout=profile.ready_timeout_ms)
        page.wait_for_timeout(SETTLE_MS)
        out = {"tbt_load5_ms": tbt_to_load_plus(page), "lcp_ms": largest_contentful_paint(pagejs.run(page, "snapshot"))}
        page.close()
        return out
    finally:
        ctx.close()


def grade_once(page) -> dict:
    """Check the Derive exercise once, the moment the runtime is ready: click -> result."""
    ex_id = GRADED["derive"][1]
    page.locator(exercise(ex_id)).locator(role(ROLE.answer)).fill(DERIVE_INPUT)
    res = pagejs.run(page, "grade_loop", {"id": ex_id, "n": 1, "timeoutMs": GRADE_TIMEOUT_MS})
    state = res["states"][0]
    if state not in (STATE.correct, STATE.incorrect):
        raise BenchError(f"first grade after ready: exercise {ex_id} ended {state!r}")
    return {"ms": res["times"][0], "state": state}


def wait_offline(page, timeout_ms: int) -> dict:
    """Wait (at most `timeout_ms`) until the page says the site is stored for offline use."""
    t0 = page.evaluate("performance.now()")
    try:
        page.wait_for_function(f"() => {list(OFFLINE_DONE)!r}.includes({OFFLINE})", timeout=timeout_ms, polling=200)
        done = True
    except Exception:
        done = False
    state = page.evaluate(OFFLINE)
    return {"state": state, "finished": done, "waited_ms": round(page.evaluate("performance.now()") - t0)}
