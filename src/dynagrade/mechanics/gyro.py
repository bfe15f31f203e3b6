"""Spinning tops and gyroscopes (Section 3.5).

A heavy axisymmetric top of mass m spins about its symmetry axis, its tip fixed at O, the
centre of mass at distance l from O on the axis. I1 is the transverse moment of inertia
about O, I3 the axial one. Euler angles: precession psi about the vertical e3, nutation
theta (axis tilt from the vertical), spin phi about the symmetry axis (see
`rotations.euler_angle_rotation`). omega3 = phi_dot + psi_dot cos(theta) is the axial
component of the angular velocity.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from dynagrade.mechanics._common import Quantity


def body_angular_velocity_from_euler_rates(theta: Quantity, phi: Quantity, psi_rate: Quantity,
                                           theta_rate: Quantity, phi_rate: Quantity) -> Quantity:
    """Body-frame components of the angular velocity from the Euler-angle rates,
    omega = (psi' sin(theta) sin(phi) + theta' cos(phi),
             psi' sin(theta) cos(phi) - theta' sin(phi),
             psi' cos(theta) + phi') (Section 3.5.1)."""
    return np.array([psi_rate * np.sin(theta) * np.sin(phi) + theta_rate * np.cos(phi),
                     psi_rate * np.sin(theta) * np.cos(phi) - theta_rate * np.sin(phi),
                     psi_rate * np.cos(theta) + phi_rate])


@dataclass(frozen=True)
class PrecessionRates:
    """The two steady precession rates of a heavy top at a given tilt and spin."""

    slow: float
    fast: float


def steady_precession_rates(m: Quantity, g: Quantity, l: Quantity, transverse_moment: Quantity,
                            axial_moment: Quantity, axial_rate: Quantity,
                            theta: Quantity) -> PrecessionRates:
    """Precession rates psi' of steady precession at constant tilt theta (0 < theta < pi/2):
    angular momentum balance about O gives m g l = psi' (I3 omega3 - I1 psi' cos(theta)),
    a quadratic in psi' whose smaller root is the slow and larger the fast precession
    (Section 3.5.2). Real only when I3^2 omega3^2 >= 4 I1 m g l cos(theta)."""
    a = transverse_moment * np.cos(theta)
    b = axial_moment * axial_rate
    c = m * g * l
    root = np.sqrt(b * b - 4.0 * a * c)
    slow = 2.0 * c / (b + root)
    fast = (b + root) / (2.0 * a)
    return PrecessionRates(slow=float(slow), fast=float(fast))


def minimum_spin_for_steady_precession(m: Quantity, g: Quantity, l: Quantity,
                                       transverse_moment: Quantity, axial_moment: Quantity,
                                       theta: Quantity) -> Quantity:
    """Smallest axial rate omega3 for which steady precession at tilt theta exists,
    omega3_min = sqrt(4 I1 m g l cos(theta)) / I3 (Section 3.5.2)."""
    return np.sqrt(4.0 * transverse_moment * m * g * l * np.cos(theta)) / axial_moment


def gyroscopic_precession_rate(moment: Quantity, spin_angular_momentum: Quantity) -> Quantity:
    """Precession rate of a gyroscope whose spin angular momentum H (along its axis) is
    turned by a moment M perpendicular to the axis and to the vertical: from
    dH/dt = psi' e3 x H, psi' = M / (H sin(theta)); for a horizontal axis psi' = M / H
    (Section 3.5.2)."""
    return moment / spin_angular_momentum


def fast_top_precession_rate(m: Quantity, g: Quantity, l: Quantity, axial_moment: Quantity,
                             axial_rate: Quantity) -> Quantity:
    """Slow precession rate of a fast top, psi' = m g l / (I3 omega3), independent of the
    tilt (fast-top approximation, Section 3.5.2)."""
    return gyroscopic_precession_rate(m * g * l, axial_moment * axial_rate)


# --- Sections 3.5.1-3.5.2: relations added for the exercise bank (issue 31, ch3 tops) ---

def body_components_of_vertical(theta: Quantity, phi: Quantity) -> Quantity:
    """Components of the space-fixed vertical e3 in the body frame of a top with nutation
    theta and spin angle phi, (sin(theta) sin(phi), sin(theta) cos(phi), cos(theta)): the
    third row of R = R3(psi) R1(theta) R3(phi), independent of psi (Section 3.5.1). A body
    vector's vertical component is its dot product with these."""
    return np.array([np.sin(theta) * np.sin(phi), np.sin(theta) * np.cos(phi),
                     np.cos(theta)])


def top_gravity_moment(m: Quantity, g: Quantity, l: Quantity, theta: Quantity,
                       phi: Quantity) -> Quantity:
    """Body-frame components of the weight's moment about the fixed tip O of a top whose
    centre of mass lies on the body axis e3^B at l from O:
    M_O = l e3^B x (-m g e3) = m g l (sin(theta) cos(phi), -sin(theta) sin(phi), 0),
    with e3's body components of :func:`body_components_of_vertical`; horizontal, of
    magnitude m g l sin(theta) (Section 3.5.1)."""
    return m * g * l * np.array([np.sin(theta) * np.cos(phi), -np.sin(theta) * np.sin(phi),
                                 0.0])


def top_kinetic_energy_rate(m: Quantity, g: Quantity, l: Quantity, theta: Quantity,
                            theta_rate: Quantity) -> Quantity:
    """Rate of change of a top's kinetic energy, dT/dt = m g l sin(theta) theta': the tip
    force does no work and the potential m g l cos(theta) is all the weight's work
    (work-energy balance, Sections 3.2.5 and 3.5.1)."""
    return m * g * l * np.sin(theta) * theta_rate


def largest_tilt_of_released_top(m: Quantity, g: Quantity, l: Quantity,
                                 transverse_moment: Quantity, axial_moment: Quantity,
                                 axial_rate: Quantity, theta: Quantity) -> Quantity:
    """Largest tilt theta_max of a heavy symmetric top released at the tilt theta with the
    axial rate omega3 and no precession or nutation rate. H3 = I3 omega3 and the vertical
    H_v = I1 psi' sin^2(theta) + I3 omega3 cos(theta) stay (gravity's moment about O is
    horizontal and normal to the axis), and so does the energy; at the turning tilt
    (theta' = 0) they give, with u = cos(theta_max), u0 = cos(theta) and
    beta = 2 I1 m g l / (I3 omega3)^2: u0 - u = beta (1 - u^2) (Section 3.5.2)."""
    beta = 2.0 * transverse_moment * m * g * l / (axial_moment * axial_rate) ** 2
    u0 = np.cos(theta)
    u = (1.0 - np.sqrt(1.0 - 4.0 * beta * (u0 - beta))) / (2.0 * beta)
    return np.arccos(u)


def precession_rate_at_largest_tilt(m: Quantity, g: Quantity, l: Quantity,
                                    axial_moment: Quantity, axial_rate: Quantity) -> Quantity:
    """Precession rate of the released top of :func:`largest_tilt_of_released_top` at its
    largest tilt: psi' = I3 omega3 (u0 - u) / (I1 (1 - u^2)) = 2 m g l / (I3 omega3),
    twice the fast-top rate, at any tilt; the precession rate swings between 0 and this
    (Section 3.5.2)."""
    return 2.0 * fast_top_precession_rate(m, g, l, axial_moment, axial_rate)
