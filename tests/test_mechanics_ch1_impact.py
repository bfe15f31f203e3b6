"""Particle impact on a fixed wall (Section 1.2.4): restitution, energy, bouncing ball
against a simulated sequence of flights."""
import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

from dynagrade.mechanics import energy, impact

unit = st.floats(0.0, 2 * np.pi)


@settings(max_examples=30, deadline=None)
@given(v=st.lists(st.floats(-10, 10), min_size=3, max_size=3), angle=unit, tilt=st.floats(0, np.pi),
       e=st.floats(0.0, 1.0), m=st.floats(0.1, 5.0))
def test_restitution_loses_exactly_one_minus_e_squared_of_the_normal_kinetic_energy(v, angle, tilt, e, m):
    v = np.array(v)
    n = np.array([np.sin(tilt) * np.cos(angle), np.sin(tilt) * np.sin(angle), np.cos(tilt)])
    v_n = v @ n
    v_after = impact.rebound_velocity(v, n, e)
    T_normal = energy.particle_kinetic_energy(m, v_n)
    lost = energy.particle_kinetic_energy(m, v) - energy.particle_kinetic_energy(m, v_after)
    assert lost == pytest.approx(impact.normal_energy_loss_fraction(e) * T_normal, abs=1e-9 * (1 + T_normal))
    assert v_after @ n == pytest.approx(impact.rebound_normal_velocity(v_n, e), abs=1e-9)
    assert np.allclose(v_after - (v_after @ n) * n, v - v_n * n, atol=1e-9)     # smooth wall
    if e == 1.0:
        assert energy.particle_kinetic_energy(m, v_after) == pytest.approx(energy.particle_kinetic_energy(m, v))
    # the wall's impulse is the change of momentum
    assert m * np.linalg.norm(v_after - v) == pytest.approx(impact.wall_impulse(m, v_n, e), abs=1e-9)


@settings(max_examples=30, deadline=None)
@given(v=st.floats(0.5, 20.0), theta=st.floats(0.01, 1.5), e=st.floats(0.05, 1.0), m=st.floats(0.1, 5.0))
def test_oblique_rebound_angle_speed_and_energy_agree_with_the_vector_rule(v, theta, e, m):
    # wall normal e2, incoming at theta to the normal
    v_in = v * np.array([np.sin(theta), -np.cos(theta)])
    v_out = impact.rebound_velocity(v_in, [0.0, 1.0], e)
    assert impact.rebound_angle(theta, e) == pytest.approx(np.arctan2(v_out[0], v_out[1]))
    assert impact.rebound_speed(v, theta, e) == pytest.approx(np.linalg.norm(v_out))
    assert impact.impact_energy_loss(m, v, theta, e) == pytest.approx(
        energy.particle_kinetic_energy(m, v_in) - energy.particle_kinetic_energy(m, v_out), abs=1e-9)
    assert impact.restitution_from_speeds(v_in[1], v_out[1]) == pytest.approx(e)


@settings(max_examples=20, deadline=None)
@given(h0=st.floats(0.1, 10.0), e=st.floats(0.1, 0.95), g=st.floats(5.0, 15.0))
def test_bouncing_ball_heights_times_and_distance_match_a_bounce_by_bounce_sum(h0, e, g):
    # drop, then flights of initial speed e^n sqrt(2 g h0): sum them explicitly
    v = impact.impact_speed_after_fall(h0, g)
    t_total, dist = np.sqrt(2 * h0 / g), h0
    for n in range(1, 400):
        v = -impact.rebound_normal_velocity(v, e)          # upward speed after the n-th bounce
        h = energy.height_gain(v, 0.0, g)
        assert h == pytest.approx(impact.rebound_height(h0, e, n), rel=1e-9, abs=1e-300)
        t_total += 2 * v / g
        dist += 2 * h
    assert impact.bouncing_time(h0, e, g) == pytest.approx(t_total, rel=1e-8)
    assert impact.bouncing_distance(h0, e) == pytest.approx(dist, rel=1e-8)
    assert impact.restitution_from_heights(h0, impact.rebound_height(h0, e)) == pytest.approx(e)
