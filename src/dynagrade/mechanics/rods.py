"""Longitudinal and torsional waves and vibrations of slender rods, Sections 5.3.1-5.3.2.

Both motions obey the wave equation u_tt = c^2 u_xx, with c = sqrt(E/rho) for the
axial displacement u (Section 5.3.1) and c = sqrt(G/rho) for the twist angle
(Section 5.3.2).  Its general solution is d'Alembert's u = f(x - c t) + g(x + c t);
on a rod of length L the standing waves u = U(x) cos(omega t) give the natural
frequencies from the end conditions (fixed: u = 0; free: u_x = 0).
"""
from __future__ import annotations

import numpy as np

from dynagrade.mechanics._common import ArrayLike, Field, Quantity
from dynagrade.mechanics import multi_dof

END_CONDITIONS = ("fixed-fixed", "free-free", "fixed-free")


def longitudinal_wave_speed(E: Quantity, rho: Quantity) -> Quantity:
    """Speed c = sqrt(E / rho) of longitudinal waves in a slender rod, Section 5.3.1."""
    return np.sqrt(E / rho)


def torsional_wave_speed(G: Quantity, rho: Quantity) -> Quantity:
    """Speed c_T = sqrt(G / rho) of torsional waves in a rod of circular section, Section 5.3.2."""
    return np.sqrt(G / rho)


def travel_time(L: Quantity, c: Quantity) -> Quantity:
    """Time t = L / c a wave front needs to cross a distance L, Section 5.3.1."""
    return L / c


def dalembert_displacement(x: ArrayLike, t: Quantity, c: Quantity, f: Field,
                           g: Field) -> Quantity:
    """d'Alembert solution u(x, t) = f(x - c t) + g(x + c t) of the wave equation, Section 5.3.1.

    ``f`` (travelling towards +x) and ``g`` (towards -x) are callables.
    """
    return f(np.asarray(x) - c * t) + g(np.asarray(x) + c * t)


def impact_stress(rho: Quantity, c: Quantity, v: Quantity) -> Quantity:
    """Stress sigma = rho c v carried by a wave whose particle velocity is v, Section 5.3.1.

    Compressive when the rod end is pushed into the rod at speed v (for a step in velocity).
    """
    return rho * c * v


def particle_velocity(sigma: Quantity, rho: Quantity, c: Quantity) -> Quantity:
    """Particle velocity v = sigma / (rho c) behind a wave front of stress sigma, Section 5.3.1."""
    return sigma / (rho * c)


def rod_wavenumbers(L: Quantity, n: int, ends: str) -> np.ndarray:
    """Wavenumbers k_j = omega_j / c of the first n natural modes of a rod, Section 5.3.1.

    fixed-fixed and free-free: k_j = j pi / L (free-free without its rigid-body mode);
    fixed-free: k_j = (2 j - 1) pi / (2 L).
    """
    j = np.arange(1, n + 1)
    if ends in ("fixed-fixed", "free-free"):
        return j * np.pi / L
    if ends == "fixed-free":
        return (2 * j - 1) * np.pi / (2.0 * L)
    raise ValueError(f"ends must be one of {END_CONDITIONS}")


def rod_natural_frequencies(c: Quantity, L: Quantity, n: int, ends: str) -> Quantity:
    """First n natural angular frequencies omega_j = c k_j of a rod, Sections 5.3.1-5.3.2."""
    return c * rod_wavenumbers(L, n, ends)


def rod_mode_shape(x: ArrayLike, L: Quantity, j: int, ends: str) -> Quantity:
    """Mode shape U_j(x) of the j-th natural mode of a rod (maximum 1), Section 5.3.1."""
    k = rod_wavenumbers(L, j, ends)[-1]
    x = np.asarray(x, dtype=float)
    return np.cos(k * x) if ends == "free-free" else np.sin(k * x)


def tip_mass_wavenumber_equation(kL: Quantity, mass_ratio: Quantity) -> Quantity:
    """Frequency equation kL tan(kL) - m_rod/m_tip of a fixed-free rod with a tip mass, Section 5.3.1.

    Written as kL sin(kL) - ratio cos(kL), which is free of the poles of tan.
    """
    return kL * np.sin(kL) - mass_ratio * np.cos(kL)


def tip_mass_fundamental_frequency(c: Quantity, L: Quantity, m_rod: Quantity,
                                   m_tip: Quantity) -> Quantity:
    """Lowest natural frequency omega_1 = c k_1 of a fixed-free rod carrying a tip mass, Section 5.3.1.

    k_1 L is the root in (0, pi/2) of kL tan(kL) = m_rod / m_tip.
    """
    from scipy.optimize import brentq
    ratio = m_rod / m_tip
    kL = brentq(lambda kL: float(tip_mass_wavenumber_equation(kL, ratio)), 1e-12, np.pi / 2.0,
                xtol=1e-14)
    return c * kL / L


def lumped_rod_matrices(E: Quantity, A: Quantity, rho: Quantity, L: Quantity, N: int,
                        ends: str = "fixed-free") -> tuple[Quantity, Quantity]:
    """(K, M) of a rod cut into N equal elements, each a spring E A N / L with its mass
    rho A L / N split onto its two end nodes, Sections 4.4.1 and 5.3.1.

    Fixed nodes are removed.  The chain's lowest frequencies approach the rod's as N grows.
    """
    h = L / N
    k = E * A / h
    m_node = np.full(N + 1, rho * A * h)
    m_node[0] = m_node[-1] = 0.5 * rho * A * h
    springs = np.full(N, k)
    if ends == "fixed-free":
        return multi_dof.chain_stiffness_matrix(springs), multi_dof.lumped_mass_matrix(m_node[1:])
    if ends == "fixed-fixed":
        return (multi_dof.chain_stiffness_matrix(springs, right_wall=True),
                multi_dof.lumped_mass_matrix(m_node[1:-1]))
    if ends == "free-free":
        return (multi_dof.chain_stiffness_matrix(np.concatenate([[0.0], springs])),
                multi_dof.lumped_mass_matrix(m_node))
    raise ValueError(f"ends must be one of {END_CONDITIONS}")


# -- issue 31, chapter 5's new exercises: rods colliding end on, a rod loaded suddenly ---

def mechanical_impedance(rho: Quantity, c: Quantity, A: Quantity) -> Quantity:
    """Impedance Z = rho c A of a rod: the force N = Z v that a wave of particle velocity v
    carries (N = sigma A with sigma = rho c v), Section 5.3.1."""
    return rho * c * A


def interface_velocity(Z_striker: Quantity, Z_struck: Quantity, v: Quantity) -> Quantity:
    """Particle velocity v_i = v Z_1 / (Z_1 + Z_2) of the contact face while a rod of
    impedance Z_1 moving at v strikes a rod of impedance Z_2 at rest, end on, Section 5.3.1.

    The wave into the struck rod carries N = Z_2 v_i, the one into the striker
    N = Z_1 (v - v_i); both forces are the one contact force. Equal rods: v_i = v / 2.
    """
    return v * Z_striker / (Z_striker + Z_struck)


def contact_duration(L_striker: Quantity, c: Quantity) -> Quantity:
    """Duration t_c = 2 L_1 / c of the contact of a rod of length L_1 striking, end on, a
    rod of the same impedance and of length L_2 >= L_1 at rest, Section 5.3.1.

    The compressive wave runs through the striker, reflects at its free end as a release
    wave and, back at the contact face after 2 L_1 / c, leaves the striker at rest.
    """
    return 2.0 * L_striker / c


def step_load_peak_displacement(F: Quantity, E: Quantity, A: Quantity, L: Quantity) -> Quantity:
    """Largest displacement 2 F L / (E A) of the free end of a rod clamped at the other end
    when a constant force F is suddenly applied there, Section 5.3.1.

    The end moves at F / (rho c A) until the wave, reflected at the clamped end, returns
    after 2 L / c: twice the static elongation F L / (E A).
    """
    return 2.0 * F * L / (E * A)


def clamped_end_peak_stress(sigma: Quantity) -> Quantity:
    """Stress 2 sigma at a clamped end when a wave of stress sigma reflects there (the
    reflected wave has the same sign and adds to the incident one), Section 5.3.1."""
    return 2.0 * sigma


def tip_mass_natural_frequencies(c: Quantity, L: Quantity, m_rod: Quantity, m_tip: Quantity,
                                 n: int) -> np.ndarray:
    """First n natural angular frequencies omega_j = c k_j of a fixed-free rod carrying a
    tip mass (or of a shaft carrying a disk: m_rod and m_tip its and the disk's mass moments
    of inertia about the axis), Sections 5.3.1-5.3.2.

    k_j L is the root of kL tan(kL) = m_rod / m_tip in ((j - 1) pi, (j - 1/2) pi): between
    a clamped end (heavy tip, (j - 1) pi) and a free one (light tip, (j - 1/2) pi).
    """
    from scipy.optimize import brentq
    ratio = m_rod / m_tip
    roots = [brentq(lambda kL: float(tip_mass_wavenumber_equation(kL, ratio)),
                    (j - 1) * np.pi + 1e-12, (j - 0.5) * np.pi, xtol=1e-14)
             for j in range(1, n + 1)]
    return c * np.array(roots) / L


def torsional_impedance(rho: Quantity, c_T: Quantity, I_p: Quantity) -> Quantity:
    """Torsional impedance rho c_T I_p of a round shaft: the torque T = rho c_T I_p Omega
    that a torsional wave of angular velocity Omega carries, Section 5.3.2."""
    return rho * c_T * I_p


def torsion_shear_stress(T: Quantity, r: Quantity, I_p: Quantity) -> Quantity:
    """Shear stress tau = T r / I_p at the radius r of a round shaft carrying the torque T,
    Section 5.3.2."""
    return T * r / I_p


def free_end_velocity(v: Quantity) -> Quantity:
    """Velocity 2 v of a free end while a wave of particle velocity v reflects there (the
    reflected wave doubles the velocity and cancels the force), Sections 5.3.1-5.3.2."""
    return 2.0 * v
