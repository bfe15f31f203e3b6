"""Rotations in 3D: rotation matrices, active and passive use, Euler angles (Section 3.4.1).

A rotation matrix R (orthogonal, det R = 1) maps the axes of a reference frame A onto
those of a rotated frame B: e_i^B = R e_i^A, i.e. the columns of R are the B axes in
A components. Used actively, R turns a vector into a new vector (v' = R v); used
passively, R^T gives the components of the same vector in the rotated frame (v_B = R^T v_A).
"""
from __future__ import annotations

import numpy as np

from dynagrade.mechanics._common import ArrayLike, Quantity


def skew_matrix(w: ArrayLike) -> Quantity:
    """Matrix [w]x of the cross product, [w]x r = w x r (Section 3.1.2)."""
    w1, w2, w3 = np.asarray(w, dtype=float)
    return np.array([[0.0, -w3, w2], [w3, 0.0, -w1], [-w2, w1, 0.0]])


def rotation_matrix(axis: ArrayLike, phi: float) -> np.ndarray:
    """Rotation by the angle phi about the unit axis n (right-hand rule), Rodrigues'
    formula R = cos(phi) I + sin(phi) [n]x + (1 - cos(phi)) n n^T (Section 3.4.1)."""
    n = np.asarray(axis, dtype=float)
    n = n / np.linalg.norm(n)
    c, s = np.cos(phi), np.sin(phi)
    return c * np.eye(3) + s * skew_matrix(n) + (1.0 - c) * np.outer(n, n)


def actively_rotated_vector(rotation: ArrayLike, vector: ArrayLike) -> np.ndarray:
    """Vector obtained by rotating v with R (active rotation), v' = R v, components in the
    same frame (Section 3.4.1)."""
    return np.asarray(rotation, dtype=float) @ np.asarray(vector, dtype=float)


def components_in_rotated_frame(rotation: ArrayLike, vector: ArrayLike) -> Quantity:
    """Components of a fixed vector in the frame whose axes are R e_i (passive rotation),
    v_B = R^T v_A (Section 3.4.1)."""
    return np.asarray(rotation, dtype=float).T @ np.asarray(vector, dtype=float)


def rotation_angle(rotation: ArrayLike) -> float:
    """Angle of a rotation matrix, phi = arccos((tr R - 1) / 2) in [0, pi] (Section 3.4.1)."""
    c = 0.5 * (np.trace(np.asarray(rotation, dtype=float)) - 1.0)
    return float(np.arccos(np.clip(c, -1.0, 1.0)))


def angular_velocity_from_rotation_rate(rotation: ArrayLike, rotation_rate: ArrayLike) -> Quantity:
    """Angular velocity omega (inertial components) of a frame rotating as R(t):
    [omega]x = dR/dt R^T (Sections 3.1.2 and 3.4.1)."""
    w = np.asarray(rotation_rate, dtype=float) @ np.asarray(rotation, dtype=float).T
    w = 0.5 * (w - w.T)
    return np.array([w[2, 1], w[0, 2], w[1, 0]])


def euler_angle_rotation(psi: float, theta: float, phi: float) -> np.ndarray:
    """Rotation matrix of the Euler angles of a top: precession psi about e3, nutation
    theta about the line of nodes, spin phi about the body's symmetry axis,
    R = R3(psi) R1(theta) R3(phi) (Sections 3.4.1 and 3.5.1)."""
    e1, e3 = np.array([1.0, 0.0, 0.0]), np.array([0.0, 0.0, 1.0])
    return rotation_matrix(e3, psi) @ rotation_matrix(e1, theta) @ rotation_matrix(e3, phi)


# --- Issue 31: turns about the body's own axes (bank exercises of Section 3.4.1) ---------


def yaw_pitch_roll_rotation(psi: float, theta: float, phi: float) -> np.ndarray:
    """Rotation matrix of a body turned by yaw psi about e3, then pitch theta about its own
    (already turned) second axis, then roll phi about its own first axis. Turns about the
    body's axes multiply from the right: R = R3(psi) R2(theta) R1(phi), the same as the
    turns about the fixed axes taken in the opposite order (Section 3.4.1)."""
    e1, e2, e3 = np.eye(3)
    return rotation_matrix(e3, psi) @ rotation_matrix(e2, theta) @ rotation_matrix(e1, phi)


def angle_above_horizontal(vector: ArrayLike) -> float:
    """Angle between a vector and the horizontal plane e1-e2, positive when it points
    upward (along e3): arcsin(v3 / |v|) (Section 3.4.1)."""
    v = np.asarray(vector, dtype=float)
    return float(np.arcsin(v[2] / np.linalg.norm(v)))


def angle_between(u: ArrayLike, w: ArrayLike) -> float:
    """Angle in [0, pi] between two vectors, arccos(u.w / (|u| |w|)) (Section 3.4.1)."""
    u, w = np.asarray(u, dtype=float), np.asarray(w, dtype=float)
    return float(np.arccos(np.clip(u @ w / (np.linalg.norm(u) * np.linalg.norm(w)), -1.0, 1.0)))
