"""The class page with a class's worth of work: 200 hand-in files (docs/assets/js/class-page.js)
handed in at once, read and every recorded answer re-graded in the page's grader. Measured
from the files being given to the page to the table drawn (the issue's aim: under a minute on
this machine); reported, never asserted.

Each learner ``s0`` … ``s199`` of class ``BENCH`` hands in chapter 0's and 1's Derive
exercises, each with two answers at their own numbers: a known slip (or a wrong number)
first, then the key; so a file's every solve is verified.
"""

from __future__ import annotations

import json
import time

from workbook import bank
from workbook.assignment import assigned_variant
from workbook.kinds.derive import Derive

CODE = "BENCH"
LEARNERS = 200
TIMEOUT_MS = 900_000


def exercise_ids() -> list[str]:
    return [ex.id for ch in (0, 1) for ex in bank.chapter(ch) if ex.kind == "derive"]


def hand_in(student: str, ids: list[str], now: int) -> bytes:
    records = {}
    for ex_id in ids:
        v = assigned_variant(CODE, student, ex_id)
        ex = bank.variant(ex_id, v)
        assert isinstance(ex, Derive), ex_id
        answer = ex.answer
        wrong = answer.slips[0].value if answer.slips else None
        first = answer.typed(wrong) if wrong is not None else "123456"
        attempts = [{"answer": first, "status": "incorrect", "at": now},
                    {"answer": answer.typed(answer.key), "status": "correct", "at": now + 1}]
        records[ex_id] = {"attempts": 2, "updated": now + 1, "variant": v, "done": [v], "clean": [v], "solved": True,
                          "assigned": {CODE: {"variant": v, "attempts": attempts}}}
    data = {"format": "robotics-math-workbook-hand-in", "version": 1, "handedIn": "2026-01-01T00:00:00Z",
            "student": student, "assignment": {"class": CODE, "exercises": ids, "due": None}, "records": records}
    return json.dumps(data).encode()


def measure(b) -> dict:
    """Open the class page in a fresh browser, hand in the files, wait for the table."""
    ids = exercise_ids()
    now = int(time.time() * 1000) - 3_600_000
    files = [{"name": f"s{i}.json", "mimeType": "application/json", "buffer": hand_in(f"s{i}", ids, now)}
             for i in range(LEARNERS)]
    ctx = b.new_context()
    try:
        page = ctx.new_page()
        page.goto(b.site + "class/")
        page.wait_for_function("() => document.documentElement.dataset.workbookRuntime === 'ready'", timeout=TIMEOUT_MS)
        t0 = time.monotonic()
        page.locator("#wb-class-files").set_input_files(files)
        page.wait_for_function("n => document.querySelector('[data-wb-class]').dataset.wbGraded === String(n)",
                               arg=LEARNERS, timeout=TIMEOUT_MS)
        total = (time.monotonic() - t0) * 1000
        verified = page.locator("td[data-wb-cell='verified']").count()
        return {"files": LEARNERS, "exercises": len(ids), "regrades": LEARNERS * len(ids) * 2,
                "verified": verified, "total_ms": round(total), "page_seconds": float(page.evaluate(
                    "() => document.querySelector('[data-wb-class]').dataset.wbSeconds"))}
    finally:
        ctx.close()
