"""The chapter 3 kinetics exercises of issue 31 (Sections 3.2.1-3.2.5) and the core
relations they added: every key at fixed parameters against numbers worked out by hand
(written beside each assertion), every new relation against a second route."""

import numpy as np
import pytest

from dynagrade.exercise import open_bank
from dynagrade.mechanics import rigid_kinetics

BANK = open_bank()


def _answers(exercise_id, **values):
    """The keys in the parts' units at the given parameters (declared units)."""
    return BANK.get(exercise_id).solve_in_part_units(values)


# -- core relations ------------------------------------------------------------------------


def test_the_axle_loads_of_a_braking_car_balance_moments_about_both_contact_points():
    # m = 1000 kg, g = 10, mu = 0.5, l_f = 1, l_r = 1.5, h = 0.5: the moments about the rear
    # contact point, N_f (l_f + l_r) = m g l_r + m (mu g) h = 15000 + 2500, give 7000 N;
    # about the front contact point N_r 2.5 = 10000 - 2500, so 3000 N
    front = rigid_kinetics.front_axle_load_when_braking(1000.0, 10.0, 0.5, 1.0, 1.5, 0.5)
    rear = rigid_kinetics.rear_axle_load_when_braking(1000.0, 10.0, 0.5, 1.0, 1.5, 0.5)
    assert front == pytest.approx(7000.0)
    assert rear == pytest.approx(3000.0)


def test_the_rear_axle_lifts_off_when_mu_h_reaches_l_f():
    assert rigid_kinetics.rear_axle_load_when_braking(1200.0, 9.81, 0.8, 1.0, 1.4, 1.25) == (
        pytest.approx(0.0, abs=1e-9))


# -- exercises -----------------------------------------------------------------------------


def test_braking_car_keys_match_the_hand_calculation():
    keys = _answers("braking-car-axle-loads", m=1500, l_f=1.1, l_r=1.75, h=0.69, mu=0.4,
                    g=9.81)
    # a = mu g = 0.4 * 9.81 = 3.924 m/s^2
    assert keys["a"] == pytest.approx(3.924, rel=1e-9)
    # N_f = 1500 * 9.81 * (1.75 + 0.4 * 0.69) / 2.85 = 14715 * 2.026 / 2.85 = 10460.6 N
    assert keys["N_f"] == pytest.approx(10460.6, rel=1e-5)
    # N_r = 14715 * (1.1 - 0.276) / 2.85 = 14715 * 0.824 / 2.85 = 4254.4 N
    assert keys["N_r"] == pytest.approx(4254.4, rel=1e-5)


def test_a_pulled_rolling_body_solves_both_momentum_balances():
    # unknowns a and f from m a - f = F and (I_C / R) a + R f = F e (e the lever arm), solved
    # as a linear system by numpy: m = 2, R = 0.2, I_C = 0.05, F = 10, e = 0.14 and -0.14
    for lever_arm in (0.14, -0.14):
        matrix = np.array([[2.0, -1.0], [0.05 / 0.2, 0.2]])
        a, f = np.linalg.solve(matrix, [10.0, 10.0 * lever_arm])
        assert rigid_kinetics.rolling_acceleration_under_horizontal_pull(
            10.0, 2.0, 0.2, 0.05, lever_arm) == pytest.approx(a)
        assert rigid_kinetics.friction_under_horizontal_pull(
            10.0, 2.0, 0.2, 0.05, lever_arm) == pytest.approx(f)


@pytest.mark.parametrize("r, k, a, f, direction", [
    # k^2/R^2 = 0.0225/0.04 = 0.5625: a = 10 (1 + 0.7) / (2 * 1.5625) = 5.44 m/s^2,
    # f = 10 (0.14 * 0.2 - 0.0225) / (0.04 + 0.0225) = 0.88 N forward
    (0.14, 0.15, 5.44, 0.88, "forward"),
    # k^2 = 0.0256: a = 10 (1.4) / (2 * 1.64) = 4.26829 m/s^2,
    # f = 10 (0.016 - 0.0256) / 0.0656 = -1.46341 N, backward
    (0.08, 0.16, 4.26829, 1.46341, "backward"),
])
def test_spool_keys_match_the_hand_calculation(r, k, a, f, direction):
    keys = _answers("spool-pulled-by-thread", m=2.0, R=0.2, r=r, k=k, F=10.0, g=9.81)
    assert keys["a"] == pytest.approx(a, rel=1e-5)
    assert keys["f"] == pytest.approx(f, rel=1e-5)
    assert keys["direction"] == direction
    # mu_min = |f| / (2 * 9.81): 0.88 / 19.62 = 0.044852, 1.46341 / 19.62 = 0.074588
    assert keys["mu_min"] == pytest.approx(f / 19.62, rel=1e-5)


def test_the_atwood_acceleration_follows_from_the_energy_of_the_drop():
    # work-energy: (m1 - m2) g h = (m1 + m2 + I/R^2) v^2 / 2 and v^2 = 2 a h;
    # m1 = 3, m2 = 1, I = 0.02, R = 0.1 (I/R^2 = 2), g = 10, h = 0.5: v^2 = 2*2*10*0.5/6
    v_squared = 2 * 2.0 * 10.0 * 0.5 / 6.0
    a = rigid_kinetics.atwood_acceleration_with_heavy_pulley(3.0, 1.0, 10.0, 0.1, 0.02)
    assert a == pytest.approx(v_squared / (2 * 0.5))
    # a rope holding a body at rest carries its weight
    assert rigid_kinetics.hanging_mass_rope_force(2.0, 9.81, 0.0) == pytest.approx(19.62)


def test_atwood_keys_match_the_hand_calculation():
    keys = _answers("atwood-massive-pulley", m1=5.0, m2=2.0, M=4.0, R=0.1, g=9.81)
    # a = 3 * 9.81 / (5 + 2 + 4/2) = 29.43 / 9 = 3.27 m/s^2
    assert keys["a"] == pytest.approx(3.27, rel=1e-9)
    # S1 = 5 (9.81 - 3.27) = 32.7 N, S2 = 2 (9.81 + 3.27) = 26.16 N
    assert keys["S1"] == pytest.approx(32.7, rel=1e-9)
    assert keys["S2"] == pytest.approx(26.16, rel=1e-9)


def test_a_spin_down_at_constant_deceleration_matches_its_integration():
    from scipy.integrate import solve_ivp
    # omega' = -alpha from omega0 = 30 rad/s, alpha = 4 rad/s^2: stops at t = 7.5 s after
    # turning 30^2 / 8 = 112.5 rad
    stop = solve_ivp(lambda t, y: (y[1], -4.0), (0.0, 20.0), (0.0, 30.0), rtol=1e-10,
                     atol=1e-10, events=lambda t, y: y[1])
    assert rigid_kinetics.spin_down_time(30.0, 4.0) == pytest.approx(stop.t_events[0][0])
    assert rigid_kinetics.spin_down_angle(30.0, 4.0) == pytest.approx(stop.y_events[0][0][0])
    # lever about its pivot: N * 0.25 = 100 * 1.0
    assert rigid_kinetics.brake_lever_shoe_force(100.0, 1.0, 0.25) == pytest.approx(400.0)


def test_flywheel_brake_keys_match_the_hand_calculation():
    keys = _answers("flywheel-lever-brake", m=50, R=0.4, omega0=600, P=100, b=1.0, c=0.25,
                    mu=0.4)
    # N = 100 * 1.0 / 0.25 = 400 N; alpha = 2 * 0.4 * 400 / (50 * 0.4) = 16 rad/s^2
    assert keys["N"] == pytest.approx(400.0)
    assert keys["alpha"] == pytest.approx(16.0)
    # omega0 = 600 * 2 pi / 60 = 62.8319 rad/s: t = 62.8319 / 16 = 3.92699 s
    assert keys["t"] == pytest.approx(3.92699, rel=1e-5)
    # phi = 62.8319^2 / 32 = 123.370 rad, n = 123.370 / (2 pi) = 19.635 revolutions
    assert keys["n"] == pytest.approx(19.635, rel=1e-4)


def test_skewed_disk_keys_match_the_hand_calculation():
    keys = _answers("skewed-disk-on-shaft", m_d=4.0, R=0.2, m_s=0.5, L=0.6, beta=20.0)
    # I_t = I_a - I_t = 4 * 0.04 / 4 = 0.04; cos^2 20 deg = 0.8830222:
    # I33 = 0.04 (1 + 0.8830222) = 0.0753209 kg m^2
    assert keys["I33"] == pytest.approx(0.0753209, rel=1e-6)
    # I13 = 0.04 sin 20 cos 20 = 0.04 * 0.3213938 = 0.0128558 kg m^2
    assert keys["I13"] == pytest.approx(0.0128558, rel=1e-5)
    # I11 = 0.04 + 0.04 * 0.1169778 + 0.5 * 0.36 / 12 = 0.0596791;
    # tan 2 gamma = 0.0257115 / (0.0753209 - 0.0596791) = 1.643769, gamma = 29.3427 deg
    assert keys["gamma"] == pytest.approx(29.3427, rel=1e-5)


def test_plate_with_hole_keys_match_the_hand_calculation():
    keys = _answers("plate-with-hole-inertia", a=0.8, b=0.5, rho=20.0, r=0.1, d=0.2)
    # m_p = 20 * 0.8 * 0.5 = 8 kg, m_h = 20 pi 0.01 = 0.628319 kg, m = 7.371681 kg
    # x_C = -0.628319 * 0.2 / 7.371681 = -0.0170468 m
    assert keys["x_C"] == pytest.approx(-0.0170468, rel=1e-5)
    # I22 = 8 * 0.64 / 12 - 0.628319 (0.01/4 + 0.04) = 0.426667 - 0.0267035 = 0.399963
    assert keys["I22"] == pytest.approx(0.399963, rel=1e-5)
    # I_O = 8 * 0.89 / 12 - 0.628319 (0.01/2 + 0.04) = 0.593333 - 0.0282743 = 0.565059
    assert keys["I_O"] == pytest.approx(0.565059, rel=1e-5)
    # about the corner A = (0.4, 0.25) directly: the plate 8 * 0.89 / 3 = 2.373333, minus the
    # hole 0.628319 (0.005 + 0.2^2 + 0.25^2) = 0.0675442: I_A = 2.305789 kg m^2
    assert keys["I_A"] == pytest.approx(2.305789, rel=1e-5)


def test_the_angular_momentum_vanishes_on_the_offset_line():
    # about a point at y_0 off the path, H = I omega + m v y_0 = 0.004 * 20 + 0.4 * 2 * y_0
    y_0 = rigid_kinetics.zero_angular_momentum_offset(0.004, 20.0, 0.4, 2.0)
    assert y_0 == pytest.approx(-0.1)
    assert 0.004 * 20.0 + 0.4 * 2.0 * y_0 == pytest.approx(0.0)


def test_spinning_puck_keys_match_the_hand_calculation():
    keys = _answers("spinning-puck-angular-momentum", m=0.4, R=0.1, v=2.0, omega=20.0,
                    y_B=-0.25)
    # H_C = 0.4 * 0.01 * 20 / 2 = 0.04 kg m^2/s
    assert keys["H_C"] == pytest.approx(0.04)
    # H_B = 0.04 + 0.4 * 2 * (-0.25) = 0.04 - 0.2 = -0.16 kg m^2/s (clockwise)
    assert keys["H_B"] == pytest.approx(-0.16)
    # y_0 = -0.01 * 20 / (2 * 2) = -0.05 m
    assert keys["y_0"] == pytest.approx(-0.05)


def test_the_moment_for_steady_rotation_is_the_rate_of_the_turning_angular_momentum():
    # H_O fixed in a body turning at omega about e3: finite difference of R(t) H_O at t = 0
    omega, h_o, dt = 5.0, np.array([0.3, -0.2, 1.0]), 1e-6
    turned = np.array([[np.cos(omega * dt), -np.sin(omega * dt), 0.0],
                       [np.sin(omega * dt), np.cos(omega * dt), 0.0], [0.0, 0.0, 1.0]]) @ h_o
    assert rigid_kinetics.moment_for_steady_rotation([0.0, 0.0, omega], h_o) == pytest.approx(
        (turned - h_o) / dt, rel=1e-5)


def test_eccentric_disk_keys_match_the_hand_calculation():
    keys = _answers("eccentric-disk-bearing-moment", m=4.0, R=0.1, e=0.02, h=0.3, Omega=600)
    # Omega = 600 * 2 pi / 60 = 62.83185 rad/s
    # H_axial = (4 * 0.01 / 2 + 4 * 0.02^2) * 62.83185 = 0.0216 * 62.83185 = 1.357168
    assert keys["H_axial"] == pytest.approx(1.357168, rel=1e-6)
    # H_perp = 4 * 0.02 * 0.3 * 62.83185 = 0.024 * 62.83185 = 1.507964
    assert keys["H_perp"] == pytest.approx(1.507964, rel=1e-6)
    # M_O = 1.507964 * 62.83185 = 94.7482 N m
    assert keys["M_O"] == pytest.approx(94.7482, rel=1e-5)


def _falling_rod(t, y, g=9.81, L=1.0):
    """Lagrange's equation of the rod with its foot on a frictionless floor."""
    s, c = np.sin(y[0]), np.cos(y[0])
    return (y[1], (g / L * s / 2 - s * c / 4 * y[1] ** 2) / (s**2 / 4 + 1 / 12))


def test_the_sliding_rod_angular_speed_matches_the_integrated_fall_and_the_foot_stays_down():
    from scipy.integrate import solve_ivp
    # from rest at 10 degrees until the rod leans at 60 degrees (L = 1, g = 9.81)
    fall = solve_ivp(_falling_rod, (0.0, 5.0), (np.radians(10), 0.0), rtol=1e-10, atol=1e-10,
                     events=lambda t, y: y[0] - np.radians(60), dense_output=True)
    assert rigid_kinetics.sliding_rod_angular_speed(
        np.radians(10), np.radians(60), 9.81, 1.0) == pytest.approx(fall.y_events[0][0][1],
                                                                    rel=1e-7)
    # the floor's push N = m (g + y_C''), y_C = cos(theta)/2, stays positive up to 85 deg
    # (the statement says the foot stays on the floor)
    times = np.linspace(0.0, fall.t_events[0][0], 50)
    theta, rate = fall.sol(times)
    accel = np.array([_falling_rod(0.0, (a, b))[1] for a, b in zip(theta, rate)])
    assert np.all(9.81 - 0.5 * (np.sin(theta) * accel + np.cos(theta) * rate**2) > 0)


def test_rod_on_frictionless_floor_keys_match_the_hand_calculation():
    keys = _answers("rod-sliding-on-frictionless-floor", L=1.2, theta0=20, theta1=60, g=9.81)
    # theta_dot^2 = 12 * 9.81 * (0.9396926 - 0.5) / (1.2 * (1 + 3 * 0.75))
    #             = 51.7601 / 3.9 = 13.27182, theta_dot = 3.643050 rad/s
    assert keys["omega"] == pytest.approx(3.64305, rel=1e-5)
    # v_C = 0.6 * 0.8660254 * 3.64305 = 1.892994 m/s; v_A = 0.6 * 0.5 * 3.64305 = 1.092915
    assert keys["v_C"] == pytest.approx(1.892994, rel=1e-5)
    assert keys["v_A"] == pytest.approx(1.092915, rel=1e-5)
    # v_land = sqrt(0.75 * 9.81 * 1.2 * 0.9396926) = sqrt(8.829 * 0.9396926) = sqrt(8.29655)
    #        = 2.880373 m/s
    assert keys["v_land"] == pytest.approx(2.880373, rel=1e-5)


def test_the_drum_speed_after_a_drop_matches_the_integrated_spin_up():
    from scipy.integrate import solve_ivp
    # (m r^2 + J) phi'' = m g r - M_f with m = 2, r = 0.1, J = 0.08, M_f = 0.3, g = 9.81,
    # until the string has paid out h = 0.8 m (phi = 8 rad)
    spin = solve_ivp(lambda t, y: (y[1], (2 * 9.81 * 0.1 - 0.3) / (2 * 0.01 + 0.08)),
                     (0.0, 10.0), (0.0, 0.0), rtol=1e-10, atol=1e-10,
                     events=lambda t, y: y[0] - 8.0)
    assert rigid_kinetics.drum_angular_speed_after_drop(2.0, 9.81, 0.8, 0.1, 0.08, 0.3) == (
        pytest.approx(spin.y_events[0][0][1], rel=1e-8))


def test_flywheel_spun_by_a_weight_keys_match_the_hand_calculation():
    keys = _answers("flywheel-spun-by-falling-weight", J=0.2, r=0.05, m=4.0, h=1.0, M_f=0.5,
                    g=9.81)
    # work: 4 * 9.81 * 1 - 0.5 * 1 / 0.05 = 39.24 - 10 = 29.24 J into 1/2 (0.01 + 0.2) w^2:
    # w^2 = 58.48 / 0.21 = 278.4762, w = 16.68761 rad/s
    assert keys["omega1"] == pytest.approx(16.68761, rel=1e-6)
    assert keys["W_f"] == pytest.approx(10.0)
    # coasting: 0.2 * 278.4762 / 2 = 27.84762 J = 0.5 * phi2, phi2 = 55.69524 rad,
    # n2 = 55.69524 / (2 pi) = 8.86417 revolutions
    assert keys["n2"] == pytest.approx(8.86417, rel=1e-5)
