"""Looping (Example 1.13) against the particle-on-a-circle equation of motion
R phi'' = -g sin(phi) integrated with solve_ivp, the normal force taken from the
radial momentum balance along that numerical solution."""
import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

from dynagrade.mechanics.examples import looping
from deferred import deferred

solve_ivp = deferred("scipy.integrate", "solve_ivp")


def _ride(v0, R, g, phi_end=2 * np.pi):
    def rhs(t, y):
        return [y[1], -g / R * np.sin(y[0])]

    def done(t, y):
        return y[0] - phi_end

    done.terminal = True

    def turns_back(t, y):
        return y[1]

    turns_back.terminal = True
    turns_back.direction = -1

    def top(t, y):
        return y[0] - np.pi

    t_end = 50.0 * 2 * np.pi * R / v0
    return solve_ivp(rhs, (0.0, t_end), [0.0, v0 / R], events=(done, turns_back, top),
                     rtol=1e-10, atol=1e-12, dense_output=True)


@settings(max_examples=20, deadline=None)
@given(R=st.floats(2.0, 30.0), g=st.floats(5.0, 15.0), factor=st.floats(1.0, 2.0),
       m=st.floats(100.0, 2000.0))
def test_speed_and_normal_force_match_the_integrated_ride(R, g, factor, m):
    v0 = factor * np.sqrt(5 * g * R)
    sol = _ride(v0, R, g)
    assert sol.t_events[0].size == 1                           # completes the looping
    t = np.linspace(0.0, sol.t_events[0][0], 40)
    phi, phidot = sol.sol(t)
    v_num = R * phidot                                          # eq. (1.114)
    N_num = m * R * phidot**2 + m * g * np.cos(phi)             # radial balance (1.115)
    assert np.allclose(looping.speed(phi, v0, R, g), v_num, rtol=1e-7)
    assert np.allclose(looping.looping_normal_force(phi, m, v0, R, g), N_num, rtol=1e-6, atol=1e-7 * m * g)
    assert looping.maximum_normal_force(m, v0, R, g) == pytest.approx(N_num.max(), rel=1e-6)
    assert looping.minimum_speed(v0, R, g) == pytest.approx(R * sol.y_events[2][0][1], rel=1e-7)


@settings(max_examples=20, deadline=None)
@given(R=st.floats(2.0, 30.0), g=st.floats(5.0, 15.0), factor=st.floats(0.3, 0.95))
def test_too_slow_car_turns_back_at_the_height_energy_predicts(R, g, factor):
    v0 = factor * looping.speed_to_reach_top(R, g)
    sol = _ride(v0, R, g)
    phi_turn = sol.y_events[1][0][0]
    # speed vanishes there: v0^2 = 2 g R (1 - cos phi_turn)
    assert looping.speed(phi_turn, v0, R, g) == pytest.approx(0.0, abs=1e-4 * v0)
    assert np.isnan(looping.speed(np.pi, v0, R, g))


def test_minimum_entry_speed_makes_the_normal_force_vanish_at_the_top_and_6mg_at_the_end():
    R, g, m = 10.0, 9.81, 800.0
    v0 = looping.minimum_entry_speed(R, g)
    assert v0 == pytest.approx(np.sqrt(5 * 9.81 * 10))
    assert looping.looping_normal_force(np.pi, m, v0, R, g) == pytest.approx(0.0, abs=1e-9)
    assert looping.looping_normal_force(2 * np.pi, m, v0, R, g) == pytest.approx(6 * m * g)   # eq. (1.119)
    phi = np.linspace(0, 2 * np.pi, 1001)
    assert np.all(looping.looping_normal_force(phi, m, v0, R, g) >= -1e-9)
    assert np.any(looping.looping_normal_force(phi, m, 0.99 * v0, R, g) < 0)


@settings(max_examples=20, deadline=None)
@given(R=st.floats(2.0, 30.0), g=st.floats(5.0, 15.0), factor=st.floats(1.0, 1.3))
def test_lift_off_angle_is_where_the_integrated_normal_force_first_vanishes(R, g, factor):
    v0 = factor * looping.speed_to_reach_top(R, g)   # both below and above sqrt(5 g R)
    sol = _ride(v0, R, g)
    t = np.linspace(0.0, sol.t_events[0][0] if sol.t_events[0].size else sol.t_events[1][0], 4000)
    phi, phidot = sol.sol(t)
    N = R * phidot**2 + g * np.cos(phi)
    phi_off = looping.lift_off_angle(v0, R, g)
    if np.all(N > 0):
        assert np.isnan(phi_off)
    else:
        first = phi[np.argmax(N <= 0)]
        assert phi_off == pytest.approx(first, abs=5e-3)


@settings(max_examples=25, deadline=None)
@given(phi=st.floats(0.0, 2 * np.pi), R=st.floats(2.0, 30.0), m=st.floats(100.0, 2000.0),
       factor=st.floats(1.0, 2.0))
def test_support_reactions_keep_the_looping_in_static_equilibrium(phi, R, m, factor):
    # Looping centred at (0, R) above the clamp A at the origin; car at
    # r = (R sin phi, R - R cos phi); the track pushes the car towards the centre with N,
    # so the car pushes the track with N (sin phi, -cos phi) at r.
    g = 9.81
    v0 = factor * np.sqrt(5 * g * R)
    N = looping.looping_normal_force(phi, m, v0, R, g)
    r = np.array([R * np.sin(phi), R - R * np.cos(phi)])
    f_car = N * np.array([np.sin(phi), -np.cos(phi)])
    s = looping.support_reactions(phi, m, v0, R, g)
    assert s.A1 + f_car[0] == pytest.approx(0.0, abs=1e-9 * abs(N) + 1e-9)
    assert s.A2 + f_car[1] == pytest.approx(0.0, abs=1e-9 * abs(N) + 1e-9)
    moment_of_car = r[0] * f_car[1] - r[1] * f_car[0]
    assert s.MA + moment_of_car == pytest.approx(0.0, abs=1e-9 * abs(N) * R + 1e-9)
    # held at rest instead (eq. 1.123): only the weight (0, -m g) acts at r
    st_ = looping.static_support_reactions(phi, m, R, g)
    assert (st_.A1, st_.A2) == pytest.approx((0.0, m * g))
    assert st_.MA + r[0] * (-m * g) == pytest.approx(0.0, abs=1e-9 * m * g * R)
