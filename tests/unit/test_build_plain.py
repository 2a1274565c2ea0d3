"""Which Build code may run again in the same sandbox (plain) and which makes the page replace it."""

import sys
from pathlib import Path

import pytest

from workbook import bank
from workbook.build_plain import plain

sys.path.insert(0, str(Path(__file__).parent))
from test_attacks import ATTACKS

BUILDS = [ex for ex in bank.all_exercises() if ex.kind == "build"]

PLAIN = {
    "numpy": "import numpy as np\n\ndef f(x, y):\n    R = np.array([[np.cos(x), -np.sin(x)], [np.sin(x), np.cos(x)]])\n"
             "    return R @ np.array([y, 0.0])\n",
    "linalg": "import numpy.linalg as la\nfrom numpy import array\n\ndef f(P):\n    return la.inv(array(P)).tolist()\n",
    "helpers and loops": "import math\nfrom functools import reduce\n\ndef _wrap(a):\n    return math.atan2(math.sin(a), math.cos(a))\n\n"
                         "def f(xs):\n    total = 0\n    for _ in range(3):\n        total += sum(x * x for x in xs)\n"
                         "    return [_wrap(t) for t in xs], {k: v for k, v in enumerate(xs)}\n",
    "a main guard": "def f(x):\n    return x\n\nif __name__ == '__main__':\n    print(f(1))\n",
    "a class with data": "from collections import namedtuple\nPoint = namedtuple('Point', 'x y')\n\nclass Arm:\n"
                         "    def reach(self, a):\n        return a * 2\n\ndef f(x):\n    return Point(x, Arm().reach(x))\n",
    "typing": "from typing import List, Tuple\n\ndef f(xs: List[float]) -> Tuple[float, float]:\n    return (min(xs), max(xs))\n",
    "random": "import random\n\ndef f():\n    return random.gauss(0, 1)\n",
}

NOT_PLAIN = {
    "import js": "import js\njs.fetch('https://example.com')\n",
    "import pyodide": "from pyodide.ffi import to_js\n",
    "pyodide_js": "import pyodide_js\n",
    "import sys": "import sys\n",
    "import gc": "import gc\n",
    "import builtins": "import builtins\n",
    "import os": "import os\nos.system('x')\n",
    "a relative import": "from . import x\n",
    "star import": "from math import *\n",
    "__import__": "m = __import__('js')\n",
    "__builtins__": "b = __builtins__\n",
    "a dunder attribute": "t = ().__class__.__base__.__subclasses__()\n",
    "a private attribute": "import random\nr = random._inst\n",
    "getattr": "g = getattr\nc = g((), '__class__')\n",
    "globals": "globals()['x'] = 1\n",
    "eval": "eval('1')\n",
    "exec": "exec('x = 1')\n",
    "exit": "exit()\n",
    "frames from a generator": "g = (i for i in [1])\nf = g.gi_frame.f_back\n",
    "a traceback's frame": "try:\n    1 / 0\nexcept Exception as e:\n    tb = e.with_traceback(None)\n    t = tb.tb_frame\n",
    "NumPy files": "import numpy as np\nnp.load('x.npy', allow_pickle=True)\n",
    "an array written to a file": "import numpy as np\nnp.zeros(3).tofile('x')\n",
    "NumPy's internals": "import numpy as np\nc = np.core\nl = np.lib\n",
    "an error callback": "import numpy as np\nnp.seterrcall(print)\n",
    "attrgetter": "from operator import attrgetter\n",
    "get_type_hints": "from typing import get_type_hints\n",
    "an attribute assignment": "import math\nm = math\nm.cos = abs\n",
    "an attribute deletion": "import math\ndel math.cos\n",
    "augmented attribute": "class A:\n    n = 0\nA.n += 1\n",
    "a finaliser": "class A:\n    def __del__(self):\n        pass\n",
    "a dunder class attribute": "class A:\n    __slots__ = ()\n",
    "a dunder keyword": "f(**{'a': 1}, __x=1)\n",
    "a match on a dunder attribute": "match 1:\n    case object(__class__=c):\n        pass\n",
    "register an ABC": "import collections\ncollections.abc.Sequence.register(int)\n",
    "syntax error": "def f(:\n",
    "a NUL byte": "x = 1\0\n",
    "full-width getattr": "ｇｅｔａｔｔｒ(1, 'real')\n",  # noqa: RUF001 (full-width, meant)
}


@pytest.mark.parametrize("ex", BUILDS, ids=lambda e: e.id)
def test_every_starter_and_solution_is_plain(ex):
    assert plain(ex.starter) and plain(ex.solution)


@pytest.mark.parametrize("name", sorted(PLAIN))
def test_ordinary_learner_code_is_plain(name):
    assert plain(PLAIN[name])


@pytest.mark.parametrize("name", sorted(NOT_PLAIN))
def test_code_that_could_leave_a_trace_is_not(name):
    assert not plain(NOT_PLAIN[name])


@pytest.mark.parametrize("name", sorted(ATTACKS))
def test_every_native_attack_is_not_plain(name):
    assert not plain(ATTACKS[name])


def test_a_deeply_nested_program_is_not_plain_and_does_not_raise():
    assert plain("x = " + "(" * 50 + "1" + ")" * 50) is True
    assert plain("x = " + "[" * 5000 + "]" * 5000) is False  # too deep to parse: a fresh sandbox then
