"""Shared test set-up: make the grading package and the MkDocs hook importable."""

import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
for path in (ROOT / "pyodide_pkg", ROOT / "docs" / "hooks", ROOT / "scripts"):
    if str(path) not in sys.path:
        sys.path.insert(0, str(path))

# Hypothesis: the same examples on every run (a test either fails or passes, on any machine,
# at any load), no deadline (speed is `make bench`'s business), no example database left
# behind. `HYPOTHESIS_PROFILE=explore` searches afresh and ten times longer, to look for bugs.
try:
    from hypothesis import settings
except ImportError:  # the serve-only tools: no property tests to run
    pass
else:
    settings.register_profile("repeatable", derandomize=True, deadline=None, database=None)
    settings.register_profile("explore", max_examples=1000, deadline=None, database=None)
    import os

    settings.load_profile(os.environ.get("HYPOTHESIS_PROFILE", "repeatable"))
