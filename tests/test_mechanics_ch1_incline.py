"""Block on a slope (Examples 1.8, 1.11, 1.15) against a numerical integration of the
linear momentum balance with Coulomb friction R = -mu |N| v/|v| (eq. 1.74)."""
import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

from dynagrade.mechanics.examples import incline
from deferred import deferred

solve_ivp = deferred("scipy.integrate", "solve_ivp")


def _slide_until_rest(v0, acceleration):
    """Integrate x'' = acceleration (constant, < 0: friction and gravity against the motion)
    from x = 0, x' = v0 until v = 0 (terminal event; the friction direction would flip after).

    The run ends a little after the hand-computed stopping time v0/|a|, with steps of at
    most a tenth of it, so a missed event cannot send the solver on a long integration;
    the event is asserted to have fired."""
    def rhs(t, y):
        return [y[1], acceleration]

    def stops(t, y):
        return y[1]

    stops.terminal = True
    stops.direction = -1
    t_stop = v0 / abs(acceleration)
    sol = solve_ivp(rhs, (0.0, 1.5 * t_stop), [0.0, v0], events=stops, rtol=1e-10, atol=1e-12,
                    max_step=0.1 * t_stop)
    assert sol.status == 1 and len(sol.t_events[0]) == 1
    return sol


def _slide_up(v0, alpha, mu, g):
    """Block moving up the slope: x'' = -g sin(a) - mu g cos(a) (x up-slope; friction opposes
    the upward motion, eq. 1.74)."""
    return _slide_until_rest(v0, -g * np.sin(alpha) - mu * g * np.cos(alpha))


@settings(max_examples=25, deadline=None)
@given(v0=st.floats(0.5, 30.0), alpha=st.floats(0.0, 1.5), mu=st.floats(0.05, 1.0),
       g=st.floats(5.0, 15.0))
def test_distance_up_slope_matches_integrated_slide(v0, alpha, mu, g):
    sol = _slide_up(v0, alpha, mu, g)
    t_stop, x_stop = sol.t_events[0][0], sol.y_events[0][0][0]
    assert incline.distance_up_slope(v0, alpha, mu, g) == pytest.approx(x_stop, rel=1e-7)
    assert incline.time_up_slope(v0, alpha, mu, g) == pytest.approx(t_stop, rel=1e-7)


@settings(max_examples=25, deadline=None)
@given(alpha=st.floats(0.0, 1.5), mu=st.floats(0.0, 1.5), g=st.floats(5.0, 15.0),
       m=st.floats(0.1, 10.0))
def test_sliding_acceleration_is_the_force_balance_along_the_slope(alpha, mu, g, m):
    # Free-body diagram of Example 1.8 in the unrotated frame: weight (0, -m g),
    # normal force N n and friction -mu N t with t the down-slope tangent; project on t.
    t = np.array([np.cos(alpha), -np.sin(alpha)])      # down-slope unit tangent
    n = np.array([np.sin(alpha), np.cos(alpha)])       # outward normal of the slope
    weight = np.array([0.0, -m * g])
    N = -weight @ n                                    # no motion normal to the slope
    force = weight + N * n - mu * N * t
    assert force @ n == pytest.approx(0.0, abs=1e-9 * m * g)
    assert incline.incline_normal_force(m, alpha, g) == pytest.approx(N, rel=1e-12, abs=1e-12)
    assert incline.friction_force(m, alpha, mu, g) == pytest.approx(mu * N, rel=1e-12, abs=1e-12)
    assert incline.sliding_acceleration(alpha, mu, g) == pytest.approx(force @ t / m, rel=1e-9, abs=1e-9 * g)


@settings(max_examples=20, deadline=None)
@given(v0=st.floats(0.5, 20.0), alpha=st.floats(0.05, 1.0), extra=st.floats(0.05, 1.0),
       g=st.floats(5.0, 15.0))
def test_block_sliding_down_with_mu_above_tan_alpha_stops_where_integration_says(v0, alpha, extra, g):
    mu = np.tan(alpha) + extra
    assert incline.decelerates_down_slope(alpha, mu)

    # moving down-slope (v > 0) until rest: x'' = g sin(a) - mu g cos(a) < 0
    sol = _slide_until_rest(v0, g * np.sin(alpha) - mu * g * np.cos(alpha))
    assert incline.stopping_distance_down_slope(v0, alpha, mu, g) == pytest.approx(
        sol.y_events[0][0][0], rel=1e-7)


def test_block_with_mu_below_tan_alpha_never_stops():
    assert not incline.decelerates_down_slope(0.5, 0.3)       # tan(0.5) = 0.546
    assert incline.stopping_distance_down_slope(2.0, 0.5, 0.3, 9.81) == np.inf
    assert incline.sliding_acceleration(0.5, 0.3, 9.81) > 0


@settings(max_examples=20, deadline=None)
@given(v0=st.floats(0.5, 30.0), mu=st.floats(0.05, 1.0), g=st.floats(5.0, 15.0))
def test_limits_of_example_1_15_recover_horizontal_sliding_and_vertical_throw(v0, mu, g):
    # alpha = 0: Example 1.11, dx = v0^2/(2 mu g); alpha = 90 deg: Example 1.9, h = v0^2/(2 g)
    assert incline.distance_up_slope(v0, 0.0, mu, g) == pytest.approx(v0**2 / (2 * mu * g))
    assert incline.distance_up_slope(v0, np.pi / 2, mu, g) == pytest.approx(v0**2 / (2 * g))


@settings(max_examples=20, deadline=None)
@given(v0=st.floats(0.5, 30.0), alpha=st.floats(0.05, 1.5), g=st.floats(5.0, 15.0))
def test_frictionless_slope_distance_is_the_energy_height_over_sin_alpha(v0, alpha, g):
    # mu -> 0: (1/2) m v0^2 = m g h with h = dx sin(alpha) (Example 1.12, remark at its end)
    assert incline.distance_up_slope(v0, alpha, 0.0, g) * np.sin(alpha) == pytest.approx(v0**2 / (2 * g))
