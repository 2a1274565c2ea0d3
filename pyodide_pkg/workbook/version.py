"""What grader is running: the package's version and a hash of its sources (the bank of
exercises, their keys and slips, and the graders that read answers). The class page names
both when it re-grades hand-ins, so a teacher can tell which grader gave a mark, and that a
fix changed it (``{"op": "version"}``, :mod:`workbook.api`).

The sources are read through :mod:`importlib.resources` and hashed as programs (their syntax
tree without docstrings, the way scripts/split_stdlib.py minifies them for the page), so the
same hash comes from an installed package, a source tree and the page's zipped standard
library. Worked out once, on the first request (the page's snapshot makes one:
scripts/build_snapshot.mjs). A start from compiled files only has no sources to hash:
``bank`` is then None.

>>> v = describe()
>>> v["version"] == VERSION and len(v["bank"] or "") == 12
True
"""

from __future__ import annotations

import ast
import functools
import hashlib
from importlib import resources
from importlib.resources.abc import Traversable

VERSION = "0.1.0"  # pyodide_pkg/pyproject.toml's (tests/unit/test_version.py checks they agree)
SOURCES = (".py", ".json")


def _files(folder: Traversable, prefix: str = "") -> list[tuple[str, Traversable]]:
    out = []
    for item in folder.iterdir():
        name = f"{prefix}{item.name}"
        if item.is_dir():
            if item.name != "__pycache__":
                out += _files(item, name + "/")
        elif item.name.endswith(SOURCES + (".pyc",)):
            out.append((name, item))
    return out


def strip_docstrings(tree: ast.AST) -> ast.AST:
    """Remove the docstring of the module and of every class and function (in place; returns the tree).
    The build's stdlib minifier (scripts/split_stdlib.py) strips them the same way."""
    for node in ast.walk(tree):
        if isinstance(node, (ast.Module, ast.ClassDef, ast.FunctionDef, ast.AsyncFunctionDef)):
            body = node.body
            if body and isinstance(body[0], ast.Expr) and isinstance(body[0].value, ast.Constant) \
                    and isinstance(body[0].value.value, str):
                body[0:1] = [] if len(body) > 1 else [ast.Pass()]
    return tree


def _program(source: bytes) -> bytes:
    """A module's syntax tree without the docstring of the module and of each class and function."""
    return ast.dump(strip_docstrings(ast.parse(source))).encode()


@functools.cache
def bank_hash() -> str | None:
    """The first 12 hex digits of SHA-256 over every Python and JSON source of the package
    (its path and bytes, in path order): any change to an exercise, a key, a slip or a grader
    changes it. None when the package is there as compiled files only."""
    files = sorted(_files(resources.files("workbook")))
    names = {name for name, _ in files}
    if any(name.endswith(".pyc") and name[:-1] not in names for name in names):
        return None
    digest = hashlib.sha256()
    for name, item in files:
        if name.endswith(SOURCES):
            data = item.read_bytes()
            digest.update(name.encode() + b"\0" + (_program(data) if name.endswith(".py") else data) + b"\0")
    return digest.hexdigest()[:12]


def describe() -> dict[str, str | None]:
    return {"version": VERSION, "bank": bank_hash()}
