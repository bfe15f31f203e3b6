"""Flexural waves and vibrations of Euler-Bernoulli beams, Section 5.3.3 of the notes.

The deflection w(x, t) obeys E I w_xxxx + rho A w_tt = 0.  Harmonic waves
w = exp(i (k x - omega t)) satisfy the dispersion relation omega = k^2 sqrt(EI/(rho A)),
so flexural waves are dispersive: the phase speed grows with frequency and the group
speed is twice the phase speed.  Standing waves w = W(x) cos(omega t) on a beam of
length L, W = a cos(beta x) + b sin(beta x) + c cosh(beta x) + d sinh(beta x), have
natural frequencies omega_j = (beta_j L)^2 / L^2 sqrt(EI / (rho A)) where beta_j L are
the positive roots of the characteristic equation of the supports.
"""
from __future__ import annotations

import numpy as np

from dynagrade.mechanics._common import ArrayLike, Quantity

SUPPORTS = ("simply supported", "cantilever", "clamped-clamped", "free-free", "clamped-pinned")


def bending_wave_parameter(EI: Quantity, rhoA: Quantity) -> Quantity:
    """Beam constant a = sqrt(E I / (rho A)) (in m^2/s) of the dispersion relation, Section 5.3.3."""
    return np.sqrt(EI / rhoA)


def wavelength(k: Quantity) -> Quantity:
    """Wavelength lambda = 2 pi / k of a harmonic wave exp(i (k x - omega t)) of wavenumber k,
    Section 5.3."""
    return 2 * np.pi / k


def flexural_frequency(k: Quantity, EI: Quantity, rhoA: Quantity) -> Quantity:
    """Angular frequency omega = k^2 sqrt(EI / (rho A)) of a flexural wave of wavenumber k, Section 5.3.3."""
    return k**2 * bending_wave_parameter(EI, rhoA)


def flexural_wavenumber(omega: Quantity, EI: Quantity, rhoA: Quantity) -> Quantity:
    """Wavenumber k = sqrt(omega / sqrt(EI / (rho A))) of a flexural wave, Section 5.3.3."""
    return np.sqrt(omega / bending_wave_parameter(EI, rhoA))


def flexural_phase_speed(omega: Quantity, EI: Quantity, rhoA: Quantity) -> Quantity:
    """Phase speed c_p = omega / k = sqrt(omega) (EI / (rho A))^(1/4) of flexural waves, Section 5.3.3."""
    return omega / flexural_wavenumber(omega, EI, rhoA)


def flexural_group_speed(omega: Quantity, EI: Quantity, rhoA: Quantity) -> Quantity:
    """Group speed c_g = d omega / d k = 2 c_p of flexural waves, Section 5.3.3."""
    return 2.0 * bending_wave_parameter(EI, rhoA) * flexural_wavenumber(omega, EI, rhoA)


def characteristic_function(beta_L: ArrayLike, support: str) -> Quantity:
    """Characteristic equation of the beam's supports, scaled by 1/cosh(beta L), Section 5.3.3.

    simply supported: sin(bL) = 0; cantilever: cos(bL) cosh(bL) + 1 = 0;
    clamped-clamped and free-free: cos(bL) cosh(bL) - 1 = 0;
    clamped-pinned: tan(bL) - tanh(bL) = 0 (as sin(bL) - cos(bL) tanh(bL) = 0).
    The scaling keeps the values finite without moving the roots.
    """
    x = np.asarray(beta_L, dtype=float)
    if support == "simply supported":
        return np.sin(x)
    if support == "cantilever":
        return np.cos(x) + 1.0 / np.cosh(x)
    if support in ("clamped-clamped", "free-free"):
        return np.cos(x) - 1.0 / np.cosh(x)
    if support == "clamped-pinned":
        return np.sin(x) - np.cos(x) * np.tanh(x)
    raise ValueError(f"support must be one of {SUPPORTS}")


def beam_eigenvalues(support: str, n: int) -> np.ndarray:
    """First n positive roots beta_j L of the characteristic equation, Section 5.3.3.

    Found by brentq, the j-th root bracketed in [j pi, (j + 1) pi] except for the
    cantilever ([(j - 1) pi, j pi]) and the simply supported beam (exactly j pi).
    """
    from scipy.optimize import brentq
    j = np.arange(1, n + 1)
    if support == "simply supported":
        return j * np.pi
    shift = -1 if support == "cantilever" else 0
    roots = []
    for jj in j:
        a, b = float((jj + shift) * np.pi), float((jj + shift + 1) * np.pi)
        if support == "cantilever" and jj == 1:
            a = 0.0
        roots.append(brentq(lambda bL: float(characteristic_function(bL, support)), a, b,
                            xtol=1e-14))
    return np.array(roots)


def beam_natural_frequencies(EI: Quantity, rhoA: Quantity, L: Quantity, support: str,
                             n: int) -> Quantity:
    """First n natural angular frequencies omega_j = (beta_j L)^2 sqrt(EI/(rho A)) / L^2, Section 5.3.3."""
    return beam_eigenvalues(support, n) ** 2 / L**2 * bending_wave_parameter(EI, rhoA)


def cantilever_mode_shape(x: ArrayLike, L: Quantity, j: int) -> Quantity:
    """Mode shape W_j(x) of the j-th mode of a cantilever clamped at x = 0 (W_j(L) = 2 (-1)^(j+1)), Section 5.3.3.

    W = cosh(bx) - cos(bx) - s (sinh(bx) - sin(bx)), s = (cos bL + cosh bL)/(sin bL + sinh bL).
    """
    bL = beam_eigenvalues("cantilever", j)[-1]
    b = bL / L
    s = (np.cos(bL) + np.cosh(bL)) / (np.sin(bL) + np.sinh(bL))
    x = np.asarray(x, dtype=float)
    return np.cosh(b * x) - np.cos(b * x) - s * (np.sinh(b * x) - np.sin(b * x))


# -- issue 31, chapter 5's new exercises: a free-free bar tuned to a pitch ---------------

def free_free_mode_shape(x: ArrayLike, L: Quantity, j: int) -> Quantity:
    """Mode shape W_j(x) of the j-th flexural mode of a free-free beam (W_j(0) = 2),
    Section 5.3.3.

    W = cosh(bx) + cos(bx) - s (sinh(bx) + sin(bx)), s = (cosh bL - cos bL)/(sinh bL - sin bL),
    which leaves both ends free of moment and shear force.
    """
    bL = beam_eigenvalues("free-free", j)[-1]
    b = bL / L
    s = (np.cosh(bL) - np.cos(bL)) / (np.sinh(bL) - np.sin(bL))
    x = np.asarray(x, dtype=float)
    return np.cosh(b * x) + np.cos(b * x) - s * (np.sinh(b * x) + np.sin(b * x))


def free_free_nodes(L: Quantity, j: int) -> np.ndarray:
    """The j + 1 nodes (points at rest) of the j-th flexural mode of a free-free beam,
    from x = 0 to L, Section 5.3.3; mode 1 has its two at 0.2242 L from the ends."""
    from scipy.optimize import brentq
    # an even count of points: the middle, a node of the even modes, falls between two
    grid = np.linspace(0.0, L, 40 * (j + 2))
    values = np.asarray(free_free_mode_shape(grid, L, j))
    return np.array([brentq(lambda x: float(free_free_mode_shape(x, L, j)), a, b, xtol=1e-15)
                     for a, b, fa, fb in zip(grid, grid[1:], values, values[1:]) if fa * fb < 0])


def beam_length_for_frequency(omega: Quantity, EI: Quantity, rhoA: Quantity, support: str,
                              j: int = 1) -> Quantity:
    """Length L = beta_j L (EI / (rho A))^(1/4) / sqrt(omega) whose j-th natural angular
    frequency is omega, the inverse of beam_natural_frequencies, Section 5.3.3."""
    return beam_eigenvalues(support, j)[-1] * np.sqrt(bending_wave_parameter(EI, rhoA) / omega)
