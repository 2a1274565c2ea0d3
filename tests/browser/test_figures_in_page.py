"""The interactive figures in the browser: move a slider with the keyboard and
the readout shows what the reference implementation predicts for the new
value (computed here, natively, with the same package)."""

from __future__ import annotations

import math
import re

import pytest

from helpers import CHAPTERS, open_chapter, role, wait_runtime
from workbook.figures import arm_2link, capstone, ekf_update, jacobian
from workbook.reference.arm import inverse_kinematics_2link, jacobian_det
from workbook.reference.ekf import ekf_predict, ekf_update_matrix, measurement_jacobian, range_bearing
from workbook.reference.pid import simulate_step_response, step_metrics
from workbook.reference.rotation2d import rotate_2d
from workbook.reference.rotation3d import euler_zyx, quat_from_matrix
from workbook.reference.transform2d import apply, chain, transform2d

rad = math.radians


def numbers(text: str) -> list[float]:
    return [float(m) for m in re.findall(r"-?\d+(?:\.\d+)?", text.replace("−", "-"))]


def assert_close(text: str, expected, digits: int = 3) -> None:
    got = numbers(text)
    assert len(got) == len(expected), (text, expected)
    for g, e in zip(got, expected):
        assert abs(g - e) <= 0.51 * 10 ** -digits, (text, expected)


def figure(page):
    return page.locator(role("figure"))


def readout(page, key: str) -> str:
    return figure(page).locator(role("readout") + f'[data-readout="{key}"]').inner_text()


def press(page, param: str, key: str, watch: str) -> str:
    """Focus the slider, press ``key``, wait for the ``watch`` readout to change; return it."""
    before = readout(page, watch)
    figure(page).locator(f'input[type="range"][data-param="{param}"]').focus()
    page.keyboard.press(key)
    page.wait_for_function(
        ("([key, before]) => document.querySelector(`" + role("readout") + "[data-readout=\"${key}\"]`).textContent !== before"),
        arg=[watch, before],
    )
    return readout(page, watch)


def slider_value(page, param: str) -> float:
    return float(figure(page).locator(f'input[data-param="{param}"]').input_value())


def test_every_chapter_page_has_a_figure(tour):
    for n in CHAPTERS:
        page = tour(n)
        fig = figure(page)
        assert fig.count() == 1
        assert fig.locator("svg").count() == 1
        assert fig.locator('input[type="range"]').count() >= 1
        assert fig.locator(role("readout")).count() >= 1


def test_ch0_rotation(tour):
    page = tour(0)  # the module's one tab: one booted grader for these tests
    text = press(page, "theta", "ArrowRight", "image")
    assert slider_value(page, "theta") == 31
    assert_close(text, rotate_2d(1.5, 0.5, rad(31)))
    assert figure(page).locator('output' + role("control-value")).first.inner_text() == "31°"


def test_ch0_controls_queue_until_the_runtime_is_ready(page, site_url):
    open_chapter(page, site_url, 0, wait_ready=False)
    text = press(page, "theta", "End", "image")  # may be pressed while Python is still loading
    wait_runtime(page)
    assert_close(text, rotate_2d(1.5, 0.5, rad(180)))


def test_ch1_frames(tour):
    page = tour(1)  # the module's one tab: one booted grader for these tests
    text = press(page, "heading", "ArrowRight", "world")
    T = chain(transform2d(1.0, 0.5, rad(31)), transform2d(0.5, 0.0, rad(20)))
    assert_close(text, apply(T, 1.2, 0.4))


def test_ch2_euler_and_gimbal_lock(tour):
    page = tour(2)  # the module's one tab: one booted grader for these tests
    text = press(page, "pitch", "End", "q")
    assert_close(text, quat_from_matrix(euler_zyx(rad(30), rad(90), rad(10))))
    assert readout(page, "gimbal").startswith("locked")
    assert "gimbal-lock" in figure(page).get_attribute("data-flags")


def test_ch3_ekf_predict(tour):
    page = tour(3)  # the module's one tab: one booted grader for these tests
    text = press(page, "steps", "ArrowRight", "pose")
    Q = [[0.05 ** 2, 0, 0], [0, 0.05 ** 2, 0], [0, 0, rad(2) ** 2]]
    state, P = (0.0, 0.0, 0.0), [[0.05 ** 2, 0, 0], [0, 0.05 ** 2, 0], [0, 0, rad(1) ** 2]]
    for _ in range(7):
        state, P = ekf_predict(state, P, 1.0, 0.3, 0.5, Q)
    assert_close(text, [state[0], state[1], round(math.degrees(state[2]), 1)])


def test_ch4_ekf_update(tour):
    page = tour(4)  # the module's one tab: one booted grader for these tests
    text = press(page, "sigma_r", "ArrowRight", "posterior")
    sigma_r = slider_value(page, "sigma_r")
    assert sigma_r == pytest.approx(0.22)
    P = [[0.25, 0, 0], [0, 0.25, 0], [0, 0, ekf_update.THETA_SIGMA ** 2]]
    R = [[sigma_r ** 2, 0], [0, rad(3) ** 2]]
    pose, landmark = ekf_update.PREDICTED, ekf_update.LANDMARK
    x, _ = ekf_update_matrix(list(pose), P, list(range_bearing(ekf_update.TRUE_POSE, landmark)),
                             list(range_bearing(pose, landmark)), measurement_jacobian(pose, landmark), R)
    assert_close(text, [x[0], x[1], round(math.degrees(x[2]), 2)])


def test_ch5_pose_graph_optimise_lowers_the_cost(tour):
    page = tour(5)  # the module's one tab: one booted grader for these tests
    press(page, "drift", "ArrowRight", "gap")
    shown = readout(page, "cost")
    before = numbers(shown)[0]
    button = figure(page).locator('button[data-param="optimise"]')
    button.focus()
    page.keyboard.press("Enter")
    page.wait_for_function("b => document.querySelector('[data-readout=cost]').textContent !== b", arg=shown)
    after = numbers(readout(page, "cost"))[0]
    assert button.get_attribute("aria-pressed") == "true"
    assert after < before
    history = numbers(readout(page, "history"))
    assert history[0] == pytest.approx(before) and history[-1] == pytest.approx(after)


def test_ch6_arm_ik_and_unreachable(tour):
    page = tour(6)  # the module's one tab: one booted grader for these tests
    text = press(page, "tx", "ArrowRight", "elbow_up")
    tx = slider_value(page, "tx")
    assert tx == pytest.approx(0.95)
    sol = inverse_kinematics_2link(arm_2link.L1, arm_2link.L2, tx, 0.8)
    shown = [float(v.replace("−", "-")) for v in re.findall(r"= (−?[\d.]+)°", text)]
    assert shown == [round(math.degrees(a), 1) for a in sol.elbow_up]
    text = press(page, "tx", "End", "reach")
    assert text.startswith("unreachable")
    assert readout(page, "elbow_up") == "none"
    assert "unreachable" in figure(page).get_attribute("data-flags")


def test_ch7_jacobian_and_singularity(tour):
    page = tour(7)  # the module's one tab: one booted grader for these tests
    text = press(page, "theta2", "ArrowRight", "det")
    assert_close(text, [jacobian_det(jacobian.L1, jacobian.L2, rad(30), rad(71))])
    assert figure(page).get_attribute("data-flags") == ""
    text = press(page, "theta2", "Home", "det")
    assert_close(text, [jacobian_det(jacobian.L1, jacobian.L2, rad(30), rad(-180))])
    assert figure(page).get_attribute("data-flags") == "singular"


def test_ch8_pid(tour):
    page = tour(8)  # the module's one tab: one booted grader for these tests
    text = press(page, "Kp", "ArrowRight", "error")
    m = step_metrics(*simulate_step_response(8.5, 0, 0, duration=10.0))
    assert_close(text, [m.steady_state_error])
    assert_close(readout(page, "overshoot"), [100 * m.overshoot], 1)
    assert_close(readout(page, "settling"), [m.settling_time], 2)


def test_ch9_capstone(tour):
    page = tour(9)  # the module's one tab: one booted grader for these tests
    text = press(page, "step", "ArrowRight", "estimate")
    s = capstone.simulate(True)[21]
    assert_close(text, [s.estimate[0], s.estimate[1], round(math.degrees(s.estimate[2]), 1)])


def test_ch10_poses_3d_chain_and_both_quaternion_orders(tour):
    """Chapter 10: the base yawed one step from the keyboard, the camera tilted to its end: the camera's
    position is T_world_base · T_base_cam's, and the two quaternion readouts are one rotation in the
    two storage orders."""
    from workbook.figures.poses_3d import chain as pose_chain
    from workbook.reference.se3 import rotation_of, translation_of

    page = tour(10)  # the module's one tab: one booted grader for these tests
    press(page, "yaw", "ArrowRight", "p")
    assert slider_value(page, "yaw") == 35
    wxyz = press(page, "tilt", "End", "wxyz")  # the tilt turns the camera about its own origin
    _wb, _bc, T_wc = pose_chain(35, 60)
    text = readout(page, "p")
    assert_close(text, translation_of(T_wc))
    q = quat_from_matrix(rotation_of(T_wc))
    assert_close(wxyz, q)
    assert_close(readout(page, "xyzw"), (*q[1:], q[0]))
    before = figure(page).locator("svg").inner_html()
    figure(page).locator('input[type="range"][data-param="view"]').focus()
    page.keyboard.press("ArrowLeft")
    page.wait_for_function("([selector, before]) => document.querySelector(selector).innerHTML !== before",
                           arg=[role("figure") + " svg", before])
    assert readout(page, "p") == text  # turning the view moves no frame


def test_ch11_arm_3d_shoulder_from_the_keyboard_and_a_view_that_moves_nothing(tour):
    """Chapter 11: the shoulder raised one step from the keyboard moves the tool where the product of
    exponentials puts it (the figure's own draw, natively); turning the view redraws the picture and
    moves no readout."""
    from workbook.figures.arm_3d import draw

    page = tour(11)
    p = press(page, "t2", "ArrowRight", "p")
    assert slider_value(page, "t2") == 45
    want = draw({"t1": 30, "t2": 45, "t3": -60, "view": -55})["readouts"]
    assert_close(p, numbers(want["p"]))
    assert_close(readout(page, "J"), numbers(want["J"]))
    before = figure(page).locator("svg").inner_html()
    figure(page).locator('input[type="range"][data-param="view"]').focus()
    page.keyboard.press("ArrowLeft")
    page.wait_for_function("([selector, before]) => document.querySelector(selector).innerHTML !== before",
                           arg=[role("figure") + " svg", before])
    assert readout(page, "p") == p


def test_ch12_bayes_grid_finds_the_robot_and_a_blind_sensor_leaves_it_lost(tour):
    """Chapter 12: ten steps from the keyboard (End) and the belief's peak is the cell the figure's own
    filter gives; with the sensor at its least reliable, the readouts are what that filter gives too."""
    from workbook.figures.bayes_grid import draw

    page = tour(12)
    best = press(page, "steps", "End", "best")
    assert slider_value(page, "steps") == 10
    want = draw({"steps": 10, "noise": 0.2, "hit": 0.8})["readouts"]
    assert best == want["best"]
    assert_close(readout(page, "prob"), numbers(want["prob"]))
    press(page, "hit", "Home", "prob")
    assert slider_value(page, "hit") == 0.5
    blind = draw({"steps": 10, "noise": 0.2, "hit": 0.5})["readouts"]
    assert readout(page, "best") == blind["best"]
    assert readout(page, "verdict") == blind["verdict"]


def test_ch13_icp_steps_onto_the_map_from_a_good_start_and_not_from_a_poor_one(tour):
    """Chapter 13: one ICP iteration from the keyboard takes the scan from 15° and 0.3 m off onto the
    map; with the first guess turned to 60° off, twelve iterations leave it in a wrong pose."""
    from workbook.figures.align_icp import draw

    page = tour(13)  # the module's one tab: one booted grader for these tests
    assert readout(page, "error") == "15.0°, 0.747 m"
    assert press(page, "steps", "ArrowRight", "error") == "0.0°, 0.000 m"
    assert slider_value(page, "steps") == 1
    figure(page).locator('input[type="range"][data-param="steps"]').focus()
    page.keyboard.press("End")
    assert slider_value(page, "steps") == 12
    figure(page).locator('input[type="range"][data-param="turn"]').focus()
    for _ in range(9):  # the turn from 15° to 60°, in steps of 5°
        page.keyboard.press("ArrowRight")
    assert slider_value(page, "turn") == 60
    want = draw({"turn": 60, "shift": 0.3, "steps": 12})["readouts"]
    assert want["error"] != "0.0°, 0.000 m"
    page.wait_for_function(
        "([selector, want]) => document.querySelector(selector).textContent === want",
        arg=[role("figure") + " " + role("readout") + '[data-readout="error"]', want["error"]],
    )
    assert "not reached" in readout(page, "verdict")
