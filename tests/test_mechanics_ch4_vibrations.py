"""Single-degree-of-freedom vibrations, Section 4.3: free and forced response against
numerical integration of m x'' + c x' + k x = F(t), energy balance and hand calculations."""
import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

from dynagrade.mechanics import vibrations
from deferred import deferred

sp = deferred("sympy")
lagrange = deferred("dynagrade.mechanics.lagrange")
solve_ivp = deferred("scipy.integrate", "solve_ivp")
minimize_scalar = deferred("scipy.optimize", "minimize_scalar")

SETTINGS = settings(max_examples=25, deadline=None)


def integrate(m, c, k, x0, v0, t_end, force=lambda t: 0.0, t_eval=None, atol=1e-12):
    rhs = lambda t, y: [y[1], (force(t) - c * y[1] - k * y[0]) / m]
    return solve_ivp(rhs, (0.0, t_end), [x0, v0], t_eval=t_eval, rtol=1e-10, atol=atol,
                     method="DOP853")


@SETTINGS
@given(m=st.floats(0.5, 5), k=st.floats(10, 1000), zeta=st.sampled_from([0.0, 0.05, 0.4, 1.0, 2.5]),
       x0=st.floats(-0.1, 0.1), v0=st.floats(-1, 1))
def test_free_response_solves_the_equation_of_motion_in_every_damping_regime(m, k, zeta, x0, v0):
    w = vibrations.natural_frequency(k, m)
    c = vibrations.damping_coefficient(zeta, k, m)
    t = np.linspace(0, 4 * 2 * np.pi / w, 60)
    scale = abs(x0) + abs(v0) / w + 1e-12
    sol = integrate(m, c, k, x0, v0, t[-1], t_eval=t, atol=1e-12 * scale)
    assert np.allclose(vibrations.free_response(t, x0, v0, w, zeta), sol.y[0], atol=1e-7 * scale)
    assert np.allclose(vibrations.free_response_velocity(t, x0, v0, w, zeta), sol.y[1], atol=1e-7 * scale * w)


@SETTINGS
@given(m=st.floats(0.5, 5), k=st.floats(10, 1000), zeta=st.floats(0.01, 3.0),
       x0=st.floats(-0.1, 0.1), v0=st.floats(-1, 1))
def test_free_damped_responses_lose_energy_monotonically(m, k, zeta, x0, v0):
    w = vibrations.natural_frequency(k, m)
    t = np.linspace(0, 10 / w, 400)
    E = vibrations.mechanical_energy(vibrations.free_response(t, x0, v0, w, zeta),
                                     vibrations.free_response_velocity(t, x0, v0, w, zeta), k, m)
    # dE/dt = -c v^2 <= 0
    assert np.all(np.diff(E) <= 1e-12 * E[0] + 1e-300)
    assert E[-1] < E[0] or E[0] == 0.0


def test_undamped_free_response_conserves_energy():
    m, k = 2.0, 800.0
    w = vibrations.natural_frequency(k, m)
    t = np.linspace(0, 3, 200)
    E = vibrations.mechanical_energy(vibrations.free_response(t, 0.02, -0.3, w, 0.0),
                                     vibrations.free_response_velocity(t, 0.02, -0.3, w, 0.0), k, m)
    assert np.allclose(E, 0.5 * k * 0.02**2 + 0.5 * m * 0.3**2, rtol=1e-12)


def test_critically_damped_hand_calculation():
    # omega_n = 2, x0 = 1, v0 = 0: x = (1 + 2 t) e^{-2 t}; at t = 0.5: 2 e^{-1}
    assert vibrations.free_response(0.5, 1.0, 0.0, 2.0, 1.0) == pytest.approx(2 * np.exp(-1), rel=1e-12)
    assert vibrations.damping_regime(1.0) == "critically damped"
    assert vibrations.damping_regime(0.2) == "underdamped"
    assert vibrations.damping_regime(1.3) == "overdamped"
    assert vibrations.damping_regime(0.0) == "undamped"


@SETTINGS
@given(zeta=st.floats(0.005, 0.6), cycles=st.integers(1, 6))
def test_logarithmic_decrement_is_the_log_ratio_of_peaks_one_period_apart(zeta, cycles):
    w = 10.0
    wd = vibrations.damped_frequency(w, zeta)
    # find successive maxima of the simulated decay numerically
    Td = 2 * np.pi / wd
    peaks = []
    for i in range(cycles + 1):
        res = minimize_scalar(lambda s: -vibrations.free_response(s, 0.0, 1.0, w, zeta),
                              bounds=(i * Td, (i + 1) * Td - Td / 2), method="bounded",
                              options={"xatol": 1e-12})
        peaks.append(-res.fun)
    delta = vibrations.logarithmic_decrement_from_amplitudes(peaks[0], peaks[-1], cycles)
    assert delta == pytest.approx(vibrations.logarithmic_decrement(zeta), rel=1e-6)
    assert vibrations.damping_ratio_from_decrement(delta) == pytest.approx(zeta, rel=1e-6)


def test_static_deflection_gives_the_natural_frequency():
    m, k, g = 3.0, 1200.0, 9.81
    d = vibrations.static_deflection(m, k, g)
    assert vibrations.natural_frequency_from_static_deflection(d, g) == pytest.approx(np.sqrt(k / m))
    assert vibrations.frequency_in_hertz(2 * np.pi * 5) == pytest.approx(5.0)
    assert vibrations.period(2 * np.pi * 5) == pytest.approx(0.2)


def test_equivalent_mass_of_a_rolling_cylinder_matches_its_lagrange_mass_matrix():
    t = sp.Symbol("t")
    x = sp.Function("x")(t)
    m, r = sp.symbols("m r", positive=True)
    J = m * r**2 / 2
    T = m * x.diff(t) ** 2 / 2 + J * (x.diff(t) / r) ** 2 / 2    # rolling: phi' = x'/r
    M = lagrange.mass_matrix(T, [x], t)[0, 0]
    assert sp.simplify(M - 3 * m / 2) == 0
    assert vibrations.equivalent_mass([2.0, 2.0 * 0.1**2 / 2], [1.0, 1 / 0.1]) == pytest.approx(3.0)
    # lever: spring k at distance a from the pivot, coordinate = rotation angle
    assert vibrations.equivalent_stiffness([500.0, 200.0], [0.3, 0.6]) == pytest.approx(500 * 0.09 + 200 * 0.36)


def steady_amplitude_and_phase_from_simulation(m, c, k, F0, Omega, force=None):
    """Integrate until transients have decayed, then fit X cos(Omega t - phi) over a few periods."""
    zeta = vibrations.damping_ratio(c, k, m)
    w = vibrations.natural_frequency(k, m)
    t_settle = 16.0 / (zeta * w)                      # e^{-16} of the transient is left
    periods = 3
    t_end = t_settle + periods * 2 * np.pi / Omega
    t = np.linspace(t_settle, t_end, 300)
    f = force or (lambda s: F0 * np.cos(Omega * s))
    sol = integrate(m, c, k, 0.0, 0.0, t_end, f, t_eval=t)
    basis = np.column_stack([np.cos(Omega * t), np.sin(Omega * t)])
    (a, b), *_ = np.linalg.lstsq(basis, sol.y[0], rcond=None)
    return np.hypot(a, b), np.arctan2(b, a), sol, t


@SETTINGS
@given(m=st.floats(0.5, 5), k=st.floats(50, 500), zeta=st.floats(0.1, 0.8), eta=st.floats(0.2, 3.0))
def test_forced_steady_state_matches_numerical_integration_after_transients(m, k, zeta, eta):
    F0 = 10.0
    c = vibrations.damping_coefficient(zeta, k, m)
    Omega = eta * vibrations.natural_frequency(k, m)
    X, phi, sol, t = steady_amplitude_and_phase_from_simulation(m, c, k, F0, Omega)
    assert X == pytest.approx(vibrations.steady_state_amplitude(F0, k, eta, zeta), rel=1e-5)
    assert phi == pytest.approx(vibrations.phase_lag(eta, zeta), abs=1e-5)
    assert np.allclose(vibrations.steady_state_response(t, F0, k, m, c, Omega), sol.y[0], atol=1e-5 * X)


@settings(max_examples=20, deadline=None)
@given(zeta=st.floats(0.02, 0.65))
def test_resonance_peak_lies_at_the_stated_frequency_ratio(zeta):
    res = minimize_scalar(lambda e: -vibrations.amplification_factor(e, zeta), bounds=(0.0, 1.0),
                          method="bounded", options={"xatol": 1e-10})
    assert res.x == pytest.approx(vibrations.resonance_frequency_ratio(zeta), abs=1e-4)
    assert -res.fun == pytest.approx(vibrations.peak_amplification(zeta), rel=1e-8)


def test_base_excitation_amplitude_matches_simulation():
    m, k, zeta, Y = 2.0, 200.0, 0.15, 0.01
    w = vibrations.natural_frequency(k, m)
    c = vibrations.damping_coefficient(zeta, k, m)
    Omega = 1.3 * w
    # m x'' = -k (x - y) - c (x' - y'), y = Y cos(Omega t): a force k y + c y' on a fixed-base oscillator
    force = lambda s: k * Y * np.cos(Omega * s) - c * Y * Omega * np.sin(Omega * s)
    X, *_ = steady_amplitude_and_phase_from_simulation(m, c, k, 0.0, Omega, force)
    assert X == pytest.approx(vibrations.base_excitation_amplitude(Y, 1.3, zeta), rel=1e-5)
    # the spring deflection z = x - y
    _, _, sol, t = steady_amplitude_and_phase_from_simulation(m, c, k, 0.0, Omega, force)
    z = sol.y[0] - Y * np.cos(Omega * t)
    assert np.max(np.abs(z)) == pytest.approx(vibrations.relative_base_excitation_amplitude(Y, 1.3, zeta), rel=1e-3)


def test_rotating_unbalance_amplitude_and_transmitted_force_match_simulation():
    M, m_u, e, k, zeta = 50.0, 0.5, 0.02, 2.0e5, 0.1
    w = vibrations.natural_frequency(k, M)
    c = vibrations.damping_coefficient(zeta, k, M)
    Omega = 1.8 * w
    # the unbalance drives the machine with m_u e Omega^2 cos(Omega t)
    force = lambda s: m_u * e * Omega**2 * np.cos(Omega * s)
    X, _, sol, t = steady_amplitude_and_phase_from_simulation(M, c, k, 0.0, Omega, force)
    assert X == pytest.approx(vibrations.unbalance_amplitude(m_u, e, M, 1.8, zeta), rel=1e-5)
    FT = np.max(np.abs(k * sol.y[0] + c * sol.y[1]))
    assert FT == pytest.approx(vibrations.transmitted_force_amplitude(X, k, c, Omega), rel=1e-3)
    # and the transmissibility says the same: F_T = TR * m_u e Omega^2
    Xc = vibrations.unbalance_amplitude(m_u, e, M, 1.8, zeta)
    assert vibrations.transmitted_force_amplitude(Xc, k, c, Omega) == pytest.approx(
        vibrations.transmissibility(1.8, zeta) * m_u * e * Omega**2, rel=1e-12)


@SETTINGS
@given(m=st.floats(0.1, 50), omega=st.floats(0.5, 200))
def test_stiffness_from_frequency_gives_back_the_frequency_and_the_period(m, omega):
    k = vibrations.stiffness_from_natural_frequency(m, omega)
    # an oscillator with this k, started from x0 = 1, is back at 1 after T = 2 pi / omega
    T = vibrations.period(omega)
    sol = integrate(m, 0.0, k, 1.0, 0.0, T)
    assert sol.y[0, -1] == pytest.approx(1.0, abs=1e-7)
    assert vibrations.angular_frequency_from_period(T) == pytest.approx(omega, rel=1e-12)


def test_road_forcing_frequency_by_hand():
    # v = 72 km/h = 20 m/s over humps lambda = 8 m apart: 2.5 humps per second,
    # Omega = 2 pi 2.5 = 15.70796... rad/s; back to the speed for that Omega
    Omega = vibrations.road_forcing_frequency(20.0, 8.0)
    assert Omega == pytest.approx(15.707963268, rel=1e-10)
    assert vibrations.road_speed_for_forcing_frequency(Omega, 8.0) == pytest.approx(20.0, rel=1e-14)
    # the base y = Y cos(2 pi x / lambda) with x = v t repeats after lambda / v = 0.4 s
    assert vibrations.period(Omega) == pytest.approx(0.4, rel=1e-14)
