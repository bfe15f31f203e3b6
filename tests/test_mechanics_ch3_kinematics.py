"""Rigid-body kinematics (Sections 3.1.1, 3.1.2) and rotations (Section 3.4.1)."""
import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

from dynagrade.mechanics import rigid_kinematics as rk
from dynagrade.mechanics import rotations
from deferred import deferred

Rotation = deferred("scipy.spatial.transform", "Rotation")

vec3 = st.lists(st.floats(-5.0, 5.0), min_size=3, max_size=3).map(np.array)
angle = st.floats(-np.pi, np.pi)


def _body_points_motion(t, r0_points, omega_axis, omega_rate, v0):
    """Points of a body translating with v0 and spinning about a fixed axis through the
    moving reference point: positions at time t (inertial)."""
    rot = Rotation.from_rotvec(omega_axis * omega_rate * t).as_matrix()
    return v0 * t + r0_points @ rot.T


@settings(max_examples=25, deadline=None)
@given(vec3, vec3, st.integers(0, 10_000))
def test_velocity_transfer_matches_differentiated_positions(v0, w, seed):
    pts = np.random.default_rng(seed).normal(size=(2, 3))
    rate = np.linalg.norm(w)
    axis = w / rate if rate > 0 else np.array([0.0, 0.0, 1.0])
    h = 1e-6
    vel = (_body_points_motion(h, pts, axis, rate, v0)
           - _body_points_motion(-h, pts, axis, rate, v0)) / (2 * h)
    assert rk.velocity_of_point(vel[0], w, pts[1] - pts[0]) == pytest.approx(vel[1], abs=1e-5)


def test_acceleration_transfer_in_planar_motion_by_hand():
    # point at r_AB = (1, 0), omega = 2, alpha = 3, A fixed:
    # a_B = alpha e3 x r - omega^2 r = (0, 3) + (-4, 0)
    a = rk.acceleration_of_point(np.zeros(2), 2.0, 3.0, np.array([1.0, 0.0]))
    assert a == pytest.approx([-4.0, 3.0])


@settings(max_examples=25, deadline=None)
@given(st.floats(-3, 3), st.floats(-3, 3), angle, st.floats(0.2, 2.0))
def test_planar_acceleration_transfer_matches_second_derivative(omega0, alpha, phi0, length):
    # B circles a fixed A: phi(t) = phi0 + omega0 t + alpha t^2 / 2
    def pos(t):
        phi = phi0 + omega0 * t + 0.5 * alpha * t**2
        return length * np.array([np.cos(phi), np.sin(phi)])
    h = 1e-4
    acc = (pos(h) - 2 * pos(0.0) + pos(-h)) / h**2
    a = rk.acceleration_of_point(np.zeros(2), omega0, alpha, pos(0.0))
    assert a == pytest.approx(acc, abs=1e-5 * (1 + abs(omega0) ** 2) * length + 1e-6)


@settings(max_examples=25, deadline=None)
@given(st.lists(st.floats(-5, 5), min_size=2, max_size=2).map(np.array),
       st.lists(st.floats(-5, 5), min_size=2, max_size=2).map(np.array),
       st.floats(0.1, 5.0), st.booleans())
def test_instantaneous_centre_of_rotation_has_zero_velocity(r_a, v_a, w, flip):
    omega = -w if flip else w
    icr = rk.instantaneous_centre_of_rotation(r_a, v_a, omega)
    assert rk.velocity_of_point(v_a, omega, icr - r_a) == pytest.approx([0.0, 0.0], abs=1e-9)


def test_angular_velocity_from_two_point_velocities():
    r_a, r_b = np.array([0.0, 0.0]), np.array([3.0, 4.0])
    v_a = np.array([1.0, 2.0])
    v_b = rk.velocity_of_point(v_a, -1.7, r_b - r_a)
    assert rk.planar_angular_velocity(r_a, v_a, r_b, v_b) == pytest.approx(-1.7)


def test_rolling_wheel_rim_velocities_by_hand():
    v, radius = 3.0, 0.4
    assert rk.rim_point_velocity(v, radius, 0.0) == pytest.approx([0.0, 0.0], abs=1e-12)
    assert rk.rim_point_velocity(v, radius, np.pi) == pytest.approx([2 * v, 0.0])
    # point level with the hub, ahead of it (phi = 90 deg): v (1, -1)
    assert rk.rim_point_velocity(v, radius, np.pi / 2) == pytest.approx([v, -v])
    assert rk.rolling_angular_velocity(v, radius) == pytest.approx(7.5)


@settings(max_examples=25, deadline=None)
@given(st.floats(0.02, 0.3), st.floats(1.5, 5.0), angle, st.floats(-50, 50))
def test_slider_velocity_matches_differentiated_slider_position(r, ratio, theta, omega):
    rod = ratio * r

    def x(th):
        return r * np.cos(th) + np.sqrt(rod**2 - (r * np.sin(th)) ** 2)

    h = 1e-6
    xdot = (x(theta + h) - x(theta - h)) / (2 * h) * omega
    assert rk.slider_velocity(r, rod, theta, omega) == pytest.approx(xdot, abs=1e-6 * r * (1 + abs(omega)))

    def beta(th):
        return rk.connecting_rod_angle(r, rod, th)

    beta_dot = (beta(theta + h) - beta(theta - h)) / (2 * h) * omega
    assert rk.connecting_rod_angular_velocity(r, rod, theta, omega) == pytest.approx(
        beta_dot, abs=1e-6 * (1 + abs(omega)))


@settings(max_examples=40, deadline=None)
@given(vec3, angle)
def test_rotation_matrices_are_orthogonal_with_unit_determinant_and_agree_with_scipy(axis, phi):
    if np.linalg.norm(axis) < 1e-3:
        axis = np.array([0.0, 0.0, 1.0])
    r = rotations.rotation_matrix(axis, phi)
    assert r @ r.T == pytest.approx(np.eye(3), abs=1e-12)
    assert np.linalg.det(r) == pytest.approx(1.0)
    n = axis / np.linalg.norm(axis)
    assert r == pytest.approx(Rotation.from_rotvec(phi * n).as_matrix(), abs=1e-12)
    assert rotations.rotation_angle(r) == pytest.approx(abs(phi), abs=1e-6)


@settings(max_examples=30, deadline=None)
@given(angle, st.floats(0.0, np.pi), angle)
def test_euler_angle_rotation_agrees_with_scipy_intrinsic_zxz(psi, theta, phi):
    expected = Rotation.from_euler("ZXZ", [psi, theta, phi]).as_matrix()
    assert rotations.euler_angle_rotation(psi, theta, phi) == pytest.approx(expected, abs=1e-12)


@settings(max_examples=30, deadline=None)
@given(vec3, angle, vec3)
def test_active_and_passive_rotations_are_inverse_to_each_other(axis, phi, v):
    if np.linalg.norm(axis) < 1e-3:
        axis = np.array([1.0, 0.0, 0.0])
    r = rotations.rotation_matrix(axis, phi)
    rotated = rotations.actively_rotated_vector(r, v)
    # the actively rotated vector has, in the rotated frame, the original components
    assert rotations.components_in_rotated_frame(r, rotated) == pytest.approx(v, abs=1e-12)
    assert np.linalg.norm(rotated) == pytest.approx(np.linalg.norm(v))


def test_passive_rotation_by_hand():
    # frame turned by 90 deg about e3: e1 of the old frame is -e2' of the new one
    r = rotations.rotation_matrix([0, 0, 1], np.pi / 2)
    assert rotations.components_in_rotated_frame(r, [1.0, 0, 0]) == pytest.approx([0, -1, 0], abs=1e-12)
    assert rotations.actively_rotated_vector(r, [1.0, 0, 0]) == pytest.approx([0, 1, 0], abs=1e-12)


@settings(max_examples=25, deadline=None)
@given(vec3, vec3)
def test_angular_velocity_from_rotation_rate_recovers_constant_spin(rotvec0, w):
    r0 = Rotation.from_rotvec(rotvec0).as_matrix()

    def rot(t):
        return Rotation.from_rotvec(w * t).as_matrix() @ r0

    h = 1e-6
    rdot = (rot(h) - rot(-h)) / (2 * h)
    assert rotations.angular_velocity_from_rotation_rate(r0, rdot) == pytest.approx(w, abs=1e-6)
