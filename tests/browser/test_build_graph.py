"""The Makefile's build graph: every output is rebuilt when any of its inputs changes,
and nothing else is.

For one file of each kind of source, ``make -n -W FILE`` (what would run if FILE
were new; nothing is touched or built) must remake exactly the expected targets.
Needs an up-to-date build (``make test`` builds the site first), so it lives with
the browser tests.
"""

from __future__ import annotations

import re
import subprocess
from pathlib import Path

import pytest

from tracked import tracked

ROOT = Path(__file__).resolve().parents[2]
VENV_TEST = ".venv/bin/.test"
GOALS = ("site/.stamp", VENV_TEST)

RUNTIME = ["build/vendor.stamp", "build/wheel.stamp", "build/stdlib.stamp", "build/snapshot.stamp",
           "build/bundle.stamp", "site/.stamp"]
PACKAGE = ["build/wheel.stamp", "build/stdlib.stamp", "build/snapshot.stamp", "build/bundle.stamp", "site/.stamp"]
BUNDLE = ["build/bundle.stamp", "site/.stamp"]
SITE = ["site/.stamp"]

# source (one of each kind) -> the targets a change to it must remake, and no others
CASES = {
    "pyodide_pkg/workbook/api.py": PACKAGE,
    "pyodide_pkg/workbook/bank/ch0_rotations_2d.py": PACKAGE,
    "pyodide_pkg/workbook/contract.json": PACKAGE,
    "pyodide_pkg/workbook_sandbox/restore.py": PACKAGE,  # the sandbox's own package, in its files and snapshot
    "pyodide_pkg/pyproject.toml": [".venv/bin/.serve", VENV_TEST, "build/casefold.json", *RUNTIME],
    "docs/assets/js/main.js": BUNDLE,
    "docs/assets/js/kinds/derive.js": BUNDLE,
    "docs/assets/js/answer-kinds/matrix.js": BUNDLE,
    "docs/assets/js/sw.js": SITE,  # the service worker's template, filled in by the offline hook
    "docs/assets/workbook.css": SITE,
    "docs/chapters/00-rotations-2d.md": SITE,
    "docs/index.md": SITE,
    "docs/teaching/index.md": SITE,  # the teacher's guide
    "docs/decisions/index.md": SITE,  # the decision records
    "docs/images/workbook.png": SITE,  # the README's picture (left out of the site, but one of its sources)
    "docs/hooks/exercises.py": SITE,
    "docs/hooks/offline.py": SITE,
    "docs/overrides/main.html": SITE,
    "docs/overrides/partials/copyright.html": SITE,
    "scripts/notices.py": SITE,  # the licences and third-party notices page
    "LICENSE-text.md": SITE,
    "mkdocs.yml": SITE,
    "scripts/bundle.mjs": BUNDLE,
    "scripts/casefold_table.py": ["build/casefold.json", *BUNDLE],  # a student id's folding, from the grader's Python
    "scripts/build_snapshot.mjs": ["build/snapshot.stamp", *BUNDLE],
    "scripts/split_stdlib.py": ["build/stdlib.stamp", "build/snapshot.stamp", *BUNDLE],
    "scripts/stdlib_probe.mjs": ["build/stdlib.stamp", "build/snapshot.stamp", *BUNDLE],
    # the wheel writes the lock file that sandbox_files.py (in the stdlib step) reads
    "scripts/build_wheel.py": PACKAGE,
    "scripts/vendor.py": RUNTIME,
    "scripts/pyodide-0.27.7.sha256": RUNTIME,
    "package-lock.json": ["node_modules/.installed", *RUNTIME],
    "requirements/serve.lock": [".venv/bin/.serve", VENV_TEST, "build/casefold.json", *RUNTIME],
    "requirements/test.lock": [VENV_TEST],
    "requirements/tools.lock": [".venv/bin/.serve", VENV_TEST, "build/casefold.json", *RUNTIME],  # uv, which installs the other two
}


def remade(*args: str) -> set[str]:
    out = subprocess.run(["make", "-n", "--debug=b", *args, *GOALS], cwd=ROOT, capture_output=True, text=True)
    assert out.returncode == 0, out.stderr
    return set(re.findall(r"Must remake target '([^']+)'", out.stdout))


@pytest.fixture(scope="module")
def up_to_date():
    stale = remade()
    if stale:
        pytest.fail(f"the build is not up to date ({sorted(stale)}): run `make test`, which builds it first")


@pytest.mark.parametrize("source", sorted(CASES))
def test_a_change_remakes_exactly_what_depends_on_it(up_to_date, source):
    assert (ROOT / source).is_file(), f"{source} is gone: update this test's list of sources"
    assert remade("-W", source) == set(CASES[source])


def test_every_kind_of_source_is_covered():
    """Each folder of sources has a case above, so a new kind of source gets one."""
    files = tracked("docs", "pyodide_pkg", "scripts")
    # scripts/scorm: the templates of `make scorm`, whose zips (dist/) are not among the goals built here;
    # scripts/typecheck: the settings of `make typecheck` (part of `make lint`), which builds nothing
    skipped = ("scripts/bench", "scripts/scorm", "scripts/typecheck", "docs/assets/vendor")
    folders = {str(Path(p).parent) for p in files if not p.startswith(skipped)}
    covered = {str(Path(p).parent) for p in CASES}
    # Folders of the same kind as a covered one: the recursive source lists take them all.
    same_kind = re.compile(r"^(pyodide_pkg/workbook/.+|pyodide_pkg/workbook_sandbox/.+|docs/assets/js/.+|docs/chapters|docs/assets)$")
    missing = sorted(f for f in folders - covered if not same_kind.match(f))
    assert missing == []
