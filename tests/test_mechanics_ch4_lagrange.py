"""Lagrange equations (Section 4.1) and equilibrium/stability (Section 4.2).

Equations of motion derived by the core from T and V are held against Newton-Euler
equations written out by hand here (linear momentum balance of each particle, with
the rod forces as unknowns where there are constraints).
"""
import functools

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

from dynagrade.mechanics.examples import hoop
from deferred import deferred

sp = deferred("sympy")
equilibrium = deferred("dynagrade.mechanics.equilibrium")
lagrange = deferred("dynagrade.mechanics.lagrange")
solve_ivp = deferred("scipy.integrate", "solve_ivp")

SETTINGS = settings(max_examples=30, deadline=None)
angle = st.floats(-3.0, 3.0)
rate = st.floats(-4.0, 4.0)


def lazily(build):
    """A function that calls the function ``build()`` returns, built on the first call:
    derivations run in the tests that use them, not when the module is collected."""
    built = functools.cache(build)
    return lambda *args: built()(*args)


def lambdified_accelerations(system):
    """The accelerations of ``system() = (T, V, q, params)`` as a numpy function."""
    def derived():
        T, V, q, params = system()
        acc = lagrange.accelerations(T, V, q, t)
        pos, vel, _ = lagrange.state_symbols(q)
        exprs = [lagrange.in_state_symbols(a, q, t) for a in acc]
        return sp.lambdify([*pos, *vel, *params], exprs, "numpy")

    return lazily(derived)


@pytest.fixture(scope="module", autouse=True)
def symbolic_models():
    """The symbols and the kinetic and potential energies T, V of the systems below (the
    plane, spring and double pendulum, the bead on the rotating hoop), bound as this
    module's globals when its tests first run, not when it is collected."""
    global t, m, m1, m2, g, L, L0, L1, L2, k, c, th, r, phi, T_sp, V_sp
    global a1, a2, T_dp, V_dp, R, Om, T_hoop, V_hoop
    t = sp.Symbol("t")
    m, m1, m2, g, L, L0, L1, L2, k, c = sp.symbols("m m1 m2 g L L0 L1 L2 k c", positive=True)
    th = sp.Function("theta")(t)
    r = sp.Function("r")(t)
    phi = sp.Function("phi")(t)
    T_sp = m * (r.diff(t) ** 2 + r**2 * phi.diff(t) ** 2) / 2
    V_sp = k * (r - L0) ** 2 / 2 - m * g * r * sp.cos(phi)
    a1 = sp.Function("theta1")(t)
    a2 = sp.Function("theta2")(t)
    x1, y1 = L1 * sp.sin(a1), -L1 * sp.cos(a1)
    x2, y2 = x1 + L2 * sp.sin(a2), y1 - L2 * sp.cos(a2)
    T_dp = (m1 * (x1.diff(t) ** 2 + y1.diff(t) ** 2) + m2 * (x2.diff(t) ** 2 + y2.diff(t) ** 2)) / 2
    V_dp = m1 * g * y1 + m2 * g * y2
    R, Om = sp.symbols("R Omega", positive=True)
    T_hoop = m * R**2 * (th.diff(t) ** 2 + Om**2 * sp.sin(th) ** 2) / 2
    V_hoop = -m * g * R * sp.cos(th)


# --- the plane pendulum ------------------------------------------------------------------
PENDULUM = lambdified_accelerations(lambda: (m * L**2 * th.diff(t) ** 2 / 2, -m * g * L * sp.cos(th),
                                             [th], [m, g, L]))


@SETTINGS
@given(theta=angle, omega=rate, mass=st.floats(0.1, 10), length=st.floats(0.2, 3))
def test_pendulum_equation_of_motion_agrees_with_newton_euler(theta, omega, mass, length):
    # tangential momentum balance: m L theta'' = -m g sin(theta)
    expected = -9.81 * np.sin(theta) / length
    (got,) = PENDULUM(theta, omega, mass, 9.81, length)
    assert got == pytest.approx(expected, rel=1e-12, abs=1e-12)


# --- the spring pendulum (elastic pendulum in polar coordinates) ------------------------
SPRING_PENDULUM = lambdified_accelerations(lambda: (T_sp, V_sp, [r, phi], [m, g, k, L0]))


@SETTINGS
@given(radius=st.floats(0.3, 2.0), phi_=angle, rdot=rate, phidot=rate,
       mass=st.floats(0.1, 5), stiff=st.floats(5, 500), rest=st.floats(0.2, 1.5))
def test_spring_pendulum_equations_agree_with_newton_euler_in_polar_coordinates(
        radius, phi_, rdot, phidot, mass, stiff, rest):
    gg = 9.81
    # radial:     m (r'' - r phi'^2) = -k (r - L0) + m g cos(phi)
    # tangential: m (r phi'' + 2 r' phi') = -m g sin(phi)
    r_dd = radius * phidot**2 - stiff / mass * (radius - rest) + gg * np.cos(phi_)
    phi_dd = (-gg * np.sin(phi_) - 2 * rdot * phidot) / radius
    got = SPRING_PENDULUM(radius, phi_, rdot, phidot, mass, gg, stiff, rest)
    assert got[0] == pytest.approx(r_dd, rel=1e-10, abs=1e-10)
    assert got[1] == pytest.approx(phi_dd, rel=1e-10, abs=1e-10)


# --- the double pendulum --------------------------------------------------------------------
DOUBLE = lambdified_accelerations(lambda: (T_dp, V_dp, [a1, a2], [m1, m2, g, L1, L2]))


def double_pendulum_newton_euler(q1, q2, w1, w2, mm1, mm2, gg, l1, l2):
    """Solve m_i a_i = rod forces + gravity for (theta1'', theta2'', S1, S2)."""
    e1 = np.array([np.sin(q1), -np.cos(q1)])      # unit vector along rod 1 (pivot -> m1)
    e2 = np.array([np.sin(q2), -np.cos(q2)])      # along rod 2 (m1 -> m2)
    t1 = np.array([np.cos(q1), np.sin(q1)])       # d e1 / d theta1
    t2 = np.array([np.cos(q2), np.sin(q2)])
    # a1 = l1 theta1'' t1 - l1 w1^2 e1 ;  a2 = a1 + l2 theta2'' t2 - l2 w2^2 e2
    # m1 a1 = -S1 e1 + S2 e2 + m1 g_vec ; m2 a2 = -S2 e2 + m2 g_vec
    gv = np.array([0.0, -gg])
    A = np.zeros((4, 4))
    b = np.zeros(4)
    A[0:2, 0] = mm1 * l1 * t1
    A[0:2, 2] = e1
    A[0:2, 3] = -e2
    b[0:2] = mm1 * gv + mm1 * l1 * w1**2 * e1
    A[2:4, 0] = mm2 * l1 * t1
    A[2:4, 1] = mm2 * l2 * t2
    A[2:4, 3] = e2
    b[2:4] = mm2 * gv + mm2 * (l1 * w1**2 * e1 + l2 * w2**2 * e2)
    sol = np.linalg.solve(A, b)
    return sol[0], sol[1]


@SETTINGS
@given(q1=angle, q2=angle, w1=rate, w2=rate, mm1=st.floats(0.1, 5), mm2=st.floats(0.1, 5),
       l1=st.floats(0.2, 2), l2=st.floats(0.2, 2))
def test_double_pendulum_equations_agree_with_newton_euler(q1, q2, w1, w2, mm1, mm2, l1, l2):
    expected = double_pendulum_newton_euler(q1, q2, w1, w2, mm1, mm2, 9.81, l1, l2)
    got = DOUBLE(q1, q2, w1, w2, mm1, mm2, 9.81, l1, l2)
    assert got[0] == pytest.approx(expected[0], rel=1e-9, abs=1e-9)
    assert got[1] == pytest.approx(expected[1], rel=1e-9, abs=1e-9)


def test_mass_matrix_of_the_double_pendulum_is_the_hessian_of_T_written_out_by_hand():
    Mq = lagrange.mass_matrix(T_dp, [a1, a2], t)
    expected = sp.Matrix([[(m1 + m2) * L1**2, m2 * L1 * L2 * sp.cos(a1 - a2)],
                          [m2 * L1 * L2 * sp.cos(a1 - a2), m2 * L2**2]])
    assert sp.simplify(Mq - expected) == sp.zeros(2, 2)


def test_a_dashpot_enters_through_the_dissipation_function():
    x = sp.Function("x")(t)
    Q = lagrange.dissipative_forces(c * x.diff(t) ** 2 / 2, [x], t)
    (acc,) = lagrange.accelerations(m * x.diff(t) ** 2 / 2, k * x**2 / 2, [x], t, Q)
    # Newton: m x'' = -k x - c x'
    assert sp.simplify(acc - (-k * x - c * x.diff(t)) / m) == 0


def test_generalized_forces_are_minus_the_gradient_of_V():
    Qg = lagrange.generalized_forces(V_sp, [r, phi])
    assert sp.simplify(Qg[0] - (-k * (r - L0) + m * g * sp.cos(phi))) == 0
    assert sp.simplify(Qg[1] - (-m * g * r * sp.sin(phi))) == 0


# --- Section 4.2: equilibrium and stability: the bead on a rotating hoop --------------------
effective_potential = functools.cache(lambda: lagrange.effective_potential(T_hoop, V_hoop, [th], t))
dV_eff = lazily(lambda: sp.lambdify([th, m, R, Om, g], sp.diff(effective_potential(), th)))
d2V_eff = lazily(lambda: sp.lambdify([th, m, R, Om, g], sp.diff(effective_potential(), th, 2)))


@settings(max_examples=20, deadline=None)
@given(radius=st.floats(0.1, 2.0), spin_factor=st.floats(1.05, 4.0))
def test_hoop_equilibria_are_the_roots_of_the_effective_potential_derivative(radius, spin_factor):
    gg = 9.81
    Omega = spin_factor * np.sqrt(gg / radius)
    roots = equilibrium.equilibrium_positions_in_interval(
        lambda x: dV_eff(x, 1.0, radius, Omega, gg), -np.pi + 1e-9, np.pi - 1e-9)
    theta_star = hoop.hoop_equilibrium_angle(radius, Omega, gg)
    assert roots == pytest.approx([-theta_star, 0.0, theta_star], abs=1e-9)
    # the lowest point is unstable, the two off-axis positions are stable (sign of V*'')
    assert equilibrium.stability([[d2V_eff(0.0, 1.0, radius, Omega, gg)]]) == "unstable"
    assert equilibrium.stability([[d2V_eff(theta_star, 1.0, radius, Omega, gg)]]) == "stable"
    assert hoop.hoop_potential_curvature(theta_star, 1.0, radius, Omega, gg) == pytest.approx(
        d2V_eff(theta_star, 1.0, radius, Omega, gg), rel=1e-9)


def test_below_the_critical_spin_only_the_lowest_point_is_stable():
    gg, radius = 9.81, 0.5
    Omega = 0.8 * hoop.hoop_critical_spin_rate(radius, gg)
    assert np.isnan(hoop.hoop_equilibrium_angle(radius, Omega, gg))
    roots = equilibrium.equilibrium_positions_in_interval(
        lambda x: dV_eff(x, 1.0, radius, Omega, gg), -np.pi / 2, np.pi / 2)
    assert roots == pytest.approx([0.0], abs=1e-12)
    assert equilibrium.stability([[d2V_eff(0.0, 1.0, radius, Omega, gg)]]) == "stable"


def test_symbolic_equilibria_of_the_hoop_include_both_poles_and_the_off_axis_angle():
    sols = equilibrium.equilibrium_positions(effective_potential(), [th])
    values = {sp.simplify(s[th]) for s in sols}
    assert 0 in values and sp.pi in values
    assert any(sp.simplify(sp.cos(v) - g / (R * Om**2)) == 0 for v in values)


@pytest.mark.parametrize("factor", [0.6, 1.7])
def test_small_oscillations_about_the_stable_equilibrium_have_the_linearized_period(factor):
    gg, radius = 9.81, 0.4
    Omega = factor * np.sqrt(gg / radius)
    theta0 = 0.0 if factor < 1 else hoop.hoop_equilibrium_angle(radius, Omega, gg)
    # theta'' = -V*'(theta) / (m R^2), integrated from a small offset; period from the
    # upward zero crossings of theta - theta0
    rhs = lambda _t, y: [y[1], -dV_eff(y[0], 1.0, radius, Omega, gg) / radius**2]
    crossing = lambda _t, y: y[0] - theta0
    crossing.direction = 1
    sol = solve_ivp(rhs, (0, 30), [theta0 + 1e-4, 0.0], events=crossing, rtol=1e-10, atol=1e-13)
    times = sol.t_events[0]
    measured = np.mean(np.diff(times))
    omega = hoop.hoop_oscillation_frequency(radius, Omega, gg)
    assert measured == pytest.approx(2 * np.pi / omega, rel=1e-4)


def test_linearized_frequency_of_the_hoop_from_the_symbolic_route_matches_the_closed_form():
    theta_star = sp.acos(g / (R * Om**2))
    w2 = equilibrium.linearized_frequency_squared(T_hoop, effective_potential(), [th], t, {th: theta_star})
    assert sp.simplify(w2 - (Om**2 - g**2 / (R**2 * Om**2))) == 0


def test_stiffness_matrix_of_the_double_pendulum_at_rest_is_diagonal_gravity_stiffness():
    K = equilibrium.stiffness_matrix(V_dp, [a1, a2], {a1: 0, a2: 0})
    assert sp.simplify(K - sp.diag((m1 + m2) * g * L1, m2 * g * L2)) == sp.zeros(2, 2)
    Kn = np.array(K.subs({m1: 1, m2: 1, g: 9.81, L1: 1, L2: 1}), dtype=float)
    assert equilibrium.stability(Kn) == "stable"
    Ku = equilibrium.stiffness_matrix(V_dp, [a1, a2], {a1: sp.pi, a2: sp.pi})
    assert equilibrium.stability(np.array(Ku.subs({m1: 1, m2: 1, g: 9.81, L1: 1, L2: 1}), dtype=float)) == "unstable"
