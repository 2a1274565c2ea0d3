"""SCORM suspend_data and the chapter's report (docs/assets/js/lms/), tested in Node.

``tests/js/suspend.test.mjs`` holds the cases: every exercise's essential state at
its widest within SCORM 1.2's 4,096 characters, what is dropped first past it, the
2004 form, merging with the local record, hostile text. This runs it with the
workbook's own exercise ids and fails with Node's report when a case fails.
"""

from __future__ import annotations

import json

from node_tests import run_node_test
from workbook import bank


def test_suspend_data_encoding_in_node():
    ids = [ex.id for ex in bank.all_exercises()]
    out = run_node_test("suspend.test.mjs", env={"WORKBOOK_IDS": json.dumps(ids)})
    assert "# fail 0" in out and "# pass 10" in out, out[-3000:]
