#!/usr/bin/env python3
"""Build the grading package's wheel reproducibly and list it in the site's lock file.

1. ``python -m build --wheel`` on ``pyodide_pkg/`` with a fixed
   ``SOURCE_DATE_EPOCH`` (the same sources give the same bytes).
2. Copy it next to the vendored Pyodide files.
3. ``pyodide lockfile add-wheels`` (pyodide-build, in its own Python 3.12 venv
   ``.venv-pyodide``) adds it to ``build/pyodide-lock.base.json`` and writes the
   site's ``pyodide-lock.json``. Where no Python 3.12 is available the same entry
   is written here, from the wheel's metadata.
4. Precompile the vendored ``python_stdlib.zip`` to .pyc with Python 3.12: Pyodide
   ships it as sources, so every start compiled the ~150 modules it imports;
   compiled once here, the runtime starts about 40 % sooner for ~1.5 MB more
   (docs/performance.md). Skipped, with a note, where there is no Python 3.12.
"""

from __future__ import annotations

import hashlib
import json
import os
import shutil
import subprocess
import sys
import zipfile
from email.parser import Parser
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
PKG = ROOT / "pyodide_pkg"
DIST = ROOT / "build" / "wheel"
VENDOR = ROOT / "docs" / "assets" / "vendor" / "pyodide"
BASE_LOCK = ROOT / "build" / "pyodide-lock.base.json"
PYODIDE_CLI = ROOT / ".venv-pyodide" / "bin" / "pyodide"
EPOCH = "1700000000"  # fixed: wheel contents depend on the sources only


def build_wheel() -> Path:
    shutil.rmtree(DIST, ignore_errors=True)
    shutil.rmtree(PKG / "build", ignore_errors=True)  # stale setuptools output would leak removed modules
    env = {**os.environ, "SOURCE_DATE_EPOCH": EPOCH}
    subprocess.run(
        [sys.executable, "-m", "build", "--wheel", "--no-isolation", "--outdir", str(DIST), str(PKG)],
        check=True, env=env, stdout=subprocess.DEVNULL,
    )
    shutil.rmtree(PKG / "build", ignore_errors=True)
    (wheel,) = DIST.glob("*.whl")
    return wheel


def lock_entry(wheel: Path) -> dict:
    """The entry ``pyodide lockfile add-wheels`` writes for a pure-Python wheel."""
    with zipfile.ZipFile(wheel) as z:
        meta_name = next(n for n in z.namelist() if n.endswith(".dist-info/METADATA"))
        meta = Parser().parsestr(z.read(meta_name).decode())
        tops = [n.split("/")[0] for n in z.namelist() if not n.split("/")[0].endswith(".dist-info")]
    name = meta["Name"].lower().replace("_", "-")
    return {
        "depends": [], "file_name": wheel.name, "imports": sorted(set(tops)), "install_dir": "site",
        "name": name, "package_type": "package",
        "sha256": hashlib.sha256(wheel.read_bytes()).hexdigest(), "unvendored_tests": False,
        "version": meta["Version"],
    }


def compile_zip(path: Path) -> None:
    """Replace every .py in the zip by its .pyc, in place. Run by Python 3.12 (Pyodide
    0.27 runs 3.12 bytecode). Reproducible: unchecked-hash .pyc files (no source
    mtime) and fixed zip timestamps, so the same zip always gives the same bytes
    (``pyodide py-compile`` stamps the current time, which would change the
    service worker's version on every build)."""
    import py_compile
    import tempfile

    assert sys.version_info[:2] == (3, 12), "compile_zip needs Python 3.12"
    out = path.with_name(path.name + ".tmp")
    with zipfile.ZipFile(path) as zin, tempfile.TemporaryDirectory() as tmp, \
            zipfile.ZipFile(out, "w", compression=zipfile.ZIP_DEFLATED, compresslevel=9) as zout:
        for info in zin.infolist():
            name, data = info.filename, zin.read(info)
            if name.endswith(".py"):
                src = Path(tmp) / "module.py"
                src.write_bytes(data)
                py_compile.compile(str(src), cfile=str(src) + "c", dfile=name, doraise=True,
                                   invalidation_mode=py_compile.PycInvalidationMode.UNCHECKED_HASH)
                name, data = name + "c", Path(str(src) + "c").read_bytes()
            entry = zipfile.ZipInfo(name, date_time=(1980, 1, 1, 0, 0, 0))
            entry.compress_type, entry.external_attr = zipfile.ZIP_DEFLATED, info.external_attr
            zout.writestr(entry, data)
    out.replace(path)


def precompile_stdlib() -> str:
    """Compile the vendored python_stdlib.zip once (a compiled zip has no .py left;
    vendor.py puts the published zip back whenever it re-vendors)."""
    stdlib = VENDOR / "python_stdlib.zip"
    with zipfile.ZipFile(stdlib) as z:
        if not any(name.endswith(".py") for name in z.namelist()):
            return "already compiled"
    probe = "import sys; sys.exit(sys.version_info[:2] != (3, 12))"
    for py in (sys.executable, str(PYODIDE_CLI.parent / "python"), shutil.which("python3.12")):
        if py and Path(py).exists() and subprocess.run([py, "-c", probe]).returncode == 0:
            subprocess.run([py, __file__, "--compile-zip", str(stdlib)], check=True)
            return "compiled to .pyc"
    return "left as sources (no Python 3.12 found)"


def main() -> None:
    wheel = build_wheel()
    for old in VENDOR.glob("robotics_workbook-*.whl"):
        old.unlink()
    shipped = VENDOR / wheel.name
    shutil.copyfile(wheel, shipped)
    target = VENDOR / "pyodide-lock.json"
    if PYODIDE_CLI.exists():
        subprocess.run(
            [str(PYODIDE_CLI), "lockfile", "add-wheels", "--input", str(BASE_LOCK), "--output", str(target),
             "--base-path", str(VENDOR), str(shipped)],
            check=True, stdout=subprocess.DEVNULL,
        )
        # pyodide-lock 0.1.x drops info.version, which Pyodide 0.27 checks at start-up: restore it.
        lock = json.loads(target.read_text())
        lock["info"] = json.loads(BASE_LOCK.read_text())["info"]
        target.write_text(json.dumps(lock, indent=2, sort_keys=True) + "\n")
        how = "pyodide lockfile add-wheels"
    else:
        lock = json.loads(BASE_LOCK.read_text())
        entry = lock_entry(shipped)
        lock["packages"][entry["name"]] = entry
        target.write_text(json.dumps(lock, indent=2, sort_keys=True) + "\n")
        how = "the built-in writer (no Python 3.12 for pyodide-build)"
    digest = hashlib.sha256(shipped.read_bytes()).hexdigest()[:12]
    print(f"wheel: {wheel.name} (sha256 {digest}…) listed in {target.relative_to(ROOT)} by {how}")
    print(f"stdlib: python_stdlib.zip {precompile_stdlib()}")


if __name__ == "__main__":
    if sys.argv[1:2] == ["--compile-zip"]:
        compile_zip(Path(sys.argv[2]))
    else:
        main()
