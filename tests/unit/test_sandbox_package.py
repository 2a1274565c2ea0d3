"""workbook_sandbox: what the sandbox worker holds. Standard library only, nothing of the
grader, and a report that is small and plain whatever the learner's code does."""

import ast
import json
import shutil
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import workbook_sandbox
from workbook_sandbox import runner
from workbook_sandbox.runner import STDOUT_CAP, TRACEBACK_CAP
from workbook_sandbox.values import ITEMS_CAP, TEXT_CAP

PACKAGE = Path(workbook_sandbox.__file__).parent
JOB = {"function": "f", "harness": "call", "cases": [[1], [2]]}


def test_it_imports_nothing_but_the_standard_library_and_itself():
    # and Pyodide's `js` (the worker's global scope, tamed in the sandbox): lazy_stdlib's default
    # fetch imports it, in the grader; the sandbox hands the finder a fetch of its own
    allowed = set(sys.stdlib_module_names) | {"workbook_sandbox", "js"}
    for path in PACKAGE.glob("*.py"):
        for node in ast.walk(ast.parse(path.read_text())):
            names = [a.name for a in node.names] if isinstance(node, ast.Import) else \
                [node.module or ""] if isinstance(node, ast.ImportFrom) and not node.level else []
            for name in names:
                assert name.split(".")[0] in allowed, f"{path.name} imports {name}"


def test_it_runs_where_the_grading_package_does_not_exist(tmp_path):
    shutil.copytree(PACKAGE, tmp_path / "workbook_sandbox", ignore=shutil.ignore_patterns("__pycache__"))
    code = "def f(x):\n    return (x, x * 2)\n"
    probe = (f"import sys, json; sys.path.insert(0, {str(tmp_path)!r})\n"
             "from workbook_sandbox import runner\n"
             "try:\n    import workbook\n    sys.exit('workbook is importable')\nexcept ImportError:\n    pass\n"
             f"print(runner.run_json(json.dumps({JOB!r}), {code!r}))\n")
    out = subprocess.run([sys.executable, "-I", "-S", "-c", probe], capture_output=True, text=True, check=True)
    report = json.loads(out.stdout)
    assert [c["value"]["text"] for c in report["cases"]] == ["(1, 2)", "(2, 4)"]


def run(code, job=JOB):
    report = runner.run(job, code)
    assert len(json.dumps(report)) < 60_000
    return report


def test_printing_is_captured_and_capped():
    report = run("def f(x):\n    print('x' * 10_000)\n    return x\n")
    assert len(report["stdout"]) == STDOUT_CAP and report["cut"] is True


def test_values_of_every_awkward_kind_are_reported_small():
    awkward = {
        "a long list": ("list(range(10 ** 6))", lambda v: v["length"] == 10 ** 6 and len(v["items"]) == ITEMS_CAP),
        "a huge int": ("10 ** 100_000", lambda v: v["number"] is None and v["text"].startswith("an int of about")),
        "a NumPy array": ("np.array([1.5, 2.5])", lambda v: [i["number"] for i in v["items"]] == [1.5, 2.5]),
        "a 0-d array": ("np.array(2.5)", lambda v: v["number"] == 2.5 and "length" not in v),
        "a NumPy float": ("np.float64(0.25)", lambda v: v["number"] == 0.25),
        "a complex": ("1 + 2j", lambda v: v["number"] is None and v["text"] == "(1+2j)"),
        "a long string": ("'y' * 10_000", lambda v: "length" not in v and len(v["text"]) == TEXT_CAP),
        "nested deeply": ("[[[[[1]]]]]", lambda v: len(json.dumps(v)) < 1000),
        "a generator": ("(i for i in range(3))", lambda v: v["number"] is None and "generator" in v["text"]),
    }
    for name, (expression, check) in awkward.items():
        report = run(f"import numpy as np\ndef f(x):\n    return {expression}\n")
        value = report["cases"][0]["value"]
        assert check(value), (name, value)


def test_objects_that_fight_back_are_reported_not_raised():
    code = ("class Bad:\n"
            "    def __len__(self):\n        raise RuntimeError('len')\n"
            "    def __iter__(self):\n        return iter(())\n"
            "    def __repr__(self):\n        raise SystemExit\n"
            "def f(x):\n    return Bad()\n")
    value = run(code)["cases"][0]["value"]
    assert value["type"] == "Bad" and value["text"] == "<Bad that cannot be shown>"
    raising = run("class E(Exception):\n    def __str__(self):\n        raise ValueError\n"
                  "def f(x):\n    raise E()\n")["cases"][0]["error"]
    assert raising["type"] == "E" and raising["message"] == "(its message cannot be shown)"


def test_a_long_message_and_a_deep_traceback_are_cut():
    error = run("def f(x):\n    raise ValueError('z' * 100_000)\n")["cases"][0]["error"]
    assert len(error["message"]) <= 300 and len(error["traceback"]) <= TRACEBACK_CAP
    error = run("def f(x):\n    return f(x)\n")["cases"][0]["error"]
    assert error["type"] == "RecursionError" and error["traceback"].count("\n") <= 8 and "..." in error["traceback"]


@pytest.mark.parametrize("code, stopped, load", [
    ("raise SystemExit(3)\n", None, "SystemExit"),
    ("raise KeyboardInterrupt\n", "interrupt", "KeyboardInterrupt"),
    ("x = [0] * 2 ** 40\n", "memory", "MemoryError"),
    ("def f(x):\n    raise KeyboardInterrupt\n", "interrupt", None),
    ("def f(x):\n    return [0] * 2 ** 40\n", "memory", None),
])
def test_a_run_stops_at_an_interrupt_or_out_of_memory_and_says_so(code, stopped, load):
    report = run(code)
    assert report["stopped"] == stopped
    if load:
        assert report["load"]["type"] == load and report["cases"] == []
    else:
        assert report["cases"][1] == {"skipped": True}


def test_syntax_errors_and_nul_bytes_are_reported_as_syntax():
    assert run("def f(:\n")["load"]["phase"] == "syntax"
    assert run("x = 1\0\n")["load"]["phase"] == "syntax"


def test_the_sandbox_call_says_when_to_start_afresh():
    report, fresh = runner.run_in_sandbox(json.dumps(JOB), "def f(x):\n    return x\n")
    assert json.loads(report)["cases"] and fresh is False
    _, fresh = runner.run_in_sandbox(json.dumps(JOB), "def f(x):\n    raise MemoryError\n")
    assert fresh is True


def test_a_run_puts_back_what_it_changed():
    import math
    import random

    run("import math, random\nmath.cos = abs\nrandom.seed(1)\nimport numpy as np\nnp.seterr(all='raise')\n"
        "def f(x):\n    return x\n")
    assert math.cos(0.0) == 1.0 and np.geterr()["divide"] == "warn"
    run("import random\nrandom.seed(1)\ndef f(x):\n    return x\n")
    after = random.random()
    random.seed(1)
    assert after != random.random()  # reseeded afresh, not left at the code's seed
