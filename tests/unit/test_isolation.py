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
