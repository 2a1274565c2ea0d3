"""The Pyodide internals the boot relies on are still there in the vendored Pyodide.

``docs/assets/js/pyodide-internals.json`` lists each internal that
``docs/assets/js/boot.js`` and the build scripts use beyond Pyodide's public API,
with a pattern to find it in the file of the npm package it lives in. When a new
Pyodide drops or changes one, this test names it and what depends on it
(DEVELOPING.md: "Upgrading Pyodide").
"""

from __future__ import annotations

import json
import re
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
LIST = ROOT / "docs" / "assets" / "js" / "pyodide-internals.json"
PYODIDE = ROOT / "node_modules" / "pyodide"


def internals() -> dict:
    return json.loads(LIST.read_text())


def missing(entries: list[dict], read) -> list[str]:
    """One clear line per internal whose pattern is not found in its file."""
    out = []
    for entry in entries:
        if not re.search(entry["pattern"], read(entry["file"])):
            out.append(f"{entry['name']} (looked for in {entry['file']}): {entry['used_by']}")
    return out


@pytest.fixture(scope="module")
def vendored():
    if not (PYODIDE / "package.json").exists():
        pytest.fail("node_modules/pyodide is missing: run `npm ci` (make does)")
    cache: dict[str, str] = {}

    def read(name: str) -> str:
        if name not in cache:
            cache[name] = (PYODIDE / name).read_text(encoding="utf-8", errors="replace")
        return cache[name]

    return read


def test_the_list_is_for_the_vendored_version():
    version = json.loads((PYODIDE / "package.json").read_text())["version"]
    assert internals()["pyodide"] == version, (
        f"node_modules has Pyodide {version}, the internals were checked for {internals()['pyodide']}: "
        "follow DEVELOPING.md's 'Upgrading Pyodide', then set 'pyodide' in docs/assets/js/pyodide-internals.json")


def test_every_internal_the_boot_relies_on_is_still_there(vendored):
    gone = missing(internals()["internals"], vendored)
    assert not gone, ("the vendored Pyodide changed internals the boot relies on (DEVELOPING.md: 'Upgrading Pyodide'):\n  - "
                      + "\n  - ".join(gone))


def test_a_changed_internal_is_named(vendored):
    """The check itself: a Pyodide whose loadPyodide no longer reads _loadSnapshot is caught, by name."""
    doctored = {name: vendored(name) for name in ("pyodide.js", "pyodide.asm.js", "pyodide-lock.json")}
    doctored["pyodide.js"] = doctored["pyodide.js"].replace("_loadSnapshot", "_loadMemorySnapshot")
    gone = missing(internals()["internals"], doctored.__getitem__)
    assert len(gone) == 1 and gone[0].startswith("_loadSnapshot (looked for in pyodide.js): boot.js")


def test_boot_js_names_the_list():
    """boot.js is the one module that starts Pyodide, and it carries the list."""
    boot = (ROOT / "docs" / "assets" / "js" / "boot.js").read_text()
    assert 'from "./pyodide-internals.json"' in boot
    others = [p.name for p in (ROOT / "docs" / "assets" / "js").rglob("*.js")
              if p.name != "boot.js" and re.search(r"\bloadPyodide\(|_loadSnapshot|instantiateStreaming", p.read_text())]
    assert others == [], f"Pyodide is started outside boot.js: {others}"
