"""Single-degree-of-freedom vibrations, Section 4.3 of the notes.

The system is m x'' + c x' + k x = F(t) (Section 4.3.1).  Free vibrations
(Section 4.3.2) are described by the natural frequency omega_n = sqrt(k/m) and the
damping ratio zeta = c / (2 sqrt(k m)); harmonic forcing F(t) = F0 cos(Omega t)
(Section 4.3.3) by the frequency ratio eta = Omega / omega_n.  Angular frequencies
are in rad/s, frequencies in Hz, angles in rad.  Functions accept floats or numpy
arrays that broadcast together.
"""
from __future__ import annotations

import numpy as np

from dynagrade.mechanics._common import ArrayLike, Quantity
from dynagrade.mechanics.energy import particle_kinetic_energy, spring_potential


# --- Section 4.3.1: definitions, equivalent mass and stiffness -------------------

def natural_frequency(k: Quantity, m: Quantity) -> Quantity:
    """Undamped natural (angular) frequency omega_n = sqrt(k/m) in rad/s, Section 4.3.1."""
    return np.sqrt(k / m)


def frequency_in_hertz(omega: Quantity) -> Quantity:
    """Frequency f = omega / (2 pi) in Hz of an angular frequency omega, Section 4.3.1."""
    return omega / (2.0 * np.pi)


def period(omega: Quantity) -> Quantity:
    """Period T = 2 pi / omega of a vibration with angular frequency omega, Section 4.3.1."""
    return 2.0 * np.pi / omega


def angular_frequency_from_period(T: Quantity) -> Quantity:
    """Angular frequency omega = 2 pi / T in rad/s of a vibration with period T, Section 4.3.1."""
    return 2.0 * np.pi / T


def stiffness_from_natural_frequency(m: Quantity, omega_n: Quantity) -> Quantity:
    """Stiffness k = m omega_n^2 that gives the mass m the natural frequency omega_n,
    omega_n = sqrt(k/m) solved for k, Section 4.3.1."""
    return m * omega_n**2


def static_deflection(m: Quantity, k: Quantity, g: Quantity) -> Quantity:
    """Static deflection delta_st = m g / k of a mass hanging on a spring, Section 4.3.1."""
    return m * g / k


def natural_frequency_from_static_deflection(delta_st: Quantity, g: Quantity) -> Quantity:
    """Natural frequency omega_n = sqrt(g / delta_st) from the static deflection, Section 4.3.1."""
    return np.sqrt(g / delta_st)


def equivalent_mass(inertias: ArrayLike, ratios: ArrayLike) -> float:
    """Equivalent mass m_eq = sum_i m_i (d u_i / d q)^2 of a 1-DOF system, Section 4.3.1.

    ``inertias`` are the masses (or mass moments of inertia) of the bodies, ``ratios``
    the kinematic transmission ratios d u_i/d q (or d phi_i/d q) of their velocities to
    the generalized velocity q', so that T = m_eq q'^2 / 2.
    """
    inertias = np.asarray(inertias, dtype=float)
    ratios = np.asarray(ratios, dtype=float)
    return float(np.sum(inertias * ratios**2))


def equivalent_stiffness(stiffnesses: ArrayLike, ratios: ArrayLike) -> float:
    """Equivalent stiffness k_eq = sum_i k_i (d u_i / d q)^2 of a 1-DOF system, Section 4.3.1.

    ``ratios`` are the elongations of the springs per unit generalized coordinate, so that
    V = k_eq q^2 / 2.
    """
    stiffnesses = np.asarray(stiffnesses, dtype=float)
    ratios = np.asarray(ratios, dtype=float)
    return float(np.sum(stiffnesses * ratios**2))


def mechanical_energy(x: Quantity, v: ArrayLike, k: Quantity, m: Quantity) -> Quantity:
    """Total mechanical energy E = m v^2/2 + k x^2/2 of the oscillator, Section 4.3.1."""
    # v is a (possibly time-sampled) scalar velocity: one component per sample
    return particle_kinetic_energy(m, np.asarray(v, dtype=float)[..., None]) + spring_potential(k, x)


# --- Section 4.3.2: free vibrations ------------------------------------------------

def critical_damping(k: Quantity, m: Quantity) -> Quantity:
    """Critical damping coefficient c_cr = 2 sqrt(k m), Section 4.3.2."""
    return 2.0 * np.sqrt(k * m)


def damping_ratio(c: Quantity, k: Quantity, m: Quantity) -> Quantity:
    """Damping ratio (Lehr's damping) zeta = c / (2 sqrt(k m)), Section 4.3.2."""
    return c / critical_damping(k, m)


def damping_coefficient(zeta: Quantity, k: Quantity, m: Quantity) -> Quantity:
    """Viscous damping coefficient c = 2 zeta sqrt(k m) for a damping ratio zeta, Section 4.3.2."""
    return zeta * critical_damping(k, m)


def damped_frequency(omega_n: Quantity, zeta: Quantity) -> Quantity:
    """Damped natural frequency omega_d = omega_n sqrt(1 - zeta^2) (zeta < 1), Section 4.3.2.

    At zeta = 0.6, omega_d = omega_n sqrt(1 - 0.36) = 0.8 omega_n.

    >>> round(float(damped_frequency(10.0, 0.6)), 12)
    8.0
    """
    return omega_n * np.sqrt(1.0 - zeta**2)


def damping_regime(zeta: float, tol: float = 1e-9) -> str:
    """Name of the free-vibration regime for a damping ratio zeta, Section 4.3.2.

    One of "undamped", "underdamped", "critically damped", "overdamped".
    """
    if zeta < 0:
        raise ValueError("the damping ratio must be non-negative")
    if zeta <= tol:
        return "undamped"
    if abs(zeta - 1.0) <= tol:
        return "critically damped"
    return "underdamped" if zeta < 1.0 else "overdamped"


def natural_frequency_from_damped(omega_d: Quantity, zeta: Quantity) -> Quantity:
    """Undamped natural frequency omega_n = omega_d / sqrt(1 - zeta^2) from a measured damped one, Section 4.3.2.

    At zeta = 0.3 a measured omega_d = 10 rad/s means omega_n = 10 / sqrt(0.91) = 10.4828 rad/s;
    without damping the two are equal.

    >>> round(float(natural_frequency_from_damped(10.0, 0.3)), 4)
    10.4828
    >>> float(natural_frequency_from_damped(10.0, 0.0))
    10.0
    """
    return omega_d / np.sqrt(1.0 - zeta**2)


def logarithmic_decrement(zeta: Quantity) -> Quantity:
    """Logarithmic decrement delta = ln(x_i / x_{i+1}) = 2 pi zeta / sqrt(1 - zeta^2), Section 4.3.2."""
    return 2.0 * np.pi * zeta / np.sqrt(1.0 - zeta**2)


def logarithmic_decrement_from_amplitudes(x_first: Quantity, x_later: Quantity,
                                          cycles: int) -> Quantity:
    """Logarithmic decrement delta = ln(x_0 / x_n) / n from two peaks n cycles apart, Section 4.3.2."""
    return np.log(x_first / x_later) / cycles


def damping_ratio_from_decrement(delta: Quantity) -> Quantity:
    """Damping ratio zeta = delta / sqrt(4 pi^2 + delta^2) from the logarithmic decrement, Section 4.3.2.

    Inverse of :func:`logarithmic_decrement`: zeta = 0.6 gives delta = 2 pi 0.6 / 0.8 = 1.5 pi.

    >>> round(float(damping_ratio_from_decrement(1.5 * np.pi)), 12)
    0.6
    """
    return delta / np.sqrt(4.0 * np.pi**2 + delta**2)


def _free_response_state(t, x0, v0, omega_n, zeta):
    """Displacement and velocity of the free response (helper of the two public relations)."""
    t = np.asarray(t, dtype=float)
    w = omega_n
    regime = damping_regime(zeta, tol=1e-7)
    if regime == "undamped":
        x = x0 * np.cos(w * t) + v0 / w * np.sin(w * t)
        v = -x0 * w * np.sin(w * t) + v0 * np.cos(w * t)
    elif regime == "underdamped":
        wd = damped_frequency(w, zeta)
        s = zeta * w
        a, b = x0, (v0 + s * x0) / wd
        e = np.exp(-s * t)
        c, sn = np.cos(wd * t), np.sin(wd * t)
        x = e * (a * c + b * sn)
        v = e * ((b * wd - s * a) * c - (a * wd + s * b) * sn)
    elif regime == "critically damped":
        b = v0 + w * x0
        e = np.exp(-w * t)
        x = (x0 + b * t) * e
        v = (b - w * (x0 + b * t)) * e
    else:
        r = w * np.sqrt(zeta**2 - 1.0)
        lam1, lam2 = -zeta * w + r, -zeta * w - r
        a1 = (v0 - lam2 * x0) / (lam1 - lam2)
        a2 = (lam1 * x0 - v0) / (lam1 - lam2)
        x = a1 * np.exp(lam1 * t) + a2 * np.exp(lam2 * t)
        v = a1 * lam1 * np.exp(lam1 * t) + a2 * lam2 * np.exp(lam2 * t)
    return x, v


def free_response(t: Quantity, x0: Quantity, v0: Quantity, omega_n: Quantity,
                  zeta: Quantity) -> Quantity:
    """Displacement x(t) of the free vibration with x(0) = x0, x'(0) = v0, Section 4.3.2.

    Covers the undamped (zeta = 0), underdamped (0 < zeta < 1), critically damped
    (zeta = 1) and overdamped (zeta > 1) cases.
    """
    return _free_response_state(t, x0, v0, omega_n, zeta)[0]


def free_response_velocity(t: Quantity, x0: Quantity, v0: Quantity, omega_n: Quantity,
                           zeta: Quantity) -> Quantity:
    """Velocity x'(t) of the free vibration with x(0) = x0, x'(0) = v0, Section 4.3.2."""
    return _free_response_state(t, x0, v0, omega_n, zeta)[1]


# --- Section 4.3.3: forced vibrations ----------------------------------------------

def frequency_ratio(Omega: Quantity, omega_n: Quantity) -> Quantity:
    """Frequency ratio eta = Omega / omega_n of excitation and natural frequency, Section 4.3.3."""
    return Omega / omega_n


def amplification_factor(eta: Quantity, zeta: Quantity) -> Quantity:
    """Dynamic amplification V = 1 / sqrt((1 - eta^2)^2 + (2 zeta eta)^2), Section 4.3.3.

    Ratio of the steady-state amplitude to the static deflection F0/k under a harmonic force.
    """
    return 1.0 / np.sqrt((1.0 - eta**2) ** 2 + (2.0 * zeta * eta) ** 2)


def phase_lag(eta: Quantity, zeta: Quantity) -> Quantity:
    """Phase lag phi in [0, pi] of the steady-state response behind the force, Section 4.3.3.

    tan(phi) = 2 zeta eta / (1 - eta^2); x(t) = X cos(Omega t - phi).
    """
    return np.arctan2(2.0 * zeta * eta, 1.0 - eta**2)


def steady_state_amplitude(F0: Quantity, k: Quantity, eta: Quantity,
                           zeta: Quantity) -> Quantity:
    """Steady-state amplitude X = (F0/k) V(eta, zeta) under F0 cos(Omega t), Section 4.3.3."""
    return F0 / k * amplification_factor(eta, zeta)


def steady_state_response(t: ArrayLike, F0: Quantity, k: Quantity, m: Quantity, c: Quantity,
                          Omega: Quantity) -> Quantity:
    """Steady-state displacement x_p(t) = X cos(Omega t - phi) under F0 cos(Omega t), Section 4.3.3."""
    w = natural_frequency(k, m)
    zeta = damping_ratio(c, k, m)
    eta = frequency_ratio(Omega, w)
    X = steady_state_amplitude(F0, k, eta, zeta)
    return X * np.cos(Omega * np.asarray(t, dtype=float) - phase_lag(eta, zeta))


def resonance_frequency_ratio(zeta: Quantity) -> Quantity:
    """Frequency ratio eta_res = sqrt(1 - 2 zeta^2) of the amplitude peak (zeta < 1/sqrt 2), Section 4.3.3."""
    return np.sqrt(1.0 - 2.0 * zeta**2)


def peak_amplification(zeta: Quantity) -> Quantity:
    """Largest dynamic amplification V_max = 1 / (2 zeta sqrt(1 - zeta^2)) (zeta < 1/sqrt 2), Section 4.3.3."""
    return 1.0 / (2.0 * zeta * np.sqrt(1.0 - zeta**2))


def transmissibility(eta: Quantity, zeta: Quantity) -> Quantity:
    """Transmissibility TR = sqrt(1 + (2 zeta eta)^2) V(eta, zeta), Section 4.3.3.

    Ratio of the absolute amplitude of a base-excited mass to the base amplitude, and
    equally of the force transmitted to the foundation to the applied force amplitude.
    """
    return np.sqrt(1.0 + (2.0 * zeta * eta) ** 2) * amplification_factor(eta, zeta)


def road_forcing_frequency(v: Quantity, wavelength: Quantity) -> Quantity:
    """Forcing frequency Omega = 2 pi v / lambda of the base of a vehicle driving at speed v over
    a wavy road of wavelength lambda (base excitation y = Y cos(Omega t)), Section 4.3.3."""
    return 2 * np.pi * v / wavelength


def road_speed_for_forcing_frequency(Omega: Quantity, wavelength: Quantity) -> Quantity:
    """Driving speed v = Omega lambda / (2 pi) at which a wavy road of wavelength lambda excites
    the base with the frequency Omega (road_forcing_frequency solved for v), Section 4.3.3."""
    return Omega * wavelength / (2 * np.pi)


def base_excitation_amplitude(Y: Quantity, eta: Quantity, zeta: Quantity) -> Quantity:
    """Absolute steady-state amplitude X = Y TR of a mass whose base moves as Y cos(Omega t), Section 4.3.3."""
    return Y * transmissibility(eta, zeta)


def relative_base_excitation_amplitude(Y: Quantity, eta: Quantity, zeta: Quantity) -> Quantity:
    """Amplitude Z = Y eta^2 V of the spring deflection under base motion Y cos(Omega t), Section 4.3.3."""
    return Y * eta**2 * amplification_factor(eta, zeta)


def unbalance_amplitude(m_u: Quantity, e: Quantity, M: Quantity, eta: Quantity,
                        zeta: Quantity) -> Quantity:
    """Steady-state amplitude X = (m_u e / M) eta^2 V of a machine with rotating unbalance, Section 4.3.3.

    ``M`` is the total vibrating mass (including the unbalance mass m_u at eccentricity e).
    """
    return m_u * e / M * eta**2 * amplification_factor(eta, zeta)


def transmitted_force_amplitude(X: Quantity, k: Quantity, c: Quantity,
                                Omega: Quantity) -> Quantity:
    """Amplitude F_T = X sqrt(k^2 + (c Omega)^2) of the force spring and damper pass to the ground, Section 4.3.3."""
    return X * np.sqrt(k**2 + (c * Omega) ** 2)


# --- issue 31, chapter 4 exercises: relations the new exercises need ----------------------

def equivalent_weight(masses: ArrayLike, ratios: ArrayLike, g: Quantity) -> float:
    """Generalized gravity force W_eq = g sum_i m_i (d u_i / d q) of a 1-DOF system, Section 4.3.1.

    ``ratios`` are the downward displacements of the bodies' centres of mass per unit
    generalized coordinate (the same transmission ratios as in :func:`equivalent_mass`, but
    not squared: gravity does the virtual work W_eq dq). The static deflection of the
    coordinate on a spring of stiffness k_eq is W_eq / k_eq.
    """
    masses = np.asarray(masses, dtype=float)
    ratios = np.asarray(ratios, dtype=float)
    return float(g * np.sum(masses * ratios))


def envelope_decay_time(omega_n: Quantity, zeta: Quantity, ratio: Quantity) -> Quantity:
    """Time t = ln(1/ratio) / (zeta omega_n) in which the envelope e^{-zeta omega_n t} of an
    underdamped free vibration falls to ``ratio`` of its start, Section 4.3.2."""
    return np.log(1.0 / ratio) / (zeta * omega_n)


def liquid_column_mass(rho: Quantity, A: Quantity, L: Quantity) -> Quantity:
    """Equivalent mass m_eq = rho A L of a liquid column of length L (measured along a tube
    of cross-section A) moving as one body, Section 4.3.1."""
    return rho * A * L


def u_tube_stiffness(rho: Quantity, A: Quantity, g: Quantity) -> Quantity:
    """Equivalent stiffness k_eq = 2 rho g A of the liquid in a U-tube, Section 4.3.1.

    Displacing the column by x along the tube raises one surface by x and lowers the other
    by x: V = rho g A x^2 (a column x lifted by x), so V = k_eq x^2 / 2.
    """
    return 2.0 * rho * g * A
