#!/usr/bin/env python3
"""Build the grading package's wheel reproducibly and list it in the site's lock file.

1. ``python -m build --wheel`` on ``pyodide_pkg/`` with a fixed
   ``SOURCE_DATE_EPOCH`` (the same sources give the same bytes).
2. Copy it next to the vendored Pyodide files.
3. ``pyodide lockfile add-wheels`` (pyodide-build, in its own Python 3.12 venv
   ``.venv-pyodide``) adds it to ``build/pyodide-lock.base.json`` and writes the
   site's ``pyodide-lock.json``. Where no Python 3.12 is available the same entry
   is written here, from the wheel's metadata.
4. Precompile the vendored NumPy wheel to .pyc with Python 3.12 (first, so the
   lock lists the compiled wheel's sha256): Pyodide ships it as sources, so
   every first ``import numpy`` compiled ~80 modules; compiled once here, it
   gets faster (docs/performance.md). Skipped, with a note, where there is no
   Python 3.12. The published file is verified before (vendor.py). The standard
   library stays as sources: the page starts from a snapshot, or, on a slow
   first visit, from the small core (scripts/split_stdlib.py), where bytes cost
   more than compiling.
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
    """Replace every .py in the zip (the stdlib zip or a wheel) by its .pyc, in place.
    Run by Python 3.12 (Pyodide 0.27 runs 3.12 bytecode). Reproducible:
    unchecked-hash .pyc files (no source mtime) and fixed zip timestamps, so the
    same zip always gives the same bytes (``pyodide py-compile`` stamps the current
    time, which would change the service worker's version on every build). A
    wheel's RECORD is rewritten to list the new files."""
    import base64
    import py_compile
    import tempfile

    assert sys.version_info[:2] == (3, 12), "compile_zip needs Python 3.12"
    out = path.with_name(path.name + ".tmp")
    files: list[tuple[zipfile.ZipInfo, bytes]] = []
    record_name = None
    with zipfile.ZipFile(path) as zin, tempfile.TemporaryDirectory() as tmp:
        for info in zin.infolist():
            name, data = info.filename, zin.read(info)
            if name.endswith(".dist-info/RECORD"):
                record_name = name
                continue
            if name.endswith(".py"):
                src = Path(tmp) / "module.py"
                src.write_bytes(data)
                py_compile.compile(str(src), cfile=str(src) + "c", dfile=name, doraise=True,
                                   invalidation_mode=py_compile.PycInvalidationMode.UNCHECKED_HASH)
                name, data = name + "c", Path(str(src) + "c").read_bytes()
            entry = zipfile.ZipInfo(name, date_time=(1980, 1, 1, 0, 0, 0))
            entry.compress_type, entry.external_attr = zipfile.ZIP_DEFLATED, info.external_attr
            files.append((entry, data))
    if record_name:
        def line(entry: zipfile.ZipInfo, data: bytes) -> str:
            digest = base64.urlsafe_b64encode(hashlib.sha256(data).digest()).rstrip(b"=").decode()
            return f"{entry.filename},sha256={digest},{len(data)}"
        record = "\n".join([*(line(e, d) for e, d in files), f"{record_name},,"]) + "\n"
        entry = zipfile.ZipInfo(record_name, date_time=(1980, 1, 1, 0, 0, 0))
        entry.compress_type, entry.external_attr = zipfile.ZIP_DEFLATED, 0o644 << 16
        files.append((entry, record.encode()))
    with zipfile.ZipFile(out, "w", compression=zipfile.ZIP_DEFLATED, compresslevel=9) as zout:
        for entry, data in files:
            zout.writestr(entry, data)
    out.replace(path)


def precompile(archive: Path) -> str:
    """Compile a vendored archive once (a compiled one has no .py left; vendor.py
    puts the published file back whenever it re-vendors)."""
    with zipfile.ZipFile(archive) as z:
        if not any(name.endswith(".py") for name in z.namelist()):
            return "already compiled"
    probe = "import sys; sys.exit(sys.version_info[:2] != (3, 12))"
    for py in (sys.executable, str(PYODIDE_CLI.parent / "python"), shutil.which("python3.12")):
        if py and Path(py).exists() and subprocess.run([py, "-c", probe]).returncode == 0:
            subprocess.run([py, __file__, "--compile-zip", str(archive)], check=True)
            return "compiled to .pyc"
    return "left as sources (no Python 3.12 found)"


def main() -> None:
    # Pyodide publishes NumPy as sources: every first `import numpy` compiled it again (docs/performance.md).
    compiled = {archive.name: precompile(archive) for archive in sorted(VENDOR.glob("numpy-*.whl"))}
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
        how = "pyodide lockfile add-wheels"
    else:
        lock = json.loads(BASE_LOCK.read_text())
        entry = lock_entry(shipped)
        lock["packages"][entry["name"]] = entry
        how = "the built-in writer (no Python 3.12 for pyodide-build)"
    # Pyodide checks each package against the lock's sha256: list the compiled wheels' own.
    for entry in lock["packages"].values():
        entry["sha256"] = hashlib.sha256((VENDOR / entry["file_name"]).read_bytes()).hexdigest()
    target.write_text(json.dumps(lock, indent=2, sort_keys=True) + "\n")
    digest = hashlib.sha256(shipped.read_bytes()).hexdigest()[:12]
    print(f"wheel: {wheel.name} (sha256 {digest}…) listed in {target.relative_to(ROOT)} by {how}")
    for name, how in compiled.items():
        print(f"precompile: {name} {how}")


if __name__ == "__main__":
    if sys.argv[1:2] == ["--compile-zip"]:
        compile_zip(Path(sys.argv[2]))
    else:
        main()
