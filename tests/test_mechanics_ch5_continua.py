"""Deformable bodies, Sections 5.1-5.3: stiffness from the unit-load (Mohr) integral,
effective masses from quadrature and exact continuum solutions, rod and beam waves and
natural frequencies against lumped-mass chains, characteristic equations and Rayleigh.

Run this file as a script to print the observed order of convergence of the lumped rod.
"""
import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

from dynagrade.mechanics import beams, continua, multi_dof, rods, stiffness, vibrations
from deferred import deferred

sp = deferred("sympy")
quad = deferred("scipy.integrate", "quad")
brentq = deferred("scipy.optimize", "brentq")

SETTINGS = settings(max_examples=25, deadline=None)


# --- Section 5.1: stiffness of massless bars, shafts and beams -----------------------------

def mohr_deflection(moment_real, moment_virtual, EI, L):
    """Deflection by the principle of virtual work: int M m / (E I) dx."""
    value, _ = quad(lambda x: moment_real(x) * moment_virtual(x) / EI, 0.0, L, epsrel=1e-12)
    return value


@SETTINGS
@given(E=st.floats(5e10, 3e11), d=st.floats(0.005, 0.05), L=st.floats(0.2, 3.0))
def test_beam_stiffnesses_agree_with_the_unit_load_method(E, d, L):
    I = stiffness.circle_second_moment(d)
    EI = E * I
    # cantilever, unit tip force: M(x) = (L - x)
    tip = mohr_deflection(lambda x: L - x, lambda x: L - x, EI, L)
    assert stiffness.cantilever_tip_stiffness(E, I, L) == pytest.approx(1.0 / tip, rel=1e-9)
    # simply supported, unit midspan force: M(x) = x/2 on the left half (symmetric)
    mid = 2 * mohr_deflection(lambda x: x / 2, lambda x: x / 2, EI, L / 2)
    assert stiffness.simply_supported_midspan_stiffness(E, I, L) == pytest.approx(1.0 / mid, rel=1e-9)
    # clamped-clamped, unit midspan force: M(x) = x/2 - L/8 on the left half
    cc = 2 * mohr_deflection(lambda x: x / 2 - L / 8, lambda x: x / 2 - L / 8, EI, L / 2)
    assert stiffness.clamped_midspan_stiffness(E, I, L) == pytest.approx(1.0 / cc, rel=1e-9)
    # guided column (top slides without rotating), unit shear: M(x) = x - h/2
    col = mohr_deflection(lambda x: x - L / 2, lambda x: x - L / 2, EI, L)
    assert stiffness.column_sway_stiffness(E, I, L) == pytest.approx(1.0 / col, rel=1e-9)


def test_bar_and_shaft_stiffness_by_hand():
    # steel bar, d = 10 mm, L = 2 m: k = 210e9 * 7.853981e-5 / 2 = 8.2467e6 N/m
    assert stiffness.axial_stiffness(210e9, stiffness.circle_area(0.01), 2.0) == pytest.approx(8.24668e6, rel=1e-5)
    G = stiffness.shear_modulus(210e9, 0.3)
    assert G == pytest.approx(80.769e9, rel=1e-4)
    # k_t = G pi d^4 / 32 / L = 80.769e9 * 9.8175e-10 / 1 = 79.29 N m
    assert stiffness.torsional_stiffness(G, stiffness.circle_polar_moment(0.01), 1.0) == pytest.approx(79.295, rel=1e-4)
    assert stiffness.rectangle_second_moment(0.02, 0.01) == pytest.approx(0.02 * 1e-6 / 12)


@SETTINGS
@given(st.lists(st.floats(10, 1e5), min_size=1, max_size=5), st.floats(1.0, 100.0))
def test_series_springs_share_the_force_and_parallel_springs_share_the_elongation(ks, F):
    # series: each spring carries F, elongations F/k_i add up
    assert F / stiffness.series_stiffness(*ks) == pytest.approx(sum(F / k for k in ks), rel=1e-12)
    # parallel: all stretch by u, forces k_i u add up to F
    u = F / stiffness.parallel_stiffness(*ks)
    assert sum(k * u for k in ks) == pytest.approx(F, rel=1e-12)
    assert stiffness.series_stiffness(*ks) <= min(ks) * (1 + 1e-12)
    assert stiffness.parallel_stiffness(*ks) >= max(ks)


# --- Section 5.2: effective masses (Rayleigh) -------------------------------------------------

def test_effective_masses_are_the_kinetic_energy_integrals_of_the_static_shapes():
    L, mu = 1.3, 2.0
    m = mu * L
    # spring / bar: psi = x / L
    assert continua.effective_mass(mu, lambda x: x / L, L) == pytest.approx(continua.spring_effective_mass(m), rel=1e-12)
    # cantilever under a tip load: psi = x^2 (3 L - x) / (2 L^3)
    psi_c = lambda x: x**2 * (3 * L - x) / (2 * L**3)
    assert continua.effective_mass(mu, psi_c, L) == pytest.approx(continua.cantilever_effective_mass(m), rel=1e-10)
    # simply supported under a midspan load: psi = (3 L^2 x - 4 x^3) / L^3 on the left half
    psi_s = lambda x: (3 * L**2 * min(x, L - x) - 4 * min(x, L - x) ** 3) / L**3
    two_halves = 2 * continua.effective_mass(mu, psi_s, L / 2)
    assert two_halves == pytest.approx(continua.simply_supported_effective_mass(m), rel=1e-10)
    assert continua.rod_effective_mass(m) == pytest.approx(m / 3)


@SETTINGS
@given(mass_ratio=st.floats(0.01, 3.0))
def test_rayleigh_spring_mass_estimate_bounds_the_exact_frequency_from_above(mass_ratio):
    # a uniform bar (mass m_rod, stiffness EA/L) fixed at one end with a tip mass:
    # exact omega_1 from kL tan kL = m_rod / m_tip, Rayleigh from m_tip + m_rod/3
    E, A, rho, L = 2e11, 1e-4, 7800.0, 1.0
    m_rod = rho * A * L
    m_tip = m_rod / mass_ratio
    c = rods.longitudinal_wave_speed(E, rho)
    exact = rods.tip_mass_fundamental_frequency(c, L, m_rod, m_tip)
    k = stiffness.axial_stiffness(E, A, L)
    estimate = continua.rayleigh_frequency(k, m_tip, continua.rod_effective_mass(m_rod))
    naive = vibrations.natural_frequency(k, m_tip)
    assert exact <= estimate * (1 + 1e-12)
    assert estimate < naive
    # a light rod is captured very well (error of order (m_rod/m_tip)^2)
    assert (estimate - exact) / exact < 0.01 * max(mass_ratio, 0.05) ** 2 * 10


def test_beam_rayleigh_quotient_with_the_static_shape_bounds_the_cantilever_frequency():
    EI, rhoA, L = 2.0e4, 3.0, 1.5
    w1 = beams.beam_natural_frequencies(EI, rhoA, L, "cantilever", 1)[0]
    trial = lambda x: x**2 * (3 * L - x)
    trial_xx = lambda x: 6 * L - 6 * x
    R = continua.beam_rayleigh_quotient(EI, rhoA, trial, trial_xx, L)
    assert R >= w1**2
    # by hand: int 36 EI (L - x)^2 = 12 EI L^3, int rho A x^4 (3L - x)^2 = 33/35 rho A L^7,
    # R = 420/33 EI/(rho A L^4): the same as k = 3EI/L^3 on the effective mass 33/140 m_b
    assert R == pytest.approx(420 / 33 * EI / (rhoA * L**4), rel=1e-10)
    assert R == pytest.approx(stiffness.cantilever_tip_stiffness(EI, 1.0, L)
                              / continua.cantilever_effective_mass(rhoA * L), rel=1e-10)
    assert np.sqrt(R) / w1 - 1 < 0.015          # the static shape is a good trial function
    # a cruder admissible shape x^2 gives a looser, still upper bound: 20 EI/(rho A L^4)
    R2 = continua.beam_rayleigh_quotient(EI, rhoA, lambda x: x**2, lambda x: 2.0 + 0 * x, L)
    assert R2 == pytest.approx(20 * EI / (rhoA * L**4), rel=1e-10)
    assert R2 > R


@SETTINGS
@given(a=st.floats(0.05, 0.5), b=st.floats(-1, 1), c=st.floats(-1, 1))
def test_rayleigh_quotient_bounds_the_first_beam_frequency_from_above(a, b, c):
    # admissible for a simply supported beam: any combination of sin(j pi x / L)
    EI, rhoA, L = 1.0e3, 2.0, 2.0
    w1 = beams.beam_natural_frequencies(EI, rhoA, L, "simply supported", 1)[0]
    s = lambda j: (lambda x: np.sin(j * np.pi * x / L))
    w = lambda x: s(1)(x) + a * b * s(2)(x) + a * c * s(3)(x)
    w_xx = lambda x: -sum(coef * (j * np.pi / L) ** 2 * s(j)(x) for j, coef in ((1, 1.0), (2, a * b), (3, a * c)))
    assert continua.beam_rayleigh_quotient(EI, rhoA, w, w_xx, L) >= w1**2 * (1 - 1e-10)


# --- Section 5.3.1-5.3.2: longitudinal and torsional waves --------------------------------------

def test_dalembert_solution_satisfies_the_wave_equation():
    x, t, c = sp.symbols("x t c", positive=True)
    f = sp.Function("f")
    g = sp.Function("g")
    u = rods.dalembert_displacement(x, t, c, f, g)
    assert sp.simplify(sp.diff(u, t, 2) - c**2 * sp.diff(u, x, 2)) == 0


def test_a_pulse_travels_the_rod_in_L_over_c():
    E, rho, L = 2.1e11, 7850.0, 2.0
    c = rods.longitudinal_wave_speed(E, rho)
    assert c == pytest.approx(5172.2, rel=1e-4)                  # sqrt(2.1e11/7850)
    pulse = lambda s: np.exp(-((s / 0.05) ** 2))
    t = rods.travel_time(L, c)
    u = rods.dalembert_displacement(np.linspace(0, L, 2001), t, c, pulse, lambda s: 0 * s)
    assert np.linspace(0, L, 2001)[np.argmax(u)] == pytest.approx(L, abs=1e-3)
    # a rod end pushed at v = 1 m/s: sigma = rho c v, about 40.6 MPa
    sigma = rods.impact_stress(rho, c, 1.0)
    assert sigma == pytest.approx(7850 * 5172.2, rel=1e-4)
    assert rods.particle_velocity(sigma, rho, c) == pytest.approx(1.0)
    G = 8.1e10
    assert rods.torsional_wave_speed(G, rho) == pytest.approx(np.sqrt(G / rho))


@pytest.mark.parametrize("ends", rods.END_CONDITIONS)
def test_rod_modes_satisfy_the_end_conditions_and_the_wave_equation(ends):
    L, c = 1.7, 3000.0
    for j in (1, 2, 3):
        k = rods.rod_wavenumbers(L, j, ends)[-1]
        U = lambda x: rods.rod_mode_shape(x, L, j, ends)
        h = 1e-6
        dU = lambda x: (U(x + h) - U(x - h)) / (2 * h)
        left, right = ends.split("-")
        for end, x0 in ((left, 0.0), (right, L)):
            if end == "fixed":
                assert abs(U(x0)) < 1e-12
            else:
                assert abs(dU(x0)) < 1e-6 * k
        # U'' = -k^2 U at an interior point
        x0 = 0.37 * L
        d2 = (U(x0 + 1e-4) - 2 * U(x0) + U(x0 - 1e-4)) / 1e-8
        assert d2 == pytest.approx(-k**2 * U(x0), rel=1e-5)
    assert rods.rod_natural_frequencies(c, L, 1, ends)[0] == pytest.approx(c * rods.rod_wavenumbers(L, 1, ends)[0])


def observed_convergence_orders(ends="fixed-free", modes=3, sizes=(8, 16, 32, 64)):
    """Relative errors of the lumped chain's lowest frequencies and the observed orders log2(e_N / e_2N)."""
    E, A, rho, L = 2.0e11, 1.0e-4, 7800.0, 1.0
    exact = rods.rod_natural_frequencies(rods.longitudinal_wave_speed(E, rho), L, modes, ends)
    errors = []
    for N in sizes:
        K, M = rods.lumped_rod_matrices(E, A, rho, L, N, ends)
        w = multi_dof.natural_frequencies(K, M)
        w = w[w > 0][:modes]
        errors.append(np.abs(w - exact) / exact)
    errors = np.array(errors)
    return errors, np.log2(errors[:-1] / errors[1:])


@pytest.mark.parametrize("ends", rods.END_CONDITIONS)
def test_lumped_chain_frequencies_converge_to_the_rod_with_order_two(ends):
    errors, orders = observed_convergence_orders(ends)
    assert np.all(np.diff(errors, axis=0) < 0)                  # the error shrinks with N
    assert orders[-1] == pytest.approx(np.full(3, 2.0), abs=0.05)
    print(f"\n{ends}: observed orders (modes 1-3, N = 16->32->64): {np.round(orders[-1], 3)}")


# --- Section 5.3.3: flexural waves and beam vibrations --------------------------------------------

@pytest.mark.parametrize("support", beams.SUPPORTS)
def test_beam_eigenvalues_satisfy_their_characteristic_equations(support):
    roots = beams.beam_eigenvalues(support, 6)
    assert np.all(np.diff(roots) > 0) and roots[0] > 0
    # unscaled equations, relative to their size
    x = roots
    unscaled = {
        "simply supported": np.sin(x),
        "cantilever": (np.cos(x) * np.cosh(x) + 1) / np.cosh(x),
        "clamped-clamped": (np.cos(x) * np.cosh(x) - 1) / np.cosh(x),
        "free-free": (np.cos(x) * np.cosh(x) - 1) / np.cosh(x),
        "clamped-pinned": (np.tan(x) - np.tanh(x)) * np.cos(x),
    }[support]
    assert np.all(np.abs(unscaled) < 1e-12)
    # no root was skipped: the count of sign changes of the equation below the last root
    grid = np.linspace(0.05, roots[-1] + 0.05, 20000)
    values = beams.characteristic_function(grid, support)
    assert np.count_nonzero(np.diff(np.sign(values)) != 0) == len(roots)


def test_known_beam_eigenvalues():
    # classical values of beta_1 L (cantilever, clamped, clamped-pinned) and large-j asymptotes
    assert beams.beam_eigenvalues("cantilever", 3) == pytest.approx([1.875104, 4.694091, 7.854757], abs=1e-6)
    assert beams.beam_eigenvalues("clamped-clamped", 2) == pytest.approx([4.730041, 7.853205], abs=1e-6)
    assert beams.beam_eigenvalues("clamped-pinned", 1) == pytest.approx([3.926602], abs=1e-6)
    j = 8
    assert beams.beam_eigenvalues("cantilever", j)[-1] == pytest.approx((2 * j - 1) * np.pi / 2, abs=1e-6)


def test_cantilever_mode_shape_satisfies_the_beam_equation_and_the_boundary_conditions():
    L = 1.2
    x = sp.Symbol("x")
    for j in (1, 2, 3):
        bL = beams.beam_eigenvalues("cantilever", j)[-1]
        b = bL / L
        s = (np.cos(bL) + np.cosh(bL)) / (np.sin(bL) + np.sinh(bL))
        W = sp.cosh(b * x) - sp.cos(b * x) - s * (sp.sinh(b * x) - sp.sin(b * x))
        d = [sp.lambdify(x, sp.diff(W, x, n)) for n in range(5)]
        scale = b**3 * 2
        assert abs(d[0](0.0)) < 1e-12 and abs(d[1](0.0)) < 1e-12            # clamped
        assert abs(d[2](L)) < 1e-8 * b**2 * 2 and abs(d[3](L)) < 1e-8 * scale  # free: M = Q = 0
        assert d[4](0.4 * L) == pytest.approx(b**4 * d[0](0.4 * L), rel=1e-8)
        assert beams.cantilever_mode_shape(0.4 * L, L, j) == pytest.approx(d[0](0.4 * L), rel=1e-10)
        assert beams.cantilever_mode_shape(L, L, j) == pytest.approx(2 * (-1) ** (j + 1), rel=1e-9)


@SETTINGS
@given(omega=st.floats(10, 1e4), EI=st.floats(10, 1e5), rhoA=st.floats(0.1, 50))
def test_flexural_group_speed_is_the_slope_of_the_dispersion_relation(omega, EI, rhoA):
    k = beams.flexural_wavenumber(omega, EI, rhoA)
    assert beams.flexural_frequency(k, EI, rhoA) == pytest.approx(omega, rel=1e-12)
    h = 1e-6 * k
    slope = (beams.flexural_frequency(k + h, EI, rhoA) - beams.flexural_frequency(k - h, EI, rhoA)) / (2 * h)
    assert beams.flexural_group_speed(omega, EI, rhoA) == pytest.approx(slope, rel=1e-7)
    assert beams.flexural_group_speed(omega, EI, rhoA) == pytest.approx(2 * beams.flexural_phase_speed(omega, EI, rhoA))


def test_simply_supported_frequencies_by_hand():
    # omega_j = (j pi / L)^2 sqrt(EI / rho A); EI = 1e4, rho A = 4, L = 2: sqrt = 50
    w = beams.beam_natural_frequencies(1e4, 4.0, 2.0, "simply supported", 2)
    assert w == pytest.approx([(np.pi / 2) ** 2 * 50, np.pi**2 * 50], rel=1e-12)


def test_tip_mass_equation_root_by_hand_for_a_heavy_tip():
    # m_rod / m_tip = 0.01: kL tan kL = 0.01 -> kL ~ sqrt(0.01 / (1 + 0.01/3)) = 0.09983
    kL = brentq(rods.tip_mass_wavenumber_equation, 1e-9, np.pi / 2, args=(0.01,))
    assert kL * np.tan(kL) == pytest.approx(0.01, rel=1e-10)
    assert kL == pytest.approx(np.sqrt(0.01 / (1 + 0.01 / 3)), rel=1e-5)


if __name__ == "__main__":
    for ends in rods.END_CONDITIONS:
        errors, orders = observed_convergence_orders(ends, sizes=(8, 16, 32, 64, 128))
        print(f"{ends}: relative errors of modes 1-3 for N = 8, 16, 32, 64, 128")
        print(np.array2string(errors, precision=3))
        print("observed order log2(e_N / e_2N):")
        print(np.array2string(orders, precision=3))


@SETTINGS
@given(omega=st.floats(10, 5000), EI=st.floats(1, 1e4), rhoA=st.floats(0.1, 50))
def test_flexural_wave_repeats_after_one_wavelength(omega, EI, rhoA):
    k = beams.flexural_wavenumber(omega, EI, rhoA)
    lam = beams.wavelength(k)
    # cos(k x) over one wavelength: phase 2 pi; and lambda = c_p T (phase speed times period)
    assert np.cos(k * (0.3 + lam)) == pytest.approx(np.cos(k * 0.3), abs=1e-9)
    assert lam == pytest.approx(beams.flexural_phase_speed(omega, EI, rhoA) * 2 * np.pi / omega,
                                rel=1e-12)
