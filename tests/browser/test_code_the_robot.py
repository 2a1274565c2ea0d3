"""The "Code the robot" Build exercises in the page: a correct solution shows every test passing; a
wrong one shows the failing case (its input, what was expected, what came back) and marks the learner's
line when their code raised.

The tests share the module's one tab (``tour``, one grader and one sandbox for them all): each
sets its own exercise's code before every run, and no test reads another's records."""

from __future__ import annotations

import pytest

from helpers import exercise, role, run_build, set_editor
from workbook import bank

# Per exercise: a slip that gives wrong values (old -> new in the model solution), and one that raises,
# with the text of the line it raises on.
WRONG = {
    "1.7": (("y = -s * dx + c * dy", "y = s * dx + c * dy"),
            ("x = c * dx + s * dy", "x = c * dx + s * dY"), "x = c * dx + s * dY"),
    "2.8": (("math.sin(angle / 2) / n", "math.sin(angle / 2)"),
            ("tt = cross(u, t)", "tt = cross(u, t, v)"), "tt = cross(u, t, v)"),
    "3.10": ((" + Q[i][j] for j", " for j"),
             ("heading = theta + omega * dt", "heading = theta + omega * dt / (dt * v)"),
             "heading = theta + omega * dt / (dt * v)"),
    "5.8": (("x[1] + d1, x[2] + d2", "x[1] - d1, x[2] - d2"),
            ("if det == 0:\n        return None", ""), "d1 = (-b[1] * h22 + b[2] * h12) / det"),
    "5.10": (("        e[2] = wrap(e[2])\n", ""),
             ("np.linalg.solve(H[3:, 3:], -b[3:])", "np.linalg.solve(H, -b[3:])"),
             "dx[3:] = np.linalg.solve(H, -b[3:])  # pose 0's rows and columns dropped"),
    "6.7": (("if elbow_up:", "if not elbow_up:"),
            ("\n    c2 = max(-1.0, min(1.0, c2))  # round-off at the edge can put c2 a hair past 1 or -1", ""),
            "theta2 = math.acos(c2)"),
    "7.8": (("abs(det) < 1e-9", "det == 0"),
            ("-L2 * s12]", "-L2 * s2]"), "J = [[-L1 * s1 - L2 * s12, -L2 * s2],"),
    "8.8": (("return (min(u_max, max(u_min, u)), new_integral)", "return (u, new_integral)"),
            (" if dt > 0 else 0.0", ""), "d = Kd * (e - e_prev) / dt  # dt = 0: no time passed"),
    "9.9": (("if z is not None:", "if False:"),
            ("y = [z[0] - r,", "y = [z[0] - r_pred,"), "y = [z[0] - r_pred, wrap(z[1] - (math.atan2(dy, dx) - x[2]))]"),
    "10.8": (("if d < 0:  # -q1", "if False:  # -q1"),
             ("omega = math.acos(min(d, 1.0))", "omega = math.acos(min(d, 1.0)) / zero"),
             "omega = math.acos(min(d, 1.0)) / zero"),
}


def changed(ex, old: str, new: str) -> str:
    assert old in ex.solution, (ex.id, old)
    return ex.solution.replace(old, new)


def rows(ex):
    return ex.locator(role("test-result"))


@pytest.mark.parametrize("ex_id", list(WRONG))
def test_code_the_robot_in_the_page(tour, ex_id):
    ex_data = bank.get(ex_id)
    page = tour(int(ex_id.split(".")[0]))
    ex = exercise(page, ex_id)
    assert ex.get_attribute("data-kind") == "build"

    set_editor(page, ex, ex_data.solution)
    assert run_build(ex) == "correct"
    assert rows(ex).count() == len(ex_data.examples) + 1
    assert ex.locator(role("test-result", '[data-passed="false"]')).count() == 0

    (old, new), (old_raise, new_raise), line_text = WRONG[ex_id]
    set_editor(page, ex, changed(ex_data, old, new))
    assert run_build(ex) == "incorrect"
    failing = ex.locator(role("test-result", '[data-passed="false"]'))
    assert failing.count() >= 1
    cells = failing.first.locator("td").all_inner_texts()
    assert cells[0].startswith(ex_data.function) and cells[1] and cells[2] and cells[1] != cells[2]

    code = changed(ex_data, old_raise, new_raise)
    set_editor(page, ex, code)
    assert run_build(ex) == "incorrect"
    failing = ex.locator(role("test-result", '[data-passed="false"]'))
    assert failing.first.locator("td").first.inner_text().startswith(ex_data.function)
    assert "raised" in failing.first.locator("td").nth(2).inner_text()
    number = code.split("\n").index(next(s for s in code.split("\n") if s.strip() == line_text.strip())) + 1
    assert f"line {number}" in ex.locator(role("tests")).inner_text()
    marked = ex.locator(".cm-line.wb-error-line")
    assert marked.count() == 1 and line_text.strip() in marked.inner_text()


def test_a_slip_of_5_10_is_named_in_its_row(tour):
    """The sentence the grader says about a known slip (workbook.bank.pose_graph_slips) reaches the page."""
    ex_data = bank.get("5.10")
    page = tour(5)
    ex = exercise(page, "5.10")
    set_editor(page, ex, changed(ex_data, "    new[:, 2] = wrap(new[:, 2])\n", "    new[0] = 0.0\n    new[:, 2] = wrap(new[:, 2])\n"))
    assert run_build(ex) == "incorrect"
    assert ex.locator(role("test-result", '[data-passed="false"]')).count() >= 1
    assert "Pose 0 moved: it is the anchor, so it comes back exactly as given." in ex.locator(role("tests")).inner_text()
