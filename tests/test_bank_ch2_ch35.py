"""The bank's new exercises for Sections 2.2.1-2.2.3 and 3.5.1-3.5.2 (issue 31), and the
core relations they added: each key against numbers worked out by hand (written in the
comments) and each new relation against an independent route (integration, a limit or a
second derivation)."""

import numpy as np
import pytest

from dynagrade.exercise import open_bank
from dynagrade.mechanics import systems

BANK = open_bank()


def solve_ivp(*args, **kwargs):
    """scipy's solve_ivp, imported when a test integrates (collecting the suite imports no
    scipy, tests/test_collection.py)."""
    from scipy.integrate import solve_ivp as integrate

    return integrate(*args, **kwargs)


def _keys(exercise_id, **values):
    """The exercise's reference answers, in its parts' units, at the given parameters
    (declared units)."""
    return BANK.get(exercise_id).solve_in_part_units(values)


# -- Section 2.2.1: walking on a boat --------------------------------------------------

def test_walking_on_a_boat_keys_match_the_hand_calculation():
    keys = _keys("walking-on-a-boat", m=80, M=240, d=3.0, u=1.0)
    # x_B = m d / (m + M) = 80 * 3 / 320 = 0.75 m
    assert keys["x_B"] == pytest.approx(0.75, rel=1e-9)
    # x_P = d - x_B = 3 - 0.75 = 2.25 m
    assert keys["x_P"] == pytest.approx(2.25, rel=1e-9)
    # v_B = m u / (m + M) = 80 * 1 / 320 = 0.25 m/s
    assert keys["v_B"] == pytest.approx(0.25, rel=1e-9)


def test_the_recoil_displacement_matches_two_bodies_pushed_apart_by_an_internal_force():
    """Integrate a person (m) and a boat (M) pushed apart by an arbitrary internal force
    F(t) = sin(t)^2 on the person and -F(t) on the boat; read the boat's displacement when
    the person has moved d = 1.5 m relative to the boat."""
    m, M, d = 70.0, 210.0, 1.5

    def rhs(t, y):
        force = 50.0 * np.sin(t) ** 2
        return [y[2], y[3], force / m, -force / M]

    def walked(t, y):
        return (y[0] - y[1]) - d
    walked.terminal = True
    run = solve_ivp(rhs, (0.0, 30.0), [0.0, 0.0, 0.0, 0.0], events=walked,
                    rtol=1e-10, atol=1e-12)
    boat = -run.y_events[0][0][1]
    # by hand: m d / (m + M) = 70 * 1.5 / 280 = 0.375 m
    assert boat == pytest.approx(0.375, rel=1e-6)
    assert systems.recoil_displacement(m, M, d) == pytest.approx(boat, rel=1e-6)


# -- Section 2.2.1: Atwood machine on a hook ---------------------------------------------

def test_atwood_hook_force_keys_match_the_hand_calculation():
    keys = _keys("atwood-hook-force", m1=6.0, m2=2.0, g=9.81)
    # a = (6 - 2)/(6 + 2) * 9.81 = 4.905 m/s^2
    assert keys["a"] == pytest.approx(4.905, rel=1e-9)
    # a_C = (6 a - 2 a)/8 = 0.5 * 4.905 = 2.4525 m/s^2 downward
    assert keys["a_C"] == pytest.approx(2.4525, rel=1e-9)
    # F = 4 * 6 * 2 / 8 * 9.81 = 58.86 N = 8 * (9.81 - 2.4525)
    assert keys["F"] == pytest.approx(58.86, rel=1e-9)


def test_the_atwood_acceleration_matches_the_energy_balance_integrated_in_time():
    """Energy route: (m1 + m2) v dv/dt = (m1 - m2) g v, i.e. the potential energy the
    blocks lose becomes kinetic energy; integrate the two blocks as particles held by a
    very stiff string and compare the mean acceleration over 0.5 s."""
    m1, m2, g, k = 3.0, 1.0, 9.81, 1e7

    def rhs(t, y):  # y = (x1 down, x2 up, v1, v2); the string stretch is x1 - x2
        tension = k * (y[0] - y[1])
        return [y[2], y[3], g - tension / m1, tension / m2 - g]
    # start with the static stretch of the accelerating state, so no string wave rings
    x0 = 2 * m1 * m2 * g / (m1 + m2) / k
    run = solve_ivp(rhs, (0.0, 0.5), [x0, 0.0, 0.0, 0.0], rtol=1e-10, atol=1e-12,
                    method="LSODA")
    # by hand: a = 2/4 * 9.81 = 4.905 m/s^2, so x1(0.5) = a t^2 / 2 = 0.613 m
    a_numeric = 2 * run.y[0][-1] / 0.5**2
    assert a_numeric == pytest.approx(4.905, rel=1e-3)
    assert systems.atwood_acceleration(m1, m2, g) == pytest.approx(a_numeric, rel=1e-3)


def test_the_total_external_force_is_the_sum_of_the_forces_on_each_block():
    """Atwood machine, m1 = 6 kg, m2 = 2 kg (up positive): the free bodies give the string
    force T = 2 m1 m2 g/(m1 + m2) = 29.43 N, so the external forces on the two blocks (two
    strands of T at the pulley, the weights) add up to 2T - M g = 58.86 - 78.48 = -19.62 N;
    the centre of mass accelerates with a_C = (-6 * 4.905 + 2 * 4.905)/8 = -2.4525 m/s^2."""
    assert systems.total_external_force(8.0, -2.4525) == pytest.approx(-19.62, rel=1e-12)
    # and it undoes centre_of_mass_acceleration, component by component
    a_c = systems.centre_of_mass_acceleration([3.0, -4.0], 2.0)
    assert np.allclose(systems.total_external_force(2.0, a_c), [3.0, -4.0])


# -- Section 2.2.2: a hanging block pulls a block across a rough table -------------------

def test_block_pulled_over_a_table_edge_keys_match_the_hand_calculation():
    keys = _keys("block-pulled-over-a-table-edge", m1=4.0, m2=3.0, mu=0.25, s=1.0, g=9.81)
    # 1/2 (4 + 3) v^2 = (3 - 0.25 * 4) * 9.81 * 1 = 19.62 J, v = sqrt(2 * 19.62 / 7) = 2.3676 m/s
    assert keys["v"] == pytest.approx(2.36763, rel=1e-5)
    # D = 0.25 * 4 * 9.81 * 1 = 9.81 J
    assert keys["D"] == pytest.approx(9.81, rel=1e-9)
    # a = v^2/(2 s) = 2.80286 m/s^2, T = 3 (9.81 - 2.80286) = 21.0214 N, W_T = T s = 21.0214 J
    assert keys["W_T"] == pytest.approx(21.0214, rel=1e-5)


# -- Section 2.2.2: a cart runs into a spring bumper ---------------------------------------

def test_cart_hits_spring_bumper_keys_match_the_hand_calculation():
    keys = _keys("cart-hits-spring-bumper", m1=2.0, m2=3.0, v0=2.0, k=1200)
    # v_C = 2 * 2 / 5 = 0.8 m/s
    assert keys["v_C"] == pytest.approx(0.8, rel=1e-9)
    # mu = 2 * 3 / 5 = 1.2 kg; x_max = 2 * sqrt(1.2 / 1200) = 0.0632456 m = 6.32456 cm
    assert keys["x_max"] == pytest.approx(6.32456, rel=1e-5)
    # V_max = 1/2 * 1.2 * 2^2 = 2.4 J
    assert keys["V_max"] == pytest.approx(2.4, rel=1e-9)


def test_the_largest_compression_matches_the_integrated_collision():
    m1, m2, k, v0 = 1.0, 4.0, 500.0, 3.0

    def rhs(t, y):
        force = k * max(y[0] - y[1], 0.0)
        return [y[2], y[3], -force / m1, force / m2]

    def closest(t, y):
        return y[2] - y[3]
    closest.terminal, closest.direction = True, -1
    run = solve_ivp(rhs, (0.0, 1.0), [0.0, 0.0, v0, 0.0], events=closest, rtol=1e-10,
                    atol=1e-12)
    x1, x2 = run.y_events[0][0][:2]
    # by hand: mu = 4/5 = 0.8 kg, x_max = 3 sqrt(0.8/500) = 0.12 m
    assert x1 - x2 == pytest.approx(0.12, rel=1e-6)
    assert systems.maximum_spring_compression_between_particles(m1, m2, k, v0) == \
        pytest.approx(x1 - x2, rel=1e-6)


# -- Section 2.2.3: two skaters on a rope ------------------------------------------------

def test_skaters_pulling_a_rope_keys_match_the_hand_calculation():
    keys = _keys("skaters-pulling-a-rope", m1=80, m2=60, L1=6.0, L2=2.0, omega1=0.5)
    # omega2 = 0.5 * (6/2)^2 = 4.5 rad/s
    assert keys["omega2"] == pytest.approx(4.5, rel=1e-9)
    # r1 = 60/140 * 2 = 0.857143 m, v1 = 0.857143 * 4.5 = 3.857143 m/s
    assert keys["v1"] == pytest.approx(3.857143, rel=1e-6)
    # mu = 80 * 60 / 140 = 34.2857 kg; T1 = 1/2 mu 6^2 0.5^2 = 154.2857 J,
    # T2 = 1/2 mu 2^2 4.5^2 = 1388.5714 J, W = 1234.2857 J
    assert keys["W"] == pytest.approx(1234.2857, rel=1e-6)


# -- Section 2.2.3: a puck tied through a hole to a hanging weight -----------------------

def test_string_through_a_table_hole_keys_match_the_hand_calculation():
    keys = _keys("string-through-a-table-hole", m1=0.5, m2=1.0, r0=0.3, v0=4.0, l=2.0,
                 g=9.81)
    # H = 0.5 * 0.3 * 4 = 0.6; r_s = (0.36 / (0.5 * 1 * 9.81))^(1/3) = 0.0733945^(1/3) = 0.41870 m
    assert keys["r_s"] == pytest.approx(0.41870, rel=1e-4)
    # a = 2 * 0.5 * 9.81 * 0.09 = 0.8829; r1 = (0.36 + sqrt(0.1296 + 4 * 0.8829 * 0.36 * 0.3))
    #   / (2 * 0.8829) = 1.074852 / 1.7658 = 0.608705 m
    assert keys["r_1"] == pytest.approx(0.608705, rel=1e-5)
    # v1 = 4 * 0.3 / 0.608705 = 1.971396 m/s; energy 4 + 2.943 = 0.971601 + 5.971396 = 6.943 J
    assert keys["v_1"] == pytest.approx(1.971396, rel=1e-5)


def _effective_energy(m1, m2, g, H):
    """Energy of puck and block at rest radially: H^2/(2 m1 r^2) + m2 g r."""
    return lambda r: H**2 / (2 * m1 * r**2) + m2 * g * r


def test_the_steady_radius_is_the_minimum_of_the_effective_energy():
    from scipy.optimize import minimize_scalar

    m1, m2, g, H = 0.8, 0.5, 9.81, 0.9
    found = minimize_scalar(_effective_energy(m1, m2, g, H), bounds=(0.05, 5.0),
                            method="bounded", options={"xatol": 1e-10}).x
    assert systems.steady_radius_through_hole(m1, m2, g, H) == pytest.approx(found, rel=1e-6)


def test_the_turning_radius_has_the_starting_radius_energy():
    from scipy.optimize import brentq

    m1, m2, g, H = 0.8, 0.5, 9.81, 0.9
    energy = _effective_energy(m1, m2, g, H)
    for r0 in (0.3, 1.5):            # inside and outside the steady radius (0.81/3.924)^(1/3) = 0.591 m
        r_s = systems.steady_radius_through_hole(m1, m2, g, H)
        bracket = (r_s, 20.0) if r0 < r_s else (1e-3, r_s)
        other = brentq(lambda r: energy(r) - energy(r0), *bracket, xtol=1e-14)
        assert systems.turning_radius_through_hole(m1, m2, g, H, r0) == \
            pytest.approx(other, rel=1e-9)


# -- Section 3.5.1: kinetic energy and angular momentum of an unsymmetric top ------------

def test_top_energy_and_momentum_keys_match_the_hand_calculation():
    # I1 = 8e-4 <= I2 + I3 = 9e-4: moments a real body can have about O
    keys = _keys("top-energy-and-momentum", I1=8e-4, I2=5e-4, I3=4e-4, theta=40, phi=90,
                 psi_dot=4.0, theta_dot=2.0, phi_dot=20.0)
    # sin 40° = 0.642788, cos 40° = 0.766044, phi = 90°:
    # omega = (4 * 0.642788, -2, 4 * 0.766044 + 20) = (2.571150, -2, 23.064178) rad/s
    # T = 1/2 (8e-4 * 6.610815 + 5e-4 * 4 + 4e-4 * 531.95630) = 1/2 * 0.2200712 = 0.1100356 J
    assert keys["T"] == pytest.approx(0.1100356, rel=1e-5)
    # H = (2.056920e-3, -1e-3, 9.225671e-3); e3 in the body frame = (0.642788, 0, 0.766044)
    # H . e3 = 1.322163e-3 + 7.067274e-3 = 8.389437e-3 kg m^2/s
    assert keys["H_v"] == pytest.approx(8.389437e-3, rel=1e-5)
    # |H| = sqrt(4.230921e-6 + 1e-6 + 8.511301e-5) = sqrt(9.034393e-5) = 9.504942e-3 kg m^2/s
    assert keys["H_abs"] == pytest.approx(9.504942e-3, rel=1e-5)


def test_the_body_components_of_the_vertical_are_the_rotations_third_row():
    from dynagrade.mechanics import gyro, rotations

    for psi, theta, phi in ((0.3, 0.7, 2.1), (-1.2, 1.4, -0.4)):
        rotation = rotations.euler_angle_rotation(psi, theta, phi)
        # the body components of e3 are R^T e3, the third row of R, for every psi
        assert np.allclose(gyro.body_components_of_vertical(theta, phi), rotation[2, :])


# -- Section 3.5.1: Euler's equations for a heavy unsymmetric top ------------------------

def test_top_angular_acceleration_keys_match_the_hand_calculation():
    keys = _keys("top-angular-acceleration", m=0.2, l=4.0, I1=1e-3, I2=6e-4, I3=4e-4,
                 theta=30, phi=90, psi_dot=4.0, theta_dot=2.0, phi_dot=20.0, g=9.81)
    # omega = (4 * 0.5, -2, 4 * 0.866025 + 20) = (2, -2, 23.464102) rad/s
    # m g l = 0.2 * 9.81 * 0.04 = 0.07848 N m; M = 0.07848 (0.5 * 0, -0.5 * 1, 0) = (0, -0.03924, 0)
    assert keys["M_O"] == pytest.approx(0.03924, rel=1e-9)
    # alpha1 = (0 + 2e-4 * (-2) * 23.464102) / 1e-3 = -9.385641
    # alpha2 = (-0.03924 + (-6e-4) * 23.464102 * 2) / 6e-4 = -112.32820
    # alpha3 = (0 + 4e-4 * 2 * (-2)) / 4e-4 = -4.0   (rad/s^2)
    assert keys["alpha"] == pytest.approx([-9.385641, -112.32820, -4.0], rel=1e-6)
    # P = m g l sin(theta) theta' = 0.07848 * 0.5 * 2 = 0.07848 W = M . omega = (-0.03924)(-2)
    assert keys["P"] == pytest.approx(0.07848, rel=1e-9)


def test_the_top_gravity_moment_is_the_weights_moment_seen_from_the_body():
    from dynagrade.mechanics import angular_momentum, gyro, rotations

    m, g, l = 0.3, 9.81, 0.05
    for psi, theta, phi in ((0.4, 0.6, 1.9), (2.0, 1.1, -0.7)):
        rotation = rotations.euler_angle_rotation(psi, theta, phi)
        r_oc = l * rotation[:, 2]                      # C on the body axis, in space axes
        moment_space = angular_momentum.torque(r_oc, [0.0, 0.0, -m * g])
        assert np.allclose(gyro.top_gravity_moment(m, g, l, theta, phi),
                           rotation.T @ moment_space)


def test_the_top_kinetic_energy_rate_is_the_power_of_the_weights_moment():
    from dynagrade.mechanics import gyro

    m, g, l, theta, phi = 0.3, 9.81, 0.05, 0.8, 2.3
    omega = gyro.body_angular_velocity_from_euler_rates(theta, phi, 3.0, -1.5, 40.0)
    power = gyro.top_gravity_moment(m, g, l, theta, phi) @ omega
    # by hand: 0.14715 * sin(0.8) * (-1.5) = 0.14715 * 0.717356 * (-1.5) = -0.158338 W
    assert power == pytest.approx(-0.158338, rel=1e-5)
    assert gyro.top_kinetic_energy_rate(m, g, l, theta, -1.5) == pytest.approx(power, rel=1e-12)


# -- Section 3.5.2: a top released without precession -------------------------------------

def test_released_top_nutation_keys_match_the_hand_calculation():
    keys = _keys("released-top-nutation", m=0.5, l=4.0, I1=1.5e-3, I3=5e-4, w3=120,
                 theta0=30, g=9.81)
    # m g l = 0.1962 N m, I3 w3 = 0.06; beta = 2 * 1.5e-3 * 0.1962 / 0.06^2 = 0.1635
    # u0 = 0.866025; u = (1 - sqrt(1 - 4 * 0.1635 * (0.866025 - 0.1635))) / (2 * 0.1635)
    #   = (1 - sqrt(0.540548)) / 0.327 = 0.264780 / 0.327 = 0.809725 -> theta_max = 35.931°
    assert keys["theta_max"] == pytest.approx(35.931, rel=1e-4)
    # psi' = 2 m g l / (I3 w3) = 2 * 0.1962 / 0.06 = 6.54 rad/s
    assert keys["psi_dot"] == pytest.approx(6.54, rel=1e-9)
    # dT = m g l (u0 - u) = 0.1962 * (0.866025 - 0.809725) = 0.011046 J
    assert keys["dT"] == pytest.approx(0.011046, rel=1e-4)


def _released_top_turning_point(m, g, l, I1, I3, w3, theta0):
    """Integrate the Lagrange equation of the symmetric top (theta; psi' from the
    conserved vertical angular momentum) from the release to the next theta' = 0."""
    def rhs(t, y):
        psi_dot = I3 * w3 * (np.cos(theta0) - np.cos(y[0])) / (I1 * np.sin(y[0]) ** 2)
        return [y[1], (I1 * psi_dot**2 * np.sin(y[0]) * np.cos(y[0])
                       - I3 * w3 * psi_dot * np.sin(y[0]) + m * g * l * np.sin(y[0])) / I1]

    def turns(t, y):
        return y[1]
    turns.terminal, turns.direction = True, -1
    run = solve_ivp(rhs, (0.0, 5.0), [theta0, 0.0], events=turns, method="DOP853",
                    rtol=1e-11, atol=1e-12)
    theta = run.y_events[0][0][0]
    return theta, I3 * w3 * (np.cos(theta0) - np.cos(theta)) / (I1 * np.sin(theta) ** 2)


def test_the_largest_tilt_and_its_precession_rate_match_the_integrated_top():
    from dynagrade.mechanics import gyro

    m, g, l, I1, I3, w3, theta0 = 0.3, 9.81, 0.05, 1e-3, 4e-4, 60.0, 0.5
    theta, psi_dot = _released_top_turning_point(m, g, l, I1, I3, w3, theta0)
    assert gyro.largest_tilt_of_released_top(m, g, l, I1, I3, w3, theta0) == \
        pytest.approx(theta, rel=1e-7)
    # 2 m g l / (I3 w3) = 2 * 0.14715 / 0.024 = 12.2625 rad/s
    assert psi_dot == pytest.approx(12.2625, rel=1e-6)
    assert gyro.precession_rate_at_largest_tilt(m, g, l, I3, w3) == pytest.approx(psi_dot,
                                                                                  rel=1e-6)
