#!/usr/bin/env python3
"""Cut the official standard library into the core the page starts with and the rest.

Pyodide's ``python_stdlib.zip`` (2.4 MB, verified by vendor.py) holds all of
Python's standard library; a start and the grader use about 130 of its files
(``build/stdlib-used.json``, written by ``scripts/stdlib_probe.mjs``). The
worker starts from

* ``python_stdlib.core.zip``: those files, every ``__init__`` above them, the
  grading package ``workbook`` itself and ``workbook_sandbox``, which it uses
  (so no package loader runs at start-up; their docstrings, doctests included,
  stay in the repository and the wheel), and ``stdlib-rest.txt``, the names of
  the modules left out;
* ``python_stdlib.rest.zip``: everything else, which ``workbook/lazy_stdlib.py``
  mounts the first time an import asks for it (the page fetches it ahead of a
  Build run that imports anything).

Both are sources: a snapshot start imports nothing, and on a slow first visit
bytes cost more than compiling. The core's sources are written without their
docstrings and comments (what ``python -OO`` drops, which the standard library
supports): 40 % fewer bytes and less to compile. That needs Python 3.12, the
version Pyodide runs, to parse them: the script refuses any other (the
Makefile's venv is 3.12). Entries are written in a fixed order with a fixed
date, so the same inputs give the same bytes.
"""

from __future__ import annotations

import ast
import json
import sys
import zipfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
SOURCE = ROOT / "build" / "stdlib" / "python_stdlib.zip"
USED = ROOT / "build" / "stdlib-used.json"
PACKAGES = (ROOT / "pyodide_pkg" / "workbook", ROOT / "pyodide_pkg" / "workbook_sandbox")
OUT = ROOT / "docs" / "assets" / "vendor" / "pyodide"
CORE, REST = "python_stdlib.core.zip", "python_stdlib.rest.zip"
INDEX = "stdlib-rest.txt"  # workbook/lazy_stdlib.py reads it


def _source_name(name: str) -> str:
    return name[:-1] if name.endswith(".pyc") else name


def _module(name: str) -> str | None:
    """``email/mime/text.py`` -> ``email.mime.text``; a package's ``__init__`` -> the package."""
    if not name.endswith(".py"):
        return None
    parts = name[:-3].split("/")
    if parts[-1] == "__init__":
        parts = parts[:-1]
    return ".".join(parts) or None


def core_files(used: list[str], names: set[str]) -> set[str]:
    """The used files, with the ``__init__.py`` of every package above them."""
    keep = {_source_name(n) for n in used} & names
    for name in list(keep):
        parts = name.split("/")[:-1]
        for i in range(1, len(parts) + 1):
            init = "/".join(parts[:i]) + "/__init__.py"
            if init in names:
                keep.add(init)
    return keep


def strip_docstrings(tree: ast.AST) -> ast.AST:
    """Remove the docstring of the module and of every class and function (in place; returns the tree)."""
    for node in ast.walk(tree):
        if isinstance(node, (ast.Module, ast.ClassDef, ast.FunctionDef, ast.AsyncFunctionDef)):
            body = node.body
            if body and isinstance(body[0], ast.Expr) and isinstance(body[0].value, ast.Constant) \
                    and isinstance(body[0].value.value, str):
                body[0:1] = [] if len(body) > 1 else [ast.Pass()]
    return tree


def minify(source: bytes, name: str) -> bytes:
    """The module without docstrings and comments, if it compiles to the same program; else as it was."""
    try:
        tree = strip_docstrings(ast.parse(source, name))
    except SyntaxError:
        return source
    out = ast.unparse(tree)
    if ast.dump(ast.parse(out)) != ast.dump(tree):
        return source
    return out.encode("utf-8")


def _write(path: Path, entries: list[tuple[str, bytes]]) -> None:
    with zipfile.ZipFile(path, "w", compression=zipfile.ZIP_DEFLATED, compresslevel=9) as z:
        for name, data in sorted(entries):
            info = zipfile.ZipInfo(name, date_time=(1980, 1, 1, 0, 0, 0))
            info.compress_type, info.external_attr = zipfile.ZIP_DEFLATED, 0o644 << 16
            z.writestr(info, data)


def package_files() -> list[tuple[str, bytes]]:
    return [(f"{package.name}/{p.relative_to(package).as_posix()}", p.read_bytes()) for package in PACKAGES
            for p in sorted(package.rglob("*")) if p.suffix in (".py", ".json") and "__pycache__" not in p.parts]


def split(source: Path, used: list[str], out: Path) -> dict:
    with zipfile.ZipFile(source) as z:
        files = {i.filename: z.read(i) for i in z.infolist() if not i.is_dir()}
    keep = core_files(used, set(files))
    rest = sorted(set(files) - keep)
    rest_modules = sorted({m for m in map(_module, rest) if m})
    core_entries = [(n, minify(files[n], n) if n.endswith(".py") else files[n]) for n in keep]
    core_entries += [(n, minify(data, n) if n.endswith(".py") else data) for n, data in package_files()]
    core_entries.append((INDEX, ("\n".join(rest_modules) + "\n").encode()))
    out.mkdir(parents=True, exist_ok=True)
    _write(out / CORE, core_entries)
    _write(out / REST, [(n, files[n]) for n in rest])
    return {"core_files": len(core_entries), "rest_files": len(rest),
            "core_bytes": (out / CORE).stat().st_size, "rest_bytes": (out / REST).stat().st_size}


def main() -> None:
    if not SOURCE.exists() or not USED.exists():
        sys.exit("split_stdlib: run scripts/vendor.py and scripts/stdlib_probe.mjs first (make does)")
    if sys.version_info[:2] != (3, 12):
        sys.exit(f"split_stdlib: needs Python 3.12 (what Pyodide 0.27 runs) to parse the standard library, not "
                 f"{sys.version.split()[0]}: run it with .venv/bin/python (make does)")
    info = split(SOURCE, json.loads(USED.read_text()), OUT)
    print(f"stdlib: core {info['core_files']} files, {info['core_bytes'] / 1e6:.2f} MB"
          " (without docstrings and comments); "
          f"rest {info['rest_files']} files, {info['rest_bytes'] / 1e6:.2f} MB (fetched on first use)")


if __name__ == "__main__":
    main()
