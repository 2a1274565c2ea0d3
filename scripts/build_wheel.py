#!/usr/bin/env python3
"""Build the grading package's wheel reproducibly and list it in the site's lock file.

1. ``python -m build --wheel`` on ``pyodide_pkg/`` with a fixed
   ``SOURCE_DATE_EPOCH`` (the same sources give the same bytes).
2. Copy it next to the vendored Pyodide files.
3. ``pyodide-lock`` (the library behind ``pyodide lockfile add-wheels``) adds it to
   ``build/pyodide-lock.base.json`` and writes the site's ``pyodide-lock.json``.
4. Precompile the vendored NumPy wheel to .pyc (first, so the lock lists the
   compiled wheel's sha256): Pyodide ships it as sources, so every first
   ``import numpy`` compiled ~80 modules; compiled once here, it gets faster
   (docs/performance.md). The published file is verified before (vendor.py). The standard
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
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
PKG = ROOT / "pyodide_pkg"
DIST = ROOT / "build" / "wheel"
VENDOR = ROOT / "docs" / "assets" / "vendor" / "pyodide"
BASE_LOCK = ROOT / "build" / "pyodide-lock.base.json"
PY312 = (3, 12)  # Pyodide 0.27 runs Python 3.12: its bytecode, its grammar (the Makefile's venv is 3.12)
EPOCH = "1700000000"  # fixed: wheel contents depend on the sources only


def build_wheel() -> Path:
    shutil.rmtree(DIST, ignore_errors=True)
    shutil.rmtree(PKG / "build", ignore_errors=True)  # stale setuptools output would leak removed modules
    # Without PYTHONDONTWRITEBYTECODE: set, setuptools warns twice that "byte-compiling is disabled"
    # (it compiles nothing for a wheel either way; the wheel's bytes are the same).
    env = {**{k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}, "SOURCE_DATE_EPOCH": EPOCH}
    subprocess.run(
        [sys.executable, "-m", "build", "--wheel", "--no-isolation", "--outdir", str(DIST), str(PKG)],
        check=True, env=env, stdout=subprocess.DEVNULL,
    )
    shutil.rmtree(PKG / "build", ignore_errors=True)
    (wheel,) = DIST.glob("*.whl")
    return wheel


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


def require_python312() -> None:
    if sys.version_info[:2] != PY312:
        sys.exit(f"{Path(sys.argv[0]).name}: needs Python 3.12 (what Pyodide 0.27 runs), not "
                 f"{sys.version.split()[0]}: run it with .venv/bin/python (make does)")


def precompile(archive: Path) -> str:
    """Compile a vendored archive once (a compiled one has no .py left; vendor.py
    puts the published file back whenever it re-vendors)."""
    with zipfile.ZipFile(archive) as z:
        if not any(name.endswith(".py") for name in z.namelist()):
            return "already compiled"
    compile_zip(archive)
    return "compiled to .pyc"


def add_to_lock(wheel: Path) -> dict:
    """The base lock with ``wheel`` added, as ``pyodide lockfile add-wheels`` writes it."""
    from pyodide_lock import PyodideLockSpec
    from pyodide_lock.utils import add_wheels_to_spec

    spec = add_wheels_to_spec(PyodideLockSpec.from_json(BASE_LOCK), [wheel], base_path=VENDOR)
    lock = json.loads(json.dumps(spec.model_dump()))  # what the CLI's to_json writes
    # pyodide-lock 0.1.x drops info.version, which Pyodide 0.27 checks at start-up: restore it.
    lock["info"] = json.loads(BASE_LOCK.read_text())["info"]
    return lock


def main() -> None:
    # Pyodide publishes NumPy as sources: every first `import numpy` compiled it again (docs/performance.md).
    compiled = {archive.name: precompile(archive) for archive in sorted(VENDOR.glob("numpy-*.whl"))}
    wheel = build_wheel()
    for old in VENDOR.glob("robotics_workbook-*.whl"):
        old.unlink()
    shipped = VENDOR / wheel.name
    shutil.copyfile(wheel, shipped)
    target = VENDOR / "pyodide-lock.json"
    lock = add_to_lock(shipped)
    # Pyodide checks each package against the lock's sha256: list the compiled wheels' own.
    for entry in lock["packages"].values():
        entry["sha256"] = hashlib.sha256((VENDOR / entry["file_name"]).read_bytes()).hexdigest()
    target.write_text(json.dumps(lock, indent=2, sort_keys=True) + "\n")
    digest = hashlib.sha256(shipped.read_bytes()).hexdigest()[:12]
    print(f"wheel: {wheel.name} (sha256 {digest}…) listed in {target.relative_to(ROOT)}")
    for name, how in compiled.items():
        print(f"precompile: {name} {how}")


if __name__ == "__main__":
    require_python312()
    main()
