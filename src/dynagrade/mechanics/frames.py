"""Rotating frames of reference: velocity and acceleration transfer, Coriolis and
centrifugal terms (Sections 3.4.2 and 3.4.3).

A frame with origin O' moves with a_O' and rotates with angular velocity Omega (rate
Omega_dot); r, v_rel and a_rel are position, velocity and acceleration seen in that frame.
All vectors are 3-vectors in one common basis.
"""
from __future__ import annotations

import numpy as np

from dynagrade.mechanics._common import ArrayLike, Quantity, cross


def absolute_velocity(v_origin: ArrayLike, omega: ArrayLike, r: ArrayLike,
                      v_rel: ArrayLike) -> Quantity:
    """Absolute velocity of a point moving in a rotating frame,
    v = v_O' + Omega x r + v_rel (Section 3.4.2)."""
    return np.asarray(v_origin, dtype=float) + cross(omega, r) + np.asarray(v_rel, float)


def coriolis_acceleration(omega: ArrayLike, v_rel: ArrayLike) -> np.ndarray:
    """Coriolis acceleration 2 Omega x v_rel (Section 3.4.2)."""
    return 2.0 * cross(omega, v_rel)


def frame_centripetal_acceleration(omega: ArrayLike, r: ArrayLike) -> Quantity:
    """Centripetal acceleration of the frame point, Omega x (Omega x r); its negative is the
    centrifugal term of the relative motion (Section 3.4.2)."""
    return cross(omega, cross(omega, r))


def absolute_acceleration(a_origin: ArrayLike, omega: Quantity, omega_dot: ArrayLike, r: Quantity,
                          v_rel: Quantity, a_rel: ArrayLike) -> Quantity:
    """Absolute acceleration of a point moving in a rotating frame,
    a = a_O' + Omega_dot x r + Omega x (Omega x r) + 2 Omega x v_rel + a_rel (Section 3.4.2)."""
    return (np.asarray(a_origin, dtype=float) + cross(omega_dot, r)
            + frame_centripetal_acceleration(omega, r) + coriolis_acceleration(omega, v_rel)
            + np.asarray(a_rel, dtype=float))


def relative_acceleration(force: ArrayLike, m: Quantity, a_origin: Quantity, omega: Quantity,
                          omega_dot: Quantity, r: Quantity, v_rel: Quantity) -> Quantity:
    """Acceleration seen in the rotating frame from the balance of linear momentum,
    m a_rel = F - m [a_O' + Omega_dot x r + Omega x (Omega x r) + 2 Omega x v_rel]
    (fictitious forces, Section 3.4.3)."""
    zero = np.zeros(3)
    frame_terms = absolute_acceleration(a_origin, omega, omega_dot, r, v_rel, zero)
    return np.asarray(force, dtype=float) / m - frame_terms


def bead_radial_position(t: Quantity, r0: Quantity, radial_speed0: Quantity,
                         omega: Quantity) -> Quantity:
    """Distance of a bead sliding without friction on a rod that spins at constant rate
    Omega in a horizontal plane: r_ddot = Omega^2 r, so
    r(t) = r0 cosh(Omega t) + (v0/Omega) sinh(Omega t) (Section 3.4.3)."""
    return r0 * np.cosh(omega * t) + radial_speed0 / omega * np.sinh(omega * t)


def bead_radial_speed(t: Quantity, r0: Quantity, radial_speed0: Quantity,
                      omega: Quantity) -> Quantity:
    """Radial speed of the bead on the spinning rod,
    r_dot(t) = r0 Omega sinh(Omega t) + v0 cosh(Omega t) (Section 3.4.3)."""
    return r0 * omega * np.sinh(omega * t) + radial_speed0 * np.cosh(omega * t)


def bead_normal_force(m: Quantity, omega: float, radial_speed: float) -> Quantity:
    """Force of the spinning rod on the bead, perpendicular to the rod in the direction of
    rotation, N = 2 m Omega r_dot: the rod supplies the Coriolis term (Section 3.4.3).
    Signed: negative when the bead moves inward."""
    return m * float(coriolis_acceleration([0.0, 0.0, omega], [radial_speed, 0.0, 0.0])[1])


def eastward_deflection_of_falling_body(h: Quantity, latitude: Quantity, earth_rate: Quantity,
                                        g: Quantity) -> Quantity:
    """Eastward deflection of a body dropped from rest from height h at latitude lambda,
    to first order in the Earth's rate Omega: d = (1/3) Omega g cos(lambda) t^3 with the
    fall time t = sqrt(2 h / g) (Coriolis term, Section 3.4.3)."""
    fall_time = np.sqrt(2.0 * h / g)
    return earth_rate * g * np.cos(latitude) * fall_time**3 / 3.0


# --- Issue 31: a spring-held mass in a turning slot (bank exercises of Section 3.4.3) -------


def spring_slot_equilibrium_radius(k: Quantity, m: Quantity, l0: Quantity,
                                   omega: Quantity) -> Quantity:
    """Radius at which a mass m, held by a spring (stiffness k, unstretched length l0) from
    the axis, rests relative to a slot turning at the constant rate Omega < sqrt(k/m):
    the spring balances the centrifugal term, k (r - l0) = m Omega^2 r, so
    r_e = k l0 / (k - m Omega^2) (Section 3.4.3)."""
    return k * l0 / (k - m * omega**2)


def spring_slot_relative_frequency(k: Quantity, m: Quantity, omega: Quantity) -> Quantity:
    """Angular frequency of the radial oscillation, seen in the turning slot, of the
    spring-held mass about r_e: m r'' = -k (r - l0) + m Omega^2 r, so
    omega_rel = sqrt(k/m - Omega^2) (Section 3.4.3)."""
    return np.sqrt(k / m - omega**2)


def relative_velocity(v: ArrayLike, v_origin: ArrayLike, omega: ArrayLike,
                      r: ArrayLike) -> Quantity:
    """Velocity seen in a rotating frame of a point with absolute velocity v at r from the
    frame's origin O': v_rel = v - v_O' - Omega x r (the velocity transfer of
    Section 3.4.2 solved for v_rel)."""
    return np.asarray(v, dtype=float) - np.asarray(v_origin, dtype=float) - cross(omega, r)
