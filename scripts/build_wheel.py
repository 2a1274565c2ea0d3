#!/usr/bin/env python3
"""Build the grading package's wheel reproducibly and list it in the site's lock file.

1. ``python -m build --wheel`` on ``pyodide_pkg/`` with a fixed
   ``SOURCE_DATE_EPOCH`` (the same sources give the same bytes).
2. Copy it next to the vendored Pyodide files.
3. ``pyodide lockfile add-wheels`` (pyodide-build, in its own Python 3.12 venv
   ``.venv-pyodide``) adds it to ``build/pyodide-lock.base.json`` and writes the
   site's ``pyodide-lock.json``. Where no Python 3.12 is available the same entry
   is written here, from the wheel's metadata.
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


if __name__ == "__main__":
    main()
