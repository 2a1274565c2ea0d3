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
* ``python_stdlib.rest.zip``: everything else, which ``workbook_sandbox/lazy_stdlib.py``
  mounts the first time an import asks for it (the page fetches it ahead of a
  Build run that imports anything).

and, for a plain start on a first visit (the snapshot skipped), the same compiled
(``.pyc``, what CPython 3.12 writes) in two parts:

* ``python_stdlib.core.compiled.zip``: the core without the grading package. The
  sandbox starts from this very file too (``docs/assets/js/sandbox.js``), so on a
  first visit its start finds it in the HTTP cache instead of downloading 0.8 MB
  more just as the learner runs code;
* ``workbook.compiled.zip``: the grading package ``workbook``, which the grader's
  worker mounts beside it; and ``workbook.compiled.chN.zip``, chapter N's part of
  it (``chapter_packages``), for that chapter's pages.

Compiling the core's sources is most of such a start: in Node, booting and
importing took 2.7 s from sources and 1.2 s compiled. The compiled files are
0.7 MB larger, so the worker takes them only on a link where that costs less than
it saves (docs/assets/js/boot.js); a snapshot start imports nothing and always
takes the sources (the snapshot's zip importer knows that file), and so does a
stored site. They are compiled without the column positions that CPython 3.12 keeps for every
instruction (``-X no_debug_ranges``, in a child interpreter: the option is the
interpreter's, not the compiler's): tracebacks through the grader's own
modules then mark no columns, and the files are 0.5 MB smaller (1.87 -> 1.35 MB).
Line numbers stay. Learner code is compiled in the sandbox and keeps them. The core's sources are written without their
docstrings and comments (what ``python -OO`` drops, which the standard library
supports): 40 % fewer bytes and less to compile. That needs Python 3.12, the
version Pyodide runs, to parse them: the script refuses any other (the
Makefile's venv is 3.12). Entries are written in a fixed order with a fixed
date, so the same inputs give the same bytes.
"""

from __future__ import annotations

import ast
import importlib.util
import json
import marshal
import subprocess
import sys
import zipfile
from pathlib import Path

from workbook.version import strip_docstrings  # the grader's version hash strips them the same way
from workbook_sandbox.lazy_stdlib import INDEX, PACKAGE_INDEX  # the indexes the finders read

ROOT = Path(__file__).resolve().parent.parent
SOURCE = ROOT / "build" / "stdlib" / "python_stdlib.zip"
USED = ROOT / "build" / "stdlib-used.json"
PACKAGES = (ROOT / "pyodide_pkg" / "workbook", ROOT / "pyodide_pkg" / "workbook_sandbox")
OUT = ROOT / "docs" / "assets" / "vendor" / "pyodide"
CORE, REST = "python_stdlib.core.zip", "python_stdlib.rest.zip"
COMPILED = "python_stdlib.core.compiled.zip"  # without the grading package: the grader's and the sandbox's
PACKAGE_COMPILED = "workbook.compiled.zip"  # the grading package, compiled: mounted beside it by the grader
CHAPTER_COMPILED = "workbook.compiled.ch{}.zip"  # chapter N's page: its part of the package only
GRADER = "workbook"  # the top-level package the sandbox must not hold
# Files earlier builds wrote here that no page asks for now (a checkout's vendored folder outlives them).
STALE = ("python_stdlib.sandbox.compiled.zip", "python_stdlib.core.compiled.ch*.zip")
ZIP_PATH = "/lib/python312.zip"  # where Pyodide 0.27 puts the standard library's zip (on sys.path)


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


def compiled(name: str, source: bytes) -> tuple[str, bytes]:
    """``name`` compiled as CPython 3.12 writes it: a ``.pyc`` (magic number, no timestamp or source size,
    which the zip importer checks only against a source beside it, and there is none), whose code names the
    path the source would have had in the zip, so that tracebacks read the same."""
    code = compile(source, f"{ZIP_PATH}/{name}", "exec", dont_inherit=True, optimize=0)  # as Pyodide runs: asserts kept
    return name + "c", importlib.util.MAGIC_NUMBER + bytes(12) + marshal.dumps(code)


def compiled_without_columns(entries: list[tuple[str, bytes]]) -> list[tuple[str, bytes]]:
    """Every ``.py`` of ``entries`` compiled (``compiled``) by a child interpreter started with
    ``-X no_debug_ranges``; the other entries as they are."""
    sources = {n: data for n, data in entries if n.endswith(".py")}
    child = subprocess.run([sys.executable, "-X", "no_debug_ranges", __file__, "--compile"],
                           input=marshal.dumps(sources), capture_output=True, check=True)
    pycs: dict[str, bytes] = marshal.loads(child.stdout)
    return [(n + "c", pycs[n]) if n in sources else (n, data) for n, data in entries]


def _compile_stdin() -> None:
    """The child's side of ``compiled_without_columns``: sources in on stdin, ``.pyc`` bytes out."""
    if not sys._xoptions.get("no_debug_ranges"):
        sys.exit("split_stdlib --compile: start it with -X no_debug_ranges")
    sources: dict[str, bytes] = marshal.loads(sys.stdin.buffer.read())
    sys.stdout.buffer.write(marshal.dumps({n: compiled(n, data)[1] for n, data in sources.items()}))


def _write(path: Path, entries: list[tuple[str, bytes]]) -> None:
    with zipfile.ZipFile(path, "w", compression=zipfile.ZIP_DEFLATED, compresslevel=9) as z:
        for name, data in sorted(entries):
            info = zipfile.ZipInfo(name, date_time=(1980, 1, 1, 0, 0, 0))
            info.compress_type, info.external_attr = zipfile.ZIP_DEFLATED, 0o644 << 16
            z.writestr(info, data)


def package_files() -> list[tuple[str, bytes]]:
    return [(f"{package.name}/{p.relative_to(package).as_posix()}", p.read_bytes()) for package in PACKAGES
            for p in sorted(package.rglob("*")) if p.suffix in (".py", ".json") and "__pycache__" not in p.parts]


def _package_module(name: str) -> str | None:
    """The package's module an entry of the compiled core is (``workbook/bank/ch0_x.pyc``), else None."""
    module = _module(_source_name(name))
    return module if module and module.split(".")[0] in ("workbook", "workbook_sandbox") else None


def grader_entry(name: str) -> bool:
    """Whether the zip entry ``name`` belongs to the grading package (the sandbox holds none)."""
    return name.split("/")[0] == GRADER


def chapter_packages(compiled_entries: list[tuple[str, bytes]], out: Path) -> dict[int, int]:
    """Write chapter N's part of the compiled grading package for every chapter of the bank: the
    package without the modules its page does not use (scripts/chapter_modules.py), whose names it
    lists in PACKAGE_INDEX. ``compiled_entries``: the package's entries. Returns each one's size."""
    import chapter_modules  # scripts/, beside this file

    package = {m for m in map(_package_module, (n for n, _ in compiled_entries)) if m}
    heads = {m.split(".")[2].partition("_")[0][2:] for m in package if m.startswith("workbook.bank.ch")}
    numbers = sorted(int(h) for h in heads if h.isdigit())  # the bank's chN_* modules
    old = set(out.glob(CHAPTER_COMPILED.format("*")))
    sizes: dict[int, int] = {}
    for n in numbers:
        keep = chapter_modules.chapter_modules(n, package)
        left_out = sorted(package - keep)
        entries = [(name, data) for name, data in compiled_entries if _package_module(name) in keep | {None}]
        entries.append((PACKAGE_INDEX, ("\n".join(left_out) + "\n").encode()))
        path = out / CHAPTER_COMPILED.format(n)
        _write(path, entries)
        old.discard(path)
        sizes[n] = path.stat().st_size
    for stale in old:
        stale.unlink()
    return sizes


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
    compiled_entries = compiled_without_columns(core_entries)
    _write(out / COMPILED, [(n, data) for n, data in compiled_entries if not grader_entry(n)])
    package = [(n, data) for n, data in compiled_entries if grader_entry(n)]
    _write(out / PACKAGE_COMPILED, package)
    chapters = chapter_packages(package, out)
    _write(out / REST, [(n, files[n]) for n in rest])
    for pattern in STALE:
        for stale in out.glob(pattern):
            stale.unlink()
    return {"core_files": len(core_entries), "rest_files": len(rest), "core_bytes": (out / CORE).stat().st_size,
            "compiled_bytes": (out / COMPILED).stat().st_size,
            "package_bytes": (out / PACKAGE_COMPILED).stat().st_size, "rest_bytes": (out / REST).stat().st_size,
            "chapter_bytes": chapters}


def main() -> None:
    if sys.argv[1:] == ["--compile"]:
        return _compile_stdin()
    if not SOURCE.exists() or not USED.exists():
        sys.exit("split_stdlib: run scripts/vendor.py and scripts/stdlib_probe.mjs first (make does)")
    if sys.version_info[:2] != (3, 12):
        sys.exit(f"split_stdlib: needs Python 3.12 (what Pyodide 0.27 runs) to parse the standard library, not "
                 f"{sys.version.split()[0]}: run it with .venv/bin/python (make does)")
    info = split(SOURCE, json.loads(USED.read_text()), OUT)
    print(f"stdlib: core {info['core_files']} files, {info['core_bytes'] / 1e6:.2f} MB"
          f" (without docstrings and comments; compiled {info['compiled_bytes'] / 1e6:.2f} MB"
          f" and the package {info['package_bytes'] / 1e6:.2f} MB); "
          f"rest {info['rest_files']} files, {info['rest_bytes'] / 1e6:.2f} MB (fetched on first use); "
          f"the package compiled per chapter {min(info['chapter_bytes'].values()) / 1e6:.2f}-"
          f"{max(info['chapter_bytes'].values()) / 1e6:.2f} MB")


if __name__ == "__main__":
    main()
