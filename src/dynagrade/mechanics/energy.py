"""Work and energy of a particle, Section 1.2.2: kinetic energy, work along a path,
potential energies, the conservative-force test, and the energy results of
Examples 1.11, 1.12 and 1.14.  SI units.
"""
from __future__ import annotations

from typing import Iterable

import numpy as np

from dynagrade.mechanics._common import ArrayLike, Field, Quantity


def particle_kinetic_energy(m: Quantity, v: ArrayLike) -> Quantity:
    """Kinetic energy T = m |v|^2 / 2, eq. (1.87); v a speed or a velocity vector (last axis)."""
    v = np.asarray(v, dtype=float)
    speed_sq = v**2 if v.ndim == 0 else np.sum(v**2, axis=-1)
    return 0.5 * m * speed_sq


def gravity_potential(m: Quantity, r: ArrayLike, g: ArrayLike) -> Quantity:
    """Potential energy of gravity V(r) = -m r . g for the gravity vector g, eq. (1.96)."""
    return -m * np.sum(np.asarray(r, dtype=float) * np.asarray(g, dtype=float), axis=-1)


def spring_potential(k: Quantity, x: ArrayLike, x0: Quantity = 0.0) -> Quantity:
    """Potential energy of a linear spring V = k (x - x0)^2 / 2, eq. (1.97)."""
    return 0.5 * k * (np.asarray(x, dtype=float) - x0) ** 2


def spring_potential_of_stretch(k: Quantity, stretch: ArrayLike) -> Quantity:
    """Potential energy of a linear spring stretched (or compressed) by ``stretch``, k s^2/2
    (eq. 1.97, the form used in eqs. 1.107 and 1.124)."""
    return 0.5 * k * np.asarray(stretch, dtype=float) ** 2


def work_along_path(force: Field, path: Field, velocity: Field, t1: float,
                    t2: float) -> float:
    """Work of a force along a parametrised path, W12 = integral F . (dr/dt) dt, eq. (1.87),
    by quadrature.  ``path(t)`` and ``velocity(t) = dr/dt`` are callables returning vectors;
    ``force(r, v)`` gets the position and the velocity (so friction and drag can be given;
    a position-only field ignores ``v``)."""
    from scipy.integrate import quad
    def power(t):
        v = np.asarray(velocity(t), dtype=float)
        return float(np.dot(np.asarray(force(np.asarray(path(t), dtype=float), v)), v))

    value, _ = quad(power, t1, t2, epsabs=1e-12, epsrel=1e-10, limit=400)
    return value


def work_from_potential(V1: Quantity, V2: Quantity) -> Quantity:
    """Work of a conservative force between two points, W12 = V(r1) - V(r2), eq. (1.99)."""
    return V1 - V2


def speed_after_work(m: Quantity, v1: Quantity, W12: Quantity) -> Quantity:
    """Speed after work W12 was done on a particle with speed v1, from the work-energy
    balance T2 - T1 = W12, eq. (1.87).  NaN when the work exceeds the kinetic energy."""
    T2 = particle_kinetic_energy(m, v1) + W12
    with np.errstate(invalid="ignore"):
        return np.where(T2 >= 0.0, np.sqrt(2.0 * np.maximum(T2, 0.0) / m), np.nan)


def curl(force: Field, r: ArrayLike, step_size: float = 1e-5) -> Quantity:
    """Curl of a 3D force field at r by central differences; it vanishes for a conservative
    force F = -dV/dr, eq. (1.94)."""
    r = np.asarray(r, dtype=float)
    jac = np.empty((3, 3))
    for j in range(3):
        step = np.zeros(3)
        step[j] = step_size
        jac[:, j] = (np.asarray(force(r + step)) - np.asarray(force(r - step))) / (2 * step_size)
    return np.array([jac[2, 1] - jac[1, 2], jac[0, 2] - jac[2, 0], jac[1, 0] - jac[0, 1]])


def is_conservative(force: Field, points: Iterable[ArrayLike], scale: float = 1.0,
                    step_size: float = 1e-5, tol: float = 1e-6) -> bool:
    """Whether a position-dependent force field has zero curl at all the given sample points
    (to the relative tolerance ``tol`` of a typical force ``scale``), the test behind
    eqs. (1.93)-(1.94)."""
    return all(np.linalg.norm(curl(force, p, step_size)) <= tol * scale for p in points)


def friction_work_on_floor(mu: Quantity, m: Quantity, g: Quantity,
                           distance: Quantity) -> Quantity:
    """Work of sliding friction on a horizontal floor over a distance, -mu m g dx, eq. (1.89)."""
    return -mu * m * g * distance


def sliding_stopping_distance(v0: Quantity, mu: Quantity, g: Quantity) -> Quantity:
    """Distance a particle sliding on a horizontal floor travels before friction stops it,
    dx = v0^2 / (2 mu g), eq. (1.91): eq. (1.128) with alpha = 0, as the notes remark.

    Example 1.11 at v0 = 10 m/s, mu = 0.5, g = 10 m/s^2: 100 / (2 * 0.5 * 10) = 10 m.

    >>> float(sliding_stopping_distance(10.0, 0.5, 10.0))
    10.0
    """
    return v0**2 / (2.0 * (g * mu))


def height_gain(v1: Quantity, v2: Quantity, g: Quantity) -> Quantity:
    """Height gained while gravity alone slows a particle from speed v1 to v2,
    (v1^2 - v2^2)/(2 g), from conservation of energy eq. (1.102) as in eq. (1.106)."""
    return (v1**2 - v2**2) / (2.0 * g)


def spring_launch_height(k: Quantity, compression: Quantity, m: Quantity,
                         g: Quantity) -> Quantity:
    """Greatest height of a particle launched upward from rest by a spring compressed by
    dx, x_2,max = k dx^2 / (2 m g), eq. (1.108).

    Example 1.12 at k = 1000 N/m, dx = 0.1 m, m = 0.5 kg, g = 10 m/s^2:
    1000 * 0.01 / (2 * 0.5 * 10) = 1 m.

    >>> round(float(spring_launch_height(1000.0, 0.1, 0.5, 10.0)), 12)
    1.0
    """
    return spring_potential_of_stretch(k, compression) / (m * g)


def slingshot_stretch(dx: Quantity, l0: Quantity) -> Quantity:
    """Elongation of a slingshot spring of natural length l0 when its end is pulled
    sideways by dx, sqrt(dx^2 + l0^2) - l0 (Example 1.14, eq. 1.124)."""
    return np.hypot(dx, l0) - l0


def slingshot_speed(k: Quantity, m: Quantity, dx: Quantity, l0: Quantity) -> Quantity:
    """Speed of the slingshot's particle when the spring is back at its natural length,
    v = sqrt(k/m) (sqrt(dx^2 + l0^2) - l0), eq. (1.125)."""
    return np.sqrt(k / m) * slingshot_stretch(dx, l0)
