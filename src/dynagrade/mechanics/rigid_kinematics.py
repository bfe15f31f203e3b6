"""Rigid-body kinematics in 2D and 3D (Sections 3.1.1 and 3.1.2).

Planar motion: vectors have two components (e1, e2), the angular velocity and the
angular acceleration are scalars about e3. Spatial motion: 3-vectors throughout.
"""
from __future__ import annotations

import numpy as np

from dynagrade.mechanics._common import ArrayLike, Quantity, spatial_cross


def _planar_or_spatial(omega, r):
    """Cross product omega x r; for a scalar omega the planar version omega e3 x r."""
    r = np.asarray(r, dtype=float)
    if np.ndim(omega) == 0:
        w = np.array([0.0, 0.0, float(omega)])
        return spatial_cross(w, r)[: r.shape[-1]]
    return spatial_cross(omega, r)


def velocity_of_point(v_a: ArrayLike, omega: Quantity, r_ab: Quantity) -> np.ndarray:
    """Velocity of a point B of a rigid body from that of A, v_B = v_A + omega x r_AB
    (velocity transfer, Sections 3.1.1 and 3.1.2)."""
    return np.asarray(v_a, dtype=float) + _planar_or_spatial(omega, r_ab)


def acceleration_of_point(a_a: ArrayLike, omega: Quantity, alpha: Quantity,
                          r_ab: Quantity) -> Quantity:
    """Acceleration of a point B of a rigid body from that of A,
    a_B = a_A + alpha x r_AB + omega x (omega x r_AB) (Sections 3.1.1 and 3.1.2);
    in 2D the last term is -omega^2 r_AB."""
    tangential = _planar_or_spatial(alpha, r_ab)
    centripetal = _planar_or_spatial(omega, _planar_or_spatial(omega, r_ab))
    return np.asarray(a_a, dtype=float) + tangential + centripetal


def planar_angular_velocity(r_a: ArrayLike, v_a: ArrayLike, r_b: ArrayLike,
                            v_b: ArrayLike) -> float:
    """Angular velocity of a body in plane motion from the velocities of two of its points,
    omega = e3 . (r_AB x (v_B - v_A)) / |r_AB|^2 (Section 3.1.1)."""
    r_ab = np.asarray(r_b, dtype=float) - np.asarray(r_a, dtype=float)
    dv = np.asarray(v_b, dtype=float) - np.asarray(v_a, dtype=float)
    return float(spatial_cross(r_ab, dv)[2] / np.dot(r_ab, r_ab))


def instantaneous_centre_of_rotation(r_a: ArrayLike, v_a: Quantity, omega: Quantity) -> Quantity:
    """Position of the instantaneous centre of rotation (the point of zero velocity) of a
    body in plane motion, r_ICR = r_A + (e3 x v_A) / omega, omega != 0 (Section 3.1.1)."""
    return np.asarray(r_a, dtype=float) + _planar_or_spatial(1.0, v_a) / omega


def rolling_angular_velocity(centre_speed: Quantity, R: Quantity) -> Quantity:
    """Angular velocity of a wheel rolling without slipping, omega = v_C / R; the contact
    point is the instantaneous centre of rotation (Section 3.1.1). Positive omega is
    clockwise for a wheel rolling in +e1 (the signed value about e3 is -v_C/R)."""
    return centre_speed / R


def rim_point_velocity(centre_speed: Quantity, R: Quantity, phi: Quantity) -> Quantity:
    """Velocity (e1, e2 components) of a point on the rim of a wheel rolling without
    slipping to the right with centre speed v_C; the point sits at the angle phi measured
    from the contact point, counter-clockwise seen from +e3 about the centre. By velocity
    transfer from the centre with omega e3 = -(v_C / R) e3 (Section 3.1.1)."""
    r_cp = R * np.array([np.sin(phi), -np.cos(phi)])
    omega = -rolling_angular_velocity(centre_speed, R)
    return velocity_of_point(np.array([centre_speed, 0.0]), omega, r_cp)


def connecting_rod_angle(crank_radius: Quantity, rod_length: Quantity,
                         crank_angle: Quantity) -> Quantity:
    """Angle beta of the connecting rod of a crank-slider mechanism with the slider on the
    line through the crank pivot: l sin(beta) = r sin(theta) (Section 3.1.1)."""
    return np.arcsin(crank_radius * np.sin(crank_angle) / rod_length)


def connecting_rod_angular_velocity(crank_radius: Quantity, rod_length: Quantity,
                                    crank_angle: Quantity, crank_rate: Quantity) -> Quantity:
    """Angular velocity of the connecting rod, beta_dot = r omega cos(theta) /
    (l cos(beta)), from transferring the crank-pin velocity to the slider whose velocity
    is along the slider line (Section 3.1.1). Signed like theta_dot, beta measured
    clockwise so that the rod tilts toward the crank pin."""
    beta = connecting_rod_angle(crank_radius, rod_length, crank_angle)
    return crank_radius * crank_rate * np.cos(crank_angle) / (rod_length * np.cos(beta))


def slider_velocity(crank_radius: Quantity, rod_length: Quantity, crank_angle: Quantity,
                    crank_rate: Quantity) -> float:
    """Velocity of the slider of a crank-slider mechanism along the slider line (positive
    away from the crank pivot): crank pin A at r(cos theta, sin theta), slider B at
    (r cos theta + l cos beta, 0), v_B = v_A + omega_rod x r_AB (Section 3.1.1)."""
    beta = connecting_rod_angle(crank_radius, rod_length, crank_angle)
    r_a = crank_radius * np.array([np.cos(crank_angle), np.sin(crank_angle)])
    v_a = velocity_of_point(np.zeros(2), crank_rate, r_a)
    r_ab = np.array([rod_length * np.cos(beta), -crank_radius * np.sin(crank_angle)])
    beta_dot = connecting_rod_angular_velocity(crank_radius, rod_length, crank_angle,
                                               crank_rate)
    return float(velocity_of_point(v_a, -beta_dot, r_ab)[0])
