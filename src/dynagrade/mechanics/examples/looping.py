"""A car (particle) in a frictionless circular looping of radius R, Example 1.13.

The car enters at the bottom (phi = 0, height 0) with speed ``v0``; ``phi`` is the angle
travelled around the looping, the height is R (1 - cos(phi)).  Floats or numpy arrays.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from dynagrade.mechanics._common import ArrayLike, Quantity


def speed(phi: Quantity, v0: Quantity, R: Quantity, g: Quantity) -> Quantity:
    """Speed at angle phi from energy conservation, sqrt(v0^2 - 2 g R (1 - cos phi)), eq. (1.110).

    NaN where the car cannot reach phi (v0^2 < 2 g R (1 - cos phi))."""
    v_sq = v0**2 - 2.0 * g * R * (1.0 - np.cos(phi))
    with np.errstate(invalid="ignore"):
        return np.where(v_sq >= 0.0, np.sqrt(np.maximum(v_sq, 0.0)), np.nan)


def minimum_speed(v0: Quantity, R: Quantity, g: Quantity) -> Quantity:
    """Lowest speed in the looping, at the top phi = pi: sqrt(v0^2 - 4 g R), eq. (1.111)."""
    return speed(np.pi, v0, R, g)


def speed_to_reach_top(R: Quantity, g: Quantity) -> Quantity:
    """Necessary entry speed for reaching the top, 2 sqrt(g R), eq. (1.112).

    Example 1.13: 2 sqrt(g R) = 4 m/s for g = 10 m/s^2, R = 0.4 m.

    >>> round(float(speed_to_reach_top(0.4, 10.0)), 12)
    4.0
    """
    return 2.0 * np.sqrt(g * R)


def looping_normal_force(phi: Quantity, m: Quantity, v0: Quantity, R: Quantity,
                         g: Quantity) -> Quantity:
    """Normal force of the track on the car, m v0^2/R + m g (3 cos phi - 2), eq. (1.116).

    Valid while the car stays on the track (N >= 0 along the way, eq. 1.113)."""
    return m * v0**2 / R + m * g * (3.0 * np.cos(phi) - 2.0)


def minimum_entry_speed(R: Quantity, g: Quantity) -> Quantity:
    """Smallest entry speed that keeps the car on the track, sqrt(5 g R), eq. (1.118).

    Example 1.13: sqrt(5 g R) = 10 m/s for g = 10 m/s^2, R = 2 m.

    >>> round(float(minimum_entry_speed(2.0, 10.0)), 12)
    10.0
    """
    return np.sqrt(5.0 * g * R)


def maximum_normal_force(m: Quantity, v0: Quantity, R: Quantity, g: Quantity) -> Quantity:
    """Largest normal force, at the bottom (phi = 0 or 2 pi): m v0^2/R + m g, eq. (1.116)/(1.119).

    Example 1.13, eq. (1.119): entering at the smallest speed sqrt(5 g R) the largest normal
    force is 6 m g (60 N for m = 1 kg, g = 10 m/s^2).

    >>> round(float(maximum_normal_force(1.0, np.sqrt(5 * 10.0 * 2.0), 2.0, 10.0)), 9)
    60.0
    """
    return looping_normal_force(0.0, m, v0, R, g)


def lift_off_angle(v0: Quantity, R: Quantity, g: Quantity) -> Quantity:
    """Angle in (0, pi] at which N(phi) of eq. (1.116) first vanishes, NaN if it never does."""
    c = (2.0 - v0**2 / (g * R)) / 3.0
    with np.errstate(invalid="ignore"):
        return np.where((c >= -1.0) & (c <= 1.0), np.arccos(np.clip(c, -1.0, 1.0)), np.nan)


@dataclass(frozen=True)
class SupportReactions:
    """Support reactions at the clamped base of the looping: forces A1 (horizontal),
    A2 (vertical) and the clamping moment MA."""

    A1: np.ndarray
    A2: np.ndarray
    MA: np.ndarray


def support_reactions(phi: Quantity, m: Quantity, v0: Quantity, R: Quantity,
                      g: Quantity) -> SupportReactions:
    """Support reactions of the looping while the car is at phi, eq. (1.122):
    A1 = -N sin(phi), A2 = N cos(phi), MA = N R sin(phi) with N from eq. (1.116)."""
    N = looping_normal_force(phi, m, v0, R, g)
    return SupportReactions(A1=-N * np.sin(phi), A2=N * np.cos(phi), MA=N * R * np.sin(phi))


def static_support_reactions(phi: ArrayLike, m: Quantity, R: Quantity,
                             g: Quantity) -> SupportReactions:
    """Support reactions with the particle held at rest at phi, eq. (1.123):
    A1 = 0, A2 = m g, MA = m g R sin(phi)."""
    phi = np.asarray(phi, dtype=float)
    return SupportReactions(A1=0.0 * phi, A2=m * g + 0.0 * phi, MA=m * g * R * np.sin(phi))
