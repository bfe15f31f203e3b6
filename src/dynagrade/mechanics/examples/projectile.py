"""Projectile motion from level ground without drag, Example 1.9 (eqs. 1.75-1.82).

The particle is thrown from the origin at t = 0 with speed ``v0`` at angle ``alpha``
above the horizontal e1; gravity ``g`` acts in -e2.  All functions accept floats or
numpy arrays (broadcast together) and return the same.
"""
from __future__ import annotations

import numpy as np

from dynagrade.mechanics._common import ArrayLike, Quantity


def position(t: ArrayLike, v0: Quantity, alpha: Quantity,
             g: Quantity) -> tuple[Quantity, Quantity]:
    """Position (x1, x2) at time t of the throw, eq. (1.78)."""
    t = np.asarray(t, dtype=float)
    x1 = v0 * t * np.cos(alpha)
    x2 = -0.5 * g * t**2 + v0 * t * np.sin(alpha)
    return x1, x2


def velocity(t: ArrayLike, v0: Quantity, alpha: Quantity,
             g: Quantity) -> tuple[Quantity, Quantity]:
    """Velocity (v1, v2) at time t, the time derivative of eq. (1.78) (see eq. 1.77)."""
    t = np.asarray(t, dtype=float)
    v1 = v0 * np.cos(alpha) + 0.0 * t
    v2 = v0 * np.sin(alpha) - g * t
    return v1, v2


def flight_time(v0: Quantity, alpha: Quantity, g: Quantity) -> Quantity:
    """Time at which the particle lands on level ground again, t_1,max of eq. (1.79).

    Example 1.9: straight up at 10 m/s with g = 10 m/s^2, 2 s in the air.

    >>> round(float(flight_time(10.0, np.pi / 2, 10.0)), 12)
    2.0
    """
    return 2.0 * v0 * np.sin(alpha) / g


def horizontal_range(v0: Quantity, alpha: Quantity, g: Quantity) -> Quantity:
    """Horizontal distance to the landing point, x_1,max = v0^2 sin(2 alpha)/g, eq. (1.80).

    Example 1.9: the largest range, at 45 degrees, is v0^2/g (10 m at v0 = 10 m/s, g = 10 m/s^2);
    30 and 60 degrees reach the same point.

    >>> round(float(horizontal_range(10.0, np.pi / 4, 10.0)), 12)
    10.0
    >>> bool(np.isclose(horizontal_range(10.0, np.pi / 6, 10.0), horizontal_range(10.0, np.pi / 3, 10.0)))
    True
    """
    return 2.0 * v0**2 * np.sin(alpha) * np.cos(alpha) / g


def peak_time(v0: Quantity, alpha: Quantity, g: Quantity) -> Quantity:
    """Time at which the highest point is reached, t_2,max of eq. (1.81)."""
    return v0 * np.sin(alpha) / g


def peak_height(v0: Quantity, alpha: Quantity, g: Quantity) -> Quantity:
    """Maximum height of the flight parabola, x_2,max = v0^2 sin^2(alpha)/(2g), eq. (1.82).

    Example 1.9: thrown straight up at 10 m/s (g = 10 m/s^2) it rises v0^2/(2g) = 5 m.

    >>> round(float(peak_height(10.0, np.pi / 2, 10.0)), 12)
    5.0
    """
    return v0**2 * np.sin(alpha) ** 2 / (2.0 * g)


def optimal_launch_angle() -> Quantity:
    """Launch angle of the largest range on level ground, pi/4 (remark after eq. 1.80)."""
    return np.pi / 4.0


def trajectory_height(x1: ArrayLike, v0: Quantity, alpha: Quantity, g: Quantity) -> Quantity:
    """Height x2 of the flight parabola above horizontal position x1 (eq. 1.78 with t eliminated)."""
    x1 = np.asarray(x1, dtype=float)
    return x1 * np.tan(alpha) - g * x1**2 / (2.0 * v0**2 * np.cos(alpha) ** 2)
