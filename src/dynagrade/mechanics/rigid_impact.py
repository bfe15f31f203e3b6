"""Eccentric impact of rigid bodies in plane motion (Section 3.3).

A smooth impact transmits an impulse F_hat along the line of impact n through the contact
point. Each body reacts to it like a particle with an effective inverse mass w: for a free
body w = 1/m + d^2/I_C (d: lever arm of the line of impact about the centre of mass), for
a body pinned at O w = d_O^2/I_O. With these, the impulse follows from the two-particle
relation of Section 2.3.1 (`collisions.impact_impulse`) and the restitution condition on
the normal velocities of the two contact points.
"""
from __future__ import annotations

from dynagrade.mechanics._common import Quantity
from dynagrade.mechanics.collisions import impact_impulse


def inverse_effective_mass_free_body(m: Quantity, moment_centre: Quantity,
                                     lever_arm: Quantity) -> Quantity:
    """Effective inverse mass of a free rigid body for an impulse whose line of action
    passes at distance d from the centre of mass: w = 1/m + d^2 / I_C (Section 3.3)."""
    return 1.0 / m + lever_arm**2 / moment_centre


def inverse_effective_mass_pinned_body(moment_pivot: Quantity, lever_arm: Quantity) -> Quantity:
    """Effective inverse mass of a body pinned at O for an impulse whose line of action
    passes at distance d from O: w = d^2 / I_O (Section 3.3)."""
    return lever_arm**2 / moment_pivot


def eccentric_impact_impulse(w1: Quantity, w2: Quantity, approach_speed: Quantity,
                             e: Quantity) -> Quantity:
    """Impulse of an eccentric impact between two bodies with effective inverse masses
    w1, w2 and normal approach speed of the contact points v_rel:
    F_hat = (1 + e) v_rel / (w1 + w2) (Section 3.3)."""
    return impact_impulse(w1, w2, approach_speed, e)


def angular_velocity_change(impulse: Quantity, lever_arm: Quantity,
                            moment_of_inertia: Quantity) -> Quantity:
    """Jump of the angular velocity of a body hit by the impulse F_hat with lever arm d
    about its centre of mass (free body) or its pivot (pinned body):
    Delta omega = F_hat d / I (angular impulse balance, Section 3.3)."""
    return impulse * lever_arm / moment_of_inertia


def angular_velocity_after_plastic_impact_on_pinned_body(particle_mass: Quantity,
                                                         particle_speed: Quantity,
                                                         lever_arm: Quantity,
                                                         moment_pivot: Quantity) -> Quantity:
    """Angular velocity of a pinned body at rest after a particle of mass m and speed v,
    moving perpendicular to the radius at distance d from the pivot, sticks to it:
    m v d = (I_O + m d^2) omega (ballistic pendulum; angular momentum about the pivot,
    Section 3.3)."""
    w_body = inverse_effective_mass_pinned_body(moment_pivot, lever_arm)
    impulse = eccentric_impact_impulse(1.0 / particle_mass, w_body, particle_speed, 0.0)
    return angular_velocity_change(impulse, lever_arm, moment_pivot)


def pivot_impulse(impulse: Quantity, lever_arm: Quantity, m: Quantity,
                  pivot_to_centre: Quantity, moment_pivot: Quantity) -> Quantity:
    """Impulsive reaction at the pivot of a body at rest struck with F_hat at distance d
    from the pivot, along the same line: R_hat = m d_C Delta omega - F_hat, with
    Delta omega = F_hat d / I_O (linear impulse balance, Section 3.3)."""
    delta_omega = angular_velocity_change(impulse, lever_arm, moment_pivot)
    return m * pivot_to_centre * delta_omega - impulse


def centre_of_percussion_distance(moment_pivot: Quantity, m: Quantity,
                                  pivot_to_centre: Quantity) -> Quantity:
    """Distance from the pivot at which a blow causes no impulsive pivot reaction,
    d = I_O / (m d_C) (Section 3.3)."""
    return moment_pivot / (m * pivot_to_centre)
