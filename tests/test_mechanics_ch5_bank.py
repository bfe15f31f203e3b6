"""The relations chapter 5's new exercises added to the core (issue 31), each against a
route of its own: a chain of masses and springs integrated step by step, a modal sum of
the rod's natural modes, a limit."""

import numpy as np
import pytest

from dynagrade.mechanics import rods


def _colliding_chains(L1, L2, E, rho, A, v, h):
    """Two rods cut into elements of length h (masses rho A h, springs E A / h), the first
    moving at v into the second at rest; the contact spring pushes only. Integrated with
    velocity Verlet until the rods separate: (contact time, striker's and struck rod's
    mean velocities after it)."""
    n1, n2 = round(L1 / h), round(L2 / h)
    m = np.full(n1 + n2 + 2, rho * A * h)
    m[[0, n1, n1 + 1, -1]] /= 2
    k = E * A / h
    x = np.zeros(n1 + n2 + 2)
    u = np.where(np.arange(n1 + n2 + 2) <= n1, v, 0.0)
    dt = 0.2 * h / np.sqrt(E / rho)

    def forces(x):
        stretch = np.diff(x) * k
        stretch[n1] = min(stretch[n1], 0.0)  # the contact only pushes
        f = np.zeros_like(x)
        f[:-1] += stretch
        f[1:] -= stretch
        return f

    a, t, touched = forces(x) / m, 0.0, False
    while True:
        u_half = u + 0.5 * dt * a
        x = x + dt * u_half
        a = forces(x) / m
        u = u_half + 0.5 * dt * a
        t += dt
        closed = x[n1 + 1] - x[n1] < 0
        touched = touched or closed
        if touched and not closed:
            break
    weights = m / A / rho
    return (t, np.sum(weights[:n1 + 1] * u[:n1 + 1]) / L1,
            np.sum(weights[n1 + 1:] * u[n1 + 1:]) / L2)


def test_equal_rods_in_contact_for_two_striker_lengths_over_c_leave_the_striker_at_rest():
    E, rho, A, v, L1, L2 = 200e9, 8000.0, 1e-4, 2.0, 0.2, 0.5
    c = np.sqrt(E / rho)  # 5000 m/s: 2 L1 / c = 80 us
    t_contact, v1, v2 = _colliding_chains(L1, L2, E, rho, A, v, h=L1 / 200)
    assert rods.contact_duration(L1, c) == pytest.approx(t_contact, rel=0.02)
    assert v1 == pytest.approx(0.0, abs=0.02 * v)
    assert v2 == pytest.approx(v * L1 / L2, rel=0.02)  # momentum m1 v = m2 v2


def test_the_contact_face_moves_at_half_the_striking_speed_between_equal_rods():
    E, rho, A, v = 200e9, 8000.0, 1e-4, 2.0
    Z = rods.mechanical_impedance(rho, np.sqrt(E / rho), A)
    assert Z == pytest.approx(8000 * 5000 * 1e-4)  # 4000 N s/m
    assert rods.interface_velocity(Z, Z, v) == pytest.approx(1.0)
    # limits: a rigid wall (Z2 -> infinity) holds the face, a vanishing rod lets it go on at v
    assert rods.interface_velocity(Z, 1e12 * Z, v) == pytest.approx(0.0, abs=1e-9)
    assert rods.interface_velocity(Z, 1e-12 * Z, v) == pytest.approx(v)


def _fixed_free_modal_sum(F, E, rho, A, L, x, t, modes=200_000):
    """u(x, t) of a rod clamped at x = 0 with a step force F at x = L, summed over the
    fixed-free modes sin(k_j x), modal mass rho A L / 2:
    u = sum 2 F sin(k_j L) sin(k_j x) / (rho A L omega_j^2) (1 - cos omega_j t)."""
    c = np.sqrt(E / rho)
    k = (2 * np.arange(1, modes + 1) - 1) * np.pi / (2 * L)
    w = c * k
    q = 2 * F * np.sin(k * L) / (rho * A * L * w**2) * (1 - np.cos(w * t))
    return np.sum(q * np.sin(k * x)), E * np.sum(q * k * np.cos(k * x))


def test_a_suddenly_loaded_rod_end_moves_twice_its_static_elongation_by_the_modal_sum():
    F, E, rho, A, L = 5000.0, 70e9, 2700.0, 2e-4, 1.5
    c = np.sqrt(E / rho)
    u_end, _ = _fixed_free_modal_sum(F, E, rho, A, L, L, 2 * L / c)
    assert rods.step_load_peak_displacement(F, E, A, L) == pytest.approx(u_end, rel=1e-4)
    # twice F L / (E A) = 5000 * 1.5 / (70e9 * 2e-4) = 5.357e-4 m: 1.0714e-3 m
    assert rods.step_load_peak_displacement(F, E, A, L) == pytest.approx(1.0714e-3, rel=1e-4)


def test_the_clamped_end_of_a_suddenly_loaded_rod_carries_twice_the_applied_stress():
    F, E, rho, A, L = 5000.0, 70e9, 2700.0, 2e-4, 1.5
    c = np.sqrt(E / rho)
    _, sigma_root = _fixed_free_modal_sum(F, E, rho, A, L, 0.0, 2 * L / c)
    assert rods.clamped_end_peak_stress(F / A) == pytest.approx(sigma_root, rel=1e-4)
