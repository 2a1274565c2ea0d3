"""What a new worker is told, in Node: a replaced grader what the page's head told the first
(docs/assets/js/runtime.js, ``tests/js/restart.test.mjs``), and a sandbox started for a run that a run
is waiting (docs/assets/js/sandbox-client.js, ``tests/js/sandbox-start.test.mjs``); and when a runtime
counts as quiet, which the sandbox's start waits for (``tests/js/quiet.test.mjs``)."""

from __future__ import annotations

from node_tests import run_node_test


def test_a_replaced_worker_gets_the_first_one_s_name_and_is_told_the_page_has_started():
    out = run_node_test("restart.test.mjs", timeout=60)
    assert "# fail 0" in out and "# pass 3" in out, out[-3000:]


def test_a_sandbox_started_for_a_run_is_told_so_and_its_replacement_is_not():
    out = run_node_test("sandbox-start.test.mjs", timeout=60)
    assert "# fail 0" in out and "# pass 2" in out, out[-3000:]


def test_a_runtime_is_quiet_only_after_nothing_was_sent_or_answered_for_the_time_asked():
    out = run_node_test("quiet.test.mjs", timeout=60)
    assert "# fail 0" in out and "# pass 3" in out, out[-3000:]
