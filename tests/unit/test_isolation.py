"""A learner's Build code cannot change what it is graded against, nor anything after it."""

import math
import random

import pytest

from workbook import bank
from workbook.kinds.build import Build

EX = bank.get("0.5")
IDENTITY = "def rotate_2d(x, y, theta):\n    return (x, y)\n"
GOOD = EX.solution

HOSTILE = {
    "reference": "import workbook.reference.rotation2d as r\nimport workbook.bank.ch0_rotations_2d as c\n"
                 "r.rotate_2d = lambda x, y, t: (x, y)\nobject.__setattr__(c.EXERCISES[4], 'reference', r.rotate_2d)\n",
    "math": "import math\nmath.cos = lambda t: 1.0\nmath.sin = lambda t: 0.0\nmath.isclose = lambda *a, **k: True\n",
    "random": "import random\nrandom.seed(0)\nrandom.Random.uniform = lambda self, a, b: 0.0\n",
    "builtins": "import builtins\nbuiltins.round = lambda *a: 0\nbuiltins.abs = lambda v: 0\nbuiltins.sum = lambda *a: 0\n",
    "grader": "import workbook.kinds.build as b\nb.as_numbers = lambda v, n: [0.0] * n\nb.Build.hidden_cases = lambda self: []\n"
              "import workbook.kinds.derive as d\nd.Derive.check = lambda self, a: None\n",
}


def expected(verdict):
    return [(row["input"], row["expected"]) for row in verdict.data["tests"]]


@pytest.mark.parametrize("attack", sorted(HOSTILE))
def test_a_hostile_run_is_graded_against_the_true_reference(attack):
    verdict = EX.check(HOSTILE[attack] + IDENTITY)
    assert verdict.status == "incorrect", attack
    # The same cases and expected values as an honest run of the same wrong function.
    assert expected(verdict) == expected(EX.check(IDENTITY))


@pytest.mark.parametrize("attack", sorted(HOSTILE))
def test_nothing_a_run_patches_outlives_it(attack):
    before = (math.cos, math.sin, math.isclose, round, abs, sum, random.Random.uniform, Build.hidden_cases)
    EX.check(HOSTILE[attack] + GOOD)
    after = (math.cos, math.sin, math.isclose, round, abs, sum, random.Random.uniform, Build.hidden_cases)
    assert before == after
    assert bank.get("0.5").reference(3, 0, math.pi / 2)[1] == pytest.approx(3.0)
    assert bank.get("0.1").check("3").status == "correct"
    assert EX.check(GOOD).status == "correct"
    assert EX.check(IDENTITY).status == "incorrect"


# A default swapped for an object whose == says "equal" to anything: the restore compares by
# identity, never by an object's own ==, so it is put back all the same.
LIAR = ("import copy\nclass Liar:\n    def __eq__(self, other):\n        return True\n    __hash__ = object.__hash__\n"
        "copy.deepcopy.__defaults__ = (Liar(), [])\n")


def test_a_default_that_claims_to_equal_anything_is_put_back():
    import copy

    before = copy.deepcopy.__defaults__
    EX.check(LIAR + GOOD)  # (its own run may break on it: its verdict is its own business)
    assert copy.deepcopy.__defaults__ is before
    assert EX.check(GOOD).status == "correct"


def test_random_is_reseeded_after_a_run_that_seeds_it():
    EX.check("import random\nrandom.seed(0)\n" + GOOD)
    first = random.random()
    random.seed(0)
    assert first != random.random()


TRACER = '''import sys, math


def hook(frame, event, arg):
    math.isclose = lambda *a, **k: True  # would make every later comparison agree
    return None


sys.settrace(hook)
sys.setprofile(lambda frame, event, arg: None)
'''

PLANTER = '''import sys, types
sys.modules["workbook.planted_probe"] = types.ModuleType("workbook.planted_probe")
sys.modules["json.planted_probe"] = object()
sys.meta_path.insert(0, object())
sys.path.insert(0, "/nowhere")
'''


@pytest.mark.parametrize("attack", ["trace", "plant"])
def test_a_run_s_hooks_and_planted_modules_do_not_outlive_it(attack):
    """Natively, as in the page's fresh sandbox: a trace or profile hook, a planted module and the import
    machinery's lists are put back, so a later correct run, wrong run and unrelated grade behave as fresh."""
    import sys

    hooks, path, meta = (sys.gettrace(), sys.getprofile()), list(sys.path), list(sys.meta_path)
    EX.check((TRACER if attack == "trace" else PLANTER) + GOOD)
    assert (sys.gettrace(), sys.getprofile()) == hooks
    assert "workbook.planted_probe" not in sys.modules and "json.planted_probe" not in sys.modules
    assert sys.path == path and sys.meta_path == meta
    assert EX.check(IDENTITY).status == "incorrect"
    assert EX.check(GOOD).status == "correct"
    assert math.isclose(1.0, 2.0) is False
    assert bank.get("4.1").check("5").status in ("correct", "incorrect")


# The sandbox keeps one restore for all its runs (runner.run_in_sandbox): it notes the interpreter
# again only when a module was loaded or dropped since its last exit; otherwise its notes hold.
JOB = {"function": "rotate_2d", "harness": "call", "cases": [[3, 0, math.pi / 2], [1, 2, 0.5]]}
ROTATE = EX.solution


def test_one_restore_serves_runs_that_load_nothing_and_still_undoes_each():
    from workbook_sandbox import runner
    from workbook_sandbox.restore import STDLIB_HOMES, Restore

    restore = Restore(STDLIB_HOMES)
    honest = runner.run(JOB, ROTATE, restore)
    notes = restore.spaces
    cos, sin = math.cos, math.sin
    for tamper in ("import math\nmath.cos = lambda t: 1.0\n", "import math\nmath.sin = abs\nmath.extra = 1\n"):
        runner.run(JOB, tamper + ROTATE, restore)
        assert restore.spaces is notes  # noted once, not on every run
        assert (math.cos, math.sin, hasattr(math, "extra")) == (cos, sin, False)
    assert runner.run(JOB, ROTATE, restore)["cases"] == honest["cases"]


def test_a_module_loaded_between_runs_is_noted_before_the_next():
    import sys
    import types

    from workbook_sandbox import runner
    from workbook_sandbox.restore import STDLIB_HOMES, Restore

    restore = Restore(STDLIB_HOMES)
    runner.run(JOB, ROTATE, restore)
    probe = types.ModuleType("wb_probe_loaded_late")
    probe.value = 1
    sys.modules[probe.__name__] = probe  # as an import before the run would (runner.preimport)
    try:
        runner.run(JOB, f"import {probe.__name__} as p\np.value = 2\np.added = 3\n" + ROTATE, restore)
        assert probe.value == 1 and not hasattr(probe, "added")
    finally:
        sys.modules.pop(probe.__name__, None)
    runner.run(JOB, ROTATE, restore)  # and with it gone again, the next run notes afresh
    assert probe.__name__ not in restore.table
