"""Moment of inertia tensors (Section 3.2.3).

Tensors are 3x3 arrays in SI (kg m^2) about the centre of mass, in the body's axes of
symmetry: the symmetry axis (rod, disk, cylinder, hoop, tube) is e3.
I = integral rho (|r|^2 1 - r (x) r) dV.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from dynagrade.mechanics._common import ArrayLike, Quantity


def inertia_tensor_point_mass(m: Quantity, r: ArrayLike) -> Quantity:
    """Inertia tensor of a point mass at r about the origin, m (|r|^2 1 - r (x) r)
    (Section 3.2.3)."""
    r = np.asarray(r, dtype=float)
    return m * (np.dot(r, r) * np.eye(3) - np.outer(r, r))


def inertia_tensor_rod(m: Quantity, L: Quantity) -> Quantity:
    """Slender rod of length L along e3 about its centre: diag(mL^2/12, mL^2/12, 0)
    (Section 3.2.3)."""
    transverse = m * L**2 / 12.0
    return np.diag([transverse, transverse, 0.0])


def inertia_tensor_box(m: Quantity, a: Quantity, b: Quantity, c: Quantity) -> Quantity:
    """Solid cuboid with edges a, b, c along e1, e2, e3 about its centre:
    diag(m(b^2+c^2)/12, m(a^2+c^2)/12, m(a^2+b^2)/12) (Section 3.2.3)."""
    return m / 12.0 * np.diag([b**2 + c**2, a**2 + c**2, a**2 + b**2])


def inertia_tensor_cylinder(m: Quantity, R: Quantity, h: Quantity) -> Quantity:
    """Solid circular cylinder of radius R and height h, axis e3, about its centre:
    diag(m(3R^2+h^2)/12, m(3R^2+h^2)/12, mR^2/2) (Section 3.2.3)."""
    transverse = m * (3.0 * R**2 + h**2) / 12.0
    return np.diag([transverse, transverse, 0.5 * m * R**2])


def inertia_tensor_disk(m: Quantity, R: Quantity) -> Quantity:
    """Thin circular disk, normal e3: diag(mR^2/4, mR^2/4, mR^2/2), the cylinder with
    h -> 0 (Section 3.2.3)."""
    return inertia_tensor_cylinder(m, R, 0.0)


def inertia_tensor_cylindrical_shell(m: Quantity, R: Quantity, h: Quantity) -> Quantity:
    """Thin-walled open tube of radius R and length h, axis e3, about its centre:
    diag(mR^2/2 + mh^2/12, mR^2/2 + mh^2/12, mR^2) (Section 3.2.3)."""
    transverse = m * R**2 / 2.0 + m * h**2 / 12.0
    return np.diag([transverse, transverse, m * R**2])


def inertia_tensor_hoop(m: Quantity, R: Quantity) -> Quantity:
    """Thin ring (hoop) of radius R, normal e3: diag(mR^2/2, mR^2/2, mR^2), the tube with
    h -> 0 (Section 3.2.3)."""
    return inertia_tensor_cylindrical_shell(m, R, 0.0)


def inertia_tensor_sphere(m: Quantity, R: Quantity) -> Quantity:
    """Solid homogeneous sphere about its centre: (2/5) m R^2 1 (Section 3.2.3)."""
    return 0.4 * m * R**2 * np.eye(3)


def inertia_tensor_spherical_shell(m: Quantity, R: Quantity) -> Quantity:
    """Thin spherical shell about its centre: (2/3) m R^2 1 (Section 3.2.3)."""
    return 2.0 / 3.0 * m * R**2 * np.eye(3)


def parallel_axis_inertia_tensor(inertia_centre: ArrayLike, m: Quantity,
                                 r_pc: Quantity) -> Quantity:
    """Inertia tensor about a point P from the one about the centre of mass C,
    I_P = I_C + m (|r_PC|^2 1 - r_PC (x) r_PC) (parallel-axis theorem, Section 3.2.3)."""
    return np.asarray(inertia_centre, dtype=float) + inertia_tensor_point_mass(m, r_pc)


def parallel_axis_moment(moment_centre: Quantity, m: Quantity, distance: Quantity) -> Quantity:
    """Moment of inertia about an axis at distance d from the parallel axis through the
    centre of mass, I = I_C + m d^2 (Steiner, Section 3.2.3)."""
    return moment_centre + m * distance**2


def rotated_inertia_tensor(inertia: ArrayLike, rotation: ArrayLike) -> Quantity:
    """Components of the inertia tensor of a body rotated by R (or, equivalently, of the
    same body in a frame rotated by R^T): I' = R I R^T (Section 3.2.3)."""
    rotation = np.asarray(rotation, dtype=float)
    return rotation @ np.asarray(inertia, dtype=float) @ rotation.T


def moment_of_inertia_about_axis(inertia: ArrayLike, axis: ArrayLike) -> float:
    """Moment of inertia about the axis n through the reference point, I_n = n . I n
    (Section 3.2.3)."""
    n = np.asarray(axis, dtype=float)
    n = n / np.linalg.norm(n)
    return float(n @ np.asarray(inertia, dtype=float) @ n)


@dataclass(frozen=True)
class PrincipalAxes:
    """Principal moments (ascending) and the matching principal axes as columns."""

    moments: np.ndarray
    axes: np.ndarray


def principal_axes(inertia: ArrayLike) -> PrincipalAxes:
    """Principal moments of inertia and principal axes: eigenvalues and orthonormal
    eigenvectors of the symmetric tensor I (Section 3.2.3)."""
    from scipy.linalg import eigh
    moments, axes = eigh(np.asarray(inertia, dtype=float))
    if np.linalg.det(axes) < 0:
        axes[:, -1] = -axes[:, -1]
    return PrincipalAxes(moments=moments, axes=axes)
