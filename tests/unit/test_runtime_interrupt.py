"""A run's time limit on an isolated page (docs/assets/js/runtime.js), in Node on a mocked clock:
the worker is terminated only while the run is still going after Python saw the signal.
``tests/js/interrupt.test.mjs`` holds the cases."""

from __future__ import annotations

from node_tests import run_node_test


def test_an_interrupted_run_is_terminated_only_when_it_goes_on():
    out = run_node_test("interrupt.test.mjs", timeout=60)
    assert "# fail 0" in out and "# pass 5" in out, out[-3000:]
