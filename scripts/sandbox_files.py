#!/usr/bin/env python3
"""The files the sandbox worker starts from: Python without the grading package.

The sandbox (``docs/assets/js/sandbox.js``) runs learner code, so it must not
hold ``workbook`` (its keys, its reference implementations). From the vendored
files this writes, next to them:

* ``python_stdlib.sandbox.zip``: the core the grader starts with
  (``scripts/split_stdlib.py``) minus ``workbook/``: the standard library's
  core, ``workbook_sandbox`` and the index of the rest. The rest of the standard
  library is the grader's own ``python_stdlib.rest.zip``, which the sandbox
  mounts on first use with the same finder (``workbook_sandbox/lazy_stdlib.py``):
  ahead of a run whose imports need it, or when an import no one saw asks. So a
  first Build run on a first visit waits for 0.4 MB, not for the whole 2 MB
  standard library (issue 48).
* nothing compiled: on a plain start over a link fast enough (the grader's rule,
  boot.js) the sandbox takes the grader's own ``python_stdlib.core.compiled.zip``,
  which holds no grading package (``scripts/split_stdlib.py`` writes the package
  beside it), and which the grader fetched already: in Node the sandbox's Python
  then starts in 0.6 s instead of 1.5 s, and on a first visit it finds the file in
  the HTTP cache.
* ``pyodide-lock.sandbox.json``: the lock file without the package that provides
  ``workbook``; it is the sandbox's manifest too: the only files its guarded
  fetch will get are the ones this lock names (and its finder fetches only the
  rest).

Entries keep the core's order and dates, so the same core gives the same bytes.
"""

from __future__ import annotations

import json
import sys
import zipfile
from pathlib import Path

from split_stdlib import GRADER, grader_entry  # scripts/, beside this file: the package the sandbox must not hold

ROOT = Path(__file__).resolve().parent.parent
VENDOR = ROOT / "docs" / "assets" / "vendor" / "pyodide"
CORE, SANDBOX = "python_stdlib.core.zip", "python_stdlib.sandbox.zip"
LOCK, SANDBOX_LOCK = "pyodide-lock.json", "pyodide-lock.sandbox.json"


def sandbox_zip(core: Path, out: Path) -> int:
    """``core`` without the grading package; the number of entries written."""
    written = 0
    with zipfile.ZipFile(out, "w", compression=zipfile.ZIP_DEFLATED, compresslevel=9) as zout, \
            zipfile.ZipFile(core) as zin:
        for info in zin.infolist():
            if not grader_entry(info.filename):
                zout.writestr(info, zin.read(info))
                written += 1
    return written


def sandbox_lock(lock: dict) -> dict:
    """The lock without any package that provides the grading package."""
    packages = {name: entry for name, entry in lock["packages"].items() if GRADER not in entry.get("imports", ())}
    return {**lock, "packages": packages}


def main(vendor: Path = VENDOR) -> None:
    if not (vendor / CORE).exists():
        sys.exit("sandbox_files: run scripts/split_stdlib.py first (make does)")
    count = sandbox_zip(vendor / CORE, vendor / SANDBOX)
    lock = sandbox_lock(json.loads((vendor / LOCK).read_text()))
    (vendor / SANDBOX_LOCK).write_text(json.dumps(lock, indent=2, sort_keys=True) + "\n")
    print(f"sandbox: {SANDBOX} {count} files, {(vendor / SANDBOX).stat().st_size / 1e6:.2f} MB; "
          f"{SANDBOX_LOCK} lists {', '.join(sorted(lock['packages'])) or 'no packages'}")


if __name__ == "__main__":
    main()
