"""Reference implementations at their edges: tiny angles, scale, and clear errors instead of ZeroDivisionError."""

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from workbook.reference.arm import cos_elbow, inverse_kinematics_2link
from workbook.reference.ekf import ekf_update, ekf_update_matrix, kalman_gain, measurement_jacobian
from workbook.reference.linalg import identity, inverse, matmul, scale
from workbook.reference.pid import d_term, pid_step, simulate_step_response, step_metrics
from workbook.reference.rotation3d import DEFAULT_AXIS, quat_axis_angle, quat_from_axis_angle, quat_from_matrix, rx


@pytest.mark.parametrize("angle", [1e-7, 1e-8, 1e-10, 1e-15, 1e-300])
def test_tiny_quaternion_angles_keep_their_size_and_a_unit_axis(angle):
    axis, got = quat_axis_angle(quat_from_axis_angle((0.0, 0.6, 0.8), angle))
    assert got > 0 and math.isclose(got, angle, rel_tol=1e-9)
    assert math.isclose(math.hypot(*axis), 1.0, rel_tol=1e-15)
    assert all(math.isclose(a, b, abs_tol=1e-12) for a, b in zip(axis, (0.0, 0.6, 0.8)))


def test_the_identity_quaternion_has_the_documented_default_axis():
    assert quat_axis_angle((1, 0, 0, 0)) == (DEFAULT_AXIS, 0.0)
    assert quat_axis_angle(quat_from_matrix(identity(3))) == (DEFAULT_AXIS, 0.0)


@settings(max_examples=200, deadline=None)
@given(st.tuples(*[st.floats(-1, 1)] * 3).filter(lambda v: math.hypot(*v) > 1e-3),
       st.floats(min_value=1e-12, max_value=2 * math.pi - 1e-9))
def test_axis_angle_round_trips(axis, angle):
    n = math.hypot(*axis)
    got_axis, got_angle = quat_axis_angle(quat_from_axis_angle(axis, angle))
    assert math.isclose(got_angle, angle, rel_tol=1e-9, abs_tol=1e-12)
    assert all(math.isclose(a, b / n, abs_tol=1e-9) for a, b in zip(got_axis, axis))


def test_a_non_unit_quaternion_still_gives_its_rotation():
    axis, angle = quat_axis_angle((2 * math.cos(0.5), 2 * math.sin(0.5), 0, 0))
    assert axis == (1.0, 0.0, 0.0) and math.isclose(angle, 1.0)


def test_zero_quaternions_and_axes_are_refused_by_name():
    with pytest.raises(ValueError, match="axis must not be the zero vector"):
        quat_from_axis_angle((0, 0, 0), 1.0)
    with pytest.raises(ValueError, match="quaternion q must not be zero"):
        quat_axis_angle((0, 0, 0, 0))


def test_inverse_is_scale_aware():
    assert inverse(scale(identity(3), 1e-13))[1][1] == pytest.approx(1e13)
    got = inverse([[2e-14, 1e-14], [1e-14, 1e-14]])
    assert [v for row in got for v in row] == pytest.approx([1e14, -1e14, -1e14, 2e14])
    for k in (1.0, 1e9, 1e-9, 1e20):
        with pytest.raises(ValueError, match="matrix is singular"):
            inverse(scale([[1, 2, 3], [4, 5, 6], [7, 8, 9]], k))
    with pytest.raises(ValueError, match="matrix is singular"):
        inverse([[1e9, 2e9], [2e9, 4e9]])
    assert inverse([]) == []


@settings(max_examples=100, deadline=None)
@given(st.floats(min_value=-15, max_value=15))
def test_inverse_of_a_rotation_at_any_scale(exponent):
    k = 10.0 ** exponent
    A = scale(rx(0.7), k)
    product = matmul(A, inverse(A))
    assert all(math.isclose(product[i][j], float(i == j), abs_tol=1e-9) for i in range(3) for j in range(3))


def test_pid_refuses_a_zero_time_step():
    for call in (lambda: pid_step(1, 3, 8, 1, 0.1, 0.5, 0), lambda: d_term(1, 2, 1, 0.0),
                 lambda: simulate_step_response(1, 0, 0, dt=0), lambda: pid_step(1, 3, 8, 1, 0.1, 0.5, -0.1)):
        with pytest.raises(ValueError, match="dt must be positive"):
            call()


def test_step_metrics_handles_a_negative_target_by_symmetry():
    up = step_metrics(*simulate_step_response(9, 0, 0, target=2.0), target=2.0)
    down = step_metrics(*simulate_step_response(9, 0, 0, target=-2.0), target=-2.0)
    assert down.overshoot == pytest.approx(up.overshoot)
    assert down.settling_time == up.settling_time
    assert down.steady_state_error == pytest.approx(-up.steady_state_error)
    with pytest.raises(ValueError, match="target must be non-zero"):
        step_metrics([0.0, 1.0], [0.0, 0.5], target=0.0)


def test_arm_functions_refuse_zero_links_by_name():
    with pytest.raises(ValueError, match="L2 must be non-zero"):
        cos_elbow(1, 0, 1, 0)
    with pytest.raises(ValueError, match="L1 must be non-zero"):
        cos_elbow(0, 1, 0, 1)
    with pytest.raises(ValueError, match="L2 must be non-zero"):
        inverse_kinematics_2link(1, 0, 1, 0)  # on the circle it can reach, but the elbow is undefined


def test_ekf_update_refuses_a_zero_innovation_covariance():
    with pytest.raises(ValueError, match=r"P \+ R must be positive"):
        ekf_update(2.0, 0.0, 3.0, 0.0)
    with pytest.raises(ValueError, match="innovation covariance S = H P Hᵀ \\+ R is singular"):
        kalman_gain([[0.0]], [[1]], [[0.0]])
    with pytest.raises(ValueError, match="innovation covariance"):
        ekf_update_matrix([0.0], [[0.0]], [1.0], [0.0], [[1]], [[0.0]])
    # R = 0 alone is a perfect sensor, not an error.
    assert ekf_update(2.0, 1.0, 3.0, 0.0) == (3.0, 0.0)


def test_a_landmark_on_the_robot_has_no_bearing():
    with pytest.raises(ValueError, match="at the robot's position"):
        measurement_jacobian((1, 2, 0.3), (1, 2))
