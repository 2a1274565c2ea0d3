"""The built site's generated runtime files agree with each other and with the sources.

No browser needed, but the built site is (``make test`` builds it first).
"""

from __future__ import annotations

import ast
import base64
import dis
import gzip
import hashlib
import importlib.util
import json
import marshal
import re
import struct
import sys
import zipfile
from pathlib import Path

from workbook.version import strip_docstrings  # the one docstring stripper (the build's minifier uses it too)

SITE = Path(__file__).resolve().parents[2] / "site"
VENDOR = SITE / "assets/vendor/pyodide"


def lock() -> dict:
    return json.loads((VENDOR / "pyodide-lock.json").read_text())


def test_every_package_matches_its_lock_entry():
    """Pyodide refuses a package whose sha256 differs from the lock's."""
    for name, entry in lock()["packages"].items():
        assert hashlib.sha256((VENDOR / entry["file_name"]).read_bytes()).hexdigest() == entry["sha256"], name


def test_numpy_ships_compiled_with_a_true_record():
    """build_wheel.py compiles NumPy's modules once, so `import numpy` does not compile them in the page."""
    with zipfile.ZipFile(VENDOR / lock()["packages"]["numpy"]["file_name"]) as wheel:
        names = wheel.namelist()
        assert not [n for n in names if n.endswith(".py")]
        assert "numpy/__init__.pyc" in names
        (record,) = [n for n in names if n.endswith(".dist-info/RECORD")]
        rows = [line.split(",") for line in wheel.read(record).decode().splitlines()]
        assert sorted(row[0] for row in rows) == sorted(names)
        for path, digest, size in rows:
            if path == record:
                continue
            data = wheel.read(path)
            expected = base64.urlsafe_b64encode(hashlib.sha256(data).digest()).rstrip(b"=").decode()
            assert (digest, int(size)) == (f"sha256={expected}", len(data)), path


def _without_docstrings(source: bytes) -> str:
    return ast.dump(strip_docstrings(ast.parse(source)))


def test_the_core_standard_library_holds_the_package_as_it_is():
    """The worker imports the grading package from the core zip (scripts/split_stdlib.py): it must be today's."""
    package = SITE.parent / "pyodide_pkg" / "workbook"
    sources = {f"workbook/{p.relative_to(package).as_posix()}": p for p in package.rglob("*")
               if p.suffix in (".py", ".json") and "__pycache__" not in p.parts}
    with zipfile.ZipFile(VENDOR / "python_stdlib.core.zip") as core:
        shipped = {n for n in core.namelist() if n.startswith("workbook/")}
        assert shipped == set(sources)
        for name, path in sources.items():
            data = core.read(name)
            if name.endswith(".json"):
                assert data == path.read_bytes(), name
            else:  # the same program, perhaps without its docstrings and comments
                try:
                    assert _without_docstrings(data) == _without_docstrings(path.read_bytes()), name
                except SyntaxError:  # written by Python 3.12 (f-strings this Python cannot read): same definitions
                    defs = {n.name for n in ast.walk(ast.parse(path.read_bytes()))
                            if isinstance(n, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef))}
                    shipped_defs = set(re.findall(rb"^\s*(?:async def|def|class)\s+(\w+)", data, re.M))
                    assert shipped_defs == {d.encode() for d in defs}, name
        rest = set(core.read("stdlib-rest.txt").decode().split())
    with zipfile.ZipFile(VENDOR / "python_stdlib.rest.zip") as z:
        assert {n[:-3].replace("/", ".").removesuffix(".__init__") for n in z.namelist() if n.endswith(".py")} == rest


def snapshot_memory(name: str, info: dict) -> bytes:
    """The interpreter's memory a snapshot file holds (zero pages put back), checked against its build record."""
    packed = gzip.decompress((VENDOR / name).read_bytes())
    assert packed[:8] == b"WBSPARSE" and len(packed) == info["sparse_bytes"] < info["bytes"]
    total, runs = struct.unpack_from("<II", packed, 8)
    memory, data = bytearray(total), 16 + 8 * runs
    for i in range(runs):
        offset, length = struct.unpack_from("<II", packed, 16 + 8 * i)
        memory[offset:offset + length] = packed[data:data + length]
        data += length
    assert data == len(packed)
    assert hashlib.sha256(memory).hexdigest() == info["sha256"] and len(memory) == info["bytes"]
    return bytes(memory)


GRADER_MODULES = (b"workbook.api", b"workbook/api.py", b"workbook.kinds", b"workbook/reference")


def test_snapshot_was_made_from_the_core_the_site_ships():
    """The snapshot holds the grading package's code: a stale one would grade with old keys."""
    info = json.loads((SITE.parent / "build/snapshot.json").read_text())
    assert info["stdlib_core_sha256"] == hashlib.sha256((VENDOR / "python_stdlib.core.zip").read_bytes()).hexdigest()
    memory = snapshot_memory("workbook.snapshot.gz", info)
    assert all(name in memory for name in GRADER_MODULES)


def test_the_sandbox_snapshot_was_made_from_its_own_python_without_the_grading_package():
    """The sandbox starts from a snapshot of its own Python (its standard library, its runner imported):
    made from the files the site ships, and holding nothing of the grading package."""
    info = json.loads((SITE.parent / "build/sandbox-snapshot.json").read_text())
    assert info["stdlib"] == "python_stdlib.sandbox.zip"
    assert info["stdlib_core_sha256"] == hashlib.sha256((VENDOR / "python_stdlib.sandbox.zip").read_bytes()).hexdigest()
    memory = snapshot_memory("sandbox.snapshot.gz", info)
    assert b"workbook_sandbox.runner" in memory
    assert not [name for name in GRADER_MODULES if name in memory]


def test_the_sandbox_holds_no_grading_package():
    """The sandbox runs learner code: its Python has workbook_sandbox as it is and the grader's core
    of the standard library with the index of the rest (which it mounts on first use, the grader's
    own rest zip), not the grading package; its lock (also its fetch's manifest) names no package
    with it."""
    package = SITE.parent / "pyodide_pkg" / "workbook_sandbox"
    with zipfile.ZipFile(VENDOR / "python_stdlib.sandbox.zip") as z:
        names = set(z.namelist())
        assert not [n for n in names if n.split("/")[0] == "workbook"]
        for path in package.glob("*.py"):
            name = f"workbook_sandbox/{path.name}"
            assert _without_docstrings(z.read(name)) == _without_docstrings(path.read_bytes()), name
    with zipfile.ZipFile(VENDOR / "python_stdlib.core.zip") as core:
        assert names == {n for n in core.namelist() if n.split("/")[0] != "workbook"}
    assert "stdlib-rest.txt" in names and "workbook_sandbox/lazy_stdlib.py" in names
    # Compiled, for a plain start on a fast enough link, the sandbox starts from the grader's own compiled
    # core (sandbox.js), which therefore holds no grading package either (the grader mounts it beside).
    with zipfile.ZipFile(VENDOR / "python_stdlib.core.compiled.zip") as compiled:
        assert not [n for n in compiled.namelist() if n.split("/")[0] == "workbook"]
        assert "workbook_sandbox/lazy_stdlib.pyc" in compiled.namelist()
    assert '"python_stdlib.core.compiled.zip"' in (SITE / "assets/dist/sandbox.js").read_text()
    assert not list(VENDOR.glob("*sandbox*compiled*"))
    sandbox_lock = json.loads((VENDOR / "pyodide-lock.sandbox.json").read_text())
    assert set(sandbox_lock["packages"]) == set(lock()["packages"]) - {"robotics-workbook"}
    assert all("workbook" not in entry["imports"] for entry in sandbox_lock["packages"].values())


def _code_objects(code):
    yield code
    for const in code.co_consts:
        if hasattr(const, "co_code"):
            yield from _code_objects(const)


def _program(code) -> list:
    """Every instruction of ``code`` and of the code inside it: operation and argument (a code object's by its
    name and program), whatever the constants' order."""
    def argument(value):
        if hasattr(value, "co_code"):
            return _program(value)
        return sorted(map(repr, value)) if isinstance(value, frozenset) else repr(value)  # a set's order is the process's
    return [(code.co_name, i.opname, argument(i.argval)) for i in dis.get_instructions(code)]


def test_the_compiled_core_is_the_core_compiled():
    """A plain start on a fast enough link imports the core compiled (scripts/split_stdlib.py), in two
    files: the compiled core holds all but the grading package, ``workbook.compiled.zip`` the package
    (``workbook/``) and nothing else. Together: every module of the core and nothing else, each compiled
    by Python 3.12 (Pyodide's) from the core's own source, naming the source's place, with line numbers
    and without column positions (a fifth of its bytes: ``-X no_debug_ranges``); every other file (the
    rest's index, the package's data) as is. The offline copy leaves both out: a stored site starts
    from its snapshot, with the sources."""
    assert sys.version_info[:2] == (3, 12)  # the venv's, as the build's: the magic number below is 3.12's
    with zipfile.ZipFile(VENDOR / "python_stdlib.core.compiled.zip") as base, \
            zipfile.ZipFile(VENDOR / "workbook.compiled.zip") as package:
        assert all(n.split("/")[0] != "workbook" for n in base.namelist())
        assert all(n.split("/")[0] == "workbook" for n in package.namelist()) and package.namelist()
        compiled = {n: base.read(n) for n in base.namelist()} | {n: package.read(n) for n in package.namelist()}
        assert len(compiled) == len(base.namelist()) + len(package.namelist())
    with zipfile.ZipFile(VENDOR / "python_stdlib.core.zip") as core:
        sources = {n for n in core.namelist() if n.endswith(".py")}
        assert {n for n in compiled if n.endswith(".pyc")} == {n + "c" for n in sources}
        others = set(core.namelist()) - sources
        assert set(compiled) - {n + "c" for n in sources} == others and "stdlib-rest.txt" in others
        for name in others:
            assert compiled[name] == core.read(name), name
        for name in sorted(sources):
            pyc = compiled[name + "c"]
            assert pyc[:4] == importlib.util.MAGIC_NUMBER, name
            code = marshal.loads(pyc[16:])
            assert code.co_filename == f"/lib/python312.zip/{name}", name
            source = compile(core.read(name), code.co_filename, "exec", dont_inherit=True)
            assert _program(code) == _program(source), name  # (equal code objects may share one constant)
            positions = [p for c in _code_objects(code) for p in c.co_positions()]
            assert all(p[2] is None and p[3] is None for p in positions), name  # no columns
            assert not positions or any(p[0] is not None for p in positions), name  # lines kept
    manifest = (SITE / "sw.js").read_text()
    assert "python_stdlib.core.compiled.zip" not in manifest and "workbook.compiled.zip" not in manifest
    assert '"assets/vendor/pyodide/python_stdlib.core.zip"' in manifest


def test_each_chapter_s_compiled_package_is_the_compiled_package_less_what_it_lists():
    """Chapter N's compiled package (scripts/split_stdlib.py, scripts/chapter_modules.py) is the compiled
    package without some of its modules, and lists exactly those (the sources' core holds them:
    the page imports them from there on first use); it keeps the chapter's own bank modules and the
    package's modules outside the bank, the figures and the references. Each chapter's page names its
    own (docs/hooks/exercises.py), and the offline copy holds none of them."""
    manifest = (SITE / "sw.js").read_text()
    with zipfile.ZipFile(VENDOR / "workbook.compiled.zip") as z:
        full = {n: z.read(n) for n in z.namelist()}
    with zipfile.ZipFile(VENDOR / "python_stdlib.core.zip") as z:
        sources = set(z.namelist())
    chapters = sorted(SITE.glob("chapters/[0-9][0-9]-*/index.html"))
    assert len(chapters) >= 14
    for page in chapters:
        n = int(page.parent.name[:2])
        name = f"workbook.compiled.ch{n}.zip"
        assert f'<meta name="wb-grader-package" content="{name}">' in page.read_text(), page
        assert name not in manifest
        with zipfile.ZipFile(VENDOR / name) as z:
            own = {m: z.read(m) for m in z.namelist()}
        left_out = own.pop("package-rest.txt").decode().split()
        assert own.items() <= full.items(), name  # the same bytes, fewer files
        gone = {m[:-4].replace("/__init__", "").replace("/", ".") for m in set(full) - set(own)}
        assert gone == set(left_out) and gone, name
        assert all(m.startswith(("workbook.bank.", "workbook.figures.", "workbook.reference.")) for m in gone), name
        assert not any(m.startswith(f"workbook.bank.ch{n}_") for m in gone), name
        assert all(m.replace(".", "/") + ".py" in sources for m in gone), name
