"""Issue 21's attacks on the grading, run natively (in the page, tests/browser/test_sandbox.py).

Natively the learner's code runs in the grader's own process (``Build.check``),
so this is the harder setting: the code can import the grading package. Each
attack is joined to a *wrong* function and must not make it pass; after each,
a correct run passes, a wrong run fails, and the other kinds grade as before.
Careless code (``exit()``, ``raise KeyboardInterrupt``, a huge integer, memory
exhaustion) gets a verdict that says what happened, and ``handle()`` answers.
"""

import json
import math

import pytest

from workbook import bank
from workbook.api import HANDLERS, handle

EX = bank.get("0.5")
WRONG = "def rotate_2d(x, y, theta):\n    return (x, y)\n"

ATTACKS = {
    "rebind builtins.all": "import builtins\nbuiltins.all = lambda *a: True\nbuiltins.sum = lambda *a: 0\n",
    "mutate api.HANDLERS": (
        "import workbook.api as api\n"
        "api.HANDLERS['run'] = api.HANDLERS['judge'] = lambda r: {'status': 'correct', 'message': 'yes', 'tag': '', 'data': {}}\n"
        "api.HANDLERS.pop('grade')\n"
    ),
    "read expected values from the caller's frames": (
        "import sys\n"
        "def rotate_2d(x, y, theta):\n"
        "    frame = sys._getframe(1)\n"
        "    while frame:\n"
        "        for value in list(frame.f_locals.values()):\n"
        "            for case in value if isinstance(value, list) else [value]:\n"
        "                want = getattr(case, 'want', None)\n"
        "                if want is not None and getattr(case, 'input', '').endswith(f'{round(theta, 6)})'):\n"
        "                    return want\n"
        "        frame = frame.f_back\n"
        "    return (x, y)\n"
    ),
    "scan gc for test rows and verdicts": (
        "import gc\n"
        "def rotate_2d(x, y, theta):\n"
        "    for obj in gc.get_objects():\n"
        "        if isinstance(obj, dict) and 'passed' in obj and 'expected' in obj:\n"
        "            obj['passed'] = True\n"
        "        if type(obj).__name__ in ('Verdict', 'Case', 'Report'):\n"
        "            try:\n"
        "                object.__setattr__(obj, 'status', 'correct')\n"
        "                object.__setattr__(obj, 'want', [x, y])\n"
        "            except Exception:\n"
        "                pass\n"
        "    return (x, y)\n"
    ),
    "swap the reference's __code__": (
        "import workbook.reference.rotation2d as r\n"
        "r.rotate_2d.__code__ = (lambda x, y, theta: (x, y)).__code__\n"
        "import workbook.bank.ch0_rotations_2d as c\n"
        "c.EXERCISES[4].random_args.__code__ = (lambda rng: (0.0, 0.0, 0.0)).__code__\n"
    ),
    "poke cached variants and exercises": (
        "import gc\n"
        "from workbook.kinds.base import Exercise\n"
        "from workbook import bank\n"
        "bank.variant('0.1', 7)\n"
        "for obj in gc.get_objects():\n"
        "    if isinstance(obj, Exercise):\n"
        "        for field in ('key', 'rel_tol', 'abs_tol', 'hidden_count', 'examples', 'answer'):\n"
        "            if field in vars(obj):\n"
        "                object.__setattr__(obj, field, {'key': 99.0, 'examples': ()}.get(field, 0))\n"
    ),
    "patch the grader's classes": (
        "from workbook.kinds.build import Build\nimport workbook.build_judge as j\n"
        "Build.judge = lambda self, report: None\nj.first_difference = lambda *a, **k: None\n"
        "j.Mismatch = Exception\nj.judge.__code__ = (lambda *a, **k: Verdict('correct', 'All 2 tests pass.')).__code__\n"
    ),
    "patch the judge's names": (  # each one runs in every judgement (build_judge.judge, compare, first_difference)
        "import workbook.build_judge as j\n"
        "j.first_difference = lambda *a, **k: None\nj.hidden_summary = lambda rows: {'passed': True}\n"
    ),
    "replace the runner and the harness": (
        "import workbook_sandbox.runner as run, workbook_sandbox.harness as h\n"
        "h.DRIVERS['call'] = lambda fn, *a: a[:2]\nrun.Run.case = lambda self, fn, args: {'value': {}}\n"
    ),
}


def _derive_still_grades():
    assert bank.get("0.1").check("3").status == "correct"
    assert json.loads(handle('{"op": "grade", "exercise": "0.1", "answer": "3"}'))["value"]["status"] == "correct"
    assert json.loads(handle('{"op": "grade", "exercise": "0.1", "answer": "4"}'))["value"]["status"] == "incorrect"


def _builds_still_grade():
    assert EX.check(EX.solution).status == "correct"
    assert EX.check(WRONG).status == "incorrect"
    assert EX.check(EX.starter).status == "incorrect"


@pytest.mark.parametrize("name", sorted(ATTACKS))
def test_an_attack_does_not_make_a_wrong_function_pass(name):
    code = ATTACKS[name] if "def rotate_2d" in ATTACKS[name] else ATTACKS[name] + WRONG
    reply = json.loads(handle(json.dumps({"op": "run", "exercise": "0.5", "code": code})))
    assert reply["ok"] and reply["value"]["status"] == "incorrect", name
    # The expected column is the true reference's, whatever the code did.
    honest = EX.check(WRONG).data["tests"]
    assert [r["expected"] for r in reply["value"]["data"]["tests"]] == [r["expected"] for r in honest]


@pytest.mark.parametrize("name", sorted(ATTACKS))
def test_nothing_an_attack_does_outlives_its_run(name):
    handlers = dict(HANDLERS)
    EX.check(ATTACKS[name] + EX.solution)
    assert dict(HANDLERS) == handlers
    assert all is __builtins__["all"] if isinstance(__builtins__, dict) else all is __builtins__.all
    assert EX.reference(3, 0, math.pi / 2)[1] == pytest.approx(3.0)
    assert bank.get("0.1").answer.key == 3 or bank.get("0.1").check("3").status == "correct"
    assert bank.variant("0.1", 7).answer.key != 99.0
    _builds_still_grade()
    _derive_still_grades()


CARELESS = {
    "exit()": ("exit()\n" + EX.solution, "Your code raised SystemExit while loading."),
    "sys.exit() in the function": ("import sys\ndef rotate_2d(x, y, theta):\n    sys.exit(3)\n", "0 of 5 tests pass."),
    "raise KeyboardInterrupt": ("def rotate_2d(x, y, theta):\n    raise KeyboardInterrupt\n", "0 of 5 tests pass."),
    "a BaseException of its own": (
        "class Stop(BaseException):\n    pass\ndef rotate_2d(x, y, theta):\n    raise Stop('no')\n", "0 of 5 tests pass."),
    "factorial(200)": ("import math\ndef rotate_2d(x, y, theta):\n    return math.factorial(200)\n", "0 of 5 tests pass."),
    "factorial(200) inside": ("import math\ndef rotate_2d(x, y, theta):\n    return (math.factorial(200), y)\n",
                              "0 of 5 tests pass."),
    "10 ** 100000": ("def rotate_2d(x, y, theta):\n    return (10 ** 100000, y)\n", "0 of 5 tests pass."),
    "out of memory": ("def rotate_2d(x, y, theta):\n    return [0] * (2 ** 40)\n",
                      "Your code ran out of memory on rotate_2d(3, 0, 1.570796); the sandbox was restarted. 0 of 5 tests pass."),
    "out of memory while loading": ("hoard = [0] * (2 ** 40)\n", "Your code ran out of memory while loading."),
    "endless recursion": ("def rotate_2d(x, y, theta):\n    return rotate_2d(x, y, theta)\n", "0 of 5 tests pass."),
    "a repr that raises": ("class V(tuple):\n    def __repr__(self):\n        raise ValueError\n"
                           "def rotate_2d(x, y, theta):\n    return V((x,))\n", "0 of 5 tests pass."),
}


@pytest.mark.parametrize("name", sorted(CARELESS))
def test_careless_code_gets_a_verdict_that_says_what_happened(name):
    code, message = CARELESS[name]
    reply = json.loads(handle(json.dumps({"op": "run", "exercise": "0.5", "code": code})))
    assert reply["ok"], reply
    verdict = reply["value"]
    assert (verdict["status"], verdict["message"]) == ("incorrect", message)
    rows = verdict["data"]["tests"]
    if rows:
        assert len(json.dumps(verdict)) < 20_000
        first = rows[0]
        assert first["passed"] is False and first["actual"] and first["message"]
    _builds_still_grade()


def test_the_rows_name_what_went_wrong():
    rows = EX.check(CARELESS["raise KeyboardInterrupt"][0]).data["tests"]
    assert rows[0]["actual"] == "raised KeyboardInterrupt" and rows[1]["actual"] == "not run"  # a run stops there
    rows = EX.check(CARELESS["a BaseException of its own"][0]).data["tests"]
    assert [r["actual"] for r in rows] == ["raised Stop"] * 5  # the others run on
    assert EX.check(CARELESS["factorial(200)"][0]).data["tests"][0]["message"] == (
        "expected a sequence of 2 numbers, got an int of 375 digits")
    inside = EX.check(CARELESS["factorial(200) inside"][0]).data["tests"][0]
    assert inside["message"] == "expected plain numbers, got a number too large for a float (an int of 375 digits)"
    assert "RecursionError" in EX.check(CARELESS["endless recursion"][0]).data["tests"][0]["actual"]
