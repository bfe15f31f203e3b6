"""Tests that pin what mutation testing of the mechanics core showed unpinned (issue 29):
mutants that survived because a function had no test, or because its tests passed an
offset (an initial position, a reference point's acceleration) only ever as zero, or
never asserted a convention. Each expected value is worked out by hand from the notes'
relation (shown beside it) or by a second route, never printed by the code under test.

`bench/mutation.py` re-runs these mutants; its survivors list names what is left."""
import math

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

from dynagrade.mechanics import frames, kinematics, multi_dof, rigid_kinematics, systems, vibrations
from dynagrade.mechanics._common import as_vectors, spatial_cross, spatial_vector
from deferred import deferred

sp = deferred("sympy")
lagrange = deferred("dynagrade.mechanics.lagrange")

SETTINGS = settings(max_examples=40, deadline=None)


# --- vibrations.natural_frequency_from_damped (Section 4.3.2): had no test at all ----------

def test_natural_frequency_from_damped_at_zeta_0_3_by_hand():
    # omega_n = omega_d / sqrt(1 - 0.09) = 10 / 0.9539392 = 10.482848 rad/s
    assert vibrations.natural_frequency_from_damped(10.0, 0.3) == pytest.approx(10.482848, rel=1e-6)


def test_without_damping_the_natural_frequency_is_the_damped_one():
    assert vibrations.natural_frequency_from_damped(7.5, 0.0) == 7.5
    # first order in zeta^2: omega_n = omega_d (1 + zeta^2/2 + ...); zeta = 1e-3 moves it by 5e-7
    assert vibrations.natural_frequency_from_damped(7.5, 1e-3) == pytest.approx(7.5 * (1 + 0.5e-6), rel=1e-9)


@SETTINGS
@given(omega_n=st.floats(0.1, 1000), zeta=st.floats(0.0, 0.95))
def test_natural_frequency_from_damped_undoes_damped_frequency(omega_n, zeta):
    omega_d = vibrations.damped_frequency(omega_n, zeta)
    assert vibrations.natural_frequency_from_damped(omega_d, zeta) == pytest.approx(omega_n, rel=1e-12)


@SETTINGS
@given(omega_n=st.floats(0.5, 50), zeta=st.floats(0.05, 0.9))
def test_natural_frequency_from_damped_matches_the_period_between_zero_crossings(omega_n, zeta):
    # A second route: the free response x(t) = exp(-zeta omega_n t) sin(omega_d t) / omega_d
    # (x0 = 0, v0 = 1) crosses zero again after half a damped period pi / omega_d.
    from scipy.optimize import brentq

    guess = math.pi / (omega_n * math.sqrt(1 - zeta**2))
    crossing = brentq(lambda t: vibrations.free_response(t, 0.0, 1.0, omega_n, zeta),
                      0.5 * guess, 1.5 * guess, xtol=1e-14)
    omega_d_measured = math.pi / crossing
    assert vibrations.natural_frequency_from_damped(omega_d_measured, zeta) == pytest.approx(omega_n, rel=1e-9)


# --- a non-zero initial position x0 (tests passed only the default 0) ----------------------

def test_linear_drag_position_starts_at_a_non_zero_x0_by_hand():
    # x(t) = x0 + v0 (1 - exp(-k t)) / k, eq. (1.14): x0 = 2, v0 = 3, k = 0.5, t = 2
    # = 2 + 6 (1 - e^-1) = 2 + 6 * 0.6321206 = 5.7927234
    assert kinematics.linear_drag_position(2.0, 3.0, 0.5, x0=2.0) == pytest.approx(5.7927234, rel=1e-7)
    assert kinematics.linear_drag_position(0.0, 3.0, 0.5, x0=2.0) == 2.0


def test_quadratic_drag_position_starts_at_a_non_zero_x0_by_hand():
    # x(t) = x0 + ln(1 + k v0 t) / k: x0 = 1.5, v0 = 2, k = 0.5, t = 1 -> 1.5 + 2 ln 2 = 2.8862944
    assert kinematics.quadratic_drag_position(1.0, 2.0, 0.5, x0=1.5) == pytest.approx(2.8862944, rel=1e-7)
    assert kinematics.quadratic_drag_position(0.0, 2.0, 0.5, x0=-1.5) == -1.5


@SETTINGS
@given(x0=st.floats(-10, 10), v0=st.floats(0.1, 10), k=st.floats(0.05, 5), t=st.floats(0, 10))
def test_moving_the_start_by_x0_moves_the_whole_drag_trajectory_by_x0(x0, v0, k, t):
    for position in (kinematics.linear_drag_position, kinematics.quadratic_drag_position):
        shifted = position(t, v0, k, x0=x0) - position(t, v0, k)
        assert shifted == pytest.approx(x0, abs=1e-9 * (1 + abs(x0) + v0 * t))


# --- a non-zero acceleration of the reference point (tests passed only zeros) ---------------

def test_acceleration_transfer_adds_the_reference_points_acceleration_by_hand():
    # a_B = a_A + alpha e3 x r_AB - omega^2 r_AB (Section 3.1.1) with a_A = (1, 2),
    # omega = 2, alpha = 3, r_AB = (1, 0): (1, 2) + (0, 3) + (-4, 0) = (-3, 5)
    a = rigid_kinematics.acceleration_of_point([1.0, 2.0], 2.0, 3.0, [1.0, 0.0])
    assert a == pytest.approx([-3.0, 5.0], abs=1e-12)


def test_absolute_acceleration_adds_the_frame_origins_acceleration_by_hand():
    # a = a_O' + Omega_dot x r + Omega x (Omega x r) + 2 Omega x v_rel + a_rel (Section 3.4.2)
    # a_O' = (1, -2, 0.5), Omega = 2 e3, Omega_dot = 3 e3, r = e1, v_rel = e1, a_rel = 0:
    # (1, -2, 0.5) + (0, 3, 0) + (-4, 0, 0) + (0, 4, 0) = (-3, 5, 0.5)
    a = frames.absolute_acceleration([1.0, -2.0, 0.5], [0, 0, 2.0], [0, 0, 3.0], [1.0, 0, 0],
                                     [1.0, 0, 0], [0.0, 0, 0])
    assert a == pytest.approx([-3.0, 5.0, 0.5], abs=1e-12)


def test_in_a_freely_falling_frame_gravity_gives_no_relative_acceleration():
    # An elevator in free fall, a_O' = g (Section 3.4.3): m a_rel = m g - m a_O' = 0.
    g = np.array([0.0, 0.0, -9.81])
    a_rel = frames.relative_acceleration(2.0 * g, 2.0, g, np.zeros(3), np.zeros(3),
                                         [0.3, 0.1, 1.0], np.zeros(3))
    assert a_rel == pytest.approx(np.zeros(3), abs=1e-12)


def test_in_an_accelerating_frame_a_free_particle_accelerates_backwards():
    a_rel = frames.relative_acceleration(np.zeros(3), 1.0, [2.0, -1.0, 0.0], np.zeros(3),
                                         np.zeros(3), np.zeros(3), np.zeros(3))
    assert a_rel == pytest.approx([-2.0, 1.0, 0.0], abs=1e-12)


# --- the mode-shape sign convention (multi_dof.mode_shapes) --------------------------------

def test_each_mode_shapes_first_non_zero_entry_is_positive():
    # Two unit masses wall-k-m-k-m (k = 1): K = [[2, -1], [-1, 1]]. omega^2 = (3 -+ sqrt 5)/2,
    # amplitude ratios x2/x1 = 2 - omega^2 = (1 + sqrt 5)/2 and (1 - sqrt 5)/2 (Section 4.4.2);
    # with Phi^T M Phi = I each column is [1, ratio] / sqrt(1 + ratio^2), first entry > 0.
    K, M = np.array([[2.0, -1.0], [-1.0, 1.0]]), np.eye(2)
    Phi = multi_dof.mode_shapes(K, M)
    for j, ratio in enumerate([(1 + math.sqrt(5)) / 2, (1 - math.sqrt(5)) / 2]):
        expected = np.array([1.0, ratio]) / math.sqrt(1 + ratio**2)
        assert Phi[:, j] == pytest.approx(expected, abs=1e-12)


def test_a_mode_with_a_zero_first_entry_takes_its_sign_from_the_next_entry():
    # Uncoupled masses: the second mode moves only the second mass, (0, 1/sqrt(2)) for m2 = 2.
    Phi = multi_dof.mode_shapes(np.diag([1.0, 4.0]), np.diag([1.0, 2.0]))
    assert Phi[:, 0] == pytest.approx([1.0, 0.0], abs=1e-12)
    assert Phi[:, 1] == pytest.approx([0.0, 1 / math.sqrt(2)], abs=1e-12)


def test_the_sign_convention_holds_whatever_sign_the_eigensolver_returns():
    rng = np.random.default_rng(29)
    for _ in range(20):
        A = rng.normal(size=(3, 3))
        K = A @ A.T + 3 * np.eye(3)
        M = np.diag(rng.uniform(0.5, 2.0, 3))
        Phi = multi_dof.mode_shapes(K, M)
        assert np.all(Phi[0, :] > 0)
        assert Phi.T @ M @ Phi == pytest.approx(np.eye(3), abs=1e-10)


# --- lagrange.state_symbols: two coordinates, two distinct accelerations -------------------

def test_two_coordinates_get_two_distinct_acceleration_symbols():
    t = sp.Symbol("t")
    x, phi = sp.Function("x")(t), sp.Function("phi")(t)
    pos, vel, acc = lagrange.state_symbols([x, phi])
    assert [s.name for s in pos] == ["x", "phi"]
    assert [s.name for s in vel] == ["x_dot", "phi_dot"]
    assert [s.name for s in acc] == ["x_ddot", "phi_ddot"]
    assert len(set(pos + vel + acc)) == 6


def test_a_two_degree_of_freedom_equation_keeps_both_accelerations_apart():
    # Cart (mass M, coordinate x) with a pendulum (m, l, angle phi), Section 4.1:
    # the x equation is (M + m) x'' + m l (phi'' cos phi - phi'^2 sin phi) = 0.
    t, M, m, l, g = sp.symbols("t M m l g", positive=True)
    x, phi = sp.Function("x")(t), sp.Function("phi")(t)
    xd, pd = sp.diff(x, t), sp.diff(phi, t)
    T = M * xd**2 / 2 + m * ((xd + l * pd * sp.cos(phi))**2 + (l * pd * sp.sin(phi))**2) / 2
    V = -m * g * l * sp.cos(phi)
    eq_x = lagrange.in_state_symbols(lagrange.equations_of_motion(T, V, [x, phi], t)[0], [x, phi], t)
    X, P, Pd, Xdd, Pdd = sp.symbols("x phi phi_dot x_ddot phi_ddot", real=True)
    hand = (M + m) * Xdd + m * l * (Pdd * sp.cos(P) - Pd**2 * sp.sin(P))
    assert sp.simplify(eq_x - hand) == 0


def test_plain_symbol_coordinates_are_named_after_themselves():
    pos, vel, acc = lagrange.state_symbols([sp.Symbol("q1"), sp.Symbol("q2")])
    assert [s.name for s in acc] == ["q1_ddot", "q2_ddot"]


# --- as_vectors: a flat sequence is split into n rows -------------------------------------

def test_a_flat_sequence_of_positions_is_read_as_one_row_per_particle():
    assert as_vectors([1, 2, 3, 4, 5, 6], 2).tolist() == [[1, 2, 3], [4, 5, 6]]
    assert as_vectors([1, 2, 3, 4, 5, 6], 3).tolist() == [[1, 2], [3, 4], [5, 6]]
    assert as_vectors([[1, 2], [3, 4]], 2).tolist() == [[1, 2], [3, 4]]


def test_the_centre_of_mass_of_flat_and_nested_positions_agree_by_hand():
    # masses 1 and 3 at (0, 0) and (4, 8): r_C = (0 + 12, 0 + 24) / 4 = (3, 6), Section 2.1
    assert systems.centre_of_mass([1.0, 3.0], [0.0, 0.0, 4.0, 8.0]) == pytest.approx([3.0, 6.0])
    assert systems.centre_of_mass([1.0, 3.0], [[0.0, 0.0], [4.0, 8.0]]) == pytest.approx([3.0, 6.0])


def test_a_stack_of_planar_vectors_is_taken_in_the_e1_e2_plane_row_by_row():
    # eqs. (1.52), (1.129): (x1, x2) is (x1, x2, 0); a stack of them, one per particle or time
    assert spatial_vector([[1.0, 2.0], [3.0, 4.0]]).tolist() == [[1.0, 2.0, 0.0], [3.0, 4.0, 0.0]]
    # e1 x e2 = e3 and e2 x e1 = -e3, row by row
    assert spatial_cross([[1.0, 0.0], [0.0, 1.0]], [[0.0, 1.0], [1.0, 0.0]]).tolist() == \
        [[0.0, 0.0, 1.0], [0.0, 0.0, -1.0]]


def test_a_damped_single_mass_has_the_textbook_steady_state_amplitude_and_lag():
    # One coordinate, Section 4.3.3: X = F0 / (k - m Omega^2 + i c Omega). k = 100, m = 1,
    # c = 4, Omega = 5: X = 10 / (75 + 20 i); |X| = 10 / sqrt(5625 + 400) = 0.128831,
    # lag = atan(20 / 75) = 0.260602 rad (the slow integration test is the second route).
    X = multi_dof.steady_state_amplitudes([[100.0]], [[1.0]], [[4.0]], [10.0], 5.0)
    assert abs(X[0]) == pytest.approx(10 / math.sqrt(6025), rel=1e-12)
    assert -np.angle(X[0]) == pytest.approx(math.atan2(20, 75), rel=1e-12)


# --- survivors of the full 160-mutant sample after issue 31 (bench/mutation.py --sample 160) ---

def test_the_hoops_oscillation_frequency_is_root_k_over_m_below_and_above_the_critical_spin():
    # R = 0.4 m, g = 9.81: g/R = 24.525 1/s^2. Below: Omega^2 = 0.36 * 24.525 = 8.829,
    # omega = sqrt(24.525 - 8.829) = sqrt(15.696) = 3.961818 rad/s. Above, Omega = 1.7
    # sqrt(g/R) = 8.418863: cos(theta*) = g/(R Omega^2) = 1/2.89 = 0.346021, omega = Omega
    # sin(theta*) = 8.418863 * 0.938225 = 7.898803 rad/s (Section 4.2)
    from dynagrade.mechanics.examples import hoop

    root = math.sqrt(9.81 / 0.4)
    assert hoop.hoop_oscillation_frequency(0.4, 0.6 * root, 9.81) == pytest.approx(3.961818, rel=1e-6)
    assert hoop.hoop_oscillation_frequency(0.4, 1.7 * root, 9.81) == pytest.approx(7.898803, rel=1e-6)


def test_a_wall_normal_of_any_length_is_made_a_unit_normal_first():
    # v = (3, -4) on the floor y = 0 given as n = (0, 2): only the direction counts,
    # v' = v - (1 + e)(v.e_n) e_n = (3, -4) - 1.5 * (-4) * (0, 1) = (3, 2) for e = 0.5
    from dynagrade.mechanics.impact import rebound_velocity

    assert rebound_velocity([3.0, -4.0], [0.0, 2.0], 0.5) == pytest.approx([3.0, 2.0])


def test_the_angle_of_a_vector_with_itself_is_zero_where_rounding_lifts_the_cosine_above_1():
    # for this vector u.u / (|u| |u|) rounds to 1 + 2.2e-16, whose arccos is nan unclipped
    from dynagrade.mechanics.rotations import angle_between

    u = [2.0427716074923303, 0.6467029962018469, 0.6630633723762617]
    assert float(np.dot(u, u) / np.dot(u, u) ** 0.5 / np.dot(u, u) ** 0.5) >= 1.0
    assert angle_between(u, u) == 0.0
    assert angle_between([1.0, 0.0, 0.0], [-2.0, 0.0, 0.0]) == pytest.approx(math.pi)


def test_the_clamped_pinned_characteristic_function_is_sin_minus_cos_tanh_as_documented():
    # at beta L = pi/2: sin = 1, cos = 0, so the value is 1 (and -1 at 3 pi / 2)
    from dynagrade.mechanics import beams

    assert beams.characteristic_function(math.pi / 2, "clamped-pinned") == pytest.approx(1.0)
    assert beams.characteristic_function(3 * math.pi / 2, "clamped-pinned") == pytest.approx(-1.0)
