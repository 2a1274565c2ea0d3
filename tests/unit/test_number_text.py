"""The page's thousands separators (docs/assets/js/number-text.js) against en-US's own, in Node:
``tests/js/number-text.test.mjs`` holds the cases."""

from __future__ import annotations

from node_tests import run_node_test


def test_group_digits_agrees_with_en_us():
    out = run_node_test("number-text.test.mjs", timeout=60)
    assert "# fail 0" in out and "# pass 1" in out, out[-3000:]
