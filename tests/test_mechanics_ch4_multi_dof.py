"""Multi-DOF vibrations, Section 4.4: modes, forced response, absorber, modal decomposition,
against numerical integration, the characteristic determinant and hand calculations."""
import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

from dynagrade.mechanics import multi_dof, vibrations
from deferred import deferred

sp = deferred("sympy")
equilibrium = deferred("dynagrade.mechanics.equilibrium")
lagrange = deferred("dynagrade.mechanics.lagrange")
solve_ivp = deferred("scipy.integrate", "solve_ivp")

SETTINGS = settings(max_examples=30, deadline=None)


@st.composite
def chain_systems(draw, n_min=2, n_max=5):
    """A random chain of masses and springs, fixed on the left (positive definite K)."""
    n = draw(st.integers(n_min, n_max))
    masses = draw(st.lists(st.floats(0.5, 10.0), min_size=n, max_size=n))
    springs = draw(st.lists(st.floats(100.0, 2000.0), min_size=n + 1, max_size=n + 1))
    right = draw(st.booleans())
    K = multi_dof.chain_stiffness_matrix(springs if right else springs[:-1], right_wall=right)
    return K, multi_dof.lumped_mass_matrix(masses)


@SETTINGS
@given(chain_systems())
def test_modes_are_mass_and_stiffness_orthogonal(system):
    K, M = system
    Phi = multi_dof.mode_shapes(K, M)
    w = multi_dof.natural_frequencies(K, M)
    assert np.allclose(Phi.T @ M @ Phi, np.eye(len(w)), atol=1e-10)
    assert np.allclose(Phi.T @ K @ Phi, np.diag(w**2), atol=1e-8 * np.max(w**2))


@SETTINGS
@given(chain_systems())
def test_natural_frequencies_make_the_characteristic_determinant_vanish(system):
    K, M = system
    w = multi_dof.natural_frequencies(K, M)
    Phi = multi_dof.mode_shapes(K, M)
    n = len(w)
    for i, wi in enumerate(w):
        D = K - wi**2 * M
        assert abs(multi_dof.frequency_determinant(K, M, wi)) <= 1e-9 * np.linalg.norm(D, 2) ** n
        # and the mode shape is its null vector
        assert np.linalg.norm(D @ Phi[:, i]) <= 1e-9 * np.linalg.norm(D, 2) * np.linalg.norm(Phi[:, i])


@SETTINGS
@given(chain_systems(), st.lists(st.floats(-0.05, 0.05), min_size=5, max_size=5),
       st.lists(st.floats(-0.5, 0.5), min_size=5, max_size=5))
def test_modal_superposition_equals_direct_integration(system, x0, v0):
    K, M = system
    n = len(K)
    x0, v0 = np.array(x0[:n]), np.array(v0[:n])
    w = multi_dof.natural_frequencies(K, M)
    t = np.linspace(0, 3 * 2 * np.pi / w[0], 50)
    Minv = np.linalg.inv(M)
    sol = solve_ivp(lambda _t, y: np.concatenate([y[n:], -Minv @ K @ y[:n]]), (0, t[-1]),
                    np.concatenate([x0, v0]), t_eval=t, rtol=1e-10, atol=1e-13, method="DOP853")
    assert np.allclose(multi_dof.modal_free_response(t, K, M, x0, v0), sol.y[:n], atol=1e-7)


def test_modal_superposition_with_proportional_damping_equals_direct_integration():
    K = multi_dof.chain_stiffness_matrix([400.0, 300.0, 200.0])
    M = multi_dof.lumped_mass_matrix([2.0, 1.5, 1.0])
    C = 0.02 * K + 0.3 * M
    x0, v0 = np.array([0.01, -0.02, 0.03]), np.array([0.1, 0.0, -0.2])
    t = np.linspace(0, 4, 80)
    Minv = np.linalg.inv(M)
    rhs = lambda _t, y: np.concatenate([y[3:], -Minv @ (K @ y[:3] + C @ y[3:])])
    sol = solve_ivp(rhs, (0, 4), np.concatenate([x0, v0]), t_eval=t, rtol=1e-10, atol=1e-13)
    assert np.allclose(multi_dof.modal_free_response(t, K, M, x0, v0, C), sol.y[:3], atol=1e-8)
    # proportional damping: each damped eigenvalue is that of a 1-DOF modal oscillator
    lam = multi_dof.damped_eigenvalues(K, M, C)
    w = multi_dof.natural_frequencies(K, M)
    z = multi_dof.modal_damping_ratios(K, M, C)
    assert np.allclose(np.sort(lam.imag[lam.imag > 0]), np.sort(vibrations.damped_frequency(w, z)), rtol=1e-9)
    assert np.allclose(np.sort(-lam.real[lam.imag > 0]), np.sort(z * w), rtol=1e-9)


def test_two_storey_shear_frame_by_hand():
    # m1 = m2 = m, k1 = k2 = k: omega^2 = (3 -+ sqrt 5)/2 k/m, ratios (1 +- sqrt 5)/2
    m, k = 1000.0, 2.0e6
    K = multi_dof.chain_stiffness_matrix([k, k])
    M = multi_dof.lumped_mass_matrix([m, m])
    w = multi_dof.natural_frequencies(K, M)
    assert w**2 == pytest.approx([(3 - np.sqrt(5)) / 2 * k / m, (3 + np.sqrt(5)) / 2 * k / m], rel=1e-12)
    ratios = multi_dof.amplitude_ratios(K, M)
    assert ratios[1] == pytest.approx([(1 + np.sqrt(5)) / 2, (1 - np.sqrt(5)) / 2], rel=1e-12)


def test_chain_matrices_equal_the_lagrange_linearization():
    t = sp.Symbol("t")
    q = [sp.Function(f"x{i}")(t) for i in range(3)]
    ms, ks = sp.symbols("m1:4", positive=True), sp.symbols("k1:5", positive=True)
    T = sum(mi * qi.diff(t) ** 2 for mi, qi in zip(ms, q)) / 2
    V = (ks[0] * q[0] ** 2 + ks[1] * (q[1] - q[0]) ** 2 + ks[2] * (q[2] - q[1]) ** 2 + ks[3] * q[2] ** 2) / 2
    Ksym = equilibrium.stiffness_matrix(V, q, {qi: 0 for qi in q})
    Msym = lagrange.mass_matrix(T, q, t)
    values = dict(zip(ks, [1.0, 2.0, 3.0, 4.0])) | dict(zip(ms, [5.0, 6.0, 7.0]))
    assert np.allclose(np.array(Ksym.subs(values), dtype=float),
                       multi_dof.chain_stiffness_matrix([1.0, 2.0, 3.0, 4.0], right_wall=True))
    assert np.allclose(np.array(Msym.subs(values), dtype=float), multi_dof.lumped_mass_matrix([5, 6, 7]))


@settings(max_examples=12, deadline=None)
@given(chain_systems(n_max=3), st.floats(0.3, 2.5))
def test_forced_steady_state_amplitudes_match_numerical_integration(system, ratio):
    K, M = system
    n = len(K)
    w = multi_dof.natural_frequencies(K, M)
    C = 0.1 * K / w[0] + 0.1 * w[0] * M                 # Rayleigh damping, every zeta >= 0.2
    F = np.zeros(n)
    F[-1] = 10.0
    Omega = ratio * w[0]
    zeta_min = np.min(multi_dof.modal_damping_ratios(K, M, C) * w)
    t_settle = 14.0 / zeta_min                         # e^{-14} of the transient left
    t = np.linspace(t_settle, t_settle + 2 * 2 * np.pi / Omega, 120)
    Minv = np.linalg.inv(M)
    rhs = lambda s, y: np.concatenate([y[n:], Minv @ (F * np.cos(Omega * s) - K @ y[:n] - C @ y[n:])])
    sol = solve_ivp(rhs, (0, t[-1]), np.zeros(2 * n), t_eval=t, rtol=1e-9, atol=1e-12, method="DOP853")
    X = multi_dof.steady_state_amplitudes(K, M, C, F, Omega)
    predicted = np.real(np.outer(X, np.exp(1j * Omega * t)))
    assert np.allclose(predicted, sol.y[:n], atol=1e-5 * np.max(np.abs(X)))


@settings(max_examples=20, deadline=None)
@given(m=st.floats(10, 200), k=st.floats(1e3, 1e5), mu=st.floats(0.05, 0.5), ratio=st.floats(0.5, 2.0))
def test_tuned_absorber_keeps_the_main_mass_still(m, k, mu, ratio):
    F0 = 100.0
    Omega = ratio * vibrations.natural_frequency(k, m)
    m_a = mu * m
    k_a = multi_dof.tuned_absorber_stiffness(m_a, Omega)
    K, M = multi_dof.absorber_system_matrices(m, k, m_a, k_a)
    X = multi_dof.steady_state_amplitudes(K, M, np.zeros((2, 2)), [F0, 0.0], Omega)
    assert abs(X[0]) <= 1e-9 * abs(X[1])
    assert X[1].real == pytest.approx(multi_dof.absorber_amplitude(F0, k_a), rel=1e-9)


def test_rayleigh_quotient_is_stationary_at_the_modes():
    K = multi_dof.chain_stiffness_matrix([300.0, 200.0, 100.0])
    M = multi_dof.lumped_mass_matrix([1.0, 2.0, 3.0])
    w = multi_dof.natural_frequencies(K, M)
    Phi = multi_dof.mode_shapes(K, M)
    for i in range(3):
        assert multi_dof.rayleigh_quotient(K, M, Phi[:, i]) == pytest.approx(w[i] ** 2, rel=1e-12)


@SETTINGS
@given(chain_systems(), st.lists(st.floats(-1, 1), min_size=5, max_size=5))
def test_rayleigh_quotient_bounds_the_first_frequency_from_above(system, x):
    K, M = system
    x = np.array(x[: len(K)])
    if np.linalg.norm(x) < 1e-6:
        x = np.ones(len(K))
    w = multi_dof.natural_frequencies(K, M)
    assert multi_dof.rayleigh_quotient(K, M, x) >= w[0] ** 2 * (1 - 1e-12)
    assert multi_dof.rayleigh_quotient(K, M, x) <= w[-1] ** 2 * (1 + 1e-12)


def test_modal_matrices_are_diagonal_and_rigid_modes_have_zero_frequency():
    K = multi_dof.chain_stiffness_matrix([0.0, 500.0])     # two free masses on one spring
    M = multi_dof.lumped_mass_matrix([2.0, 3.0])
    w = multi_dof.natural_frequencies(K, M)
    assert w[0] == 0.0
    assert w[1] == pytest.approx(np.sqrt(500.0 * (2 + 3) / (2 * 3)), rel=1e-12)
    Mm, Km = multi_dof.modal_matrices(K, M)
    assert np.allclose(Mm, np.eye(2)) and np.allclose(Km, np.diag(w**2), atol=1e-9)
    # the rigid mode drifts: x(t) = x0 + v t for equal initial velocities
    x = multi_dof.modal_free_response([2.0], K, M, [0.0, 0.0], [1.0, 1.0])
    assert np.allclose(x[:, 0], [2.0, 2.0])
