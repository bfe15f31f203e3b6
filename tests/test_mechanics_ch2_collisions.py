"""Collisions of two particles (Section 2.3.1): momentum and energy balances."""
import numpy as np
import pytest
from hypothesis import assume, given, settings, strategies as st

from dynagrade.mechanics import collisions

mass = st.floats(0.05, 50.0)
speed = st.floats(-20.0, 20.0)
restitution = st.floats(0.0, 1.0)


@settings(max_examples=50, deadline=None)
@given(mass, mass, speed, speed, restitution)
def test_momentum_is_conserved_in_every_central_collision(m1, m2, v1, v2, e):
    after = collisions.velocities_after_central_impact(m1, m2, v1, v2, e)
    assert m1 * after.v1 + m2 * after.v2 == pytest.approx(m1 * v1 + m2 * v2, abs=1e-9)


@settings(max_examples=50, deadline=None)
@given(mass, mass, speed, speed, restitution)
def test_energy_lost_equals_half_reduced_mass_times_one_minus_e_squared_times_v_rel_squared(
        m1, m2, v1, v2, e):
    after = collisions.velocities_after_central_impact(m1, m2, v1, v2, e)
    t_before = 0.5 * m1 * v1**2 + 0.5 * m2 * v2**2
    t_after = 0.5 * m1 * after.v1**2 + 0.5 * m2 * after.v2**2
    mu = m1 * m2 / (m1 + m2)
    expected = 0.5 * mu * (1 - e**2) * (v1 - v2) ** 2
    assert t_before - t_after == pytest.approx(expected, rel=1e-7, abs=1e-8)
    assert collisions.kinetic_energy_lost_in_impact(m1, m2, v1 - v2, e) == pytest.approx(
        t_before - t_after, rel=1e-7, abs=1e-8)


@settings(max_examples=50, deadline=None)
@given(mass, mass, speed, speed, restitution)
def test_relative_velocity_reverses_by_the_factor_e(m1, m2, v1, v2, e):
    assume(abs(v1 - v2) > 1e-3)
    after = collisions.velocities_after_central_impact(m1, m2, v1, v2, e)
    assert collisions.coefficient_of_restitution(v1, v2, after.v1, after.v2) == pytest.approx(
        e, abs=1e-9)


@settings(max_examples=40, deadline=None)
@given(mass, mass, st.integers(0, 10_000), restitution)
def test_momentum_is_conserved_and_tangential_velocity_kept_in_oblique_collision(m1, m2, seed, e):
    rng = np.random.default_rng(seed)
    v1, v2, n = rng.normal(size=(3, 3)) * 5
    n = n / np.linalg.norm(n)
    after = collisions.velocities_after_oblique_impact(m1, m2, v1, v2, n, e)
    assert m1 * after.v1 + m2 * after.v2 == pytest.approx(m1 * v1 + m2 * v2, abs=1e-8)
    # tangential parts unchanged
    assert after.v1 - (after.v1 @ n) * n == pytest.approx(v1 - (v1 @ n) * n, abs=1e-9)
    assert after.v2 - (after.v2 @ n) * n == pytest.approx(v2 - (v2 @ n) * n, abs=1e-9)
    # energy lost only in the normal relative motion
    approach = (v1 - v2) @ n
    lost = (0.5 * m1 * v1 @ v1 + 0.5 * m2 * v2 @ v2
            - 0.5 * m1 * after.v1 @ after.v1 - 0.5 * m2 * after.v2 @ after.v2)
    mu = m1 * m2 / (m1 + m2)
    assert lost == pytest.approx(0.5 * mu * (1 - e**2) * approach**2, rel=1e-7, abs=1e-7)


def test_elastic_collision_of_equal_masses_exchanges_velocities():
    after = collisions.velocities_after_central_impact(1.3, 1.3, 4.0, -1.0, 1.0)
    assert (after.v1, after.v2) == pytest.approx((-1.0, 4.0))


def test_plastic_collision_by_hand():
    # 2 kg at 3 m/s into 1 kg at rest: common velocity 6/3 = 2 m/s, energy 9 -> 6 J
    assert collisions.common_velocity_after_plastic_impact(2.0, 1.0, 3.0, 0.0) == pytest.approx(2.0)
    assert collisions.kinetic_energy_lost_in_impact(2.0, 1.0, 3.0, 0.0) == pytest.approx(3.0)


def test_billiard_balls_leave_at_right_angles_in_elastic_oblique_impact():
    v1 = np.array([2.0, 0.0, 0.0])
    n = np.array([np.cos(0.6), np.sin(0.6), 0.0])
    after = collisions.velocities_after_oblique_impact(0.17, 0.17, v1, np.zeros(3), n, 1.0)
    assert after.v1 @ after.v2 == pytest.approx(0.0, abs=1e-12)
    assert after.v2 / np.linalg.norm(after.v2) == pytest.approx(n)


def test_velocity_after_impulse_by_hand():
    # 0.2 kg at 5 m/s receives -1.5 N s: v' = 5 - 7.5 = -2.5 m/s
    assert collisions.velocity_after_impulse(0.2, 5.0, -1.5) == pytest.approx(-2.5, rel=1e-12)


@settings(max_examples=30, deadline=None)
@given(mass, speed, st.floats(-50.0, 50.0))
def test_momentum_changes_by_the_impulse(m, v, impulse):
    v_after = collisions.velocity_after_impulse(m, v, impulse)
    assert m * v_after - m * v == pytest.approx(impulse, abs=1e-9)
