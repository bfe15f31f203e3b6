"""Balance of angular momentum in the body frame: Euler's equations, torque-free rotation
and the stability of rotation about the principal axes (Section 3.4.4).

Principal moments I = (I1, I2, I3) and body-frame components of omega and of the moment M
about the centre of mass (or a fixed point).
"""
from __future__ import annotations

import numpy as np

from dynagrade.mechanics._common import ArrayLike, Quantity


def angular_acceleration_euler(principal_moments: ArrayLike, omega: ArrayLike,
                               moment: ArrayLike) -> Quantity:
    """Body-frame angular acceleration from Euler's equations,
    I1 w1' = M1 + (I2 - I3) w2 w3 and cyclic (Section 3.4.4)."""
    i1, i2, i3 = np.asarray(principal_moments, dtype=float)
    w1, w2, w3 = np.asarray(omega, dtype=float)
    m1, m2, m3 = np.asarray(moment, dtype=float)
    return np.array([(m1 + (i2 - i3) * w2 * w3) / i1,
                     (m2 + (i3 - i1) * w3 * w1) / i2,
                     (m3 + (i1 - i2) * w1 * w2) / i3])


def gyroscopic_moment(principal_moments: ArrayLike, omega: ArrayLike,
                      omega_dot: ArrayLike) -> Quantity:
    """Moment needed to keep up a prescribed body-frame rotation,
    M = I omega_dot + omega x (I omega) (Euler's equations, Section 3.4.4)."""
    inertia = np.asarray(principal_moments, dtype=float)
    omega = np.asarray(omega, dtype=float)
    return inertia * np.asarray(omega_dot, dtype=float) + np.cross(omega, inertia * omega)


def perturbation_growth_exponent_squared(principal_moments: ArrayLike, axis: int,
                                         spin_rate: Quantity) -> Quantity:
    """Squared growth rate of small perturbations of a steady rotation with rate Omega about
    the principal axis k: lambda^2 = Omega^2 (I_k - I_i)(I_j - I_k) / (I_i I_j), with i, j
    the other two axes. lambda^2 < 0: the perturbation oscillates (stable rotation);
    lambda^2 > 0: it grows exponentially (unstable) (linearized Euler equations,
    Section 3.4.4)."""
    inertia = np.asarray(principal_moments, dtype=float)
    i, j = [a for a in range(3) if a != axis]
    ik = inertia[axis]
    return spin_rate**2 * (ik - inertia[i]) * (inertia[j] - ik) / (inertia[i] * inertia[j])


def wobble_frequency(principal_moments: Quantity, axis: int, spin_rate: Quantity) -> Quantity:
    """Angular frequency of the small wobble of a stable rotation about principal axis k,
    sqrt(-lambda^2) (Section 3.4.4)."""
    return np.sqrt(-perturbation_growth_exponent_squared(principal_moments, axis, spin_rate))


def is_stable_rotation_axis(principal_moments: Quantity, axis: int) -> bool:
    """True if torque-free rotation about principal axis k is (linearly) stable: k is the
    axis of the largest or of the smallest of three distinct principal moments
    (Section 3.4.4)."""
    return bool(perturbation_growth_exponent_squared(principal_moments, axis, 1.0) < 0.0)


def body_precession_rate(axial_moment: Quantity, transverse_moment: Quantity,
                         axial_rate: Quantity) -> Quantity:
    """Rate at which omega circles the symmetry axis of a torque-free axisymmetric body,
    seen in the body frame, Omega_p = (I3 - I1) omega3 / I1 (Section 3.4.4)."""
    return (axial_moment - transverse_moment) * axial_rate / transverse_moment


# --- Issue 31: a rotor spinning on its shaft (bank exercises of Section 3.4.4) -------------


def bearing_force_of_couple(moment: Quantity, span: Quantity) -> Quantity:
    """Force each of two bearings a span l apart exerts when together they supply the couple
    M that Euler's equations ask of a steadily spinning rotor with no net force (its
    centre on the axis): two equal and opposite forces, F = M / l (Section 3.4.4)."""
    return moment / span


def angular_speed_rate(omega: ArrayLike, omega_dot: ArrayLike) -> float:
    """Rate of change of the angular speed |omega|, d|omega|/dt = omega . omega_dot / |omega|
    (body-frame components serve: the frame turns with omega, so omega_dot is the same in
    both frames; Section 3.4.4)."""
    w = np.asarray(omega, dtype=float)
    return float(w @ np.asarray(omega_dot, dtype=float) / np.linalg.norm(w))
