"""Balance of angular momentum of a particle, Section 1.2.3, with Examples 1.16-1.19.
SI units; vectors as numpy arrays (2D vectors are taken in the e1-e2 plane).
"""
from __future__ import annotations

import numpy as np

from dynagrade.mechanics._common import ArrayLike, Quantity, spatial_vector
from dynagrade.mechanics.vibrations import period


def particle_angular_momentum(r_BP: ArrayLike, m: Quantity, v_P: ArrayLike) -> Quantity:
    """Angular momentum about B, H_B = r_BP x m v_P, eq. (1.129) (3D vector)."""
    return np.cross(spatial_vector(r_BP), m * spatial_vector(v_P))


def torque(r_BP: ArrayLike, F: ArrayLike) -> Quantity:
    """Resultant torque about B of the force F acting at P, M_B = r_BP x F, eq. (1.131)."""
    return np.cross(spatial_vector(r_BP), spatial_vector(F))


def angular_momentum_rate(M_B: ArrayLike, v_B: ArrayLike, P: ArrayLike) -> Quantity:
    """Rate of change of H_B from the angular momentum balance M_B = H_B' + v_B x P,
    eq. (1.132): H_B' = M_B - v_B x P."""
    return spatial_vector(M_B) - np.cross(spatial_vector(v_B), spatial_vector(P))


def planar_angular_momentum(m: Quantity, r: Quantity, phidot: Quantity) -> Quantity:
    """Out-of-plane angular momentum about the pole in 2D polar coordinates, m r^2 phi',
    the e3 component derived before eq. (1.137)."""
    return m * r**2 * phidot


def planar_torque(m: Quantity, r: Quantity, rdot: Quantity, phidot: Quantity,
                  phiddot: Quantity) -> Quantity:
    """Torque about a fixed pole needed for a planar polar motion, M_B = m r (r phi'' + 2 r' phi')
    = m a_phi r, eq. (1.138)."""
    return m * r * (r * phiddot + 2.0 * rdot * phidot)


def particle_moment_of_inertia(m: Quantity, R: Quantity) -> Quantity:
    """Moment of inertia of a particle at distance R from the pole, I_B = m R^2, eq. (1.139)."""
    return m * R**2


def angular_acceleration(M_B: Quantity, I_B: Quantity) -> Quantity:
    """Angular acceleration at constant radius from M_B = I_B phi'', eq. (1.139)."""
    return M_B / I_B


def conserved_tangential_speed(v_t0: Quantity, r0: Quantity, r: Quantity) -> Quantity:
    """Tangential speed after the radius changes from r0 to r without torque,
    r0 v_t0 = r v_t, eqs. (1.135) and (1.154)."""
    return r0 * v_t0 / r


def conserved_angular_velocity(omega0: Quantity, I0: Quantity, I1: Quantity) -> Quantity:
    """Angular velocity after the moment of inertia about a fixed axis changes from I0 to I1
    without external torque, I0 omega0 = I1 omega1 (eq. 1.135 summed over the masses,
    Example 1.19)."""
    return I0 * omega0 / I1


def pulled_string_angular_velocity(omega0: Quantity, l0: Quantity, l: Quantity) -> Quantity:
    """Angular velocity of a particle whose string is pulled in from l0 to l on a frictionless
    plane, omega = (l0/l)^2 omega0, eq. (1.155).

    Example 1.18: pulling the string in to half its length quadruples the angular velocity.

    >>> round(float(pulled_string_angular_velocity(3.0, 2.0, 1.0)), 12)
    12.0
    """
    return conserved_angular_velocity(omega0, particle_moment_of_inertia(1.0, l0),
                                      particle_moment_of_inertia(1.0, l))


def drag_torque(k: Quantity, R: Quantity, phidot: Quantity) -> Quantity:
    """Torque of linear air drag on a particle circling at radius R, M_B = -k R^2 phi',
    eq. (1.143) (e3 component)."""
    return -k * R**2 * phidot


def rotation_decay_rate(k: Quantity, m: Quantity) -> Quantity:
    """Decay rate k/m of the angular velocity in the equation of motion phi'' + (k/m) phi' = 0,
    eq. (1.144)."""
    return k / m


def drag_angular_velocity(t: ArrayLike, omega0: Quantity, k: Quantity, m: Quantity) -> Quantity:
    """Angular velocity of a particle circling in air, phi'(t) = phi'(0) exp(-k t/m),
    solution of eq. (1.144)."""
    return omega0 * np.exp(-rotation_decay_rate(k, m) * np.asarray(t, dtype=float))


def drag_rotation_angle(t: ArrayLike, omega0: Quantity, k: Quantity, m: Quantity) -> Quantity:
    """Angle turned by time t by the particle of Example 1.16, (m omega0/k)(1 - exp(-k t/m)),
    eq. (1.144) integrated."""
    return omega0 / rotation_decay_rate(k, m) * (1.0 - np.exp(-rotation_decay_rate(k, m)
                                                              * np.asarray(t, dtype=float)))


def particle_pendulum_angular_acceleration(phi: Quantity, phidot: Quantity, g: Quantity,
                                           R: Quantity, k: Quantity = 0.0,
                                           m: Quantity = 1.0) -> Quantity:
    """Angular acceleration of a particle pendulum with optional linear air drag,
    phi'' = -(k/m) phi' - (g/R) sin(phi), eqs. (1.145) and (1.149)."""
    return -rotation_decay_rate(k, m) * phidot - g / R * np.sin(phi)


def pendulum_natural_frequency(g: Quantity, R: Quantity) -> Quantity:
    """Angular frequency of small pendulum oscillations, sqrt(g/R), from eq. (1.147)."""
    return np.sqrt(g / R)


def pendulum_small_angle_period(g: Quantity, R: Quantity) -> Quantity:
    """Period of small pendulum oscillations, 2 pi sqrt(R/g), from eq. (1.147).

    Example 1.17: 2 pi sqrt(R/g); a pendulum of length R = g / pi^2 (about 0.994 m on Earth)
    beats seconds, a period of 2 s.

    >>> round(float(pendulum_small_angle_period(9.81, 9.81 / np.pi**2)), 12)
    2.0
    """
    return period(pendulum_natural_frequency(g, R))


def pendulum_string_force(m: Quantity, R: Quantity, g: Quantity, phi: Quantity,
                          phidot: Quantity) -> Quantity:
    """Force in the pendulum string (tension positive), m R phi'^2 + m g cos(phi), from the
    radial linear momentum balance of Example 1.17 (a_r = -R phi'^2, eq. 1.33)."""
    return m * R * phidot**2 + m * g * np.cos(phi)
