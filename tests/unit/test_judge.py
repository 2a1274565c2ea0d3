"""The grader reads the sandbox's report as data: a forged or broken one can claim outputs for the
learner's own function and nothing more; it never makes wrong values pass, never breaks the grader,
and never makes a large reply."""

import json
import math

import pytest

from workbook import bank
from workbook.api import handle
from workbook_sandbox import runner

EX = bank.get("0.5")


def judge(outputs):
    reply = json.loads(handle(json.dumps({"op": "judge", "exercise": "0.5", "outputs": outputs})))
    assert len(json.dumps(reply)) < 30_000
    return reply


def value(numbers):
    return {"type": "tuple", "length": len(numbers), "text": "?",
            "items": [{"type": "float", "number": n, "text": str(n)} for n in numbers]}


def report_of(outputs, **extra):
    return json.dumps({"load": None, "missing": False, "stopped": None, "stdout": "",
                       "cases": [{"value": value(o)} for o in outputs], **extra})


def true_outputs():
    return [list(EX.reference(*args)) for args in EX.arguments()]


def test_the_cases_op_gives_the_job_and_whether_the_code_is_plain():
    reply = json.loads(handle(json.dumps({"op": "cases", "exercise": "0.5", "code": EX.solution})))["value"]
    job = json.loads(reply["job"])
    assert job["function"] == "rotate_2d" and job["harness"] == "call" and len(job["cases"]) == 4 + 20
    assert reply["plain"] is True and reply["limit"] == 5
    assert json.loads(handle(json.dumps({"op": "cases", "exercise": "0.5", "code": "import js"})))["value"]["plain"] is False
    assert "want" not in reply["job"] and "expected" not in reply["job"]  # arguments only


def test_only_the_true_outputs_pass():
    assert judge(report_of(true_outputs()))["value"]["status"] == "correct"
    wrong = true_outputs()
    wrong[7][0] += 0.01
    verdict = judge(report_of(wrong))["value"]
    assert verdict["status"] == "incorrect" and verdict["data"]["tests"][-1]["passed"] is False


@pytest.mark.parametrize("forged", [
    {"cases": []},
    {"cases": [{"value": value([0.0, 3.0])}]},  # fewer cases than the job: the rest were not run
    {"cases": [{"passed": True}] * 24},
    {"cases": [{"value": {"type": "tuple", "length": 2, "items": [{"number": "0"}, {"number": True}]}}] * 24},
    {"cases": [{"value": {"type": "tuple", "length": 2, "items": [{"number": math.inf}] * 2}}] * 24},
    {"verdict": "correct", "status": "correct", "cases": None},
    {"cases": [{"value": {"length": 2, "items": [[0.0], [3.0]]}}] * 24},
])
def test_a_forged_report_cannot_pass_without_the_true_outputs(forged):
    reply = judge(json.dumps(forged))
    assert (not reply["ok"] and reply["error"]["kind"] == "bad-request") or reply["value"]["status"] == "incorrect"


@pytest.mark.parametrize("outputs", ["", "not json", "[]", "null", "[" * 100_000, "1e999", "x" * 2_000_000])
def test_a_report_that_is_not_one_is_a_bad_request(outputs):
    reply = judge(outputs)
    assert reply["error"]["kind"] == "bad-request"


def test_everything_a_report_says_is_cut_to_size():
    long = "z" * 200_000
    error = {"type": long, "message": long, "line": 10 ** 30, "traceback": long}
    reply = judge(json.dumps({"cases": [{"error": error}] + [{"error": {}}] * 10_000, "stdout": long}))["value"]
    rows = reply["data"]["tests"]
    assert len(rows) == 5 and all(len(r["message"]) <= 2000 and len(r["actual"]) <= 80 for r in rows)
    assert rows[0].get("line") is None and reply["data"]["stdout"].endswith("(output cut)")


def test_a_report_from_the_real_runner_judges_like_a_native_run():
    for code in (EX.solution, EX.starter, "def rotate_2d(x, y, theta):\n    return 1 / 0\n"):
        report = runner.run_json(EX.job(), code)
        assert judge(report)["value"] == EX.check(code).to_dict()


@pytest.mark.parametrize("field, bad", [("stdout", 5), ("stdout", ["a"]), ("stdout", {"a": 1}), ("cut", "yes"),
                                        ("stopped", 3), ("missing", "no"), ("load", 7)])
def test_a_report_field_of_the_wrong_type_still_gives_a_verdict_on_the_values(field, bad):
    """Issue 28: `stdout` a number made the grader fail "unexpectedly (TypeError)"."""
    reply = judge(report_of(true_outputs(), **{field: bad}))
    assert reply["ok"], reply
    assert reply["value"]["status"] == "correct"
    wrong = judge(report_of([[9.0, 9.0]] * len(true_outputs()), **{field: bad}))
    assert wrong["ok"] and wrong["value"]["status"] == "incorrect"
