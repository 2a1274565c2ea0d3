"""The page's thousands separators (docs/assets/js/number-text.js) against en-US's own, in Node:
``tests/js/number-text.test.mjs`` holds the cases."""

from __future__ import annotations

import shutil
import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]


def test_group_digits_agrees_with_en_us():
    node = shutil.which("node")
    if node is None:
        pytest.fail("Node is needed for the page-side tests (README: Node 20+)")
    run = subprocess.run([node, "--experimental-default-type=module", "--no-warnings", "--test", "tests/js/number-text.test.mjs"],
                         cwd=ROOT, capture_output=True, text=True, timeout=60)
    assert run.returncode == 0, run.stdout[-4000:] + run.stderr[-2000:]
    assert "# fail 0" in run.stdout and "# pass 1" in run.stdout, run.stdout[-3000:]
