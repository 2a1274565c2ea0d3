"""The golden transcript: every learner-facing message of every exercise, in one file.

For each exercise it replays the key, each known slip, the typical invalid
inputs and, for Build, the starter, the solution and broken programs, and
records what the grader says (status, tag, message; for Build the test rows
too). ``transcript.json`` beside this file is the reviewed copy:
``tests/unit/test_golden.py`` fails when the grader's words change, and

    python tests/golden/transcript.py --write

rewrites it, so a change of wording is one diff to review.
"""

from __future__ import annotations

import json
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "pyodide_pkg"))

from workbook import bank  # noqa: E402
from workbook.kinds.derive import fmt  # noqa: E402
from workbook.verdict import GradingError  # noqa: E402

FILE = Path(__file__).with_name("transcript.json")
INVALID = ("", "   ", "2,5", "3 4", "abc", "x + 1", "1/0", "sqrt(-1)", "((1)", "1e999")
BROKEN = {
    "syntax": "def f(:\n    pass\n",
    "raises": "def {fn}(*args):\n    return 1 / 0\n",
    "missing": "x = 1\n",
    "wrong-shape": "def {fn}(*args):\n    return 5\n",
    "loads-badly": "import no_such_module_here\n",
}


def said(verdict) -> dict:
    out = {"status": verdict.status, "tag": verdict.tag, "message": verdict.message}
    rows = verdict.data.get("tests") if isinstance(verdict.data, dict) else None
    if rows:
        out["tests"] = [f"{'pass' if r['passed'] else 'FAIL'} {r['input']} -> {r['actual']}"
                        + (f" | {r['message']}" if r.get("message") else "") for r in rows]
    return out


def attempt(ex, answer) -> dict:
    try:
        return said(ex.check(answer))
    except GradingError as err:
        return {"error": err.kind, "message": err.message}


def derive(ex) -> dict:
    key = ex.key
    tries = {"key": repr(key), "printed": fmt(key) + ("°" if ex.angle == "deg" else "")}
    if key:
        tries["negated"] = repr(-key)
        tries["off by 1%"] = repr(key * 1.01)
        tries["off by 10%"] = repr(key * 1.1)
    else:
        tries["off by 0.01"] = "0.01"
    if ex.angle == "deg":
        tries["in radians"] = repr(key * 3.141592653589793 / 180)
        tries["in radians, with the unit"] = f"{key * 3.141592653589793 / 180!r} rad"
        tries["as a sum of degrees"] = f"{key / 2!r}° + {key / 2!r}°"
        tries["plus a turn"] = f"{key + 360!r}°"
    if ex.unit in ("m", "m/s"):
        tries["with its unit"] = f"{fmt(key)} {ex.unit}"
        tries["in centimetres"] = f"{key * 100!r} cm" + ("/s" if ex.unit == "m/s" else "")
    tries["with a unit of the wrong kind"] = f"{fmt(key)} s"
    for i, slip in enumerate(ex.slips, start=1):
        tries[f"slip {i}"] = repr(slip.value)
    for text in INVALID:
        tries[f"invalid {text!r}"] = text
    return {name: {"answer": text, **attempt(ex, text)} for name, text in tries.items()}


def build(ex) -> dict:
    programs = {"starter": ex.starter, "solution": ex.solution}
    programs.update({name: code.format(fn=ex.function) for name, code in BROKEN.items()})
    return {name: attempt(ex, code) for name, code in programs.items()}


def choices(ex) -> dict:
    if ex.kind == "trace":
        answers = [o.key for o in ex.options] + [None, "z"]
    elif ex.kind == "debug":
        answers = list(range(1, len(ex.lines) + 1)) + [None, 0, "x"]
    else:  # design
        answers = [list(ex.shown), list(ex.solution), list(ex.solution)[::-1], [], None]
    return {json.dumps(a, ensure_ascii=False): attempt(ex, a) for a in answers}


def transcript() -> dict:
    out = {}
    for ex in bank.all_exercises():
        replay = derive if ex.kind == "derive" else build if ex.kind == "build" else choices
        out[ex.id] = {"kind": ex.kind, "title": ex.title, "said": replay(ex)}
    return out


def dumps(data: dict) -> str:
    return json.dumps(data, indent=1, ensure_ascii=False, sort_keys=False) + "\n"


if __name__ == "__main__":
    if "--write" not in sys.argv:
        sys.exit("usage: python tests/golden/transcript.py --write   (rewrites transcript.json)")
    FILE.write_text(dumps(transcript()), encoding="utf-8")
    print(f"wrote {FILE.relative_to(ROOT)}")
