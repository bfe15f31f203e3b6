"""Angular momentum (Section 1.2.3, Examples 1.16-1.19) against simulations and the
angular momentum balance evaluated along them."""
import numpy as np
import pytest
from hypothesis import example, given, settings, strategies as st

from dynagrade.mechanics import angular_momentum as am
from dynagrade.mechanics import particle
from deferred import deferred

solve_ivp = deferred("scipy.integrate", "solve_ivp")


@settings(max_examples=20, deadline=None)
@given(m=st.floats(0.1, 5.0), strength=st.floats(1.0, 50.0), r0=st.floats(0.5, 3.0),
       vr=st.floats(-2, 2), vt=st.floats(0.5, 5.0), law=st.sampled_from(["spring", "inverse-square"]))
def test_angular_momentum_about_the_centre_is_conserved_under_a_central_force(m, strength, r0, vr, vt, law):
    def force(t, r, v):
        dist = np.linalg.norm(r)
        magnitude = strength * dist if law == "spring" else strength / dist**2
        return -magnitude * r / dist

    def too_close(t, r, v):
        return np.linalg.norm(r) - 0.05 * r0

    too_close.terminal = True
    traj = particle.simulate(m, [r0, 0.0, 0.0], [vr, vt, 0.0], force, 3.0, events=(too_close,))
    H = am.particle_angular_momentum(traj.r, m, traj.v)
    H0 = am.particle_angular_momentum([r0, 0.0, 0.0], m, [vr, vt, 0.0])
    assert np.allclose(H, H0, rtol=0, atol=1e-7 * np.linalg.norm(H0))
    assert np.allclose(am.torque(traj.r[5], force(0, traj.r[5], None)), 0.0, atol=1e-9 * strength)


@settings(max_examples=20, deadline=None)
@given(m=st.floats(0.1, 5.0), vB=st.lists(st.floats(-3, 3), min_size=3, max_size=3),
       F=st.lists(st.floats(-5, 5), min_size=3, max_size=3))
def test_angular_momentum_balance_about_a_moving_point_matches_finite_differences(m, vB, F):
    # particle under a constant force F, point B moving uniformly with vB: compare
    # H_B'(t) by central differences with M_B - v_B x P of eq. (1.132)
    F, vB = np.array(F), np.array(vB)
    r0, v0, rB0 = np.array([1.0, -0.5, 0.3]), np.array([0.2, 1.0, -0.7]), np.array([-0.4, 0.1, 0.9])
    r = lambda t: r0 + v0 * t + 0.5 * F / m * t**2
    v = lambda t: v0 + F / m * t
    rB = lambda t: rB0 + vB * t
    H = lambda t: am.particle_angular_momentum(r(t) - rB(t), m, v(t))
    t, h = 0.7, 1e-4
    Hdot = (H(t + h) - H(t - h)) / (2 * h)
    M = am.torque(r(t) - rB(t), F)
    assert np.allclose(am.angular_momentum_rate(M, vB, particle.particle_linear_momentum(m, v(t))), Hdot, atol=1e-6)


@settings(max_examples=20, deadline=None)
@given(m=st.floats(0.1, 5.0), r=st.floats(0.2, 3.0), rd=st.floats(-2, 2), phd=st.floats(-3, 3),
       rdd=st.floats(-2, 2), phdd=st.floats(-3, 3))
def test_planar_torque_is_the_rate_of_m_r2_phidot(m, r, rd, phd, rdd, phdd):
    # d/dt (m r^2 phi') with r(t) = r + rd t + rdd t^2/2, phi'(t) = phd + phdd t, at t = 0
    H = lambda t: am.planar_angular_momentum(m, r + rd * t + 0.5 * rdd * t**2, phd + phdd * t)
    h = 1e-5
    assert am.planar_torque(m, r, rd, phd, phdd) == pytest.approx((H(h) - H(-h)) / (2 * h), abs=1e-6)
    # and the 3D vector formula agrees with the planar one (eq. before 1.137)
    H3 = am.particle_angular_momentum([r, 0.0], m, [rd, r * phd])
    assert H3[2] == pytest.approx(am.planar_angular_momentum(m, r, phd))


@example(m=0.1015625, k=1.5, R=0.25, w0=1.0, t=3.25)  # omega ~ 1e-21 rad/s: the simulation's noise wins
@settings(max_examples=20, deadline=None)
@given(m=st.floats(0.1, 5.0), k=st.floats(0.01, 2.0), R=st.floats(0.2, 3.0), w0=st.floats(0.5, 20.0),
       t=st.floats(0.0, 5.0))
def test_rotating_particle_in_air_matches_the_simulated_drag_motion(m, k, R, w0, t):
    # Example 1.16 simulated in Cartesian coordinates: drag -k v plus the rod force that keeps
    # |r| = R, the latter taken as the centripetal force m |v|^2 / R
    def force(tt, r, v):
        return particle.linear_drag_force(v, k) - m * np.dot(v, v) / R * r / np.linalg.norm(r)

    traj = particle.simulate(m, [R, 0.0], [0.0, R * w0], force, max(t, 1e-3))
    r_end, v_end = traj.at(t)
    omega_num = np.cross(r_end, v_end) / np.dot(r_end, r_end)
    # once drag has all but stopped the particle (omega ~ 1e-21 rad/s at k t/m ~ 48) the
    # integrator's own error (~1e-12 rad/s) dominates: compare to a millionth, or to 1e-9 w0
    assert am.drag_angular_velocity(t, w0, k, m) == pytest.approx(omega_num, rel=1e-6, abs=1e-9 * w0)
    phi_num = np.unwrap(np.arctan2(*traj.at(np.linspace(0, t, 400))[0][:, ::-1].T))[-1]
    assert am.drag_rotation_angle(t, w0, k, m) == pytest.approx(phi_num, rel=1e-6, abs=1e-9)
    assert am.drag_torque(k, R, w0) == pytest.approx(
        am.torque([R, 0.0], particle.linear_drag_force([0.0, R * w0], k))[2])


@settings(max_examples=15, deadline=None)
@given(g=st.floats(5.0, 15.0), R=st.floats(0.2, 3.0), amp=st.floats(0.005, 0.02))
def test_small_angle_pendulum_period_matches_integration(g, R, amp):
    def rhs(t, y):
        return [y[1], am.particle_pendulum_angular_acceleration(y[0], y[1], g, R)]

    def crosses(t, y):
        return y[0]

    crosses.direction = -1
    T0 = am.pendulum_small_angle_period(g, R)
    sol = solve_ivp(rhs, (0, 2.5 * T0), [amp, 0.0], events=crosses, rtol=1e-10, atol=1e-13)
    downward = sol.t_events[0]
    period = downward[1] - downward[0]
    # the exact period exceeds the small-angle one by about amp^2/16
    assert period == pytest.approx(T0 * (1 + amp**2 / 16), rel=1e-5)


def test_pendulum_string_force_and_drag_terms():
    # hanging at rest: tension m g; at the bottom with phi' = w: m g + m R w^2
    assert am.pendulum_string_force(2.0, 1.5, 9.81, 0.0, 0.0) == pytest.approx(19.62)
    assert am.pendulum_string_force(2.0, 1.5, 9.81, 0.0, 2.0) == pytest.approx(19.62 + 2 * 1.5 * 4)
    # eq. (1.149): phi'' = -(k/m) phi' - (g/R) sin phi
    assert am.particle_pendulum_angular_acceleration(0.3, 1.2, 9.81, 2.0, k=0.4, m=2.0) == pytest.approx(
        -0.2 * 1.2 - 9.81 / 2.0 * np.sin(0.3))


@settings(max_examples=20, deadline=None)
@given(m=st.floats(0.1, 5.0), l0=st.floats(0.5, 2.0), ratio=st.floats(0.2, 0.9), w0=st.floats(0.5, 5.0),
       T=st.floats(0.5, 3.0))
def test_string_pulled_inward_keeps_angular_momentum_as_simulated(m, l0, ratio, w0, T):
    # Example 1.18 in polar coordinates with a prescribed l(t) = l0 (1 - (1 - ratio) s^2 (3 - 2 s)),
    # s = t/T: the tangential balance 2 l' phi' + l phi'' = 0 (eq. 1.138 with M_B = 0)
    l = lambda t: l0 * (1 - (1 - ratio) * (t / T) ** 2 * (3 - 2 * t / T))
    ld = lambda t: l0 * (-(1 - ratio) * (6 * t / T - 6 * (t / T) ** 2) / T)
    sol = solve_ivp(lambda t, y: [y[1], -2 * ld(t) * y[1] / l(t)], (0, T), [0.0, w0],
                    rtol=1e-10, atol=1e-12)
    w_end = sol.y[1, -1]
    assert am.pulled_string_angular_velocity(w0, l0, l(T)) == pytest.approx(w_end, rel=1e-7)
    assert am.conserved_tangential_speed(l0 * w0, l0, l(T)) == pytest.approx(l(T) * w_end, rel=1e-7)


def test_rotating_chair_angular_velocity_by_hand():
    # Example 1.19 setting: chair + person I = 1.2 kg m^2, two 5 kg masses moved from 0.8 m to 0.2 m
    I0 = 1.2 + 2 * am.particle_moment_of_inertia(5.0, 0.8)     # 7.6
    I1 = 1.2 + 2 * am.particle_moment_of_inertia(5.0, 0.2)     # 1.6
    assert am.conserved_angular_velocity(2.0, I0, I1) == pytest.approx(2.0 * 7.6 / 1.6)
    assert am.angular_acceleration(3.0, am.particle_moment_of_inertia(2.0, 0.5)) == pytest.approx(6.0)
    assert am.rotation_decay_rate(0.3, 1.5) == pytest.approx(0.2)
    assert am.pendulum_natural_frequency(9.81, 9.81) == pytest.approx(1.0)
