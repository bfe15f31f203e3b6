"""Rotating frames (Sections 3.4.2-3.4.3), Euler's equations (Section 3.4.4) and tops
(Section 3.5), checked against simulations in the inertial frame."""
import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

from dynagrade.mechanics import euler_equations as ee
from dynagrade.mechanics import frames, gyro
from dynagrade.mechanics.rotations import (angular_velocity_from_rotation_rate,
                                           euler_angle_rotation, rotation_matrix)
from deferred import deferred

solve_ivp = deferred("scipy.integrate", "solve_ivp")
Rotation = deferred("scipy.spatial.transform", "Rotation")

E3 = np.array([0.0, 0.0, 1.0])


@settings(max_examples=10, deadline=None)
@given(st.floats(-3.0, 3.0), st.floats(0.5, 10.0), st.integers(0, 10_000))
def test_motion_solved_in_rotating_frame_agrees_with_inertial_frame(spin, k, seed):
    rng = np.random.default_rng(seed)
    r0, v0 = rng.normal(size=(2, 3))
    omega = spin * E3
    m, t_end = 1.3, 1.5

    def inertial(t, y):                 # isotropic spring to the origin plus gravity
        return np.concatenate([y[3:], -k / m * y[:3] - 9.81 * E3])

    def rotating(t, y):
        r, v_rel = y[:3], y[3:]
        rot_t = rotation_matrix(E3, spin * t)
        force_rel = (-k * r) + rot_t.T @ (-m * 9.81 * E3)   # gravity: e3 is the spin axis
        a_rel = frames.relative_acceleration(force_rel, m, np.zeros(3), omega, np.zeros(3),
                                             r, v_rel)
        return np.concatenate([v_rel, a_rel])

    y_in = solve_ivp(inertial, (0, t_end), np.concatenate([r0, v0]), rtol=1e-10, atol=1e-12).y[:, -1]
    v_rel0 = v0 - np.cross(omega, r0)
    y_rot = solve_ivp(rotating, (0, t_end), np.concatenate([r0, v_rel0]), rtol=1e-10, atol=1e-12).y[:, -1]
    rot = rotation_matrix(E3, spin * t_end)
    assert rot @ y_rot[:3] == pytest.approx(y_in[:3], abs=1e-6)
    v_abs = frames.absolute_velocity(np.zeros(3), omega, y_rot[:3], y_rot[3:])
    assert rot @ v_abs == pytest.approx(y_in[3:], abs=1e-6)


def test_absolute_acceleration_of_point_on_turntable_by_hand():
    # r = (1,0,0) in a frame spinning at 2 rad/s (rate 3 rad/s^2), moving outward at 0.5 m/s
    a = frames.absolute_acceleration(np.zeros(3), [0, 0, 2.0], [0, 0, 3.0], [1.0, 0, 0],
                                     [0.5, 0, 0], np.zeros(3))
    # centripetal -4 e1, Euler 3 e2, Coriolis 2*2*0.5 e2 = 2 e2
    assert a == pytest.approx([-4.0, 5.0, 0.0])


@settings(max_examples=20, deadline=None)
@given(st.floats(0.05, 1.0), st.floats(-1.0, 1.0), st.floats(0.5, 8.0), st.floats(0.0, 1.5),
       st.floats(0.05, 2.0))
def test_bead_on_spinning_rod_by_inertial_acceleration(r0, v0, spin, t, m):
    def position(s):
        r = frames.bead_radial_position(s, r0, v0, spin)
        return r * np.array([np.cos(spin * s), np.sin(spin * s)])

    h = 1e-4
    acc = (position(t + h) - 2 * position(t) + position(t - h)) / h**2
    e_r = np.array([np.cos(spin * t), np.sin(spin * t)])
    e_phi = np.array([-e_r[1], e_r[0]])
    scale = 1e-5 * (1 + position(t) @ position(t)) * spin**2
    assert acc @ e_r == pytest.approx(0.0, abs=scale)           # frictionless along the rod
    rdot = frames.bead_radial_speed(t, r0, v0, spin)
    assert frames.bead_normal_force(m, spin, rdot) == pytest.approx(m * acc @ e_phi, abs=m * scale)
    num_rdot = (frames.bead_radial_position(t + h, r0, v0, spin)
                - frames.bead_radial_position(t - h, r0, v0, spin)) / (2 * h)
    assert rdot == pytest.approx(num_rdot, rel=1e-6, abs=1e-9)


def test_eastward_deflection_matches_simulation_with_coriolis_term():
    h, lat, g, earth = 150.0, np.radians(47.4), 9.81, 7.292e-5
    # local frame: e1 east, e2 north, e3 up; Earth's rate has north and up components
    omega = earth * np.array([0.0, np.cos(lat), np.sin(lat)])

    def rhs(t, y):
        a = frames.relative_acceleration(-g * E3, 1.0, np.zeros(3), omega, np.zeros(3),
                                         np.zeros(3), y[3:])   # centrifugal part is in g
        return np.concatenate([y[3:], a])

    def ground(t, y):
        return y[2]
    ground.terminal = True
    sol = solve_ivp(rhs, (0, 20), [0, 0, h, 0, 0, 0], events=ground, rtol=1e-11, atol=1e-12)
    east = sol.y_events[0][0][0]
    assert frames.eastward_deflection_of_falling_body(h, lat, earth, g) == pytest.approx(east, rel=1e-3)


def _torque_free(inertia_diag, w0, t_end, **kw):
    inertia_diag = np.asarray(inertia_diag)

    def rhs(t, w):   # written out here: I w' = -w x (I w)
        return -np.cross(w, inertia_diag * w) / inertia_diag
    return solve_ivp(rhs, (0, t_end), w0, rtol=1e-10, atol=1e-12, **kw)


moments_st = st.lists(st.floats(0.5, 5.0), min_size=3, max_size=3, unique=True)


@settings(max_examples=15, deadline=None)
@given(moments_st, st.integers(0, 10_000))
def test_torque_free_euler_equations_conserve_energy_and_angular_momentum_magnitude(moments, seed):
    moments = np.array(moments)
    w0 = np.random.default_rng(seed).normal(size=3)
    sol = solve_ivp(lambda t, w: ee.angular_acceleration_euler(moments, w, np.zeros(3)),
                    (0, 5.0), w0, rtol=1e-10, atol=1e-12)
    w_end = sol.y[:, -1]
    assert 0.5 * moments @ w_end**2 == pytest.approx(0.5 * moments @ w0**2, rel=1e-6)
    assert np.linalg.norm(moments * w_end) == pytest.approx(np.linalg.norm(moments * w0), rel=1e-6)
    # and they are the same equations as written out independently
    assert w_end == pytest.approx(_torque_free(moments, w0, 5.0).y[:, -1], abs=1e-6)


@settings(max_examples=8, deadline=None)
@given(st.floats(1.0, 1.5), st.floats(2.5, 3.0), st.floats(4.0, 5.0), st.floats(2.0, 6.0))
def test_rotation_about_intermediate_axis_is_unstable_and_about_extreme_axes_stable(i1, i2, i3, spin):
    moments = np.array([i1, i2, i3])
    for axis in range(3):
        w0 = np.full(3, 1e-3 * spin)
        w0[axis] = spin
        sol = _torque_free(moments, w0, 25.0 / spin)   # growth rate >= 0.36 spin if unstable
        deviation = np.max(np.abs(np.delete(sol.y, axis, axis=0)))
        stable = ee.is_stable_rotation_axis(moments, axis)
        assert stable == (axis != 1)
        if stable:
            assert deviation < 0.01 * spin
        else:
            assert deviation > 0.3 * spin


def test_wobble_frequency_matches_simulated_quarter_period():
    moments, spin = np.array([1.0, 2.0, 3.5]), 4.0
    eps = 1e-5
    nu = ee.wobble_frequency(moments, 2, spin)

    def crossing(t, w):
        return w[0]
    crossing.terminal = True
    sol = _torque_free(moments, [eps, 0.0, spin], 10.0, events=crossing)
    assert sol.t_events[0][0] == pytest.approx(np.pi / (2 * nu), rel=1e-4)


def test_body_precession_rate_of_axisymmetric_body_matches_simulation():
    i1, i3, w3, w_perp = 2.0, 3.0, 5.0, 0.7
    sol = _torque_free([i1, i1, i3], [w_perp, 0.0, w3], 1.0)
    angle = np.arctan2(sol.y[1, -1], sol.y[0, -1])
    # omega_perp turns by +Omega_p t in the body frame (w1' = -Omega_p w2, w2' = Omega_p w1)
    assert ee.body_precession_rate(i3, i1, w3) * 1.0 == pytest.approx(angle, rel=1e-6)


@settings(max_examples=20, deadline=None)
@given(moments_st, st.integers(0, 10_000))
def test_gyroscopic_moment_inverts_euler_equations(moments, seed):
    rng = np.random.default_rng(seed)
    w, m = rng.normal(size=(2, 3))
    wdot = ee.angular_acceleration_euler(moments, w, m)
    assert ee.gyroscopic_moment(moments, w, wdot) == pytest.approx(m, abs=1e-10)


@settings(max_examples=25, deadline=None)
@given(st.floats(-3, 3), st.floats(0.1, 3.0), st.floats(-3, 3), st.floats(-5, 5),
       st.floats(-5, 5), st.floats(-5, 5))
def test_euler_angle_rates_give_the_angular_velocity_of_the_rotation(psi, theta, phi, dpsi, dth, dphi):
    def rot(t):
        return euler_angle_rotation(psi + dpsi * t, theta + dth * t, phi + dphi * t)

    h = 1e-6
    rdot = (rot(h) - rot(-h)) / (2 * h)
    w_inertial = angular_velocity_from_rotation_rate(rot(0.0), rdot)
    w_body = gyro.body_angular_velocity_from_euler_rates(theta, phi, dpsi, dth, dphi)
    assert rot(0.0) @ w_body == pytest.approx(w_inertial, abs=1e-6)


def _simulate_top(m, g, length, i1, i3, theta, psi_rate, omega3, t_end):
    """Heavy top from Euler's equations about the fixed tip and dR/dt = R [w]x (body w)."""
    inertia = np.array([i1, i1, i3])
    r0 = euler_angle_rotation(0.0, theta, 0.0)
    spin_rate = omega3 - psi_rate * np.cos(theta)
    w_body0 = r0.T @ (psi_rate * E3) + spin_rate * E3

    def rhs(t, y):
        rot = y[:9].reshape(3, 3)
        w = y[9:]
        gravity_body = rot.T @ (-m * g * E3)
        moment = np.cross(length * E3, gravity_body)
        wdot = (moment - np.cross(w, inertia * w)) / inertia
        wx = np.array([[0, -w[2], w[1]], [w[2], 0, -w[0]], [-w[1], w[0], 0]])
        return np.concatenate([(rot @ wx).ravel(), wdot])

    sol = solve_ivp(rhs, (0, t_end), np.concatenate([r0.ravel(), w_body0]),
                    rtol=1e-10, atol=1e-12, dense_output=True)
    ts = np.linspace(0, t_end, 60)
    axes = np.array([sol.sol(t)[:9].reshape(3, 3) @ E3 for t in ts])
    tilt = np.arccos(np.clip(axes[:, 2], -1, 1))
    azimuth = np.unwrap(np.arctan2(axes[:, 1], axes[:, 0]))
    return tilt, azimuth[-1] - azimuth[0]


@pytest.mark.parametrize("branch", ["slow", "fast"])
def test_steady_precession_keeps_the_tilt_constant_in_simulation(branch):
    m, g, length, i1, i3, theta, omega3 = 1.0, 9.81, 0.1, 0.02, 0.01, 0.5, 60.0
    rates = gyro.steady_precession_rates(m, g, length, i1, i3, omega3, theta)
    psi_rate = getattr(rates, branch)
    t_end = 1.0
    tilt, turned = _simulate_top(m, g, length, i1, i3, theta, psi_rate, omega3, t_end)
    assert np.max(np.abs(tilt - theta)) < 1e-5
    assert turned == pytest.approx(psi_rate * t_end, rel=1e-5)


def test_off_steady_precession_rate_makes_the_top_nod():
    m, g, length, i1, i3, theta, omega3 = 1.0, 9.81, 0.1, 0.02, 0.01, 0.5, 60.0
    slow = gyro.steady_precession_rates(m, g, length, i1, i3, omega3, theta).slow
    tilt, _ = _simulate_top(m, g, length, i1, i3, theta, 0.5 * slow, omega3, 1.0)
    assert np.max(np.abs(tilt - theta)) > 1e-3


def test_fast_top_approximation_is_the_large_spin_limit_of_slow_precession():
    m, g, length, i1, i3, theta = 0.5, 9.81, 0.05, 4e-4, 3e-4, 0.7
    for omega3 in (1e3, 1e4):
        exact = gyro.steady_precession_rates(m, g, length, i1, i3, omega3, theta).slow
        approx = gyro.fast_top_precession_rate(m, g, length, i3, omega3)
        # next-order term: psi' ~ mgl/H (1 + I1 cos(theta) mgl / H^2)
        assert approx == pytest.approx(exact, rel=2 * i1 * m * g * length / (i3 * omega3) ** 2)
    # the gyroscope with a horizontal axis: psi' = M / H
    assert gyro.gyroscopic_precession_rate(2.0, 8.0) == pytest.approx(0.25)


def test_at_the_minimum_spin_slow_and_fast_precession_coincide():
    m, g, length, i1, i3, theta = 0.5, 9.81, 0.05, 4e-4, 3e-4, 0.7
    w_min = gyro.minimum_spin_for_steady_precession(m, g, length, i1, i3, theta)
    rates = gyro.steady_precession_rates(m, g, length, i1, i3, w_min, theta)
    assert rates.slow == pytest.approx(rates.fast, rel=1e-6)
    assert rates.slow == pytest.approx(i3 * w_min / (2 * i1 * np.cos(theta)))
