"""contract.json holds names and limits only; the facts other parts own are checked against them.

The JSON is bundled into the page and both workers, so it carries no prose (CONTRACT.md
explains every entry). What CONTRACT.md says of other parts is checked against those parts:
its table of Build functions against the bank, and which kinds each request (op) applies to
against what the worker answers.
"""

import json
import re
from pathlib import Path

import pytest

from markdown_table import table_after
from workbook import bank
from workbook.api import handle
from workbook.contract import DATA, KINDS, OPS

ROOT = Path(__file__).resolve().parents[2]
# CONTRACT.md is the index; its parts, one per audience, are contract/*.md: the prose is all of them.
CONTRACT_MD = "\n".join(path.read_text(encoding="utf-8")
                        for path in [ROOT / "CONTRACT.md", *sorted((ROOT / "contract").glob("*.md"))])
NAME = re.compile(r"[A-Za-z][A-Za-z0-9_.-]*( [a-z]+)?")  # a name ("data-exercise-id", "variant texts")


def _strings(value):
    if isinstance(value, str):
        yield value
    elif isinstance(value, dict):
        for key, item in value.items():
            yield key
            yield from _strings(item)
    elif isinstance(value, list):
        for item in value:
            yield from _strings(item)


def test_the_json_holds_names_and_limits_only():
    prose = [s for s in _strings(DATA) if not NAME.fullmatch(s)]
    assert not prose, f"contract.json holds text that is not a name (it belongs in CONTRACT.md): {prose[:3]}"
    assert all(type(v) is int for v in DATA["limits"].values())


def test_contract_md_explains_every_name():
    for section in ("roles", "tags", "errors", "ops", "kinds", "states"):
        missing = [name for name in DATA[section] if f"`{name}`" not in CONTRACT_MD]
        assert not missing, f"CONTRACT.md does not explain {section} {missing}"


def _table(heading: str) -> list[list[str]]:
    """The rows of the first Markdown table after the line that starts with ``heading``."""
    return table_after(CONTRACT_MD, heading)


def test_the_build_functions_in_contract_md_are_the_banks():
    # One row per Build exercise, its signature the bank's (a new Build exercise adds its row: AUTHORING.md).
    table = {row[0]: row[1].strip("`") for row in _table("The Build exercises' functions")}
    assert table == {ex.id: ex.signature for ex in bank.all_exercises() if ex.kind == "build"}
    # The four of the shared guide's minimum keep their signatures.
    assert {k: table[k] for k in ("0.5", "4.5", "6.5", "8.4")} == {
        "0.5": "rotate_2d(x, y, theta)",
        "4.5": "ekf_update(x, P, z, R)",
        "6.5": "forward_kinematics_2link(L1, L2, theta1, theta2)",
        "8.4": "pid_step(e, e_prev, integral, Kp, Ki, Kd, dt)",
    }


REQUESTS = {  # a well-formed request of each op that names an exercise
    "grade": {"answer": "1"}, "run": {"code": "x = 1\n"}, "split": {"text": "1 2"}, "read": {"answer": "1"},
    "draw": {"variant": 1, "texts": {}}, "cases": {"code": "x = 1\n"}, "judge": {"outputs": '{"cases": []}'},
    "run-figure": {"outputs": '{"cases": []}'},
}


@pytest.mark.parametrize("op", sorted(OPS))
def test_the_kinds_each_op_applies_to_are_what_the_worker_answers(op):
    # CONTRACT.md's table of requests names the kinds of each op; the worker refuses every other
    # kind with wrong-op (and an op without an exercise, such as figure, names none).
    documented = {row[0].strip("`"): row[3] for row in _table("| op | request |")}
    said = {kind.strip() for kind in documented[op].split(",") if kind.strip()}
    assert said <= set(KINDS)
    if op not in REQUESTS:
        assert "exercise" not in OPS[op]["request"] and not said
        return
    applies = set()  # the kinds with an exercise the op is not refused for (split: a shaped answer only)
    for ex in bank.all_exercises():
        if ex.kind not in applies:
            reply = json.loads(handle(json.dumps({"op": op, "exercise": ex.id, **REQUESTS[op]})))
            if reply["ok"] or reply["error"]["kind"] != "wrong-op":
                applies.add(ex.kind)
    assert applies == said


def test_the_course_pages_names_are_in_the_contract():
    """Every course-page name CONTRACT.md promises as stable (data-wb-… attributes, actions, fields,
    cell states, ids) is in contract.json's ``course``, which the page code reads, and each is explained."""
    course = DATA["course"]
    promised = set(re.findall(r"data-wb-[a-z-]+", CONTRACT_MD))
    assert promised <= set(course["attributes"].values()), sorted(promised - set(course["attributes"].values()))
    for value in course["attributes"].values():
        assert value in CONTRACT_MD, f"CONTRACT.md does not explain {value}"
    for section in ("actions", "fields", "cells"):
        missing = [name for name in course[section] if f'"{name}"' not in CONTRACT_MD and f"`{name}`" not in CONTRACT_MD]
        assert not missing, f"CONTRACT.md does not explain course {section} {missing}"
    for name in course["ids"]:
        assert f"#{name}" in CONTRACT_MD, f"CONTRACT.md does not explain #{name}"
    assert all(type(DATA["limits"][k]) is int for k in ("classCode", "student", "slipName", "code"))
