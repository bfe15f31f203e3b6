"""A bead on a hoop spinning about its vertical diameter, the example of Section 4.2.

A bead of mass m slides without friction on a hoop of radius R that spins at the constant
rate Omega about its vertical diameter; theta is measured from the lowest point.
T = m R^2 (theta'^2 + Omega^2 sin^2 theta) / 2, V = -m g R cos theta; the general
equilibrium and stability relations are those of :mod:`dynagrade.mechanics.equilibrium`.
"""
from __future__ import annotations

import numpy as np

from dynagrade.mechanics import vibrations
from dynagrade.mechanics._common import Quantity
from dynagrade.mechanics.angular_momentum import pendulum_natural_frequency


def hoop_critical_spin_rate(R: Quantity, g: Quantity) -> Quantity:
    """Spin rate Omega_c = sqrt(g/R) above which the lowest point of the hoop is unstable, Section 4.2:
    the small-oscillation frequency of a pendulum of length R (eq. 1.147)."""
    return pendulum_natural_frequency(g, R)


def hoop_equilibrium_angle(R: Quantity, Omega: Quantity, g: Quantity) -> Quantity:
    """Off-axis equilibrium angle theta* = arccos(g / (R Omega^2)) for Omega > sqrt(g/R), Section 4.2.

    Returns nan when the spin is too slow for an off-axis equilibrium to exist.
    """
    ratio = g / (R * Omega**2)
    return np.arccos(ratio) if ratio <= 1.0 else np.nan


def hoop_potential_curvature(theta: Quantity, m: Quantity, R: Quantity, Omega: Quantity,
                             g: Quantity) -> Quantity:
    """Second derivative d^2 V*/d theta^2 = m R (g cos theta - R Omega^2 cos 2 theta) of the
    effective potential of the bead at angle theta, Section 4.2."""
    return m * R * (g * np.cos(theta) - R * Omega**2 * np.cos(2.0 * theta))


def hoop_oscillation_frequency(R: float, Omega: float, g: float) -> Quantity:
    """Angular frequency of small oscillations of the bead about its stable equilibrium, Section 4.2.

    sqrt(g/R - Omega^2) about the lowest point for Omega < sqrt(g/R); Omega sin(theta*)
    about the off-axis equilibrium otherwise.
    """
    theta = 0.0 if abs(Omega) <= hoop_critical_spin_rate(R, g) else hoop_equilibrium_angle(R, Omega, g)
    # k_eq = V*''(theta), m_eq = m R^2 (unit mass: the frequency does not depend on m)
    return vibrations.natural_frequency(hoop_potential_curvature(theta, 1.0, R, Omega, g), R**2)
