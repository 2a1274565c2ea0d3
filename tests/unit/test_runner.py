"""The Build test runner: what a learner sees for each kind of code."""

import json

import numpy as np  # noqa: F401  (available natively; the worker loads it on demand)
import pytest

from workbook import bank
from workbook.api import handle
from workbook.kinds.build import STDOUT_CAP


def run_build(ex, code):
    return ex.check(code)


EX = bank.get("0.5")
GOOD = "import math\ndef rotate_2d(x, y, theta):\n    c, s = math.cos(theta), math.sin(theta)\n    return (c*x - s*y, s*x + c*y)\n"


def test_correct_solution_passes_visible_and_hidden_tests():
    result = run_build(EX, GOOD)
    assert result.status == "correct"
    rows = result.data["tests"]
    assert len(rows) == len(EX.examples) + 1
    assert all(r["passed"] for r in rows)
    assert rows[0]["input"].startswith("rotate_2d(3, 0, ")


def test_lists_tuples_and_numpy_arrays_are_all_fine():
    for wrap in ("list", "tuple", "np.array"):
        code = "import numpy as np\n" + GOOD.replace("return (c*x - s*y, s*x + c*y)", f"return {wrap}([c*x - s*y, s*x + c*y])")
        assert run_build(EX, code).status == "correct", wrap


def test_wrong_type_and_shape_are_named():
    r = run_build(EX, "def rotate_2d(x, y, theta):\n    return 5\n")
    assert "expected a sequence of 2 numbers, got int" in r.data["tests"][0]["message"]
    r = run_build(EX, "def rotate_2d(x, y, theta):\n    return (1, 2, 3)\n")
    assert "expected 2 numbers, got 3" in r.data["tests"][0]["message"]
    r = run_build(EX, "def rotate_2d(x, y, theta):\n    return [[1], [2]]\n")
    assert "plain numbers" in r.data["tests"][0]["message"]


def test_syntax_error_points_at_the_learners_line():
    r = run_build(EX, "import math\n\ndef rotate_2d(x, y, theta)\n    return x, y\n")
    assert (r.status, r.tag) == ("incorrect", "syntax")
    assert r.data["error"]["line"] == 3
    assert "line 3" in r.message.lower()


def test_exception_traceback_shows_only_learner_frames():
    code = "def helper(v):\n    return v / 0\n\ndef rotate_2d(x, y, theta):\n    return helper(x), y\n"
    r = run_build(EX, code)
    assert r.tag == "exception"
    tb = r.data["error"]["traceback"]
    assert "line 5, in rotate_2d" in tb and "line 2, in helper" in tb
    assert "ZeroDivisionError" in tb
    assert "runner.py" not in tb and "workbook" not in tb
    assert r.data["error"]["line"] == 2


def test_error_while_loading_the_code():
    r = run_build(EX, "import math\nundefined_name\n")
    assert r.tag == "exception" and r.data["error"]["line"] == 2


def test_missing_function_is_named():
    r = run_build(EX, "def rotate(x, y, theta):\n    return x, y\n")
    assert r.tag == "missing" and "rotate_2d(x, y, theta)" in r.message


def test_print_output_is_captured_and_capped():
    r = run_build(EX, GOOD.replace("    c, s", "    print('x' * 1000)\n    c, s"))
    assert r.status == "correct"
    assert len(r.data["stdout"]) <= STDOUT_CAP + 40
    assert r.data["stdout"].endswith("(output cut)")


def test_hidden_cases_report_the_first_failing_input():
    code = "import math\ndef rotate_2d(x, y, theta):\n    if abs(theta) < 0.2:\n        return (x, y)\n    c, s = math.cos(theta), math.sin(theta)\n    return (c*x - s*y, s*x + c*y)\n"
    r = run_build(EX, code)
    hidden = r.data["tests"][-1]
    assert hidden["passed"] is False and hidden["input"].startswith("rotate_2d(")


def test_memory_error_is_a_verdict_that_names_it():
    reply = json.loads(handle(json.dumps({"op": "run", "exercise": "0.5",
                                          "code": "def rotate_2d(x, y, theta):\n    raise MemoryError\n"})))
    verdict = reply["value"]
    assert (verdict["status"], verdict["tag"]) == ("incorrect", "exception")
    assert verdict["message"].startswith("Your code ran out of memory on rotate_2d(3, 0, 1.570796)")
    rows = verdict["data"]["tests"]
    assert rows[0]["actual"] == "raised MemoryError" and rows[1]["actual"] == "not run"


def via_api(code):
    return json.loads(handle(json.dumps({"op": "run", "exercise": "0.5", "code": code})))


@pytest.mark.parametrize("body", ["raise ValueError('no')", "raise MemoryError", "return 'x' * 10 ** 15",
                                  "return 5", "return str(self)"])
@pytest.mark.parametrize("where", ["in the function", "while loading"])
def test_an_exception_whose_message_fails_is_a_plain_verdict(body, where):
    """Issue 28: an exception whose __str__ raised (MemoryError too) escaped the runner: "sandbox
    crashed" or "out of memory" instead of a verdict about the learner's code."""
    ex = bank.get("0.5")
    cls = f"class Odd(Exception):\n    def __str__(self):\n        {body}\n"
    if where == "in the function":
        code = cls + "def rotate_2d(x, y, theta):\n    raise Odd()\n"
    else:
        code = cls + "raise Odd()\n" + ex.solution
    reply = via_api(code)
    assert reply["ok"], reply
    verdict = reply["value"]
    assert verdict["status"] == "incorrect", verdict
    assert "memory" not in verdict["message"] and "crash" not in verdict["message"], verdict["message"]
    if where == "while loading":
        assert "Odd" in verdict["message"], verdict["message"]
    else:
        row = verdict["data"]["tests"][0]
        assert row["actual"] == "raised Odd" and "its message cannot be shown" in row["message"], row


def test_a_run_still_stops_at_an_interrupt_raised_while_a_message_is_made():
    code = ("class Odd(Exception):\n    def __str__(self):\n        raise KeyboardInterrupt\n"
            "def rotate_2d(x, y, theta):\n    raise Odd()\n")
    from workbook_sandbox.runner import run
    report = run({"function": "rotate_2d", "harness": "call", "cases": [[1, 2, 0], [3, 4, 0]]}, code)
    assert report["stopped"] == "interrupt"
    assert report["cases"][0]["error"]["type"] == "Odd" and report["cases"][1] == {"skipped": True}


NUMPY_GOOD = ("import numpy as np\n\ndef rotate_2d(x, y, theta):\n"
              "    r = np.array([[np.cos(theta), -np.sin(theta)], [np.sin(theta), np.cos(theta)]], dtype='float64')\n"
              "    v = r @ np.array([x, y], dtype='float64')\n    return (float(v[0]), float(v[1]))\n")


@pytest.mark.parametrize("tamper", [
    "numpy.sctypeDict['float64'] = numpy.float16",
    "numpy.sctypeDict.update(float64=numpy.float16, double=numpy.float16)",
    "numpy.sctypeDict.clear()",
])
def test_plain_code_cannot_change_numpy_for_later_runs(tamper):
    """Issue 28: a write into one of NumPy's module-level dicts outlived the run."""
    from workbook.build_plain import plain
    code = f"import numpy\n{tamper}\ndef rotate_2d(x, y, theta):\n    return (x, y)\n"
    assert plain(code)  # the sandbox is kept after it: the restore must undo it
    assert via_api(code)["value"]["status"] == "incorrect"
    assert via_api(NUMPY_GOOD)["value"]["status"] == "correct", via_api(NUMPY_GOOD)["value"]["message"]
