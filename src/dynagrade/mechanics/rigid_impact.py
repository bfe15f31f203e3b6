"""Eccentric impact of rigid bodies in plane motion (Section 3.3).

A smooth impact transmits an impulse F_hat along the line of impact n through the contact
point. Each body reacts to it like a particle with an effective inverse mass w: for a free
body w = 1/m + d^2/I_C (d: lever arm of the line of impact about the centre of mass), for
a body pinned at O w = d_O^2/I_O. With these, the impulse follows from the two-particle
relation of Section 2.3.1 (`collisions.impact_impulse`) and the restitution condition on
the normal velocities of the two contact points.
"""
from __future__ import annotations

import numpy as np

from dynagrade.mechanics._common import ArrayLike, Quantity
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


# --- Issue 31: impacts about a stopped edge (bank exercises of Sections 3.3-3.4) -------------


def angular_velocity_after_edge_impact(m: Quantity, v_c: ArrayLike, edge_to_centre: ArrayLike,
                                       moment_edge: Quantity) -> float:
    """Angular velocity (about e3, counter-clockwise positive) of a plane body translating
    with v_C whose edge E strikes an obstacle, sticks to it without rebound and becomes a
    pivot: the impulse at E has no moment about E, so the angular momentum about E is
    kept, m (r_EC x v_C) = I_E omega' (Section 3.3)."""
    r = np.asarray(edge_to_centre, dtype=float)
    v = np.asarray(v_c, dtype=float)
    return float(m * (r[0] * v[1] - r[1] * v[0]) / moment_edge)


def impulse_at_edge(m: Quantity, v_c: ArrayLike, omega: Quantity,
                    edge_to_centre: ArrayLike) -> np.ndarray:
    """Impulse (2 components) the obstacle gives a plane body whose centre moved with v_C
    before and turns about the stopped edge E with omega' after, the centre's velocity then
    being omega' e3 x r_EC: linear impulse balance F_hat = m (v_C' - v_C) (Section 3.3)."""
    r = np.asarray(edge_to_centre, dtype=float)
    v_after = omega * np.array([-r[1], r[0]])
    return m * (v_after - np.asarray(v_c, dtype=float))


def angular_speed_to_tip_over(m: Quantity, g: Quantity, centre_rise: Quantity,
                              moment_edge: Quantity) -> Quantity:
    """Least angular speed about the edge E with which a body turning about E lifts its
    centre of mass by Delta h, to above E, and tips over: (1/2) I_E omega^2 = m g Delta h
    (energy balance after the impact, Sections 3.2 and 3.3)."""
    return np.sqrt(2.0 * m * g * centre_rise / moment_edge)
