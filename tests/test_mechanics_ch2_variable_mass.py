"""Variable mass (Section 2.3.2): closed forms against the integrated momentum balance."""
import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

from dynagrade.mechanics import variable_mass
from deferred import deferred

solve_ivp = deferred("scipy.integrate", "solve_ivp")


@settings(max_examples=15, deadline=None)
@given(st.floats(500.0, 4000.0), st.floats(100.0, 1000.0), st.floats(0.2, 0.9),
       st.floats(5.0, 60.0), st.sampled_from([0.0, 9.81]))
def test_rocket_equation_agrees_with_integrated_momentum_balance(u, m0, fuel_fraction, t_b, g):
    fuel = fuel_fraction * m0
    q = fuel / t_b

    # m dv/dt = u q - m g, m = m0 - q t ; dh/dt = v
    def rhs(t, y):
        return [u * q / (m0 - q * t) - g, y[0]]

    sol = solve_ivp(rhs, (0, t_b), [0.0, 0.0], rtol=1e-10, atol=1e-8)
    v_num, h_num = sol.y[:, -1]
    assert variable_mass.vertical_rocket_speed(t_b, 0.0, u, m0, q, g) == pytest.approx(v_num, rel=1e-6)
    assert variable_mass.vertical_rocket_height(t_b, 0.0, u, m0, q, g) == pytest.approx(h_num, rel=1e-6)
    if g == 0.0:
        assert variable_mass.rocket_speed_gain(u, m0, m0 - fuel) == pytest.approx(v_num, rel=1e-6)


def test_rocket_speed_gain_by_hand():
    # u = 2000 m/s, mass ratio e^1.5: Delta v = 3000 m/s
    assert variable_mass.rocket_speed_gain(2000.0, np.exp(1.5), 1.0) == pytest.approx(3000.0)
    assert variable_mass.burn_time(300.0, 5.0) == pytest.approx(60.0)
    assert variable_mass.thrust(2500.0, 4.0) == pytest.approx(10_000.0)


def test_chain_falling_on_scale_reads_three_times_the_weight_on_it():
    lam, g, big_l = 0.8, 9.81, 2.0
    # momentum of the still-falling part P(t) = lam (L - x) v, x = g t^2/2, v = g t
    # scale force N = lam L g - dP/dt (down positive); differentiate numerically
    def momentum(t):
        return lam * (big_l - 0.5 * g * t**2) * g * t

    for t in (0.1, 0.3, 0.55):
        h = 1e-6
        dp_dt = (momentum(t + h) - momentum(t - h)) / (2 * h)
        n = lam * big_l * g - dp_dt
        x = 0.5 * g * t**2
        assert variable_mass.chain_on_scale_force(lam, x, g) == pytest.approx(n, rel=1e-6)
        assert variable_mass.chain_on_scale_force(lam, x, g) == pytest.approx(3 * lam * g * x)


@settings(max_examples=15, deadline=None)
@given(st.floats(50.0, 500.0), st.floats(0.5, 5.0), st.floats(1.0, 20.0), st.floats(1.0, 30.0))
def test_cart_collecting_load_keeps_its_momentum(m0, v0, rate, t_end):
    # m dv/dt = -m_dot v (load arrives without horizontal velocity)
    sol = solve_ivp(lambda t, y: [-rate * y[0] / (m0 + rate * t)], (0, t_end), [v0],
                    rtol=1e-10, atol=1e-12)
    assert variable_mass.speed_after_accretion(m0, v0, m0 + rate * t_end) == pytest.approx(
        sol.y[0, -1], rel=1e-6)


def test_force_to_keep_conveyor_speed_by_hand():
    # sand falls at 20 kg/s onto a belt moving at 1.5 m/s: F = 30 N
    assert variable_mass.force_to_keep_speed_while_accreting(20.0, 1.5) == pytest.approx(30.0)


def test_mass_at_time_by_hand():
    # 100 kg gaining 2.5 kg/s for 8 s: 120 kg; losing it: 80 kg
    assert variable_mass.mass_at_time(8.0, 100.0, 2.5) == pytest.approx(120.0, rel=1e-12)
    assert variable_mass.mass_at_time(8.0, 100.0, -2.5) == pytest.approx(80.0, rel=1e-12)


def test_accreting_cart_speed_with_linear_mass_growth_matches_integrated_momentum_balance():
    # m(t) = m0 + q t, load arriving without horizontal velocity: m v' = -q v
    m0, q, v0, t_end = 200.0, 15.0, 4.0, 6.0
    sol = solve_ivp(lambda t, y: [-q * y[0] / (m0 + q * t)], (0, t_end), [v0], rtol=1e-10,
                    atol=1e-12)
    mass = variable_mass.mass_at_time(t_end, m0, q)
    assert variable_mass.speed_after_accretion(m0, v0, mass) == pytest.approx(sol.y[0, -1],
                                                                              rel=1e-7)
