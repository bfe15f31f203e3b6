"""A block sliding on an inclined plane with Coulomb friction, Examples 1.8 and 1.15.

The slope is inclined at ``alpha`` to the horizontal; ``mu`` is the kinetic friction
coefficient (eq. 1.74); e1 points along the slope.  Floats or numpy arrays.
"""
from __future__ import annotations

import numpy as np

from dynagrade.mechanics._common import ArrayLike, Quantity


def incline_normal_force(m: Quantity, alpha: Quantity, g: Quantity) -> Quantity:
    """Normal force of the slope on the block, N = m g cos(alpha), eq. (1.72)."""
    return m * g * np.cos(alpha)


def friction_force(m: Quantity, alpha: Quantity, mu: Quantity, g: Quantity) -> Quantity:
    """Magnitude of the kinetic friction force while sliding, R = mu m g cos(alpha), eq. (1.73)."""
    return mu * incline_normal_force(m, alpha, g)


def sliding_acceleration(alpha: Quantity, mu: Quantity, g: Quantity) -> Quantity:
    """Acceleration of a block sliding DOWN the slope, down-slope positive:
    g (sin(alpha) - mu cos(alpha)), eq. (1.73).  Negative means it decelerates."""
    return g * (np.sin(alpha) - mu * np.cos(alpha))


def deceleration_up_slope(alpha: Quantity, mu: Quantity, g: Quantity) -> Quantity:
    """Magnitude of the deceleration of a block sliding UP the slope,
    g (sin(alpha) + mu cos(alpha)) (Example 1.15, friction and gravity both act down-slope)."""
    return g * (np.sin(alpha) + mu * np.cos(alpha))


def distance_up_slope(v0: Quantity, alpha: Quantity, mu: Quantity, g: Quantity) -> Quantity:
    """Distance travelled up the slope until rest, v0^2 / (2 g (sin a + mu cos a)), eq. (1.128).

    Example 1.15 and its remark: at alpha = 0 it is Example 1.11's v0^2/(2 mu g) (10 m at
    v0 = 10 m/s, mu = 0.5, g = 10 m/s^2); up a vertical wall the vertical throw's v0^2/(2g) = 5 m.

    >>> round(float(distance_up_slope(10.0, 0.0, 0.5, 10.0)), 12)
    10.0
    >>> round(float(distance_up_slope(10.0, np.pi / 2, 0.5, 10.0)), 12)
    5.0
    """
    return v0**2 / (2.0 * deceleration_up_slope(alpha, mu, g))


def time_up_slope(v0: Quantity, alpha: Quantity, mu: Quantity, g: Quantity) -> Quantity:
    """Time until a block launched up the slope with speed v0 comes to rest (Example 1.15)."""
    return v0 / deceleration_up_slope(alpha, mu, g)


def decelerates_down_slope(alpha: Quantity, mu: ArrayLike) -> Quantity:
    """Whether a block sliding down decelerates (and eventually stops): mu > tan(alpha),
    discussion after eq. (1.73)."""
    return np.asarray(mu) > np.tan(alpha)


def stopping_distance_down_slope(v0: Quantity, alpha: Quantity, mu: Quantity,
                                 g: Quantity) -> Quantity:
    """Distance a block sliding down with speed v0 travels until rest when mu > tan(alpha),
    v0^2 / (2 g (mu cos a - sin a)) (eq. 1.73 integrated as in Example 1.11); inf otherwise."""
    a = sliding_acceleration(alpha, mu, g)
    with np.errstate(divide="ignore"):
        return np.where(a < 0.0, v0**2 / (2.0 * np.abs(a)), np.inf)
