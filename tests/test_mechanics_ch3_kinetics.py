"""Rigid-body kinetics (Sections 3.2.1-3.2.5) and eccentric impact (Section 3.3)."""
import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

from dynagrade.mechanics import inertia, rigid_impact, rigid_kinetics
from deferred import deferred

solve_ivp = deferred("scipy.integrate", "solve_ivp")

# I_C / (m R^2) of the round bodies: hoop, solid cylinder, solid sphere, spherical shell
ROUND = {"hoop": 1.0, "cylinder": 0.5, "sphere": 0.4, "shell": 2.0 / 3.0}


@settings(max_examples=30, deadline=None)
@given(st.sampled_from(sorted(ROUND)), st.floats(0.1, 10.0), st.floats(0.02, 1.0),
       st.floats(0.05, 1.4), st.floats(0.1, 3.0))
def test_rolling_without_slip_conserves_energy(body, m, radius, alpha, t):
    g = 9.81
    i_c = ROUND[body] * m * radius**2
    a = rigid_kinetics.rolling_acceleration_on_incline(alpha, g, m, radius, i_c)
    v, s = a * t, 0.5 * a * t**2
    kinetic = rigid_kinetics.rigid_body_kinetic_energy(m, [v, 0, 0], np.diag([0, 0, i_c]), [0, 0, v / radius])
    assert kinetic == pytest.approx(m * g * s * np.sin(alpha), rel=1e-10)
    h = s * np.sin(alpha)
    assert rigid_kinetics.rolling_speed_after_drop(h, g, m, radius, i_c) == pytest.approx(v)


def test_rolling_acceleration_is_the_limit_of_stiff_slip_friction():
    # cylinder with a very stiff viscous slip force F = c (v - omega R): no constraint used
    m, radius, alpha, g = 2.0, 0.3, 0.5, 9.81
    i_c = 0.5 * m * radius**2
    c = 2e4

    def rhs(t, y):
        v, w = y
        f = c * (v - w * radius)
        return [g * np.sin(alpha) - f / m, f * radius / i_c]

    sol = solve_ivp(rhs, (0, 0.5), [0.0, 0.0], method="Radau", rtol=1e-8, atol=1e-10)
    a_num = sol.y[0, -1] / 0.5
    a = rigid_kinetics.rolling_acceleration_on_incline(alpha, g, m, radius, i_c)
    assert a == pytest.approx(a_num, rel=1e-3)
    assert a == pytest.approx(2 / 3 * g * np.sin(alpha))  # hand result for a cylinder


@settings(max_examples=30, deadline=None)
@given(st.sampled_from(sorted(ROUND)), st.floats(0.1, 10.0), st.floats(0.02, 1.0),
       st.floats(0.05, 1.4))
def test_friction_on_rolling_body_closes_the_linear_momentum_balance(body, m, radius, alpha):
    g = 9.81
    i_c = ROUND[body] * m * radius**2
    a = rigid_kinetics.rolling_acceleration_on_incline(alpha, g, m, radius, i_c)
    friction = rigid_kinetics.friction_for_rolling_on_incline(alpha, g, m, radius, i_c)
    assert m * a == pytest.approx(m * g * np.sin(alpha) - friction)
    mu = rigid_kinetics.minimum_friction_coefficient_for_rolling(alpha, g, m, radius, i_c)
    assert mu == pytest.approx(friction / (m * g * np.cos(alpha)))


@settings(max_examples=30, deadline=None)
@given(st.integers(0, 10_000))
def test_rigid_body_momentum_and_energy_equal_sums_over_its_particles(seed):
    rng = np.random.default_rng(seed)
    m = rng.uniform(0.1, 2.0, 6)
    rho = rng.normal(size=(6, 3))
    rho -= (m[:, None] * rho).sum(axis=0) / m.sum()      # positions relative to C
    r_c, v_c, omega, b = rng.normal(size=(4, 3))
    v = v_c + np.cross(omega, rho)
    i_c = sum(mi * (ri @ ri * np.eye(3) - np.outer(ri, ri)) for mi, ri in zip(m, rho))
    h_b = sum(mi * np.cross(r_c + ri - b, vi) for mi, ri, vi in zip(m, rho, v))
    t = sum(0.5 * mi * vi @ vi for mi, vi in zip(m, v))
    assert rigid_kinetics.rigid_body_linear_momentum(m.sum(), v_c) == pytest.approx((m[:, None] * v).sum(axis=0))
    assert rigid_kinetics.rigid_body_angular_momentum_about_point(i_c, omega, m.sum(), r_c - b, v_c) == pytest.approx(h_b)
    assert rigid_kinetics.rigid_body_kinetic_energy(m.sum(), v_c, i_c, omega) == pytest.approx(t)


@settings(max_examples=20, deadline=None)
@given(st.floats(0.1, 5.0), st.floats(0.1, 2.0), st.floats(0.2, 3.0))
def test_pendulum_speed_from_energy_agrees_with_integrated_equation_of_motion(m, length, phi0):
    # rod pendulum pivoted at its end, released from rest at phi0; speed at phi = 0
    g = 9.81
    i_o = inertia.parallel_axis_moment(m * length**2 / 12, m, length / 2)
    k = m * g * (length / 2) / i_o

    def hit_bottom(t, y):
        return y[0]
    hit_bottom.terminal = True
    sol = solve_ivp(lambda t, y: [y[1], -k * np.sin(y[0])], (0, 20), [phi0, 0.0],
                    events=hit_bottom, rtol=1e-10, atol=1e-12)
    rate = abs(sol.y_events[0][0][1])
    assert rigid_kinetics.angular_speed_of_pendulum_from_energy(
        phi0, 0.0, g, m, length / 2, i_o) == pytest.approx(rate, rel=1e-6)
    assert rigid_kinetics.compound_pendulum_angular_acceleration(phi0, g, m, length / 2, i_o) == pytest.approx(
        -k * np.sin(phi0))


@settings(max_examples=40, deadline=None)
@given(st.floats(0.01, 5.0), st.floats(0.5, 20.0), st.floats(0.2, 3.0), st.floats(0.0, 1.0),
       st.floats(0.05, 1.0), st.floats(0.5, 30.0))
def test_impact_on_pinned_rod_conserves_angular_momentum_about_pivot(m, big_m, length, e, frac, v):
    d = frac * length
    i_o = big_m * length**2 / 3
    w_body = rigid_impact.inverse_effective_mass_pinned_body(i_o, d)
    impulse = rigid_impact.eccentric_impact_impulse(1 / m, w_body, v, e)
    v_after = v - impulse / m
    omega = rigid_impact.angular_velocity_change(impulse, d, i_o)
    assert m * v * d == pytest.approx(m * v_after * d + i_o * omega)
    assert omega * d - v_after == pytest.approx(e * v)     # restitution at the contact


@settings(max_examples=40, deadline=None)
@given(st.floats(0.01, 5.0), st.floats(0.5, 20.0), st.floats(0.2, 3.0), st.floats(0.0, 1.0),
       st.floats(-0.5, 0.5), st.floats(0.5, 30.0))
def test_impact_on_free_rod_conserves_momentum_and_angular_momentum(m, big_m, length, e, frac, v):
    # rod along e2 centred at the origin, particle moving along e1 hits it at y = d
    d = frac * length
    i_c = big_m * length**2 / 12
    w_body = rigid_impact.inverse_effective_mass_free_body(big_m, i_c, d)
    impulse = rigid_impact.eccentric_impact_impulse(1 / m, w_body, v, e)
    v_after, v_c = v - impulse / m, impulse / big_m
    # impulse along +e1 at (0, d): angular impulse about C is -d * impulse (e3)
    omega = -rigid_impact.angular_velocity_change(impulse, d, i_c)
    assert m * v == pytest.approx(m * v_after + big_m * v_c)
    # angular momentum about the origin (e3): particle r x mv = -d m v
    assert -d * m * v == pytest.approx(-d * m * v_after + i_c * omega)
    contact_speed = v_c - omega * d      # e1-velocity of the rod point (0, d)
    assert contact_speed - v_after == pytest.approx(e * v)


def test_ballistic_pendulum_by_hand():
    # 10 g bullet at 400 m/s into a 2 kg point-like bob on a massless 1 m arm (I_O = 2):
    # omega = m v d / (I_O + m d^2) = 4 / 2.01
    omega = rigid_impact.angular_velocity_after_plastic_impact_on_pinned_body(0.01, 400.0, 1.0, 2.0)
    assert omega == pytest.approx(4.0 / 2.01)


def test_centre_of_percussion_of_a_rod_is_two_thirds_down_and_gives_no_pivot_impulse():
    m, length = 1.5, 0.9
    i_o = m * length**2 / 3
    d = rigid_impact.centre_of_percussion_distance(i_o, m, length / 2)
    assert d == pytest.approx(2 * length / 3)
    assert rigid_impact.pivot_impulse(3.0, d, m, length / 2, i_o) == pytest.approx(0.0, abs=1e-12)
    # struck at the centre instead: the pivot takes I_hat (1 - m d_C^2 / I_O) = 1/4 of it
    assert rigid_impact.pivot_impulse(4.0, length / 2, m, length / 2, i_o) == pytest.approx(-1.0)
