"""Kinetics of rigid bodies: momentum, angular momentum and energy (Sections 3.2.1-3.2.5).

Inertia tensors are 3x3 arrays (see `inertia`), angular velocities 3-vectors; the
planar helpers take scalar moments of inertia about the axis normal to the plane.
"""
from __future__ import annotations

import numpy as np

from dynagrade.mechanics._common import ArrayLike, Quantity
from dynagrade.mechanics import particle
from dynagrade.mechanics.angular_momentum import angular_acceleration
from dynagrade.mechanics.energy import particle_kinetic_energy as translational_kinetic_energy
from dynagrade.mechanics.systems import angular_momentum_transfer


def rigid_body_linear_momentum(m: Quantity, v_c: Quantity) -> Quantity:
    """Linear momentum of a rigid body, P = m v_C (Section 3.2.1)."""
    return particle.particle_linear_momentum(m, v_c)


def rigid_body_angular_momentum(inertia: ArrayLike, omega: ArrayLike) -> Quantity:
    """Angular momentum about the centre of mass, or about a fixed point of the body when
    I is taken about that point: H = I omega (Section 3.2.2)."""
    return np.asarray(inertia, dtype=float) @ np.asarray(omega, dtype=float)


def rigid_body_angular_momentum_about_point(inertia_centre: Quantity, omega: Quantity,
                                            m: Quantity, r_bc: Quantity,
                                            v_c: Quantity) -> Quantity:
    """Angular momentum of a rigid body about an arbitrary point B,
    H_B = I_C omega + r_BC x m v_C (angular momentum transfer formula, Section 3.2.4)."""
    return angular_momentum_transfer(rigid_body_angular_momentum(inertia_centre, omega), m, r_bc, v_c)


def angular_acceleration_about_fixed_axis(moment: Quantity,
                                          moment_of_inertia: Quantity) -> Quantity:
    """Angular acceleration of a body rotating about a fixed axis, omega_dot = M / I with
    M and I about that axis (balance of angular momentum, Section 3.2.2)."""
    return angular_acceleration(moment, moment_of_inertia)


def rotational_kinetic_energy(inertia: ArrayLike, omega: ArrayLike) -> float:
    """Kinetic energy of the rotation, 1/2 omega . I omega (Section 3.2.5)."""
    omega = np.asarray(omega, dtype=float)
    return float(0.5 * omega @ np.asarray(inertia, dtype=float) @ omega)


def rigid_body_kinetic_energy(m: Quantity, v_c: Quantity, inertia_centre: Quantity,
                              omega: Quantity) -> Quantity:
    """Kinetic energy of a rigid body, T = 1/2 m |v_C|^2 + 1/2 omega . I_C omega
    (translation of the centre of mass plus rotation about it, Section 3.2.5)."""
    return (float(translational_kinetic_energy(m, v_c))
            + rotational_kinetic_energy(inertia_centre, omega))


def rolling_acceleration_on_incline(alpha: Quantity, g: Quantity, m: Quantity, R: Quantity,
                                    moment_centre: Quantity) -> Quantity:
    """Acceleration of the centre of a round body rolling without slipping down an incline
    of angle alpha: a = g sin(alpha) / (1 + I_C / (m R^2)) (linear and angular momentum
    balance, Sections 3.2.1-3.2.2)."""
    return g * np.sin(alpha) / (1.0 + moment_centre / (m * R**2))


def rolling_speed_after_drop(h: Quantity, g: Quantity, m: Quantity, R: Quantity,
                             moment_centre: Quantity) -> Quantity:
    """Speed of the centre of a body rolling without slipping after descending a height h
    from rest: m g h = 1/2 m v^2 + 1/2 I_C (v/R)^2 (work-energy balance, Section 3.2.5)."""
    return np.sqrt(2.0 * g * h / (1.0 + moment_centre / (m * R**2)))


def friction_for_rolling_on_incline(alpha: Quantity, g: Quantity, m: Quantity, R: Quantity,
                                    moment_centre: Quantity) -> Quantity:
    """Static friction force on a body rolling without slipping down an incline,
    F = I_C a / R^2 (angular momentum balance about the centre, Section 3.2.2)."""
    a = rolling_acceleration_on_incline(alpha, g, m, R, moment_centre)
    return moment_centre * a / R**2


def minimum_friction_coefficient_for_rolling(alpha: Quantity, g: Quantity, m: Quantity,
                                             R: Quantity, moment_centre: Quantity) -> Quantity:
    """Smallest static friction coefficient that allows rolling without slipping down an
    incline, mu_min = F / (m g cos(alpha)) (Sections 3.2.1-3.2.2)."""
    friction = friction_for_rolling_on_incline(alpha, g, m, R, moment_centre)
    return friction / (m * g * np.cos(alpha))


def compound_pendulum_angular_acceleration(phi: Quantity, g: Quantity, m: Quantity,
                                           pivot_to_centre: Quantity,
                                           moment_pivot: Quantity) -> Quantity:
    """Angular acceleration of a compound (physical) pendulum about its fixed pivot,
    phi_ddot = -m g d sin(phi) / I_O (Section 3.2.2)."""
    return angular_acceleration_about_fixed_axis(-m * g * pivot_to_centre * np.sin(phi),
                                                 moment_pivot)


def angular_speed_of_pendulum_from_energy(phi1: Quantity, phi2: Quantity, g: Quantity,
                                          m: Quantity, pivot_to_centre: Quantity,
                                          moment_pivot: Quantity,
                                          phidot1: Quantity = 0.0) -> Quantity:
    """Angular speed of a compound pendulum at angle phi2 after swinging from phi1 with
    rate phi1_dot: 1/2 I_O phi_dot^2 - m g d cos(phi) is conserved (Section 3.2.5)."""
    energy = 0.5 * moment_pivot * phidot1**2 + m * g * pivot_to_centre * (
        np.cos(phi2) - np.cos(phi1))
    return np.sqrt(2.0 * energy / moment_pivot)


# -- issue 31, chapter 3 kinetics bank (Sections 3.2.1-3.2.5) ------------------------------


def front_axle_load_when_braking(m: Quantity, g: Quantity, mu: Quantity, l_f: Quantity,
                                 l_r: Quantity, h: Quantity) -> Quantity:
    """Normal force on the front wheels of a car braking with all wheels locked (sliding
    friction mu at both axles), its centre of mass l_f behind the front axle, l_r ahead of
    the rear one and h above the road: N_f = m g (l_r + mu h) / (l_f + l_r). The car
    translates, so the balance of linear momentum (Section 3.2.1) gives m a = -mu m g and
    the balance of angular momentum about the centre of mass has no rate: the moments of
    N_f, N_r and the friction about C cancel (Section 3.2.2)."""
    return m * g * (l_r + mu * h) / (l_f + l_r)


def rear_axle_load_when_braking(m: Quantity, g: Quantity, mu: Quantity, l_f: Quantity,
                                l_r: Quantity, h: Quantity) -> Quantity:
    """Normal force on the rear wheels of the same braking car,
    N_r = m g (l_f - mu h) / (l_f + l_r) (Sections 3.2.1-3.2.2); it vanishes when the
    rear wheels lift off, mu h = l_f."""
    return m * g * (l_f - mu * h) / (l_f + l_r)


def rolling_acceleration_under_horizontal_pull(F: Quantity, m: Quantity, R: Quantity,
                                               moment_centre: Quantity,
                                               lever_arm: Quantity) -> Quantity:
    """Acceleration of the centre of a round body (radius R, I_C about its axis) rolling
    without slipping on level ground, pulled by a horizontal force F whose line of action
    lies lever_arm above the centre (negative: below):
    a = F (1 + lever_arm / R) / (m + I_C / R^2). From m a = F + f and
    I_C a / R = F lever_arm - f R (balances of linear and angular momentum,
    Sections 3.2.1-3.2.2) with the rolling condition a = R omega_dot."""
    return F * (1.0 + lever_arm / R) / (m + moment_centre / R**2)


def friction_under_horizontal_pull(F: Quantity, m: Quantity, R: Quantity,
                                   moment_centre: Quantity, lever_arm: Quantity) -> Quantity:
    """Static friction of the ground on the same pulled rolling body, positive along the
    pull: f = m a - F = F (lever_arm / R - I_C / (m R^2)) / (1 + I_C / (m R^2))
    (Sections 3.2.1-3.2.2); it vanishes when lever_arm = I_C / (m R)."""
    return m * rolling_acceleration_under_horizontal_pull(F, m, R, moment_centre,
                                                          lever_arm) - F


def atwood_acceleration_with_heavy_pulley(m1: Quantity, m2: Quantity, g: Quantity,
                                          R: Quantity, moment_centre: Quantity) -> Quantity:
    """Acceleration of the masses of an Atwood machine whose pulley (radius R, I_C about
    its frictionless axle) turns with the rope without slipping, m1 descending:
    a = (m1 - m2) g / (m1 + m2 + I_C / R^2). The balance of angular momentum of the
    pulley, I_C a / R = (S1 - S2) R (Section 3.2.2), couples the two rope forces."""
    return (m1 - m2) * g / (m1 + m2 + moment_centre / R**2)


def hanging_mass_rope_force(m: Quantity, g: Quantity, a: Quantity) -> Quantity:
    """Force of a vertical rope on a hanging body of mass m accelerating upward with a
    (negative: downward), S = m (g + a) (balance of linear momentum, Section 3.2.1)."""
    return m * (g + a)


def brake_lever_shoe_force(P: Quantity, arm_force: Quantity, arm_shoe: Quantity) -> Quantity:
    """Normal force of a brake shoe on a wheel, pressed by a lever pivoted on the line of
    the shoe's friction force (so friction has no moment about the pivot): the lever's
    moment balance about its pivot, N arm_shoe = P arm_force (Section 3.2.2, statics)."""
    return P * arm_force / arm_shoe


def spin_down_time(omega0: Quantity, alpha: Quantity) -> Quantity:
    """Time a body spinning at omega0 takes to stop under a constant angular deceleration
    alpha > 0 (constant braking moment, balance of angular momentum about the fixed axis,
    Section 3.2.2): t = omega0 / alpha."""
    return omega0 / alpha


def spin_down_angle(omega0: Quantity, alpha: Quantity) -> Quantity:
    """Angle (rad) a body turns while it stops from omega0 under a constant angular
    deceleration alpha > 0: phi = omega0^2 / (2 alpha) (Section 3.2.2)."""
    return omega0**2 / (2.0 * alpha)


def zero_angular_momentum_offset(moment_centre: Quantity, omega: Quantity, m: Quantity,
                                 v: Quantity) -> Quantity:
    """Signed distance, along e3 x e_v from the centre of mass, of the line of points about
    which the angular momentum of a body in plane motion vanishes:
    H_B = I_C omega + m v y_B = 0 gives y_B = -I_C omega / (m v) (angular momentum transfer
    formula, Section 3.2.4; omega counter-clockwise positive, v > 0)."""
    return -moment_centre * omega / (m * v)


def moment_for_steady_rotation(omega: ArrayLike, H_O: ArrayLike) -> Quantity:
    """Moment about a fixed point O of the axis that keeps a body turning at the constant
    angular velocity omega about that fixed axis: H_O keeps its components in the body, so
    M_O = dH_O/dt = omega x H_O (balance of angular momentum, Section 3.2.2, with H_O from
    the transfer formula, Section 3.2.4)."""
    return np.cross(np.asarray(omega, dtype=float), np.asarray(H_O, dtype=float))


def sliding_rod_angular_speed(theta0: Quantity, theta: Quantity, g: Quantity,
                              L: Quantity) -> Quantity:
    """Angular speed of a slender rod of length L whose lower end slides on a frictionless
    floor, released from rest at theta0 from the vertical, when it leans at theta: no
    horizontal force, so C falls vertically with v_C = (L/2) sin(theta) theta_dot, and the
    work-energy balance m g (L/2)(cos theta0 - cos theta) = 1/2 m v_C^2
    + 1/2 (m L^2/12) theta_dot^2 gives
    theta_dot^2 = 12 g (cos theta0 - cos theta) / (L (1 + 3 sin^2 theta)) (Section 3.2.5)."""
    return np.sqrt(12.0 * g * (np.cos(theta0) - np.cos(theta))
                   / (L * (1.0 + 3.0 * np.sin(theta) ** 2)))


def drum_angular_speed_after_drop(m: Quantity, g: Quantity, h: Quantity, r: Quantity,
                                  moment_centre: Quantity,
                                  friction_moment: Quantity) -> Quantity:
    """Angular speed of a wheel (I_C about its axle) spun up from rest by a mass m on a
    string unwinding from its drum of radius r, after the mass has dropped h against a
    constant bearing friction moment: the work-energy balance
    m g h - M_f h / r = 1/2 (m r^2 + I_C) omega^2 (Section 3.2.5)."""
    work = m * g * h - friction_moment * h / r
    return np.sqrt(2.0 * work / (m * r**2 + moment_centre))
