"""A replaced grader is told what the page's head told the first (docs/assets/js/runtime.js), in Node:
``tests/js/restart.test.mjs`` holds the cases."""

from __future__ import annotations

from node_tests import run_node_test


def test_a_replaced_worker_gets_the_first_one_s_name():
    out = run_node_test("restart.test.mjs", timeout=60)
    assert "# fail 0" in out and "# pass 2" in out, out[-3000:]
