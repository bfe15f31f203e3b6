"""Stiffness of massless deformable bodies acting as springs, Section 5.1 of the notes.

A massless bar, shaft or beam that carries a rigid mass acts as a linear spring whose
stiffness follows from elastostatics (Mechanics 2): force (or torque) per unit
displacement (or rotation) of the point where the mass sits.  E is Young's modulus,
G the shear modulus, A the cross-section, I its second moment of area, I_p its polar
moment, L the length; all SI.
"""
from __future__ import annotations

import numpy as np

from dynagrade.mechanics._common import Quantity


def shear_modulus(E: Quantity, nu: Quantity) -> Quantity:
    """Shear modulus G = E / (2 (1 + nu)) of an isotropic material, Section 5.1."""
    return E / (2.0 * (1.0 + nu))


def circle_area(d: Quantity) -> Quantity:
    """Cross-sectional area A = pi d^2 / 4 of a solid circular section, Section 5.1."""
    return np.pi * d**2 / 4.0


def circle_second_moment(d: Quantity) -> Quantity:
    """Second moment of area I = pi d^4 / 64 of a solid circular section, Section 5.1."""
    return np.pi * d**4 / 64.0


def circle_polar_moment(d: Quantity) -> Quantity:
    """Polar moment of area I_p = pi d^4 / 32 of a solid circular section, Section 5.1."""
    return np.pi * d**4 / 32.0


def rectangle_second_moment(b: Quantity, h: Quantity) -> Quantity:
    """Second moment of area I = b h^3 / 12 of a b x h rectangle bent about its b-axis, Section 5.1."""
    return b * h**3 / 12.0


def axial_stiffness(E: Quantity, A: Quantity, L: Quantity) -> Quantity:
    """Axial stiffness k = E A / L of a bar (force per unit elongation), Section 5.1."""
    return E * A / L


def torsional_stiffness(G: Quantity, I_p: Quantity, L: Quantity) -> Quantity:
    """Torsional stiffness k_t = G I_p / L of a shaft (torque per unit twist angle), Section 5.1."""
    return G * I_p / L


def cantilever_tip_stiffness(E: Quantity, I: Quantity, L: Quantity) -> Quantity:
    """Tip stiffness k = 3 E I / L^3 of a cantilever under a transverse tip force, Section 5.1."""
    return 3.0 * E * I / L**3


def simply_supported_midspan_stiffness(E: Quantity, I: Quantity, L: Quantity) -> Quantity:
    """Midspan stiffness k = 48 E I / L^3 of a simply supported beam, Section 5.1."""
    return 48.0 * E * I / L**3


def clamped_midspan_stiffness(E: Quantity, I: Quantity, L: Quantity) -> Quantity:
    """Midspan stiffness k = 192 E I / L^3 of a beam clamped at both ends, Section 5.1."""
    return 192.0 * E * I / L**3


def column_sway_stiffness(E: Quantity, I: Quantity, h: Quantity) -> Quantity:
    """Sway stiffness k = 12 E I / h^3 of a column clamped at both ends whose top slides
    without rotating (storey stiffness of a shear frame), Section 5.1."""
    return 12.0 * E * I / h**3


def series_stiffness(*k: Quantity) -> Quantity:
    """Stiffness of springs in series, 1/k = sum 1/k_i (same force, elongations add), Section 5.1."""
    return 1.0 / sum(1.0 / ki for ki in k)


def parallel_stiffness(*k: Quantity) -> float:
    """Stiffness of springs in parallel, k = sum k_i (same elongation, forces add), Section 5.1."""
    return float(sum(k))
