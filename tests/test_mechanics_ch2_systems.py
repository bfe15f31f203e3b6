"""Systems of particles (Sections 2.1-2.2): checked by hand values and by simulating
particles with internal forces."""
import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

from dynagrade.mechanics import systems
from deferred import deferred

solve_ivp = deferred("scipy.integrate", "solve_ivp")
trapezoid = deferred("scipy.integrate", "trapezoid")

masses_st = st.lists(st.floats(0.1, 10.0), min_size=2, max_size=5)


def test_centre_of_mass_of_two_particles_by_hand():
    # 1 kg at x=0 and 3 kg at x=4: x_C = (0 + 12)/4 = 3
    r_c = systems.centre_of_mass([1.0, 3.0], [[0.0, 0.0], [4.0, 0.0]])
    assert r_c == pytest.approx([3.0, 0.0])


def test_total_momentum_equals_total_mass_times_centre_velocity():
    rng = np.random.default_rng(1)
    m = rng.uniform(0.5, 2.0, 4)
    v = rng.normal(size=(4, 3))
    v_c = (m[:, None] * v).sum(axis=0) / m.sum()
    assert systems.total_momentum(m, v) == pytest.approx(m.sum() * v_c)


def _pair_forces(m, k, rest, r):
    """Internal forces: springs between every pair (equal and opposite, central)."""
    n = len(m)
    f = np.zeros_like(r)
    for i in range(n):
        for j in range(i + 1, n):
            d = r[j] - r[i]
            dist = np.linalg.norm(d)
            fij = k * (dist - rest) * d / dist
            f[i] += fij
            f[j] -= fij
    return f


@settings(max_examples=10, deadline=None)
@given(masses_st, st.integers(0, 1000))
def test_centre_of_mass_moves_as_particle_under_total_external_force(m, seed):
    m = np.array(m)
    n = m.size
    rng = np.random.default_rng(seed)
    r0 = rng.normal(size=(n, 3))
    v0 = rng.normal(size=(n, 3))
    f_ext = rng.normal(size=(n, 3))          # constant external force on each particle
    g = np.array([0.0, 0.0, -9.81])

    def rhs(t, y):
        r = y[: 3 * n].reshape(n, 3)
        v = y[3 * n:].reshape(n, 3)
        f = _pair_forces(m, 50.0, 1.0, r) + f_ext + m[:, None] * g
        return np.concatenate([v.ravel(), (f / m[:, None]).ravel()])

    t_end = 0.8
    sol = solve_ivp(rhs, (0, t_end), np.concatenate([r0.ravel(), v0.ravel()]),
                    rtol=1e-9, atol=1e-10)
    r_end = sol.y[: 3 * n, -1].reshape(n, 3)
    mass = systems.total_mass(m)
    a_c = systems.centre_of_mass_acceleration(f_ext.sum(axis=0) + mass * g, mass)
    r_c0 = systems.centre_of_mass(m, r0)
    v_c0 = systems.total_momentum(m, v0) / mass
    expected = r_c0 + v_c0 * t_end + 0.5 * a_c * t_end**2
    assert systems.centre_of_mass(m, r_end) == pytest.approx(expected, abs=1e-6)


@settings(max_examples=30, deadline=None)
@given(masses_st, st.integers(0, 1000))
def test_angular_momentum_about_point_is_centre_part_plus_centre_of_mass_part(m, seed):
    m = np.array(m)
    rng = np.random.default_rng(seed)
    r = rng.normal(size=(m.size, 3))
    v = rng.normal(size=(m.size, 3))
    b = rng.normal(size=3)
    # direct sum about B
    direct = sum(mi * np.cross(ri - b, vi) for mi, ri, vi in zip(m, r, v))
    h_c = systems.angular_momentum_about_centre_of_mass(m, r, v)
    r_bc = systems.centre_of_mass(m, r) - b
    v_c = systems.total_momentum(m, v) / m.sum()
    assert systems.system_angular_momentum_about_point(m, r, v, b) == pytest.approx(direct)
    assert systems.angular_momentum_transfer(h_c, m.sum(), r_bc, v_c) == pytest.approx(direct)


def test_angular_momentum_about_fixed_point_changes_with_external_moment_only():
    # three particles joined by springs (central internal forces), gravity as external
    m = np.array([1.0, 2.0, 1.5])
    rng = np.random.default_rng(7)
    r0 = rng.normal(size=(3, 3))
    v0 = rng.normal(size=(3, 3))
    g = np.array([0.0, 0.0, -9.81])

    def rhs(t, y):
        r = y[:9].reshape(3, 3)
        v = y[9:].reshape(3, 3)
        f = _pair_forces(m, 30.0, 1.0, r) + m[:, None] * g
        return np.concatenate([v.ravel(), (f / m[:, None]).ravel()])

    sol = solve_ivp(rhs, (0, 0.5), np.concatenate([r0.ravel(), v0.ravel()]),
                    rtol=1e-10, atol=1e-11, dense_output=True)
    ts = np.linspace(0, 0.5, 201)
    h = np.array([systems.system_angular_momentum_about_point(
        m, sol.sol(t)[:9].reshape(3, 3), sol.sol(t)[9:].reshape(3, 3), np.zeros(3))
        for t in ts])
    # external moment about O: sum r_i x m_i g = r_C x M g
    moments = np.array([np.cross(systems.centre_of_mass(m, sol.sol(t)[:9].reshape(3, 3)),
                                 m.sum() * g) for t in ts])
    integral = trapezoid(moments, ts, axis=0)
    assert h[-1] - h[0] == pytest.approx(integral, abs=1e-4)


@settings(max_examples=30, deadline=None)
@given(masses_st, st.integers(0, 1000))
def test_kinetic_energy_splits_into_centre_of_mass_and_relative_parts(m, seed):
    m = np.array(m)
    v = np.random.default_rng(seed).normal(size=(m.size, 3))
    v_c = systems.total_momentum(m, v) / m.sum()
    t_total = sum(0.5 * mi * vi @ vi for mi, vi in zip(m, v))
    assert systems.system_kinetic_energy(m, v) == pytest.approx(t_total)
    assert (0.5 * m.sum() * v_c @ v_c
            + systems.kinetic_energy_relative_to_centre_of_mass(m, v)) == pytest.approx(t_total)


def test_relative_kinetic_energy_of_two_particles_is_the_non_centre_part():
    m1, m2, v1, v2 = 2.0, 3.0, 4.0, -1.0
    v_c = (m1 * v1 + m2 * v2) / (m1 + m2)
    t_rel = 0.5 * m1 * v1**2 + 0.5 * m2 * v2**2 - 0.5 * (m1 + m2) * v_c**2
    assert systems.relative_kinetic_energy(m1, m2, v1 - v2) == pytest.approx(t_rel)


def test_spring_released_between_carts_by_momentum_and_energy():
    # carts 2 kg and 6 kg at rest, spring energy 12 J: momentum 2 v1 = 6 v2,
    # energy 1/2 2 v1^2 + 1/2 6 v2^2 = 12 -> v1 = 3, v2 = 1, relative speed 4
    assert systems.relative_speed_from_internal_work(2.0, 6.0, 12.0) == pytest.approx(4.0)


def test_relative_speed_split_by_hand():
    # 1 kg and 3 kg separating at 4 m/s with the centre of mass at rest: 3 m/s and 1 m/s
    speeds = systems.speeds_relative_to_centre_of_mass(1.0, 3.0, 4.0)
    assert (speeds.v1, speeds.v2) == pytest.approx((3.0, 1.0), rel=1e-12)


@settings(max_examples=30, deadline=None)
@given(st.floats(0.1, 10.0), st.floats(0.1, 10.0), st.floats(0.0, 20.0))
def test_split_speeds_carry_zero_momentum_and_the_relative_kinetic_energy(m1, m2, v_rel):
    speeds = systems.speeds_relative_to_centre_of_mass(m1, m2, v_rel)
    assert speeds.v1 + speeds.v2 == pytest.approx(v_rel, abs=1e-9)
    assert m1 * speeds.v1 - m2 * speeds.v2 == pytest.approx(0.0, abs=1e-9)
    kinetic = systems.system_kinetic_energy([m1, m2], [[speeds.v1, 0.0], [-speeds.v2, 0.0]])
    assert kinetic == pytest.approx(systems.relative_kinetic_energy(m1, m2, v_rel), rel=1e-9,
                                    abs=1e-12)
