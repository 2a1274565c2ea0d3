"""SCORM suspend_data and the chapter's report (docs/assets/js/lms/), tested in Node.

``tests/js/suspend.test.mjs`` holds the cases: every exercise's essential state at
its widest within SCORM 1.2's 4,096 characters, what is dropped first past it, the
2004 form, merging with the local record, hostile text. This runs it with the
workbook's own exercise ids and fails with Node's report when a case fails.
"""

from __future__ import annotations

import json
import os
import shutil
import subprocess
from pathlib import Path

import pytest

from workbook import bank

ROOT = Path(__file__).resolve().parents[2]


def test_suspend_data_encoding_in_node():
    node = shutil.which("node")
    if node is None:
        pytest.fail("Node is needed for the page-side tests (README: Node 20+)")
    ids = [ex.id for ex in bank.all_exercises()]
    env = {**os.environ, "WORKBOOK_IDS": json.dumps(ids)}
    run = subprocess.run([node, "--experimental-default-type=module", "--no-warnings", "--test", "tests/js/suspend.test.mjs"],
                         cwd=ROOT, env=env, capture_output=True, text=True, timeout=120)
    assert run.returncode == 0, run.stdout[-6000:] + run.stderr[-2000:]
    assert "# fail 0" in run.stdout and "# pass 8" in run.stdout, run.stdout[-3000:]
