"""Projectile closed forms (Example 1.9) against a numerical integration of the
linear momentum balance m x1'' = 0, m x2'' = -m g with landing and apex events."""
import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

from dynagrade.mechanics.examples import projectile
from deferred import deferred

solve_ivp = deferred("scipy.integrate", "solve_ivp")

RTOL, ATOL = 1e-10, 1e-12


def _integrate_throw(v0, alpha, g):
    def rhs(t, y):
        return [y[2], y[3], 0.0, -g]

    def lands(t, y):
        return y[1]

    lands.terminal = True
    lands.direction = -1

    def apex(t, y):
        return y[3]

    apex.direction = -1
    t_guess = 10.0 * v0 / g + 1.0
    return solve_ivp(rhs, (0.0, t_guess), [0.0, 0.0, v0 * np.cos(alpha), v0 * np.sin(alpha)],
                     events=(lands, apex), rtol=RTOL, atol=ATOL, dense_output=True,
                     first_step=1e-6 * t_guess)


throws = dict(v0=st.floats(1.0, 60.0), alpha=st.floats(0.05, 1.5), g=st.floats(1.0, 25.0))


@settings(max_examples=25, deadline=None)
@given(**throws)
def test_flight_time_range_and_peak_match_integrated_flight(v0, alpha, g):
    sol = _integrate_throw(v0, alpha, g)
    t_land = sol.t_events[0][0]
    x_land = sol.y_events[0][0][0]
    t_apex = sol.t_events[1][0]
    h_apex = sol.y_events[1][0][1]
    scale = v0**2 / g
    assert projectile.flight_time(v0, alpha, g) == pytest.approx(t_land, rel=1e-7)
    assert projectile.horizontal_range(v0, alpha, g) == pytest.approx(x_land, rel=1e-7, abs=1e-9 * scale)
    assert projectile.peak_time(v0, alpha, g) == pytest.approx(t_apex, rel=1e-7)
    assert projectile.peak_height(v0, alpha, g) == pytest.approx(h_apex, rel=1e-7, abs=1e-9 * scale)


@settings(max_examples=20, deadline=None)
@given(**throws, frac=st.floats(0.0, 1.0))
def test_position_and_velocity_follow_the_integrated_path(v0, alpha, g, frac):
    sol = _integrate_throw(v0, alpha, g)
    t = frac * sol.t_events[0][0]
    y = sol.sol(t)
    scale = v0**2 / g
    assert np.allclose(projectile.position(t, v0, alpha, g), y[:2], rtol=1e-7, atol=1e-8 * scale)
    assert np.allclose(projectile.velocity(t, v0, alpha, g), y[2:], rtol=1e-7, atol=1e-8 * v0)
    assert projectile.trajectory_height(y[0], v0, alpha, g) == pytest.approx(y[1], rel=1e-6, abs=1e-8 * scale)


def test_range_is_largest_at_45_degrees_with_value_v0_squared_over_g():
    # remark after eq. (1.80): x_1,max = v0^2/g at alpha = pi/4
    alphas = np.linspace(0.01, np.pi / 2 - 0.01, 2001)
    ranges = projectile.horizontal_range(20.0, alphas, 9.81)
    assert alphas[np.argmax(ranges)] == pytest.approx(projectile.optimal_launch_angle(), abs=1e-3)
    assert projectile.horizontal_range(20.0, np.pi / 4, 9.81) == pytest.approx(400.0 / 9.81)


def test_hand_worked_throw():
    # v0 = 10 m/s, alpha = 30 deg, g = 10: t_flight = 2*10*0.5/10 = 1 s,
    # range = 2*100*0.5*(sqrt(3)/2)/10 = 5 sqrt(3) m, peak = 100*0.25/20 = 1.25 m at 0.5 s
    a = np.pi / 6
    assert projectile.flight_time(10.0, a, 10.0) == pytest.approx(1.0)
    assert projectile.horizontal_range(10.0, a, 10.0) == pytest.approx(5 * np.sqrt(3))
    assert projectile.peak_height(10.0, a, 10.0) == pytest.approx(1.25)
    assert projectile.peak_time(10.0, a, 10.0) == pytest.approx(0.5)


def test_functions_broadcast_over_arrays():
    v0 = np.array([5.0, 10.0, 20.0])
    r = projectile.horizontal_range(v0, np.pi / 4, 10.0)
    assert r.shape == (3,)
    assert np.allclose(r, v0**2 / 10.0)
