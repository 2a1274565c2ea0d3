"""The baseline: a bare page that calls ``loadPyodide()`` on the main thread.

Stock Pyodide 0.27.7 core files, the site's lock file and wheels, then the
workbook's package and ``import workbook.api``: the way many Pyodide exercise
sites start. ``baseline.html`` (beside this file) is the page.
"""

from __future__ import annotations

import hashlib
import shutil
from pathlib import Path

from . import ROOT

PYODIDE_CORE = ("pyodide.js", "pyodide.asm.js", "pyodide.asm.wasm", "python_stdlib.zip")
PAGE = Path(__file__).with_name("baseline.html")


def stage_baseline(site: Path, target: Path) -> dict:
    """The baseline's Pyodide folder: the site's lock file and wheels, with the core
    files as published (node_modules/pyodide, checked against the pinned hashes),
    so that a change to the site's own copies (e.g. a precompiled stdlib) shows
    up against stock Pyodide. Falls back to the site's copies."""
    shutil.copytree(site / "assets" / "vendor" / "pyodide", target)
    pins = {}
    pin_file = ROOT / "scripts" / "pyodide-0.27.7.sha256"
    if pin_file.exists():
        for line in pin_file.read_text().splitlines():
            if line.strip() and not line.startswith("#"):
                digest, name = line.split()
                pins[name] = digest
    stock = ROOT / "node_modules" / "pyodide"
    source = {}
    for name in PYODIDE_CORE:
        src = stock / name
        if src.exists() and pins.get(name) == hashlib.sha256(src.read_bytes()).hexdigest():
            shutil.copyfile(src, target / name)
            source[name] = "stock pyodide@0.27.7 (npm, hash-checked)"
        else:
            source[name] = "the site's copy"
    return source


def write_baseline(site: Path, folder: Path, url_path: str) -> dict:
    """Stage the baseline under `folder` (served at `url_path`); return where its core files came from."""
    folder.mkdir(parents=True, exist_ok=True)
    files = stage_baseline(site, folder / "pyodide")
    (folder / "index.html").write_text(PAGE.read_text().format(base=url_path + "pyodide/"))
    return files
