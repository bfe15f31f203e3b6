"""Deformable bodies with non-negligible mass, Section 5.2 of the notes.

A spring or beam of mass m_s that carries a mass m vibrates, to a good approximation,
in its static deflection shape psi(x) (normalized to 1 where the mass sits).  Its
kinetic energy is then that of an effective mass

    m_eff = integral of mu(x) psi(x)^2 dx,     (mu: mass per unit length)

added to m (Rayleigh's method); the estimate omega^2 = k / (m + m_eff) bounds the
true fundamental frequency from above.  For a continuous beam the Rayleigh quotient
omega^2 <= integral EI w''^2 dx / integral rho A w^2 dx holds for any admissible w.
"""
from __future__ import annotations

import numpy as np

from dynagrade.mechanics._common import Function, Quantity
from dynagrade.mechanics.vibrations import natural_frequency


def effective_mass(rhoA: float | Function, shape: Function, L: float) -> float:
    """Effective mass m_eff = int_0^L rho A psi(x)^2 dx of a body moving in the shape psi, Section 5.2.

    ``rhoA`` is the mass per length rho A (a number or a callable of x), ``shape`` the callable psi(x)
    normalized to 1 at the point whose coordinate is the degree of freedom.
    """
    from scipy.integrate import quad
    mu = rhoA if callable(rhoA) else (lambda x: rhoA)
    value, _ = quad(lambda x: mu(x) * shape(x) ** 2, 0.0, L, epsabs=0.0, epsrel=1e-12)
    return value


def spring_effective_mass(m_s: Quantity) -> Quantity:
    """Effective mass m_s / 3 of a uniform spring of mass m_s (linear velocity profile), Section 5.2."""
    return m_s / 3.0


def cantilever_effective_mass(m_b: Quantity) -> Quantity:
    """Effective tip mass 33 m_b / 140 of a uniform cantilever of mass m_b (static tip-load shape), Section 5.2."""
    return 33.0 * m_b / 140.0


def simply_supported_effective_mass(m_b: Quantity) -> Quantity:
    """Effective midspan mass 17 m_b / 35 of a uniform simply supported beam (static midspan-load shape), Section 5.2."""
    return 17.0 * m_b / 35.0


def rod_effective_mass(m_r: Quantity) -> Quantity:
    """Effective end mass m_r / 3 of a uniform bar or shaft in axial or torsional motion, Section 5.2.

    The static shape is linear, as for the spring; for torsion m_r stands for the
    polar mass moment of inertia of the shaft.
    """
    return spring_effective_mass(m_r)


def rayleigh_frequency(k: Quantity, m: Quantity, m_eff: Quantity) -> Quantity:
    """Rayleigh's estimate omega = sqrt(k / (m + m_eff)) of the fundamental frequency, Section 5.2."""
    return natural_frequency(k, m + m_eff)


def beam_rayleigh_quotient(EI: float, rhoA: float, w: Function, w_xx: Function,
                           L: float) -> float:
    """Rayleigh quotient int EI w''^2 dx / int rho A w^2 dx (an upper bound of omega_1^2), Section 5.2.

    ``w`` and ``w_xx`` are the trial deflection and its second derivative (callables);
    the trial shape must satisfy the geometric boundary conditions.
    """
    from scipy.integrate import quad
    num, _ = quad(lambda x: EI * w_xx(x) ** 2, 0.0, L, epsabs=0.0, epsrel=1e-12)
    den, _ = quad(lambda x: rhoA * w(x) ** 2, 0.0, L, epsabs=0.0, epsrel=1e-12)
    return num / den
