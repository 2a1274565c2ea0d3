"""Progress schema 5 (docs/assets/js/assignment-schema.js, progress-schema.js): the named slips
counted per exercise (merged per name as the larger count, bounded) and an assignment's graded
answers (merged as the union of attempts, bounded); both checked on import. Run in Node: the
modules are pure."""

from __future__ import annotations

import json
import shutil
import subprocess
from pathlib import Path

import pytest

JS = Path(__file__).resolve().parents[2] / "docs" / "assets" / "js"
pytestmark = pytest.mark.skipif(shutil.which("node") is None, reason="needs Node")

SCRIPT = """
import { countSlip, mergeSlips, mergeAssigned, addAttempt, isSlips, isAssigned, MAX_SLIPS, MAX_ATTEMPTS } from "%(a)s";
import { mergeRecord, parseImport, SCHEMA_VERSION, canonical } from "%(p)s";
import { LIMIT } from "%(c)s";
const out = {};
let s = {};
for (let i = 0; i < 40; i++) s = countSlip(s, `slip: ${i %% 30}`);
s = countSlip(s, "sign"); s = countSlip(s, "sign");
out.bounded = Object.keys(s).length <= MAX_SLIPS && s.sign === 2 && isSlips(s);
out.newKept = countSlip(s, "fresh").fresh === 1;
const a = { "sign": 3, "slip: x": 1 }, b = { "sign": 1, "transpose": 2 };
out.mergeSlips = mergeSlips(a, b);
out.slipsOrderFree = canonical(mergeSlips(a, b)) === canonical(mergeSlips(b, a)) && canonical(mergeSlips(a, mergeSlips(a, b))) === canonical(mergeSlips(a, b));
const t = (at, status) => ({ answer: String(at), status, at });
const x = addAttempt(addAttempt({}, "ROB", 5, t(1, "incorrect")), "ROB", 5, t(3, "correct"));
const y = addAttempt({}, "ROB", 5, t(2, "incorrect"));
const m = mergeAssigned(x, y);
out.attempts = m.ROB.attempts.map((q) => q.at);
out.assignedOrderFree = canonical(m) === canonical(mergeAssigned(y, x)) && canonical(mergeAssigned(m, x)) === canonical(m);
let many = {};
for (let i = 1; i <= 30; i++) many = addAttempt(many, "ROB", 5, t(i, "incorrect"));
out.attemptsBounded = many.ROB.attempts.length === MAX_ATTEMPTS && many.ROB.attempts[0].at === 30 - MAX_ATTEMPTS + 1 && isAssigned(many);
out.record = mergeRecord({ slips: a, assigned: x, updated: 1 }, { slips: b, assigned: y, updated: 2 });
out.version = SCHEMA_VERSION;
const file = (r) => JSON.stringify({ format: "robotics-math-workbook-progress", version: 5, exercises: { "0.1": r } });
out.goodImport = parseImport(file({ slips: { sign: 2 }, assigned: x }), new Set(["0.1"])).ok;
out.bad = [
  { slips: { sign: 0 } }, { slips: { ["x".repeat(81)]: 1 } }, { slips: JSON.parse('{"__proto__": 1}') },
  { assigned: { ROB: { variant: 5, attempts: [{ answer: "1", status: "correct", at: 1, extra: 1 }] } } },
  { assigned: { ROB: { variant: 1e7, attempts: [] } } },
  { assigned: { ROB: { variant: 5, attempts: [{ answer: "1", status: "maybe", at: 1 }] } } },
].map((r) => parseImport(file(r), new Set(["0.1"])).ok);
// One schema: an attempt carries what a request may (contract.json limits: given 8, steps 12), no more.
const given = (n) => Object.fromEntries(Array.from({ length: n }, (_, i) => [`0.${i + 1}`, { answer: "1", variant: 0 }]));
const steps = (n) => Object.fromEntries(Array.from({ length: n }, (_, i) => [`s${i}`, "1"]));
const one = (extra) => isAssigned({ ROB: { variant: 5, attempts: [{ answer: "1", status: "incorrect", at: 1, ...extra }] } });
out.limits = { given: LIMIT.given, steps: LIMIT.steps };
out.given = [5, 8, 9].map((n) => one({ given: given(n) }));
out.steps = [12, 13].map((n) => one({ steps: steps(n) }));
out.run = [isAssigned({ ROB: { variant: 0, attempts: [{ code: "x = 1", status: "correct", at: 1 }] } }),
  isAssigned({ ROB: { variant: 0, attempts: [{ status: "incorrect", at: 1 }] } }),
  one({ code: "x = 1" }), isAssigned({ ROB: { variant: 0, attempts: [{ code: "x".repeat(LIMIT.code + 1), status: "correct", at: 1 }] } })];
out.lastInImport = parseImport(file({ last: [["1", "2"], ["3", "4"]], assigned: { ROB: { variant: 5, attempts: [{ answer: "1", status: "incorrect", at: 1, given: given(8) }] } } }), new Set(["0.1"])).ok;
out.v4 = parseImport(JSON.stringify({ format: "robotics-math-workbook-progress", version: 4, exercises: { "0.1": { solved: true } } }), new Set(["0.1"])).ok;
process.stdout.write(JSON.stringify(out));
"""


def test_slips_and_assigned_merge_and_check(tmp_path):
    script = tmp_path / "run.mjs"
    script.write_text(SCRIPT % {"a": (JS / "assignment-schema.js").as_uri(), "p": (JS / "progress-schema.js").as_uri(),
                                "c": (JS / "contract.js").as_uri()})
    out = json.loads(subprocess.run(["node", str(script)], capture_output=True, text=True, check=True).stdout)
    assert out["bounded"] and out["newKept"] and out["slipsOrderFree"] and out["assignedOrderFree"] and out["attemptsBounded"]
    assert out["mergeSlips"] == {"sign": 3, "transpose": 2, "slip: x": 1}
    assert out["attempts"] == [1, 2, 3]
    assert out["record"]["slips"] == {"sign": 3, "transpose": 2, "slip: x": 1}
    assert [q["at"] for q in out["record"]["assigned"]["ROB"]["attempts"]] == [1, 2, 3]
    assert out["version"] == 5 and out["goodImport"] and out["v4"]
    assert out["bad"] == [False] * 6
    # One schema with the grader's limits: an attempt with 5 to 8 earlier answers is kept (assignment-schema.js
    # allowed 4, so such an attempt set aside every class's attempts on the next load), 9 are not.
    assert out["limits"] == {"given": 8, "steps": 12}
    assert out["given"] == [True, True, False] and out["steps"] == [True, False]
    assert out["lastInImport"]
    # A Build run's attempt holds the code it ran (or none, when too long), never both code and answer.
    assert out["run"] == [True, True, False, False]
