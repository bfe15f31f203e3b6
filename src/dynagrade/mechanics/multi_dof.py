"""Multi-degree-of-freedom vibrations, Section 4.4 of the notes.

The linear system M x'' + C x' + K x = f(t) (Section 4.4.1) with symmetric mass,
damping and stiffness matrices.  Free undamped vibrations (Section 4.4.2) solve the
generalized eigenvalue problem (K - omega^2 M) phi = 0; damped and forced vibrations
(Section 4.4.3) and the modal decomposition (Section 4.4.4) build on its modes.
Mode shapes are returned as the columns of the modal matrix Phi, normalized so that
Phi^T M Phi = I.  Matrices are numpy arrays in SI units.
"""
from __future__ import annotations

import numpy as np

from dynagrade.mechanics._common import ArrayLike, Quantity, as_floats
from dynagrade.mechanics import vibrations


# --- Section 4.4.1: equations of motion -----------------------------------------------

def chain_stiffness_matrix(springs: ArrayLike, right_wall: bool = False) -> np.ndarray:
    """Stiffness matrix of masses in a line joined by springs, Section 4.4.1.

    ``springs[0]`` ties mass 1 to a fixed wall, ``springs[i]`` joins masses i and i+1;
    with ``right_wall`` the last spring ties the last mass to a second wall (then there
    is one spring more than masses).  A zero first spring leaves the left end free.
    Also the storey-stiffness matrix of a shear frame (storey i between floors i-1, i).
    """
    k = np.asarray(springs, dtype=float)
    n = len(k) - 1 if right_wall else len(k)
    K = np.zeros((n, n))
    for i in range(n):
        K[i, i] += k[i]
        if i > 0:
            K[i, i - 1] -= k[i]
            K[i - 1, i] -= k[i]
            K[i - 1, i - 1] += k[i]
    if right_wall:
        K[n - 1, n - 1] += k[n]
    return K


def lumped_mass_matrix(masses: ArrayLike) -> np.ndarray:
    """Diagonal mass matrix of point masses, Section 4.4.1."""
    return np.diag(np.asarray(masses, dtype=float))


# --- Section 4.4.2: free, undamped vibrations -------------------------------------------

def natural_frequencies(K: ArrayLike, M: ArrayLike) -> np.ndarray:
    """Natural angular frequencies omega_i (ascending) from det(K - omega^2 M) = 0, Section 4.4.2.

    Rigid-body modes (zero eigenvalues, up to round-off) give omega = 0.
    """
    from scipy.linalg import eigh
    lam = eigh(as_floats(K), as_floats(M), eigvals_only=True)
    scale = max(1.0, float(np.max(np.abs(lam))))
    lam = np.where(np.abs(lam) < 1e-12 * scale, 0.0, lam)
    if np.any(lam < 0):
        raise ValueError("K is not positive semi-definite: the equilibrium is unstable")
    return np.sqrt(lam)


def mode_shapes(K: ArrayLike, M: ArrayLike) -> np.ndarray:
    """Modal matrix Phi whose columns are the mode shapes, Phi^T M Phi = I, Section 4.4.2.

    Columns are ordered like :func:`natural_frequencies`; the sign of each column is
    fixed so that its first non-zero entry is positive.
    """
    from scipy.linalg import eigh
    _, Phi = eigh(as_floats(K), as_floats(M))
    for j in range(Phi.shape[1]):
        col = Phi[:, j]
        idx = np.flatnonzero(np.abs(col) > 1e-12 * np.max(np.abs(col)))[0]
        if col[idx] < 0:
            Phi[:, j] = -col
    return Phi


def amplitude_ratios(K: ArrayLike, M: ArrayLike) -> np.ndarray:
    """Mode shapes scaled so that the first coordinate is 1 (columns), Section 4.4.2."""
    Phi = mode_shapes(K, M)
    return Phi / Phi[0, :]


def frequency_determinant(K: ArrayLike, M: ArrayLike, omega: Quantity) -> float:
    """Characteristic determinant det(K - omega^2 M), zero at the natural frequencies, Section 4.4.2."""
    return float(np.linalg.det(np.asarray(K) - omega**2 * np.asarray(M)))


def rayleigh_quotient(K: ArrayLike, M: ArrayLike, x: ArrayLike) -> float:
    """Rayleigh quotient R(x) = x^T K x / x^T M x >= omega_1^2 for any trial vector x, Section 4.4.2."""
    x = as_floats(x)
    return float(x @ as_floats(K) @ x / (x @ as_floats(M) @ x))


# --- Section 4.4.3: damped and forced vibrations ----------------------------------------

def steady_state_amplitudes(K: ArrayLike, M: ArrayLike, C: ArrayLike, F: ArrayLike,
                            Omega: float) -> np.ndarray:
    """Complex amplitudes X = (K - Omega^2 M + i Omega C)^{-1} F under f(t) = Re(F e^{i Omega t}), Section 4.4.3.

    |X_j| is the amplitude of coordinate j, -angle(X_j) its phase lag behind the force.
    """
    from scipy.linalg import solve
    D = np.asarray(K) - Omega**2 * np.asarray(M) + 1j * Omega * np.asarray(C)
    return solve(D, np.asarray(F, dtype=complex))


def damped_eigenvalues(K: ArrayLike, M: ArrayLike, C: ArrayLike) -> np.ndarray:
    """Eigenvalues lambda of the damped free vibration x = X e^{lambda t}, Section 4.4.3.

    Roots of det(lambda^2 M + lambda C + K) = 0 from the first-order form, sorted by
    imaginary part; Re(lambda) < 0 is the decay rate, Im(lambda) the damped frequency.
    """
    from scipy.linalg import eig
    K, C = as_floats(K), as_floats(C)
    n = len(K)
    Minv = np.linalg.inv(as_floats(M))
    A = np.block([[np.zeros((n, n)), np.eye(n)], [-Minv @ K, -Minv @ C]])
    lam = eig(A, right=False)
    return lam[np.argsort(lam.imag)]


def tuned_absorber_stiffness(m_a: Quantity, Omega: Quantity) -> Quantity:
    """Absorber stiffness k_a = m_a Omega^2 that keeps the main mass still at Omega, Section 4.4.3."""
    return m_a * Omega**2


def absorber_amplitude(F0: Quantity, k_a: Quantity) -> Quantity:
    """Amplitude X_a = -F0 / k_a of a tuned absorber (main mass at rest) under F0 cos(Omega t), Section 4.4.3.

    The absorber spring then passes exactly the force -F0 cos(Omega t) to the main mass.
    """
    return -F0 / k_a


def absorber_system_matrices(m: float, k: float, m_a: float,
                             k_a: float) -> tuple[np.ndarray, np.ndarray]:
    """(K, M) of a main mass m on a spring k carrying an absorber m_a on a spring k_a, Section 4.4.3."""
    return chain_stiffness_matrix([k, k_a]), lumped_mass_matrix([m, m_a])


# --- Section 4.4.4: modal decomposition ---------------------------------------------------

def modal_matrices(K: ArrayLike, M: ArrayLike, C: ArrayLike | None = None) -> tuple[np.ndarray, ...]:
    """Modal mass, stiffness (and damping) matrices Phi^T M Phi, Phi^T K Phi (, Phi^T C Phi), Section 4.4.4."""
    Phi = mode_shapes(K, M)
    out = [Phi.T @ as_floats(M) @ Phi, Phi.T @ as_floats(K) @ Phi]
    if C is not None:
        out.append(Phi.T @ as_floats(C) @ Phi)
    return tuple(out)


def modal_damping_ratios(K: ArrayLike, M: ArrayLike, C: ArrayLike) -> np.ndarray:
    """Modal damping ratios zeta_i = phi_i^T C phi_i / (2 omega_i) for proportional damping, Section 4.4.4."""
    Phi = mode_shapes(K, M)
    return np.diag(Phi.T @ as_floats(C) @ Phi) / (2.0 * natural_frequencies(K, M))


def modal_coordinates(K: ArrayLike, M: ArrayLike, x: ArrayLike) -> np.ndarray:
    """Modal coordinates eta = Phi^T M x of a displacement (or velocity) vector x, Section 4.4.4."""
    return mode_shapes(K, M).T @ as_floats(M) @ as_floats(x)


def modal_free_response(t: ArrayLike, K: ArrayLike, M: ArrayLike, x0: ArrayLike, v0: ArrayLike,
                        C: ArrayLike | None = None) -> np.ndarray:
    """Displacements x(t) (shape n x len(t)) of the free vibration by modal superposition, Section 4.4.4.

    x(t) = sum_i phi_i eta_i(t) with each modal coordinate a 1-DOF free response
    (Section 4.3.2); C, if given, must be proportional (diagonal in the modes).
    """
    t = np.atleast_1d(np.asarray(t, dtype=float))
    Phi = mode_shapes(K, M)
    w = natural_frequencies(K, M)
    zeta = np.zeros_like(w) if C is None else modal_damping_ratios(K, M, C)
    eta0 = modal_coordinates(K, M, x0)
    deta0 = modal_coordinates(K, M, v0)
    x = np.zeros((len(w), len(t)))
    for i in range(len(w)):
        if w[i] == 0.0:
            eta = eta0[i] + deta0[i] * t
        else:
            eta = vibrations.free_response(t, eta0[i], deta0[i], w[i], zeta[i])
        x += np.outer(Phi[:, i], eta)
    return x


# --- issue 31, chapter 4 exercises: relations the new exercises need ----------------------

def bounce_pitch_matrices(m: float, J: float, k1: float, k2: float, l1: float,
                          l2: float) -> tuple[np.ndarray, np.ndarray]:
    """(K, M) of a rigid body on two springs in bounce and pitch, q = (x, theta), Section 4.4.1.

    x is the upward displacement of the centre of mass, theta the pitch angle
    (counter-clockwise, front up); spring k1 sits the distance l1 ahead of the centre,
    k2 the distance l2 behind it, so they stretch by x + l1 theta and x - l2 theta and
    V = k1 (x + l1 theta)^2 / 2 + k2 (x - l2 theta)^2 / 2, T = m x'^2 / 2 + J theta'^2 / 2.
    The off-diagonal k1 l1 - k2 l2 couples bounce and pitch (static coupling).
    """
    c = k1 * l1 - k2 * l2
    K = np.array([[k1 + k2, c], [c, k1 * l1**2 + k2 * l2**2]], dtype=float)
    return K, lumped_mass_matrix([m, J])


def node_position(x: Quantity, theta: Quantity) -> Quantity:
    """Distance s = -x/theta ahead of the reference point of the point of a rigid body that a
    mode (x, theta) of bounce and pitch leaves at rest, Section 4.4.2.

    The point at the distance s ahead moves x + s theta; negative s lies behind.
    """
    return -x / theta


def rayleigh_damping_matrix(M: ArrayLike, K: ArrayLike, alpha: Quantity, beta: Quantity) -> np.ndarray:
    """Proportional (Rayleigh) damping matrix C = alpha M + beta K, Section 4.4.4.

    It is diagonal in the undamped modes, with the modal damping ratios
    zeta_i = alpha / (2 omega_i) + beta omega_i / 2 (:func:`modal_damping_ratios`).
    """
    return alpha * as_floats(M) + beta * as_floats(K)
