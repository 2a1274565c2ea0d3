"""The golden transcript: every learner-facing message of every exercise, in one file.

For each exercise it replays the key, each known slip, the typical invalid
inputs, for a chained exercise an answer carried forward from a wrong earlier one,
and, for Build, the starter, the solution and broken programs, and
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

from workbook import bank, chains  # noqa: E402
from workbook.api import handle  # noqa: E402
from workbook.number_format import fmt  # noqa: E402

FILE = Path(__file__).with_name("transcript.json")
INVALID = ("", "   ", "2,5", "3 4", "abc", "x + 1", "1/0", "sqrt(-1)", "((1)", "1e999")
BROKEN = {
    "syntax": "def f(:\n    pass\n",
    "raises": "def {fn}(*args):\n    return 1 / 0\n",
    "missing": "x = 1\n",
    "wrong-shape": "def {fn}(*args):\n    return 5\n",
    "loads-badly": "import no_such_module_here\n",
}


def ask(ex, answer, **more) -> dict:
    """The reply to a learner's attempt, through the worker's own entry point (``api.handle``)."""
    request = ({"op": "run", "code": answer} if ex.kind == "build" else {"op": "grade", "answer": answer})
    return json.loads(handle(json.dumps({**request, "exercise": ex.id, **more})))


def said(reply: dict) -> dict:
    if not reply["ok"]:
        return {"error": reply["error"]["kind"], "message": reply["error"]["message"]}
    verdict = reply["value"]
    out = {"status": verdict["status"], "tag": verdict["tag"], "message": verdict["message"]}
    rows = verdict["data"].get("tests")
    if rows:
        out["tests"] = [f"{'pass' if r['passed'] else 'FAIL'} {r['input']} -> {r['actual']}"
                        + (f" | {r['message']}" if r.get("message") else "") for r in rows]
    return out


def attempt(ex, answer) -> dict:
    return said(ask(ex, answer))


def derive(ex) -> dict:
    a = ex.answer
    key = a.key
    deg = "°" if a.angle == "deg" else ""
    tries = {"key": repr(key), "printed": fmt(key) + deg}
    if key and not isinstance(key, int):
        tries["3 significant figures"] = f"{key:.3g}{deg}"
        tries["2 significant figures"] = f"{key:.2g}{deg}"
        tries["as LaTeX"] = "\\frac{" + fmt(2 * key) + "}{2}" + ("^{\\circ}" if deg else "")
    if key:
        tries["negated"] = repr(-key)
        tries["off by 1%"] = repr(key * 1.01)
        tries["off by 10%"] = repr(key * 1.1)
    else:
        tries["off by 0.01"] = "0.01"
    if a.angle == "deg":
        tries["in radians"] = repr(key * 3.141592653589793 / 180)
        tries["in radians, with the unit"] = f"{key * 3.141592653589793 / 180!r} rad"
        tries["as a sum of degrees"] = f"{key / 2!r}° + {key / 2!r}°"
        tries["plus a turn"] = f"{key + 360!r}°"
    if a.unit in ("m", "m/s"):
        tries["with its unit"] = f"{fmt(key)} {a.unit}"
        tries["in centimetres"] = f"{key * 100!r} cm" + ("/s" if a.unit == "m/s" else "")
    tries["with a unit of the wrong kind"] = f"{fmt(key)} s"
    for i, slip in enumerate(a.slips, start=1):
        tries[f"slip {i}"] = repr(slip.value)
    for text in INVALID:
        tries[f"invalid {text!r}"] = text
    return {name: {"answer": text, **attempt(ex, text)} for name, text in tries.items()}


def _grid(rows) -> list[list[str]]:
    return [[fmt(v) for v in row] for row in rows]


def shaped(ex) -> dict:
    """A vector or matrix answer: grids of entry texts, and pasted strings."""
    a = ex.answer
    key = _grid(a.cleaned)
    tries = {"key grid": key, "worked text": ex.worked_text(), "the Answer line's LaTeX": a.worked_tex()}
    tries["to 3 significant figures"] = [[f"{v:.3g}" for v in row] for row in a.cleaned]
    tries["transposed"] = [list(col) for col in zip(*key)]
    tries["negated"] = _grid([[-v for v in row] for row in a.cleaned])
    if a.names:
        names = [n.split("|")[0] for n in a.names]
        flat = [v for row in key for v in row]
        tries["named, in reverse order"] = ", ".join(f"{n} = {v}" for n, v in reversed(list(zip(names, flat))))
        tries["named, two names swapped"] = ", ".join(
            f"{n} = {v}" for n, v in zip(names[1::-1] + names[2:], flat))
    wrong = [row[:] for row in key]
    wrong[-1][-1] = fmt(a.cleaned[-1][-1] + 1)
    tries["one entry wrong"] = wrong
    empty = [row[:] for row in key]
    empty[0][0] = ""
    tries["an empty entry"] = empty
    tries["pasted as [[...]]"] = "[" + ", ".join("[" + ", ".join(row) + "]" for row in key) + "]"
    tries["pasted as a b; c d"] = "; ".join(" ".join(row) for row in key)
    tries["pasted, wrong shape"] = "1 2 3 4 5 6 7 8 9 10 11 12 13"
    for i, slip in enumerate(a.slips, start=1):
        tries[f"slip {i}"] = _grid(slip.value)
    tries["not a grid"] = 5
    return {name: {"answer": text, **attempt(ex, text), **_marked(ex, text)} for name, text in tries.items()}


def _marked(ex, answer) -> dict:
    reply = ask(ex, answer)
    data = reply["value"]["data"] if reply["ok"] else {}
    return {k: data[k] for k in ("wrong", "invalid", "close") if k in data}


# Each formula exercise's slips typed as a learner would, in the order of ex.slips (the slip itself is a
# function; tests/unit/test_bank.py checks that each text is its slip).
SLIP_TEXTS = {
    "3.9": ("v*sin(theta)*dt", "-v*cos(theta)*dt", "-v*sin(theta)", "v*cos(theta)*dt"),
    "4.8": ("-dy/(dx^2 + dy^2)", "dy/sqrt(dx^2 + dy^2)", "-dx/(dx^2 + dy^2)", "-dx/sqrt(dx^2 + dy^2)"),
    "6.6": ("L1*cos(theta1) + L2*cos(theta2)", "L1*sin(theta1) + L2*sin(theta1 + theta2)",
            "(L1 + L2)*cos(theta1 + theta2)"),
    "7.7": ("L1*sin(theta1) + L2*sin(theta1 + theta2)", "-L1*sin(theta1)", "-L2*sin(theta1 + theta2)",
            "L1*cos(theta1) + L2*cos(theta1 + theta2)"),
}


FORMULA_WRONG = "1 + 0*pi"


def formula(ex) -> dict:
    """A formula answer: the worked formula, the slips, a wrong formula, an unknown name, empty."""
    a = ex.answer
    tries = {"answer text": a.answer_text, "the Answer line's LaTeX": a.worked_tex()}
    for i, text in enumerate(SLIP_TEXTS[ex.id], start=1):
        tries[f"slip {i}"] = text
    tries["a wrong formula"] = FORMULA_WRONG
    tries["an unknown name"] = a.answer_text + " + q7"
    tries["empty"] = ""
    tries["unbalanced"] = "(" + a.answer_text
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


REPLAYS = {"number": derive, "matrix": shaped, "expression": formula}  # one per answer kind


def carried(ex) -> dict:
    """A chained exercise: a wrong earlier answer (10 % and 0.3 off), and the answer that follows from it."""
    out = {}
    for link in ex.uses:
        at = link.variant(ex.params)
        if at is None:
            continue
        source = bank.variant(link.source, at)
        key = source.answer.key
        wrong = (tuple(tuple(v * 1.1 + 0.3 for v in row) for row in key) if isinstance(key, tuple)
                 else key * 1.1 + 0.3)
        typed = source.answer.typed(wrong)
        theirs = ex.carried_answer({link.name: chains.value_of(source.answer.reader.read(source.answer, typed))})
        answer = theirs.typed(theirs.key)
        reply = ask(ex, answer, given={link.source: {"answer": typed, "variant": at}})
        out[f"from {link.source}"] = {"earlier": typed, "answer": answer, **said(reply), **reply["value"]["data"]}
    return out


def transcript() -> dict:
    out = {}
    for ex in bank.all_exercises():
        if ex.kind == "derive":
            replay = REPLAYS[ex.answer_kind]
        else:
            replay = build if ex.kind == "build" else choices
        out[ex.id] = {"kind": ex.kind, "title": ex.title, "said": replay(ex)}
        if getattr(ex, "uses", ()):
            out[ex.id]["carried"] = carried(ex)
    return out


def dumps(data: dict) -> str:
    return json.dumps(data, indent=1, ensure_ascii=False, sort_keys=False) + "\n"


if __name__ == "__main__":
    if "--write" not in sys.argv:
        sys.exit("usage: python tests/golden/transcript.py --write   (rewrites transcript.json)")
    FILE.write_text(dumps(transcript()), encoding="utf-8")
    print(f"wrote {FILE.relative_to(ROOT)}")
