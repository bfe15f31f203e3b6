"""Collisions of two particles: central and oblique impact with restitution (Section 2.3.1).

The impact is short: only the impulsive contact force along the line of impact n acts.
Linear momentum of the pair is conserved, and the relative normal velocity after the
impact is -e times that before (Newton's coefficient of restitution e, 0 <= e <= 1).
Inverse masses w = 1/m are used so that the rigid-body impact (Section 3.3) can reuse the
same relations with effective inverse masses.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from dynagrade.mechanics._common import ArrayLike, Quantity
from dynagrade.mechanics.systems import relative_kinetic_energy


@dataclass(frozen=True)
class PairVelocities:
    """Velocities of the two bodies after an impact."""

    v1: Quantity
    v2: Quantity


def impact_impulse(w1: Quantity, w2: Quantity, approach_speed: Quantity,
                   e: Quantity) -> Quantity:
    """Normal impulse of an impact, F_hat = (1 + e) v_approach / (w1 + w2), with w the
    (effective) inverse masses and v_approach = (v1 - v2).n > 0 the normal speed of
    approach (momentum balance + restitution, Section 2.3.1)."""
    return (1.0 + e) * approach_speed / (w1 + w2)


def velocity_after_impulse(m: Quantity, v: Quantity, impulse: Quantity) -> Quantity:
    """Velocity of a particle of mass m after the impulse F_hat acted on it in its direction
    of motion, v' = v + F_hat/m (linear momentum balance integrated over the short impact,
    Section 2.3.1)."""
    return v + impulse / m


def velocities_after_central_impact(m1: Quantity, m2: Quantity, v1: Quantity, v2: Quantity,
                                    e: Quantity) -> PairVelocities:
    """Velocities after a central (head-on) collision on a line:
    v1' = v1 - (1+e) m2/(m1+m2) (v1 - v2), v2' = v2 + (1+e) m1/(m1+m2) (v1 - v2)
    (Section 2.3.1). Scalars along the line, positive in the same direction."""
    impulse = impact_impulse(1.0 / m1, 1.0 / m2, v1 - v2, e)
    return PairVelocities(velocity_after_impulse(m1, v1, -impulse),
                          velocity_after_impulse(m2, v2, impulse))


def velocities_after_oblique_impact(m1: Quantity, m2: Quantity, v1: ArrayLike, v2: ArrayLike,
                                    n: ArrayLike, e: Quantity) -> PairVelocities:
    """Velocity vectors after an oblique collision of smooth particles: the normal
    components (along n, the line of impact) change as in a central impact, the tangential
    components are unchanged (Section 2.3.1)."""
    v1 = np.asarray(v1, dtype=float)
    v2 = np.asarray(v2, dtype=float)
    n = np.asarray(n, dtype=float)
    e_n = n / np.linalg.norm(n)
    approach = float(np.dot(v1 - v2, e_n))
    impulse = impact_impulse(1.0 / m1, 1.0 / m2, approach, e)
    return PairVelocities(v1 - impulse / m1 * e_n, v2 + impulse / m2 * e_n)


def coefficient_of_restitution(v1: Quantity, v2: Quantity, v1_after: Quantity,
                               v2_after: Quantity) -> Quantity:
    """Coefficient of restitution e = -(v1' - v2') / (v1 - v2) from normal velocity
    components before and after the impact (Section 2.3.1)."""
    return -(v1_after - v2_after) / (v1 - v2)


def kinetic_energy_lost_in_impact(m1: Quantity, m2: Quantity, approach_speed: Quantity,
                                  e: Quantity) -> Quantity:
    """Kinetic energy dissipated in a collision, Delta T = 1/2 mu (1 - e^2) v_rel^2 with
    the reduced mass mu and the normal relative speed of approach (Section 2.3.1)."""
    return (1.0 - e**2) * relative_kinetic_energy(m1, m2, approach_speed)


def common_velocity_after_plastic_impact(m1: Quantity, m2: Quantity, v1: Quantity,
                                         v2: Quantity) -> Quantity:
    """Common velocity after a perfectly plastic impact (e = 0):
    v' = (m1 v1 + m2 v2) / (m1 + m2), from momentum conservation (Section 2.3.1)."""
    return velocities_after_central_impact(m1, m2, v1, v2, 0.0).v2
