"""Feedback a learner sees in the page: each message of the grading policy.

The tests share the module's one tab (``tour``: one grader, one sandbox): each grades its own
exercises from the answer or code it sets, and reads no record another test wrote."""

from __future__ import annotations

import re

from helpers import answer_derive, editor_code, exercise, feedback, role, run_build, set_editor
from workbook import bank


def test_derive_messages(tour):
    page = tour(4)
    bearing = exercise(page, "4.2")
    assert answer_derive(bearing, "0.9273") == "incorrect"
    assert bearing.get_attribute("data-feedback") == "radians"
    assert "radians" in feedback(bearing)
    assert answer_derive(bearing, "0.9273 rad") == "correct"
    assert answer_derive(bearing, "54") == "incorrect"
    assert bearing.get_attribute("data-feedback") == "close"
    assert "close" in feedback(bearing).lower()
    h11 = exercise(page, "4.3")
    assert answer_derive(h11, "0.6") == "incorrect"
    assert h11.get_attribute("data-feedback") == "slip"  # 4.3 names where its sign comes from: the chain rule
    assert "sign" in feedback(h11).lower() and "∂dx/∂x = −1" in feedback(h11)
    innovation = exercise(page, "4.4")
    assert answer_derive(innovation, "0.2") == "incorrect"
    assert innovation.get_attribute("data-feedback") == "slip"
    for bad in ("", "2,5", "3 4", "banana", "[1, 2]"):
        assert answer_derive(innovation, bad) == "invalid", bad
        assert feedback(innovation).strip()


def test_known_slip_in_chapter_3(tour):
    page = tour(3)
    ex = exercise(page, "3.4")
    assert answer_derive(ex, "1.11") == "incorrect"
    assert ex.get_attribute("data-feedback") == "slip"


def test_build_traceback_points_at_the_learners_line(tour):
    page = tour(0)
    ex = exercise(page, "0.5")
    set_editor(page, ex, "import math\n\ndef rotate_2d(x, y, theta):\n    c = math.cos(theta)\n    return (c * x - s * y, 0)\n")
    assert run_build(ex) == "incorrect"
    text = ex.locator(role("tests")).inner_text()
    assert "line 5, in rotate_2d" in text and "NameError" in text
    assert "runner.py" not in text
    marked = ex.locator(".cm-line.wb-error-line")
    assert marked.count() == 1 and "return (c * x - s * y, 0)" in marked.inner_text()


def test_build_syntax_error_and_print_output(tour):
    page = tour(0)
    ex = exercise(page, "0.5")
    set_editor(page, ex, "def rotate_2d(x, y, theta)\n    return x, y\n")
    assert run_build(ex) == "incorrect"
    assert re.search(r"syntax error on line 1", feedback(ex), re.I)
    set_editor(page, ex, "def rotate_2d(x, y, theta):\n    print('debug', x)\n    return x, y\n")
    run_build(ex)
    assert "debug 3" in ex.locator(role("stdout")).inner_text()


def test_build_with_numpy_loads_it_on_demand(tour):
    page = tour(6)
    ex = exercise(page, "6.5")
    code = (
        "import numpy as np\n\n"
        "def forward_kinematics_2link(L1, L2, theta1, theta2):\n"
        "    a = np.array([theta1, theta1 + theta2])\n"
        "    return np.array([L1 * np.cos(a[0]) + L2 * np.cos(a[1]), L1 * np.sin(a[0]) + L2 * np.sin(a[1])])\n"
    )
    set_editor(page, ex, code)
    assert run_build(ex, timeout=120_000) == "correct"


def test_build_time_limit_message(tour):
    page = tour(8)
    ex = exercise(page, "8.4")
    set_editor(page, ex, "def pid_step(e, e_prev, integral, Kp, Ki, Kd, dt):\n    while True:\n        integral += 1\n")
    assert run_build(ex, timeout=60_000) == "error"
    assert ex.get_attribute("data-feedback") == "timeout"
    assert "stopped after 5 s" in feedback(ex).lower()


def test_memory_error_is_a_verdict_and_the_sandbox_replaced(tour):
    page = tour(0)
    ex = exercise(page, "0.5")
    set_editor(page, ex, "def rotate_2d(x, y, theta):\n    hoard = [0] * (2 ** 30)\n    return x, y\n")
    recycled = page.evaluate("workbook.sandbox?.recycles || 0")  # the tab's earlier tests may have replaced it
    assert run_build(ex, timeout=60_000) == "incorrect"
    assert ex.get_attribute("data-feedback") == "exception"
    assert "ran out of memory" in feedback(ex)
    assert page.evaluate("workbook.sandbox.recycles") == recycled + 1
    # The grader never saw the code: it answers at once; a fresh sandbox runs the next code.
    assert answer_derive(exercise(page, "0.1"), "3") == "correct"
    assert "2 ** 30" in editor_code(ex)
    set_editor(page, ex, bank.get("0.5").solution)
    assert run_build(ex, timeout=60_000) == "correct"


# The exercise's height in each state its Check takes it through, with the last result's feedback in place.
HEIGHTS = """(el) => {
  const kept = el.getAttribute('data-state');
  const out = {};
  for (const state of ['pending', 'incorrect', 'correct', 'invalid']) {
    el.setAttribute('data-state', state);
    out[state] = el.getBoundingClientRect().height;
  }
  el.setAttribute('data-state', kept);
  return out;
}"""


def test_checking_again_does_not_move_the_page(tour):
    """While a Check waits ("checking…") the exercise keeps its height: nothing below it moves, and the
    theme does not measure the whole page again (its table of contents follows the page's size). The
    label of the pending state made the card 1.8 px taller and shorter again on every Check."""
    page = tour(3)
    ex = exercise(page, "3.4")
    assert answer_derive(ex, "1.11") == "incorrect"  # a result with its feedback shown
    heights = ex.evaluate(HEIGHTS)
    assert len(set(heights.values())) == 1, heights
