"""Impact of a particle on a fixed, smooth wall or floor, Section 1.2.4 (the standard
relations of the coefficient of restitution e; the notes' text of this section is not
included in our copy).  SI units; angles in rad measured from the wall normal.
"""
from __future__ import annotations

import numpy as np

from dynagrade.mechanics._common import ArrayLike, Quantity
from dynagrade.mechanics.collisions import impact_impulse
from dynagrade.mechanics.energy import particle_kinetic_energy


def rebound_normal_velocity(v_n: Quantity, e: Quantity) -> Quantity:
    """Normal velocity component after impact on a fixed wall, v_n' = -e v_n (Section 1.2.4)."""
    return -e * v_n


def restitution_from_speeds(v_before: Quantity, v_after: Quantity) -> Quantity:
    """Coefficient of restitution from the normal speeds before and after impact,
    e = |v_n'| / |v_n| (Section 1.2.4)."""
    return np.abs(v_after) / np.abs(v_before)


def restitution_from_heights(h0: Quantity, h1: Quantity) -> Quantity:
    """Coefficient of restitution of a ball dropped from h0 that bounces back to h1,
    e = sqrt(h1/h0) (Section 1.2.4 with energy conservation in flight, eq. 1.102).

    Dropped from 4 m and back to 1 m: e = sqrt(1/4) = 0.5.

    >>> float(restitution_from_heights(4.0, 1.0))
    0.5
    """
    return np.sqrt(h1 / h0)


def impact_speed_after_fall(h: ArrayLike, g: Quantity) -> Quantity:
    """Speed after falling freely from rest through height h, sqrt(2 g h) (eq. 1.102)."""
    return np.sqrt(2.0 * g * np.asarray(h, dtype=float))


def rebound_height(h0: Quantity, e: Quantity, n: int = 1) -> Quantity:
    """Height reached after the n-th bounce of a ball dropped from h0 onto a floor,
    e^(2n) h0 (Section 1.2.4).

    Section 1.2.4: with e = 1/2 each bounce keeps a quarter of the height; 16 m, then 4 m, then 1 m.

    >>> float(rebound_height(16.0, 0.5, 2))
    1.0
    """
    return e ** (2 * n) * h0


def rebound_velocity(v: ArrayLike, normal: ArrayLike, e: Quantity) -> Quantity:
    """Velocity after impact on a fixed smooth wall with unit normal ``normal``: the tangential
    part is kept, the normal part reversed and scaled by e, v' = v - (1 + e)(v.n) n
    (Section 1.2.4)."""
    v = np.asarray(v, dtype=float)
    n = np.asarray(normal, dtype=float)
    n = n / np.linalg.norm(n)
    # the wall is immovable (inverse mass 0); per unit particle mass (inverse mass 1)
    impulse_per_mass = impact_impulse(1.0, 0.0, np.sum(v * n, axis=-1, keepdims=True), e)
    return v - impulse_per_mass * n


def rebound_angle(theta: Quantity, e: Quantity) -> Quantity:
    """Angle to the wall normal after an oblique impact on a smooth wall, arctan(tan(theta)/e)
    for an incidence angle theta to the normal (Section 1.2.4)."""
    return np.arctan2(np.tan(theta), e)


def rebound_speed(v: Quantity, theta: Quantity, e: Quantity) -> Quantity:
    """Speed after an oblique impact on a smooth wall, v sqrt(sin^2 theta + e^2 cos^2 theta)
    (Section 1.2.4)."""
    return v * np.sqrt(np.sin(theta) ** 2 + (e * np.cos(theta)) ** 2)


def normal_energy_loss_fraction(e: Quantity) -> Quantity:
    """Fraction of the kinetic energy of the normal motion lost in the impact, 1 - e^2
    (Section 1.2.4).

    e = 0.5 loses three quarters of the normal motion's kinetic energy; e = 1 none.

    >>> float(normal_energy_loss_fraction(0.5)), float(normal_energy_loss_fraction(1.0))
    (0.75, 0.0)
    """
    return 1.0 - e**2


def impact_energy_loss(m: Quantity, v: Quantity, theta: Quantity, e: Quantity) -> Quantity:
    """Kinetic energy lost in an oblique impact on a smooth wall,
    (1 - e^2) m (v cos theta)^2 / 2 (Section 1.2.4)."""
    normal_speed = np.asarray(v * np.cos(theta), dtype=float)[..., None]   # one-component vector
    return normal_energy_loss_fraction(e) * particle_kinetic_energy(m, normal_speed)


def wall_impulse(m: Quantity, v_n: Quantity, e: Quantity) -> Quantity:
    """Magnitude of the impulse the wall gives the particle, m (1 + e) |v_n| (Section 1.2.4,
    the two-body impulse of Section 2.3.1 with an immovable wall)."""
    return impact_impulse(1.0 / m, 0.0, np.abs(v_n), e)


def bouncing_time(h0: Quantity, e: Quantity, g: Quantity) -> Quantity:
    """Total time until a ball dropped from rest at h0 stops bouncing (geometric series of
    flight times), sqrt(2 h0/g) (1 + e)/(1 - e) for e < 1 (Section 1.2.4)."""
    return np.sqrt(2.0 * h0 / g) * (1.0 + e) / (1.0 - e)


def bouncing_distance(h0: Quantity, e: Quantity) -> Quantity:
    """Total distance travelled by a ball dropped from h0 until it comes to rest,
    h0 (1 + e^2)/(1 - e^2) for e < 1 (Section 1.2.4)."""
    return h0 * (1.0 + e**2) / (1.0 - e**2)
