"""The bank's exercises of Sections 3.3 and 3.4 (rigid impact, rotations, rotating frames,
Euler's equations) against variants worked by hand, and the core relations they added
against a second route."""

from __future__ import annotations

import numpy as np
import pytest

from dynagrade.exercise import open_bank
from dynagrade.exercise.scoring import grade_variant
from deferred import deferred
from dynagrade.mechanics import rigid_impact

solve_ivp = deferred("scipy.integrate", "solve_ivp")

BANK = open_bank()


def _answers(exercise_id, values):
    exercise = BANK.get(exercise_id)
    return exercise, exercise.variant(0, values)


# -- core relations -----------------------------------------------------------------------


def test_the_edge_impact_agrees_with_the_impulse_balances_solved_as_a_linear_system():
    # box m = 3 kg, b = 0.5 m, h = 0.8 m moving at v_C = (2, -0.5) m/s; E at the front bottom
    m, b, h = 3.0, 0.5, 0.8
    v_c = np.array([2.0, -0.5])
    r = np.array([-b / 2, h / 2])                     # from E to C
    i_c = m * (b**2 + h**2) / 12
    # unknowns omega, Fx, Fy: m (v_C' - v_C) = F, I_C omega = (r_CE x F)_z, v_C' = omega e3 x r
    system = np.array([[-m * r[1], -1.0, 0.0],
                       [m * r[0], 0.0, -1.0],
                       [i_c, -r[1], r[0]]])           # r_CE = -r: (r_CE x F)_z = -r0 Fy + r1 Fx
    rhs = np.array([m * v_c[0], m * v_c[1], 0.0])
    omega, fx, fy = np.linalg.solve(system, rhs)
    i_e = i_c + m * (r @ r)
    assert rigid_impact.angular_velocity_after_edge_impact(m, v_c, r, i_e) == pytest.approx(omega)
    assert rigid_impact.impulse_at_edge(m, v_c, omega, r) == pytest.approx([fx, fy])


@pytest.mark.parametrize("factor, tips", [(1.01, True), (0.99, False)])
def test_a_body_turning_about_its_edge_tips_over_just_above_the_least_angular_speed(factor, tips):
    # box b = 0.4 m, h = 0.6 m about its edge: I_E = m (b^2 + h^2)/3, C rises by
    # sqrt(b^2 + h^2)/2 - h/2 = 0.0606 m; integrate I_E phi'' = m g rho sin(phi - phi0),
    # phi the turn from rest position, C above E when phi = atan(b/h)
    m, b, h, g = 2.0, 0.4, 0.6, 9.81
    rho, i_e = np.hypot(b, h) / 2, m * (b**2 + h**2) / 3
    top = np.arctan2(b, h)
    omega = factor * rigid_impact.angular_speed_to_tip_over(m, g, rho - h / 2, i_e)

    def turn(t, y):
        return (y[1], -m * g * rho * np.sin(top - y[0]) / i_e)

    def over(t, y):
        return y[0] - top
    over.terminal = True

    def back(t, y):
        return y[1]
    back.terminal = True
    run = solve_ivp(turn, (0.0, 5.0), (0.0, omega), events=(over, back), rtol=1e-9, atol=1e-12)
    assert (run.t_events[0].size == 1) is tips


# -- 3.3: rod on ice struck by a puck -------------------------------------------------------


# M = 2 kg, L = 1.2 m, m = 0.5 kg, v = 6 m/s, d = 0.4 m, e = 0.5
# I_C = 2 * 1.44 / 12 = 0.24 kg m^2; d^2/I_C = 0.16/0.24 = 0.666667 1/kg
# F = 1.5 * 6 / (2 + 0.5 + 0.666667) = 9 / 3.166667 = 2.842105 N s
# v_C = F/M = 1.421053 m/s; omega = F d / I_C = 2.842105 * 0.4 / 0.24 = 4.736842 rad/s
# v' = 6 - 2.842105/0.5 = 0.315789 m/s; dT = 0.5 * 0.75 * 36 / 3.166667 = 4.263158 J
ROD = {"M": 2.0, "L": 1.2, "m": 0.5, "v": 6.0, "d": 0.4, "e": 0.5}


def test_the_rod_on_ice_matches_the_hand_calculation():
    _, variant = _answers("rod-on-ice-struck-by-puck", ROD)
    assert variant.answers["v_C"] == pytest.approx(1.421053, rel=1e-6)
    assert variant.answers["omega"] == pytest.approx(4.736842, rel=1e-6)
    assert variant.answers["v_after"] == pytest.approx(0.315789, rel=1e-5)
    assert variant.answers["dT"] == pytest.approx(4.263158, rel=1e-6)


def test_the_rod_treated_as_a_particle_is_named():
    # particle: F = 9 / (2 + 0.5) = 3.6 N s, v_C = 1.8 m/s
    exercise, variant = _answers("rod-on-ice-struck-by-puck", ROD)
    (result,) = [r for r in grade_variant(exercise, variant, {"v_C": "1.8"}).parts
                 if r.name == "v_C"]
    assert not result.correct and result.misconception == "rod treated as a particle"


# -- 3.3: crate tipping at a kerb -------------------------------------------------------------


# m = 10 kg, b = 0.4 m, h = 0.6 m, v = 2 m/s: I_E = 10 * 0.52 / 3 = 1.733333 kg m^2
# omega = m v h/2 / I_E = 6 / 1.733333 = 3.461538 rad/s
# v_C' = omega (h/2, b/2) = (1.038462, 0.692308); F = 10 (-0.961538, 0.692308),
# |F| = sqrt(9.615385^2 + 6.923077^2) = 11.848401 N s
# rise = sqrt(0.13)/2 - 0.3 = 0.060555 m; omega_tip = sqrt(2*10*9.81*0.060555/1.733333)
# = 2.618093 rad/s; v_min = omega_tip * I_E / (m h/2) = 2.618093 * 1.733333 / 3 = 1.512672
CRATE = {"m": 10.0, "b": 0.4, "h": 0.6, "v": 2.0}


def test_the_crate_matches_the_hand_calculation():
    _, variant = _answers("crate-tipping-at-kerb", CRATE)
    assert variant.answers["omega"] == pytest.approx(3.461538, rel=1e-6)
    assert variant.answers["J"] == pytest.approx(11.848401, rel=1e-6)
    assert variant.answers["v_min"] == pytest.approx(1.512672, rel=1e-5)
    assert variant.answers["tips"] == "yes"


def test_a_slower_crate_does_not_tip_over():
    # v = 1.3 m/s < v_min = 1.5127 m/s (v_min does not depend on v)
    _, variant = _answers("crate-tipping-at-kerb", {**CRATE, "v": 1.3})
    assert variant.answers["tips"] == "no"


# -- 3.4.1: camera on a gimbal ----------------------------------------------------------------


def test_yaw_pitch_roll_about_the_body_axes_is_scipys_intrinsic_zyx_rotation():
    from scipy.spatial.transform import Rotation

    from dynagrade.mechanics import rotations
    angles = np.radians([70.0, -25.0, 40.0])
    expected = Rotation.from_euler("ZYX", angles).as_matrix()   # upper case: intrinsic
    assert rotations.yaw_pitch_roll_rotation(*angles) == pytest.approx(expected, abs=1e-12)


def test_a_vector_along_the_diagonal_of_a_vertical_square_is_45_degrees_above_horizontal():
    from dynagrade.mechanics import rotations
    assert np.degrees(rotations.angle_above_horizontal([1.0, 1.0, np.sqrt(2)])) == \
        pytest.approx(45.0)
    assert np.degrees(rotations.angle_above_horizontal([0.0, 3.0, -3.0])) == pytest.approx(-45.0)


# psi = 90, theta = 30, phi = 45 deg, g = 9.81 m/s^2
# b1 = (cos 90 cos 30, sin 90 cos 30, -sin 30) = (0, 0.866025, -0.5)
# R^T g e3 = 9.81 (-sin 30, cos 30 sin 45, cos 30 cos 45) = (-4.905, 6.007374, 6.007374), 0.6123724 * 9.81 = 6.0073736
# tilt = arcsin(cos 30 sin 45) = arcsin(0.612372) = 37.7612 deg
GIMBAL = {"psi": 90.0, "theta": 30.0, "phi": 45.0}


def test_the_camera_gimbal_matches_the_hand_calculation():
    _, variant = _answers("camera-gimbal-yaw-pitch-roll", GIMBAL)
    assert variant.answers["n"] == pytest.approx((0.0, 0.866025, -0.5), abs=1e-6)
    assert variant.answers["f"] == pytest.approx((-4.905, 6.007374, 6.007374), abs=1e-5)
    assert variant.answers["tilt"] == pytest.approx(37.7612, abs=1e-4)


def test_the_camera_turned_about_the_fixed_axes_is_named():
    # R1(45) R2(30) R3(90) e1 = R1(45) R2(30) e2 = R1(45) e2 = (0, 0.707107, 0.707107)
    exercise, variant = _answers("camera-gimbal-yaw-pitch-roll", GIMBAL)
    (result,) = [r for r in grade_variant(exercise, variant, {"n": "[0, 0.7071, 0.7071]"}).parts
                 if r.name == "n"]
    assert not result.correct and result.misconception == "turns about the fixed axes"


# -- 3.4.1: inertia tensor of a turned plate --------------------------------------------------


def test_the_angle_between_two_vectors_in_a_plane_is_the_difference_of_their_directions():
    from dynagrade.mechanics import rotations
    u = [np.cos(0.3), np.sin(0.3), 0.0]
    w = [2 * np.cos(1.9), 2 * np.sin(1.9), 0.0]
    assert rotations.angle_between(u, w) == pytest.approx(1.6)
    assert rotations.angle_between([1.0, 0.0, 0.0], [-3.0, 0.0, 0.0]) == pytest.approx(np.pi)


# m = 1.2 kg, a = 1.0 m, b = 0.4 m, alpha = 60 deg, omega = 5 rad/s
# A = 1.2 * 0.16 / 12 = 0.016, B = 1.2 * 1 / 12 = 0.1 kg m^2
# I11 = 0.016 * 0.25 + 0.1 * 0.75 = 0.079; I12 = (0.016 - 0.1) * sin 60 cos 60 = -0.0363731
# |H| = 5 sqrt(0.079^2 + 0.0363731^2) = 5 sqrt(0.007564) = 0.434857 kg m^2/s
# delta = atan(0.0363731 / 0.079) = atan(0.460419) = 24.723 deg
PLATE = {"m": 1.2, "a": 1.0, "b": 0.4, "alpha": 60.0, "omega": 5.0}


def test_the_turned_plate_matches_the_hand_calculation():
    _, variant = _answers("turned-plate-inertia-tensor", PLATE)
    assert variant.answers["I11"] == pytest.approx(0.079, rel=1e-9)
    assert variant.answers["I12"] == pytest.approx(-0.0363731, rel=1e-5)
    assert variant.answers["H"] == pytest.approx(0.434857, rel=1e-5)
    assert variant.answers["delta"] == pytest.approx(24.723, abs=0.01)


def test_the_frame_turned_instead_of_the_plate_is_named():
    # R^T I R flips the sign of I12: +0.0363731
    exercise, variant = _answers("turned-plate-inertia-tensor", PLATE)
    (result,) = [r for r in grade_variant(exercise, variant, {"I12": "0.0363731"}).parts
                 if r.name == "I12"]
    assert not result.correct and result.misconception == "passive instead of active"


# -- 3.4.2: rail car on a turning platform ----------------------------------------------------


# m = 50 kg, r = 2 m, Omega = 1 rad/s, u = -0.5 m/s (against the turn)
# v = |Omega r + u| = |2 - 0.5| = 1.5 m/s; Coriolis -2 Omega u e_r = +1.0 e_r: 1 m/s^2 outward
# F = m (Omega r + u)^2 / r = 50 * 2.25 / 2 = 56.25 N
# Coriolis left out: m (Omega^2 r + u^2 / r) = 50 * (2 + 0.125) = 106.25 N
CAR = {"m": 50.0, "r": 2.0, "Omega": 1.0, "u": -0.5}


def test_the_car_on_the_platform_matches_the_hand_calculation():
    _, variant = _answers("car-on-turntable-track", CAR)
    assert variant.answers["v"] == pytest.approx(1.5)
    assert variant.answers["a_C"] == pytest.approx(1.0)
    assert variant.answers["coriolis_points"] == "outward"
    assert variant.answers["F"] == pytest.approx(56.25)


def test_a_car_running_with_the_platform_has_its_coriolis_term_inward():
    # u = +0.5: -2 Omega u e_r = -1.0 e_r; F = 50 * 2.5^2 / 2 = 156.25 N
    _, variant = _answers("car-on-turntable-track", {**CAR, "u": 0.5})
    assert variant.answers["coriolis_points"] == "inward"
    assert variant.answers["F"] == pytest.approx(156.25)


def test_the_coriolis_term_left_out_is_named():
    exercise, variant = _answers("car-on-turntable-track", CAR)
    (result,) = [r for r in grade_variant(exercise, variant, {"F": "106.25"}).parts
                 if r.name == "F"]
    assert not result.correct and result.misconception == "Coriolis term left out"


# -- 3.4.3: spring-held mass in a turning slot --------------------------------------------------


def test_the_slot_mass_rests_at_r_e_and_swings_about_it_with_omega_rel():
    # integrate m r'' = -k (r - l0) + m Omega^2 r with m = 0.8, k = 60, l0 = 0.25, Omega = 5
    from dynagrade.mechanics import frames
    m, k, l0, omega = 0.8, 60.0, 0.25, 5.0
    r_e = frames.spring_slot_equilibrium_radius(k, m, l0, omega)
    w = frames.spring_slot_relative_frequency(k, m, omega)

    def radial(t, y):
        return (y[1], -k / m * (y[0] - l0) + omega**2 * y[0])
    at_rest = solve_ivp(radial, (0.0, 1.0), (r_e, 0.0), rtol=1e-10, atol=1e-12)
    assert at_rest.y[0, -1] == pytest.approx(r_e, rel=1e-8)

    def turning_back(t, y):   # the radial speed changes sign from + to -: once per period
        return y[1]
    turning_back.direction = -1
    swing = solve_ivp(radial, (0.0, 3.0), (r_e, 0.01), events=turning_back, rtol=1e-10,
                      atol=1e-12)
    assert np.diff(swing.t_events[0])[0] == pytest.approx(2 * np.pi / w, rel=1e-6)


# m = 0.5 kg, k = 50 N/m, l0 = 0.2 m, Omega = 6 rad/s: m Omega^2 = 18 N/m
# r_e = 50 * 0.2 / (50 - 18) = 0.3125 m; omega_rel = sqrt(100 - 36) = 8 rad/s
# amplitude 0.3125 - 0.2 = 0.1125 m, fastest r' = 0.1125 * 8 = 0.9 m/s
# N_max = 2 m Omega r'_max = 2 * 0.5 * 6 * 0.9 = 5.4 N
SLOT = {"m": 0.5, "k": 50.0, "l0": 0.2, "Omega": 6.0}


def test_the_slot_mass_matches_the_hand_calculation():
    _, variant = _answers("spring-mass-in-turning-slot", SLOT)
    assert variant.answers["r_e"] == pytest.approx(0.3125)
    assert variant.answers["omega_rel"] == pytest.approx(8.0)
    assert variant.answers["N_max"] == pytest.approx(5.4)


def test_the_rotation_ignored_frequency_is_named():
    # sqrt(k/m) = sqrt(100) = 10 rad/s
    exercise, variant = _answers("spring-mass-in-turning-slot", SLOT)
    (result,) = [r for r in grade_variant(exercise, variant, {"omega_rel": "10"}).parts
                 if r.name == "omega_rel"]
    assert not result.correct and result.misconception == "rotation ignored"


# -- 3.4.4: rotor mounted askew -----------------------------------------------------------------


def test_a_bearing_pair_makes_its_couple_with_forces_of_moment_over_span():
    from dynagrade.mechanics import euler_equations
    # 30 N m over 0.6 m: two opposite forces of 50 N
    assert euler_equations.bearing_force_of_couple(30.0, 0.6) == pytest.approx(50.0)


# m = 10 kg, R = 0.1 m, h = 0.05 m, beta = 10 deg, omega = 100 rad/s, l = 0.5 m
# I1 = 10 (0.03 + 0.0025)/12 = 0.0270833, I3 = 10 * 0.01 / 2 = 0.05 kg m^2
# |M| = 100^2 (0.05 - 0.0270833) sin 10 cos 10 = 229.1667 * 0.1710101 = 39.1898 N m
# F = 39.1898 / 0.5 = 78.3796 N
# H from b3: atan(0.541667 tan 10) = atan(0.0955104) = 5.4558 deg < beta: same side
# delta = 10 - 5.4558 = 4.5442 deg
ROTOR = {"m": 10.0, "R": 0.1, "h": 0.05, "beta": 10.0, "omega": 100.0, "l": 0.5}


def test_the_askew_rotor_matches_the_hand_calculation():
    _, variant = _answers("tilted-rotor-bearing-forces", ROTOR)
    assert variant.answers["delta"] == pytest.approx(4.5442, abs=2e-4)
    assert variant.answers["side"] == "same"
    assert variant.answers["M"] == pytest.approx(39.1898, rel=1e-5)
    assert variant.answers["F"] == pytest.approx(78.3796, rel=1e-5)


def test_a_long_rotor_has_its_angular_momentum_beyond_the_shaft():
    # h = 0.3 m: I1 = 10 (0.03 + 0.09)/12 = 0.1 > I3 = 0.05, H tilts atan(2 tan 10) = 19.43
    # deg from b3, beyond the shaft at 10 deg: delta = 9.43 deg
    # |M| = 10^4 * 0.05 * 0.1710101 = 85.505 N m; bearings l = 0.6 m apart: F = 142.51 N
    _, variant = _answers("tilted-rotor-bearing-forces", {**ROTOR, "h": 0.3, "l": 0.6})
    assert variant.answers["side"] == "opposite"
    assert variant.answers["delta"] == pytest.approx(9.43, abs=0.01)
    assert variant.answers["M"] == pytest.approx(85.505, rel=1e-4)
    assert variant.answers["F"] == pytest.approx(142.51, rel=1e-4)


def test_the_angular_speed_rate_is_the_component_of_the_acceleration_along_omega():
    # |omega(t)| differentiated numerically: omega(t) = (3, 4, 0) + t (1, -2, 5)
    from dynagrade.mechanics import euler_equations
    w, wd, dt = np.array([3.0, 4.0, 0.0]), np.array([1.0, -2.0, 5.0]), 1e-6
    numeric = (np.linalg.norm(w + dt * wd) - np.linalg.norm(w - dt * wd)) / (2 * dt)
    assert euler_equations.angular_speed_rate(w, wd) == pytest.approx(numeric, rel=1e-6)
    assert euler_equations.angular_speed_rate(w, wd) == pytest.approx((3 - 8) / 5)


# m = 1.2 kg, a = 0.1, b = 0.3, c = 0.5 m; omega = (2, -3, 4) rad/s
# I1 = 0.1 (0.09 + 0.25) = 0.034, I2 = 0.1 (0.01 + 0.25) = 0.026, I3 = 0.1 (0.01 + 0.09) = 0.01
# w1' = 0.016 * (-12) / 0.034 = -5.647059; w2' = -0.024 * 8 / 0.026 = -7.384615;
# w3' = 0.008 * (-6) / 0.01 = -4.8 rad/s^2
# T = 0.5 (0.034 * 4 + 0.026 * 9 + 0.01 * 16) = 0.265 J
# omega . omega' = -11.2941176 + 22.1538462 - 19.2 = -8.3402714; |omega| = sqrt(29) = 5.3851648
# d|omega|/dt = -8.3402714 / 5.3851648 = -1.548750 rad/s^2
BOX = {"m": 1.2, "a": 0.1, "b": 0.3, "c": 0.5, "w1": 2.0, "w2": -3.0, "w3": 4.0}


def test_the_tossed_box_matches_the_hand_calculation():
    _, variant = _answers("box-tossed-with-skew-spin", BOX)
    assert variant.answers["omega_dot"] == pytest.approx((-5.647059, -7.384615, -4.8), abs=1e-6)
    assert variant.answers["T"] == pytest.approx(0.265)
    assert variant.answers["speed_rate"] == pytest.approx(-1.548750, rel=1e-6)


def test_no_angular_acceleration_without_a_moment_is_named():
    exercise, variant = _answers("box-tossed-with-skew-spin", BOX)
    (result,) = [r for r in grade_variant(exercise, variant, {"omega_dot": "[0, 0, 0]"}).parts
                 if r.name == "omega_dot"]
    assert not result.correct
    assert result.misconception == "no moment, so no angular acceleration"


# -- 3.4.2: cyclist seen from a carousel ------------------------------------------------------


def test_the_relative_velocity_undoes_the_velocity_transfer():
    from dynagrade.mechanics import frames
    v, v_o, omega, r = [1.0, -2.0, 0.5], [0.3, 0.0, -0.1], [0.2, -0.4, 1.1], [2.0, 1.0, -1.0]
    v_rel = frames.relative_velocity(v, v_o, omega, r)
    assert frames.absolute_velocity(v_o, omega, r, v_rel) == pytest.approx(v)
    # by hand: Omega x r = (-0.4*-1 - 1.1*1, 1.1*2 - 0.2*-1, 0.2*1 - -0.4*2) = (-0.7, 2.4, 1.0)
    assert v_rel == pytest.approx([1.0 - 0.3 + 0.7, -2.0 - 2.4, 0.5 + 0.1 - 1.0])


# Omega = 0.5 rad/s, Omega_dot = 0.1 rad/s^2, d = 8 m, u = 6 m/s
# v_rel = (0, u - Omega d) = (0, 6 - 4) = (0, 2) m/s
# a_rel = (2 Omega u - Omega^2 d, -Omega_dot d) = (6 - 2, -0.8) = (4, -0.8) m/s^2
# rho = |v_rel|^2 / |a_rel,r| = 4 / 4 = 1 m
CYCLIST = {"Omega": 0.5, "Omega_dot": 0.1, "d": 8.0, "u": 6.0}


def test_the_cyclist_seen_from_the_carousel_matches_the_hand_calculation():
    _, variant = _answers("cyclist-seen-from-carousel", CYCLIST)
    assert variant.answers["v_rel"] == pytest.approx((0.0, 2.0), abs=1e-12)
    assert variant.answers["a_rel"] == pytest.approx((4.0, -0.8), abs=1e-12)
    assert variant.answers["rho"] == pytest.approx(1.0)


def test_the_coriolis_term_left_out_of_the_seen_acceleration_is_named():
    # only the centrifugal and Euler terms: (Omega^2 d, -Omega_dot d) = (2, -0.8)
    exercise, variant = _answers("cyclist-seen-from-carousel", CYCLIST)
    (result,) = [r for r in grade_variant(exercise, variant, {"a_rel": "[2, -0.8]"}).parts
                 if r.name == "a_rel"]
    assert not result.correct and result.misconception == "Coriolis term left out"


# -- the constraint helper --------------------------------------------------------------------


@pytest.mark.parametrize("values, apart", [
    ((1.0, 2.0, 3.0), True),
    ((1.0, 1.04, 3.0), False),         # 1 and 1.04 differ by 3.8 % of 1.04
    ((1.0, -1.1, 3.0), True),          # magnitudes: 1 and 1.1 differ by 9.1 %
    ((2.0, -2.02), False),
])
def test_numbers_apart_holds_when_every_two_magnitudes_differ_by_over_five_percent(values, apart):
    from dynagrade.exercise.apart import numbers_apart
    assert numbers_apart(values) is apart
