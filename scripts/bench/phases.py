"""The measurement phases: each opens its own browser(s) and adds its records to a run."""

from __future__ import annotations

import json
import statistics
import sys
import time
import traceback
from typing import Any

from workbook import bank
from workbook.contract import ATTR, ROLE, STATE
from workbook.kinds.build import Build
from workbook.kinds.derive import Derive

from . import class_page, first_visit, pagejs, waiting
from .browser import BenchError, Browsers
from .config import (
    BUILD_HEAVY_ID,
    BUILD_ID,
    BUILD_LOOP,
    BUILD_NEW_ID,
    BUILD_NUMPY,
    BUILD_PLAIN,
    CH0,
    CH1,
    CH3,
    CH9,
    DERIVE_INPUT,
    GRADE_TIMEOUT_MS,
    GRADED,
    NUMPY_TIMEOUT_MS,
    READY_TIMEOUT_MS,
    Profile,
)
from .pagejs import exercise, role
from .records import percentile

GRADED_STATES = (STATE.correct, STATE.incorrect)


def _build(ex_id: str) -> Build:
    ex = bank.get(ex_id)
    assert isinstance(ex, Build), ex_id
    return ex


def _answer(ex_id: str) -> Any:
    """A Derive exercise's answer: the AnswerKind its variant built (``key``, ``answer_text``)."""
    ex = bank.get(ex_id)
    assert isinstance(ex, Derive), ex_id
    return ex.answer


LOCAL_PHASES = ("startup", "first_feedback", "baseline", "ready", "class_page", "waiting")


class Phases:
    """The phases of one profile's bench, by name: ``startup``, ``first_feedback``,
    ``baseline``, ``ready`` (localhost), and ``first_visit`` / ``first_visit_baseline``
    (every profile; see first_visit.py)."""

    def __init__(self, browsers: Browsers, args, profile: Profile):
        self.b, self.args, self.profile = browsers, args, profile
        self.runs: list[dict] = []

    # -- start-up, then grading on the warm page ----------------------------------
    def ready(self, run: dict) -> None:
        self.startup(run, ready_only=True)

    def startup(self, run: dict, ready_only: bool = False) -> None:
        """Cold visit (new profile), then a revisit in the same profile (warm); then,
        on the warm page and two more, grading, Build runs and the recovery."""
        b = self.b
        ctx = b.new_context()
        try:
            page, cold = b.visit(ctx, b.site + CH0)
            b.settle_sw(page)
            page.close()
            page, warm = b.visit(ctx, b.site + CH0)
            run["cold"], run["warm"] = cold, warm
            if ready_only:
                return
            grading: dict = {}
            self.grade_kinds(page, CH0, grading)
            self.draws(page, run)
            self.build(page, run)
            self.recovery(page, run)
            page.close()
            for chapter in (CH3, CH1):
                page, _ = b.visit(ctx, b.site + chapter)
                self.grade_kinds(page, chapter, grading)
                if chapter == CH1:
                    run["build_new"] = self.build_series(page, BUILD_NEW_ID, _build(BUILD_NEW_ID).solution,
                                                         READY_TIMEOUT_MS)
                page.close()
            page, _ = b.visit(ctx, b.site + CH9)
            run["build_heavy"] = self.build_series(
                page, BUILD_HEAVY_ID, _build(BUILD_HEAVY_ID).solution, READY_TIMEOUT_MS
            )
            page.close()
            run["grading"] = grading
        finally:
            ctx.close()

    def grade_kinds(self, page, chapter: str, grading: dict) -> None:
        for kind, (ch, ex_id) in GRADED.items():
            if ch != chapter:
                continue
            ex = page.locator(exercise(ex_id))
            if kind == "derive":
                ex.locator(role(ROLE.answer)).fill(DERIVE_INPUT)
            elif kind == "trace":
                ex.locator(role(ROLE.choice)).first.check()
            elif kind == "debug":
                ex.locator(f'{role(ROLE.line)}[{ATTR.line}="1"]').click()
            elif kind == "matrix":  # the key's entries, one of them off: the whole diagnosis runs
                rows = [[f"{v:.6g}" for v in row] for row in _answer(ex_id).key]
                rows[0][0] = "sqrt(2)/2"
                for i, row in enumerate(rows, 1):
                    for j, text in enumerate(row, 1):
                        ex.locator(f'{role(ROLE.entry)}[{ATTR.row}="{i}"][{ATTR.col}="{j}"]').fill(text)
            elif kind == "formula":
                ex.locator(role(ROLE.answer)).fill(_answer(ex_id).answer_text)
            res = pagejs.run(page, "grade_loop", {"id": ex_id, "n": self.args.checks, "timeoutMs": GRADE_TIMEOUT_MS})
            bad = [s for s in res["states"] if s not in GRADED_STATES]
            if bad:
                raise BenchError(f"grading {kind} {ex_id}: unexpected states {sorted(set(bad))}")
            times = res["times"]
            grading[kind] = {"exercise": ex_id, "first_ms": times[0], "p50_ms": percentile(times, 50),
                             "p95_ms": percentile(times, 95), "max_ms": max(times), "n": len(times),
                             "outcome": res["states"][0]}

    def draws(self, page, run: dict) -> None:
        """New numbers on every Derive exercise of the page, ``--draws`` rounds (issue 13: p50 <= 30 ms)."""
        ids = page.locator(f"[{ATTR.exercise}][{ATTR.templates}]").evaluate_all(
            "(els, a) => els.map((e) => e.getAttribute(a))", ATTR.exercise)
        if not ids:
            raise BenchError("no exercise on the page draws variants")
        res = pagejs.run(page, "draw_loop", {"ids": ids, "n": self.args.draws, "timeoutMs": GRADE_TIMEOUT_MS})
        times = res["times"]
        run["draw"] = {"exercises": ids, "first_ms": times[0], "p50_ms": percentile(times, 50),
                       "p95_ms": percentile(times, 95), "max_ms": max(times), "n": len(times)}
        page.evaluate("() => { for (const id of Object.keys(window.workbook.progress.all())) "
                      "window.workbook.progress.update(id, {variant: 0}); }")

    def build(self, page, run: dict) -> None:
        out = {label: self.build_series(page, BUILD_ID, code, first_timeout, label)
               for label, code, first_timeout in (("plain", BUILD_PLAIN, GRADE_TIMEOUT_MS),
                                                  ("numpy", BUILD_NUMPY, NUMPY_TIMEOUT_MS))}
        # The sandbox that ran them (docs/assets/js/sandbox.js): its start, and its interpreter's memory.
        out["sandbox"] = page.evaluate("() => { const s = window.workbook.sandbox; return s && s.ready ? "
                                       "{start_ms: s.readyAt - s.startedAt, wasm_bytes: s.startStages.wasmBytes} : "
                                       "null; }")
        run["build"] = out

    def build_series(self, page, ex_id: str, code: str, first_timeout: float, label: str = "plain") -> dict:
        """A first Build run of ``code`` on exercise ``ex_id``, then the repeats: their times and bytes."""
        ex = page.locator(exercise(ex_id))
        ex.evaluate("(el, ms) => window.__bench.openEditor(el, ms).then(() => null)", READY_TIMEOUT_MS)
        mark = self.b.server.mark()
        results = []
        for i in range(1 + self.args.build_repeats):
            r = pagejs.run(page, "build_run", {"id": ex_id, "code": code if i == 0 else None,
                                               "timeoutMs": first_timeout if i == 0 else GRADE_TIMEOUT_MS})
            if r["state"] != STATE.correct or not r["passed"] or not all(r["passed"]):
                msg = ex.locator(role(ROLE.feedback)).inner_text()
                raise BenchError(f"build {ex_id} {label} run {i + 1}: state {r['state']}, tests {r['passed']}: "
                                 f"{msg[:300]}")
            results.append(r["ms"])
        return {"first_ms": results[0], "repeat_median_ms": statistics.median(results[1:]),
                "repeat_ms": results[1:], "bytes": sum(e["bytes"] for e in self.b.server.since(mark))}

    def recovery(self, page, run: dict) -> None:
        res = pagejs.run(page, "recovery", {"buildId": BUILD_ID, "deriveId": GRADED["derive"][1], "code": BUILD_LOOP,
                                            "answer": DERIVE_INPUT, "timeoutMs": 60_000})
        if res.get("deriveState") not in GRADED_STATES:
            raise BenchError(f"recovery: derive exercise ended {res.get('deriveState')!r}")
        run["recovery"] = {"recovery_ms": res["recoveryMs"], "run_to_limit_ms": res["runToLimitMs"],
                           "build_state": res["buildState"], "message": res["message"][:160]}
        page.locator(exercise(BUILD_ID)).evaluate("(el, sel) => el.querySelector(sel).wbEditor.setCode('')",
                                                  role(ROLE.editor))

    # -- a learner who clicks Check the instant the page opens ----------------------
    def first_feedback(self, run: dict) -> None:
        """Type an answer and click Check the instant the page opens (cold)."""
        b = self.b
        ctx = b.new_context()
        try:
            page = b.new_page(ctx)
            page.goto(b.site + CH0, wait_until="commit", timeout=30_000)
            ex_id = GRADED["derive"][1]
            ex = page.locator(exercise(ex_id))
            ex.locator(role(ROLE.answer)).fill(DERIVE_INPUT, timeout=30_000)
            ex.locator(role(ROLE.check)).click(timeout=30_000)
            waiting = (STATE.pending, STATE.unanswered)
            expr = ("() => (window.__bench.states || []).some(([id, s]) => id === %s && !%s.includes(s))"
                    % (json.dumps(ex_id), json.dumps(waiting)))
            try:
                page.wait_for_function(expr, timeout=READY_TIMEOUT_MS, polling=50)
            except Exception as err:
                docs = page.evaluate("() => window.__bench && window.__bench.docs")
                raise BenchError(f"first feedback: no result ({str(err).splitlines()[0]}); "
                                 f"documents loaded: {docs}") from None
            snap = pagejs.run(page, "snapshot")
            shift = snap["sinceTabStart"]  # > 0 when the click reloaded the page
            state, first = next((s, t) for i, s, t in snap["states"] if i == ex_id and s not in waiting)
            ready = next((t for s, t in snap["runtime"] if s == "ready"), None)
            run["first_feedback"] = {"feedback_ms": first + shift, "click_ms": (snap["tabClicks"] or [None])[0],
                                     "ready_ms": None if ready is None else ready + shift, "state": state,
                                     "documents": snap["docs"], "reloaded": snap["docs"] > 1}
            page.close()
        finally:
            ctx.close()

    # -- the bare loadPyodide page ------------------------------------------------
    def baseline(self, run: dict) -> None:
        b = self.b
        ctx = b.new_context()
        try:
            page, cold = b.visit(ctx, b.baseline_url, baseline=True)
            page.close()
            page, warm = b.visit(ctx, b.baseline_url, baseline=True)
            page.close()
            run["baseline_cold"], run["baseline_warm"] = cold, warm
        finally:
            ctx.close()

    # -- the class page: 1,000 hand-ins read and re-graded (class_page.py) ---------
    def class_page(self, run: dict) -> None:
        run["class_page"] = class_page.measure(self.b, self.args.class_files)

    # -- a first visit through Chromium's throttling: what the learner waits for (waiting.py)
    def waiting(self, run: dict) -> None:
        run["waiting"] = waiting.slow_first_visit(self.b)

    # -- a first visit on this profile's link, ours and the baseline's --------------
    def first_visit(self, run: dict) -> None:
        run["first_visit"] = first_visit.ours(self.b, self.profile)

    def first_visit_baseline(self, run: dict) -> None:
        run["first_visit_baseline"] = first_visit.baseline(self.b, self.profile)

    def first_visit_stock(self, run: dict) -> None:
        run["first_visit_stock"] = first_visit.stock(self.b, self.profile)

    # -- all of them, `runs` times ------------------------------------------------
    def run_all(self, names: list[str], runs: int) -> list[dict]:
        """`names` (of LOCAL_PHASES) then the first visits, ours, the baseline's and the stock page's,
        rotating which goes first from run to run."""
        local = [name for name in LOCAL_PHASES if name in names]
        for i in range(runs):
            # ours, the baseline and the stock page, each run starting one further along
            three = ["first_visit", "first_visit_baseline", "first_visit_stock"]
            order = local + three[i % 3:] + three[:i % 3]
            run: dict = {"index": i + 1, "profile": self.profile.name, "errors": {}}
            for name in order:
                self.run_phase(run, name, getattr(self, name))
            self.runs.append(run)
            print(f"  {self.profile.name} run {i + 1}/{runs} done ({sum(run['phase_seconds'].values()):.0f} s)"
                  + (f", errors in {sorted(run['errors'])}" if run["errors"] else ""), file=sys.stderr)
        return self.runs

    def run_phase(self, run: dict, name: str, fn) -> None:
        """One phase, timed; an error is recorded and the bench goes on."""
        if time.monotonic() > self.b.deadline:
            run["errors"][name] = "skipped: time budget spent"
            return
        t0 = time.monotonic()
        try:
            fn(run)
        except Exception as err:  # record and go on: one bad run must not lose the others
            detail = str(err) if isinstance(err, BenchError) else traceback.format_exc(limit=3)
            run["errors"][name] = detail
            print(f"  {self.profile.name} run {run['index']} {name}: ERROR {detail.splitlines()[0]}", file=sys.stderr)
        run.setdefault("phase_seconds", {})[name] = round(time.monotonic() - t0, 1)
        self.b.remove_profiles()
