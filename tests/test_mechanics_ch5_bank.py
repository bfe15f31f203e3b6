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


def _shaft_with_disk_chain(G, rho, I_p, L, J_disk, N=200):
    """Lowest two angular frequencies of the shaft cut into N twisting springs G I_p N / L
    with the inertia rho I_p L / N lumped at the nodes and the disk at the free end, from
    numpy's symmetric eigen-solver (Sections 4.4.2 and 5.3.2)."""
    h = L / N
    k = G * I_p / h
    J = np.full(N, rho * I_p * h)
    J[-1] = rho * I_p * h / 2 + J_disk
    K = 2 * k * np.eye(N) - k * np.eye(N, k=1) - k * np.eye(N, k=-1)
    K[-1, -1] = k
    scale = 1 / np.sqrt(J)
    return np.sqrt(np.linalg.eigvalsh(scale[:, None] * K * scale[None, :])[:2])


def test_a_shaft_with_a_disk_has_the_lumped_chains_lowest_two_frequencies():
    G, rho, d, L, J_disk = 80e9, 7800.0, 0.04, 1.2, 0.02
    I_p = np.pi * d**4 / 32  # 2.513e-7 m^4; the shaft's own inertia rho I_p L = 2.352e-3 kg m^2
    chain = _shaft_with_disk_chain(G, rho, I_p, L, J_disk)
    exact = rods.tip_mass_natural_frequencies(np.sqrt(G / rho), L, rho * I_p * L, J_disk, 2)
    assert exact == pytest.approx(chain, rel=1e-4)


def test_a_heavy_tip_turns_the_free_end_into_a_clamped_one_and_a_light_tip_leaves_it_free():
    c, L = 3000.0, 1.0
    heavy = rods.tip_mass_natural_frequencies(c, L, 1.0, 1e9, 3)
    light = rods.tip_mass_natural_frequencies(c, L, 1.0, 1e-9, 3)
    # heavy: k_1 L -> sqrt(ratio) = omega of a massless spring c/L sqrt(m_rod/m_tip), then pi, 2 pi
    assert heavy[0] == pytest.approx(c / L * np.sqrt(1e-9), rel=1e-6)
    assert heavy[1:] == pytest.approx([np.pi * c / L, 2 * np.pi * c / L], rel=1e-6)
    # light: the fixed-free rod's (2 j - 1) pi c / (2 L)
    assert light == pytest.approx([np.pi / 2 * c / L, 3 * np.pi / 2 * c / L, 5 * np.pi / 2 * c / L], rel=1e-6)


def test_a_torsional_wave_carries_as_much_power_as_its_torque_puts_in():
    # energy flux: c (kinetic + strain energy per length) = c (rho I_p W^2 / 2 + G I_p (W/c)^2 / 2)
    G, rho, I_p, W = 80e9, 8000.0, 2.5e-7, 30.0
    c = np.sqrt(G / rho)
    T = rods.torsional_impedance(rho, c, I_p) * W  # the torque of the wave
    assert T * W == pytest.approx(c * (rho * I_p * W**2 / 2 + G * I_p * (W / c) ** 2 / 2))
    # shear strain at the surface r theta_x = r W / c: tau = G r W / c
    r = 0.02
    assert rods.torsion_shear_stress(T, r, I_p) == pytest.approx(G * r * W / c)


def test_a_free_end_moves_at_twice_the_waves_velocity_by_the_dalembert_solution():
    # an incoming step f(x - c t) and its mirror image g = -f(2L - ...) in displacement,
    # u = f(x - c t) + f(2 L - x - c t) with f(s) = -v s / c for s < 0: at x = L, u_t = 2 v
    c, L, v, t = 5000.0, 1.0, 0.7, 1.5 / 5000.0
    f = lambda s: np.where(s < 0, -v * s / c, 0.0)  # noqa: E731
    u = lambda time: rods.dalembert_displacement(L, time, c, f, lambda s: f(2 * L - s))  # noqa: E731
    dt = 1e-9
    assert (u(t + dt) - u(t - dt)) / (2 * dt) == pytest.approx(rods.free_end_velocity(v), rel=1e-6)


def test_a_free_free_mode_shape_has_no_moment_and_no_shear_at_either_end():
    from dynagrade.mechanics import beams

    L, h = 0.3, 1e-4
    for j in (1, 2):
        W = lambda x: beams.free_free_mode_shape(x, L, j)  # noqa: E731
        for end in (2 * h, L - 2 * h):  # second and third central differences near each end
            w2 = (W(end + h) - 2 * W(end) + W(end - h)) / h**2
            w3 = (W(end + 2 * h) - 2 * W(end + h) + 2 * W(end - h) - W(end - 2 * h)) / (2 * h**3)
            bL = beams.beam_eigenvalues("free-free", j)[-1]
            assert abs(w2) < 2e-2 * (bL / L) ** 2 and abs(w3) < 2e-2 * (bL / L) ** 3


def test_the_first_free_free_mode_rests_at_0_2242_of_the_length_from_each_end():
    from dynagrade.mechanics import beams

    # the classical nodes of a xylophone bar's fundamental: 0.224 L and 0.776 L
    nodes = beams.free_free_nodes(2.0, 1)
    assert nodes == pytest.approx([2 * 0.22416, 2 * (1 - 0.22416)], abs=2e-5)
    assert len(beams.free_free_nodes(2.0, 2)) == 3
    assert beams.free_free_nodes(2.0, 2)[1] == pytest.approx(1.0, abs=1e-9)  # mode 2: middle


def test_the_length_for_a_frequency_gives_that_frequency_back():
    from dynagrade.mechanics import beams

    EI, rhoA, omega = 12.0, 0.8, 2 * np.pi * 440
    for support in ("free-free", "cantilever"):
        L = beams.beam_length_for_frequency(omega, EI, rhoA, support)
        assert beams.beam_natural_frequencies(EI, rhoA, L, support, 1)[0] == pytest.approx(omega, rel=1e-12)
