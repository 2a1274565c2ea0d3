"""Whether a learner's Build code is *plain*: code that cannot leave a trace in the sandbox.

The sandbox worker is reused from one run to the next (starting one costs about
a second), and after every run it puts back what the code rebound in loaded
modules (``workbook_sandbox.restore``). That is enough for plain code, and only
for it: code that can reach the interpreter's or the worker's insides (``sys``,
``gc``, ``js``, frames, dunder attributes, ``eval``...) could change the sandbox
in ways no restore sees. The page therefore replaces the sandbox after every
run whose code is not plain.

This is a decision about *hygiene*, taken by the grader on the code's text
before it runs; it guards neither the grading nor the site (those hold by
construction: the sandbox has no keys and no capabilities, and the grader
writes every verdict). So it errs one way only: code that is plain by this
test uses

* imports of the modules in :data:`PLAIN_MODULES` only (absolute);
* no name that starts with two underscores (``__name__`` aside), and no name
  of :data:`REFLECTIVE_NAMES` (``getattr``, ``globals``, ``eval``, ...);
* no attribute that starts with an underscore, that reaches frames or code
  (``gi_frame``, ``f_back``, ``tb_frame``...) or that reads or writes files or
  hooks (:data:`RISKY_ATTRIBUTES`);
* no assignment to or deletion of an attribute (``x.y = ...``).

Anything else is simply run in a sandbox that is replaced afterwards.

>>> plain("import math\\ndef f(x):\\n    return math.cos(x), [v * 2 for v in range(3)]\\n")
True
>>> [plain(code) for code in ("import sys", "math.cos = abs", "().__class__", "getattr(1, 'real')", "x.gi_frame")]
[False, False, False, False, False]
"""

from __future__ import annotations

import ast

PLAIN_MODULES = frozenset({"math", "cmath", "random", "numpy", "numpy.linalg", "numpy.random", "itertools",
                           "functools", "statistics", "fractions", "collections", "typing"})
REFLECTIVE_NAMES = frozenset({"getattr", "setattr", "delattr", "vars", "globals", "locals", "dir", "eval", "exec",
                              "compile", "open", "breakpoint", "input", "help", "exit", "quit", "memoryview",
                              "copyright", "credits", "license"})
FRAME_PREFIXES = ("gi_", "cr_", "ag_", "f_", "tb_", "co_")
RISKY_ATTRIBUTES = frozenset({
    # files, pickles and raw memory (NumPy)
    "tofile", "fromfile", "dump", "dumps", "load", "loads", "save", "savez", "savez_compressed", "savetxt",
    "loadtxt", "genfromtxt", "memmap", "ctypes", "ctypeslib", "lib", "core", "testing", "f2py", "distutils",
    "DataSource", "fromregex", "frombuffer", "getbuffer",
    # hooks and global switches that outlive a run
    "seterrcall", "set_string_function", "setbufsize", "register", "get_type_hints", "ForwardRef",
    "attrgetter", "methodcaller", "setstate", "set_state",
})


def plain(code: str) -> bool:
    """True when ``code`` parses and uses nothing beyond what :mod:`workbook.build_plain` allows."""
    try:
        tree = ast.parse(code)
    except (SyntaxError, ValueError, RecursionError, MemoryError):
        return False  # it will not run far; a fresh sandbox costs nothing then
    try:
        return all(_plain_node(node) for node in ast.walk(tree))
    except RecursionError:
        return False


def _plain_name(name: str) -> bool:
    return name == "__name__" or not (name.startswith("__") or name in REFLECTIVE_NAMES)


def _plain_attribute(name: str) -> bool:
    return not (name.startswith("_") or name.startswith(FRAME_PREFIXES) or name in RISKY_ATTRIBUTES)


def _plain_node(node: ast.AST) -> bool:
    if isinstance(node, ast.Import):
        return all(alias.name in PLAIN_MODULES for alias in node.names)
    if isinstance(node, ast.ImportFrom):
        return (node.level == 0 and node.module in PLAIN_MODULES
                and all(alias.name != "*" and _plain_attribute(alias.name) for alias in node.names))
    if isinstance(node, ast.Attribute):
        return _plain_attribute(node.attr) and isinstance(node.ctx, ast.Load)
    if isinstance(node, ast.Name):
        return _plain_name(node.id)
    if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)):
        return not node.name.startswith("__")
    if isinstance(node, ast.arg):
        return _plain_name(node.arg)
    if isinstance(node, ast.keyword):
        return node.arg is None or not node.arg.startswith("__")
    if isinstance(node, ast.alias):
        return _plain_name(node.asname or node.name.split(".")[0])
    if isinstance(node, ast.MatchClass):
        return all(_plain_attribute(name) for name in node.kwd_attrs)
    if isinstance(node, (ast.Global, ast.Nonlocal)):
        return all(_plain_name(name) for name in node.names)
    if isinstance(node, (ast.MatchAs, ast.MatchStar)):
        return node.name is None or _plain_name(node.name)
    if isinstance(node, ast.MatchMapping):
        return node.rest is None or _plain_name(node.rest)
    return True
