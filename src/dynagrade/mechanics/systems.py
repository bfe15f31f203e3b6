"""Systems of particles: centre of mass, momentum, energy and angular momentum (Sections 2.1-2.2).

Masses are given as a sequence of length N, positions and velocities as arrays of
shape (N, d) with d = 2 or 3. All quantities in SI units.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from dynagrade.mechanics._common import (ArrayLike, Quantity, as_floats, as_vectors, spatial_cross,
                                         spatial_vector)
from dynagrade.mechanics.energy import particle_kinetic_energy


def total_mass(masses: ArrayLike) -> float:
    """Total mass M = sum of m_i of a system of particles (Section 2.1)."""
    return float(np.sum(as_floats(masses)))


def centre_of_mass(masses: ArrayLike, positions: ArrayLike) -> Quantity:
    """Position of the centre of mass r_C = (1/M) sum m_i r_i (Section 2.1)."""
    m = as_floats(masses)
    r = as_vectors(positions, m.size)
    return (m[:, None] * r).sum(axis=0) / m.sum()


def centre_of_mass_velocity(masses: Quantity, velocities: Quantity) -> Quantity:
    """Velocity of the centre of mass, v_C = dr_C/dt = (1/M) sum m_i v_i, the mass-weighted
    mean of the particles' velocities (the time derivative of r_C, Section 2.1)."""
    return centre_of_mass(masses, velocities)


def positions_relative_to_centre_of_mass(masses: ArrayLike, positions: ArrayLike) -> Quantity:
    """Each particle's position relative to the centre of mass, rho_i = r_i - r_C, so that
    r_i = r_C + rho_i and sum m_i rho_i = 0 (relative coordinates, Section 2.1). Applied to
    velocities it gives the velocities relative to the centre of mass, v_i - v_C."""
    m = as_floats(masses)
    r = as_vectors(positions, m.size)
    return r - centre_of_mass(m, r)


def total_momentum(masses: ArrayLike, velocities: ArrayLike) -> Quantity:
    """Total linear momentum P = sum m_i v_i = M v_C of a system (Section 2.2.1)."""
    m = as_floats(masses)
    v = as_vectors(velocities, m.size)
    return (m[:, None] * v).sum(axis=0)


def centre_of_mass_acceleration(total_external_force: ArrayLike, M: Quantity) -> Quantity:
    """Acceleration of the centre of mass a_C = F_ext / M: the centre of mass moves like a
    particle of the total mass under the total external force; internal forces cancel
    pairwise (balance of linear momentum of a system, Section 2.2.1)."""
    return np.asarray(total_external_force, dtype=float) / M


def system_kinetic_energy(masses: ArrayLike, velocities: ArrayLike) -> float:
    """Kinetic energy T = sum 1/2 m_i |v_i|^2 of a system of particles (Section 2.2.2)."""
    m = as_floats(masses)
    return float(np.sum(particle_kinetic_energy(m, as_vectors(velocities, m.size))))


def kinetic_energy_relative_to_centre_of_mass(masses: ArrayLike, velocities: ArrayLike) -> Quantity:
    """Kinetic energy of the motion relative to the centre of mass,
    T' = sum 1/2 m_i |v_i - v_C|^2, so that T = 1/2 M |v_C|^2 + T' (Section 2.2.2)."""
    m = as_floats(masses)
    v = as_vectors(velocities, m.size)
    v_c = total_momentum(m, v) / m.sum()
    return system_kinetic_energy(m, v - v_c)


def reduced_mass(m1: Quantity, m2: Quantity) -> Quantity:
    """Reduced mass mu = m1 m2 / (m1 + m2) of two particles (Sections 2.2.2 and 2.3.1)."""
    return m1 * m2 / (m1 + m2)


def relative_kinetic_energy(m1: Quantity, m2: Quantity, relative_speed: Quantity) -> Quantity:
    """Kinetic energy of the relative motion of two particles, 1/2 mu v_rel^2: the part
    of T that internal forces between the two can change (Section 2.2.2)."""
    return 0.5 * reduced_mass(m1, m2) * relative_speed**2


def relative_speed_from_internal_work(m1: Quantity, m2: Quantity, internal_work: Quantity,
                                      initial_relative_speed: Quantity = 0.0) -> Quantity:
    """Relative speed of two particles after internal forces did the work W_int on them
    (e.g. a compressed spring between two carts released): 1/2 mu v_rel^2 grows by W_int
    while the centre-of-mass motion is unchanged (work-energy balance, Section 2.2.2)."""
    t_rel = relative_kinetic_energy(m1, m2, initial_relative_speed) + internal_work
    return np.sqrt(2.0 * t_rel / reduced_mass(m1, m2))


@dataclass(frozen=True)
class PairSpeeds:
    """Speeds of the two particles of a pair."""

    v1: Quantity
    v2: Quantity


def speeds_relative_to_centre_of_mass(m1: float, m2: float,
                                      relative_speed: Quantity) -> PairSpeeds:
    """How the relative speed of two particles splits between them in the centre-of-mass
    frame: m1 v1 = m2 v2 (total momentum zero) and v1 + v2 = v_rel give
    v1 = m2/(m1+m2) v_rel, v2 = m1/(m1+m2) v_rel, opposite in direction
    (balance of linear momentum, Section 2.2.1)."""
    total = total_mass([m1, m2])
    return PairSpeeds(m2 / total * relative_speed, m1 / total * relative_speed)


def system_angular_momentum_about_point(masses: ArrayLike, positions: ArrayLike,
                                        velocities: ArrayLike, point: ArrayLike) -> Quantity:
    """Angular momentum of a system about a fixed point B,
    H_B = sum (r_i - r_B) x m_i v_i (Section 2.2.3). Planar input returns a 3-vector."""
    m = as_floats(masses)
    r = as_vectors(positions, m.size) - np.asarray(point, dtype=float)
    v = as_vectors(velocities, m.size)
    return (m[:, None] * spatial_cross(r, v)).sum(axis=0)


def angular_momentum_about_centre_of_mass(masses: ArrayLike, positions: ArrayLike,
                                          velocities: ArrayLike) -> Quantity:
    """Angular momentum about the centre of mass, H_C = sum (r_i - r_C) x m_i (v_i - v_C)
    (relative and absolute velocities give the same H_C; Section 2.2.3)."""
    m = as_floats(masses)
    r = as_vectors(positions, m.size)
    v = as_vectors(velocities, m.size)
    v_c = total_momentum(m, v) / m.sum()
    return system_angular_momentum_about_point(m, r, v - v_c, centre_of_mass(m, r))


def angular_momentum_transfer(h_c: ArrayLike, M: Quantity, r_bc: ArrayLike,
                              v_c: ArrayLike) -> Quantity:
    """Angular momentum about a point B from that about the centre of mass,
    H_B = H_C + r_BC x M v_C (Section 2.2.3; for rigid bodies Section 3.2.4)."""
    return np.asarray(h_c, dtype=float) + M * spatial_cross(r_bc, v_c)


# --- Sections 2.2.1-2.2.3: relations added for the exercise bank (issue 31, ch2 systems) ---

def recoil_displacement(m: Quantity, M: Quantity, relative_displacement: Quantity) -> Quantity:
    """Distance a body of mass M moves back while a body of mass m on it moves by d
    relative to it, the two starting at rest with no external force along the motion
    (a person walking on a floating boat): the centre of mass stays put, so
    m (d - x) = M x and x = m d / (m + M) (balance of linear momentum, Section 2.2.1)."""
    return m * relative_displacement / (m + M)


def atwood_acceleration(m1: Quantity, m2: Quantity, g: Quantity) -> Quantity:
    """Acceleration of the blocks of an Atwood machine (two masses on an inextensible
    string over a light, frictionless pulley), positive when m1 descends:
    a = (m1 - m2) g / (m1 + m2), from the momentum balance along the string of the two
    blocks together, whose string forces are internal (Section 2.2.1)."""
    return (m1 - m2) * g / (m1 + m2)


def total_external_force(M: Quantity, a_c: ArrayLike) -> Quantity:
    """Total external force on a system of total mass M whose centre of mass accelerates
    with a_C: F_ext = dP/dt = M a_C (balance of linear momentum of a system,
    Section 2.2.1; the inverse of :func:`centre_of_mass_acceleration`)."""
    return M * np.asarray(a_c, dtype=float)


def maximum_spring_compression_between_particles(m1: Quantity, m2: Quantity, k: Quantity,
                                                 relative_speed: Quantity) -> Quantity:
    """Largest compression of a light spring (stiffness k) between two particles that
    approach with the relative speed v_rel: at the largest compression both move with the
    centre-of-mass velocity, so all of the relative kinetic energy 1/2 mu v_rel^2 is
    stored, x_max = v_rel sqrt(mu / k) (work-energy balance, Section 2.2.2)."""
    return relative_speed * np.sqrt(reduced_mass(m1, m2) / k)


def steady_radius_through_hole(m1: Quantity, m2: Quantity, g: Quantity, H: Quantity) -> Quantity:
    """Radius of steady circling of a particle m1 on a smooth table, tied by a string
    through a hole to a hanging particle m2, with the system's angular momentum H about
    the hole: m2 g = m1 r phidot^2 with phidot = H/(m1 r^2) gives
    r = (H^2 / (m1 m2 g))^(1/3) (balance of angular momentum of a system, Section 2.2.3)."""
    return np.cbrt(H**2 / (m1 * m2 * g))


def turning_radius_through_hole(m1: Quantity, m2: Quantity, g: Quantity, H: Quantity,
                                r0: Quantity) -> Quantity:
    """The other turning radius of the particle m1 of :func:`steady_radius_through_hole`
    that starts at r0 with no radial velocity: H stays (the string and the weights have
    no moment about the hole's vertical), and the energy
    H^2/(2 m1 r^2) + m2 g r takes the same value at both turning radii, which gives
    2 m1 m2 g r0^2 r^2 - H^2 r - H^2 r0 = 0 (Sections 2.2.2 and 2.2.3)."""
    a = 2.0 * m1 * m2 * g * r0**2
    return (H**2 + np.sqrt(H**4 + 4.0 * a * H**2 * r0)) / (2.0 * a)

# --- Bank exercises of issue 31, Section 2.1: two particles on a rigid link -----------------

def rigid_link_second_velocity(theta: Quantity, v1: ArrayLike, u2: Quantity) -> Quantity:
    """Second (e2) velocity component of particle 2 joined to particle 1 by a rigid link
    that points from 1 to 2 at the angle theta from e1, given particle 1's velocity v1
    and particle 2's e1 component u2: the link keeps |r2 - r1| constant, one kinematic
    constraint (eq. (1.21) applied to the system), whose rate is (r2 - r1) . (v2 - v1) = 0,
    so v2_2 = v1_2 - (u2 - v1_1) cot(theta) (Section 2.1)."""
    v1 = np.asarray(v1, dtype=float)
    return v1[1] - (u2 - v1[0]) * np.cos(theta) / np.sin(theta)


def rigid_link_angular_velocity(theta: Quantity, L: Quantity, v1: ArrayLike,
                                v2: ArrayLike) -> Quantity:
    """Angular velocity (about e3, counter-clockwise positive) of a rigid link of length L
    from particle 1 to particle 2 at the angle theta from e1: the relative velocity is
    perpendicular to the link, v2 - v1 = omega L e_phi, so omega = e3 . (r2 - r1) x (v2 - v1)
    / L^2 (polar coordinates of particle 2 about particle 1, eqs. (1.31), (1.36))."""
    relative = np.asarray(v2, dtype=float) - np.asarray(v1, dtype=float)
    return (np.cos(theta) * relative[1] - np.sin(theta) * relative[0]) / L
