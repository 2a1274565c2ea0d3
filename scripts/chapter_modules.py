#!/usr/bin/env python3
"""Which modules of the grading package a chapter's page uses: the part of the package its
compiled core carries (``scripts/split_stdlib.py``).

A chapter's page asks the grader for its own exercises only: grades, draws, reads and splits of
them, its figure (the chapter's ``::: figure`` blocks) and its Build exercises' run figures. The
bank, the figures and the reference implementations are one module per topic, and a page needs
those of its own chapter. So the compiled core of chapter N holds every module of the package but
the bank's, the figures' and the references' that chapter N's requests do not import, found by
making those requests here, in a fresh interpreter per chapter (natively: the package is the same
pure Python). A module left out is still there on the page, from the sources' core, fetched the
first time it is imported (``workbook_sandbox/lazy_stdlib.py``).

``python scripts/chapter_modules.py N`` prints chapter N's modules as JSON.
"""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parent.parent
PACKAGE = ROOT / "pyodide_pkg"
BY_TOPIC = ("workbook.bank.", "workbook.figures.", "workbook.reference.")  # one module per topic: only the page's


def _requests(n: int) -> None:
    """Make chapter N's page's requests, so that what they import is imported."""
    from workbook import api, bank, figures
    from workbook.figures import runs

    exercises = bank.chapter(n)
    ids = [ex.id for ex in exercises]
    for request in json.loads(api.warm_up(ids)):
        api.handle(json.dumps(request))
    for ex in exercises:
        asks: list[dict[str, Any]] = [{"op": "grade", "exercise": ex.id, "answer": "1"}] if ex.op == "grade" else []
        if ex.kind == "derive":
            asks += [{"op": "draw", "exercise": ex.id, "variant": 1, "texts": {}},
                     {"op": "read", "exercise": ex.id, "answer": "1"},
                     {"op": "split", "exercise": ex.id, "text": "1 2"}]
        if ex.kind == "build":
            asks.append({"op": "cases", "exercise": ex.id, "code": "def f():\n    pass\n"})
            run_figure = getattr(ex, "run_figure", "")
            if run_figure:
                runs.get(run_figure)
        for request in asks:
            api.handle(json.dumps(request))
    for name in figures.names():  # every figure (see above)
        figures.render(name, None)


def used(n: int) -> set[str]:
    """The package's modules that chapter N's requests import (in this interpreter)."""
    import workbook.api  # noqa: F401  (what every start imports)
    import workbook_sandbox.lazy_stdlib  # noqa: F401

    _requests(n)
    return {name for name in sys.modules if name.split(".")[0] in ("workbook", "workbook_sandbox")}


def chapter_modules(n: int, everything: set[str]) -> set[str]:
    """Chapter N's part of ``everything`` (module names of the package): what a fresh interpreter's
    requests for chapter N import, and every module outside the bank, the figures and the references."""
    child = subprocess.run([sys.executable, __file__, str(n)], capture_output=True, text=True, check=True,
                           env={"PYTHONPATH": str(PACKAGE), "PATH": ""})
    imported = set(json.loads(child.stdout))
    return {m for m in everything if m in imported or not m.startswith(BY_TOPIC)}


def main() -> None:
    sys.path.insert(0, str(PACKAGE))
    print(json.dumps(sorted(used(int(sys.argv[1])))))


if __name__ == "__main__":
    main()
