"""Shared test set-up: make the grading package and the MkDocs hook importable."""

import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
for path in (ROOT / "pyodide_pkg", ROOT / "docs" / "hooks", ROOT / "scripts"):
    if str(path) not in sys.path:
        sys.path.insert(0, str(path))
