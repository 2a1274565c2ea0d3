"""The hand-in file's one home (docs/assets/js/hand-in.js): what the assignment page builds, the
class page reads back (the grader's version and the time kept, a record checked as an import's
is), and a file name that tells students apart whatever their names' script. Run in Node."""

from __future__ import annotations

import json
import shutil
import subprocess
from pathlib import Path

import pytest

JS = Path(__file__).resolve().parents[2] / "docs" / "assets" / "js"
pytestmark = pytest.mark.skipif(shutil.which("node") is None, reason="needs Node")

SCRIPT = """
import { buildHandIn, handInName, readHandIn, HAND_IN_FORMAT } from "%(h)s";
import { studentTag } from "%(a)s";
const records = { "0.1": { attempts: 1, updated: 1, assigned: { ROB: { variant: 5, attempts: [{ answer: "1", status: "correct", at: 1 }] } } } };
const progress = { get: (id) => records[id] ?? {} };
const assignment = { code: "ROB", ids: ["0.1", "0.4"], due: "2026-12-01" };
const now = new Date("2026-11-30T10:00:00Z");
const built = buildHandIn({ progress, assignment, student: "Ada", grader: { version: "1.0", bank: "abcdef012345" }, now });
const plain = buildHandIn({ progress, assignment: { ...assignment, due: null }, student: "Ada", now });
const known = new Set(["0.1", "0.4"]);
const out = { built, plainKeys: Object.keys(plain), read: readHandIn(JSON.parse(JSON.stringify(built)), known) };
out.badRecord = readHandIn({ ...built, records: { "0.1": { attempts: -1 } } }, known);
out.longClass = readHandIn({ ...built, assignment: { ...built.assignment, class: "x".repeat(201) } }, known);
out.names = {};
for (const s of ["李雷", "王芳", "Émile Zola", "  ada  "]) out.names[s] = handInName("AUDIT-A2", s, await studentTag(s));
out.format = HAND_IN_FORMAT;
process.stdout.write(JSON.stringify(out));
"""


def test_a_hand_in_is_built_read_back_and_named_apart(tmp_path):
    script = tmp_path / "run.mjs"
    script.write_text(SCRIPT % {"h": (JS / "hand-in.js").as_uri(), "a": (JS / "assignment-hash.js").as_uri()})
    out = json.loads(subprocess.run(["node", str(script)], capture_output=True, text=True, check=True).stdout)
    built = out["built"]
    assert built["format"] == out["format"] == "robotics-math-workbook-hand-in" and built["version"] == 1
    assert built["handedIn"] == "2026-11-30T10:00:00.000Z" and built["assignment"] == {"class": "ROB", "exercises": ["0.1", "0.4"], "due": "2026-12-01"}
    assert built["grader"] == {"version": "1.0", "bank": "abcdef012345"} and list(built["records"]) == ["0.1"]  # 0.4 untouched: no record
    assert "grader" not in out["plainKeys"]
    read = out["read"]
    assert read["ok"] and read["learner"]["grader"] == built["grader"] and read["learner"]["handedIn"] == built["handedIn"]
    assert read["learner"]["records"] == built["records"] and read["learner"]["due"] == "2026-12-01"
    assert not out["badRecord"]["ok"] and "not valid" in out["badRecord"]["reason"]
    assert out["longClass"] == {"ok": False, "reason": "names no class code"}
    names = out["names"]
    assert len(set(names.values())) == 4 and names["  ada  "].startswith("hand-in-AUDIT-A2-ada-")  # tidied "ada": its own tag
    assert names["李雷"] != names["王芳"] and names["Émile Zola"].startswith("hand-in-AUDIT-A2-Emile-Zola-")
