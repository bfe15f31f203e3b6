"""The chapter-4 exercises added for issue 31, each at fixed parameters against values
worked out by hand (the arithmetic is in the comments), and the core relations they
added, each against a second route."""
import numpy as np
import pytest

from dynagrade.mechanics import multi_dof, vibrations


def answers(bank, exercise_id, **values):
    """The keys in the parts' units at the given parameters (declared units)."""
    exercise = bank.get(exercise_id)
    given = {p.name: values.get(p.name, p.draw(np.random.default_rng(0))) for p in exercise.params}
    assert not exercise.broken_constraints(given), exercise.broken_constraints(given)
    return exercise.solve_in_part_units(given)


# --- core relations ---------------------------------------------------------------------

def test_equivalent_weight_of_a_hinged_bar_is_its_moment_about_the_hinge_over_the_tip_arm():
    # bar 3 kg of length 1 m (centre at 0.5 m) and 2 kg at the tip: moment about the
    # hinge (2*1 + 3*0.5)*9.81 = 34.335 N m over the tip arm 1 m = 34.335 N
    assert vibrations.equivalent_weight([2.0, 3.0], [1.0, 0.5], 9.81) == pytest.approx(34.335)


def test_bounce_pitch_matrices_are_the_hessians_of_the_energies_derived_by_sympy():
    import sympy as sp

    from dynagrade.mechanics import equilibrium, lagrange

    t = sp.Symbol("t")
    x, th = sp.Function("x")(t), sp.Function("theta")(t)
    m, J, k1, k2, l1, l2 = 1200.0, 2000.0, 3.0e4, 2.5e4, 1.2, 1.6
    # the spring ends move with the body's points l1 ahead and l2 behind the centre
    V = k1 * (x + l1 * sp.sin(th)) ** 2 / 2 + k2 * (x - l2 * sp.sin(th)) ** 2 / 2
    T = m * x.diff(t) ** 2 / 2 + J * th.diff(t) ** 2 / 2
    rest = {x: 0, th: 0}
    K_sympy = np.array(equilibrium.stiffness_matrix(V, [x, th], rest), dtype=float)
    M_sympy = np.array(lagrange.mass_matrix(T, [x, th], t).subs(rest), dtype=float)
    K, M = multi_dof.bounce_pitch_matrices(m, J, k1, k2, l1, l2)
    assert K == pytest.approx(K_sympy) and M == pytest.approx(M_sympy)


def test_the_node_a_mode_leaves_at_rest_does_not_move():
    # x = 0.02, theta = 0.01: the point s = -2 m ahead moves 0.02 + (-2)(0.01) = 0
    s = multi_dof.node_position(0.02, 0.01)
    assert s == pytest.approx(-2.0) and 0.02 + s * 0.01 == pytest.approx(0.0)


def test_rayleigh_damping_is_diagonal_in_the_modes_with_alpha_plus_beta_omega_squared():
    K = multi_dof.chain_stiffness_matrix([8e6, 4e6])
    M = multi_dof.lumped_mass_matrix([4000.0, 2000.0])
    C = multi_dof.rayleigh_damping_matrix(M, K, 1.0, 1e-3)
    # C = diag(4000, 2000) + 1e-3 K: C11 = 4000 + 12000, C12 = -4000, C22 = 2000 + 4000
    assert C == pytest.approx(np.array([[16000.0, -4000.0], [-4000.0, 6000.0]]))
    # numpy's eigenvectors of M^-1 K, scaled to phi^T M phi = 1: phi^T C phi = 1 + 1e-3 w^2
    w2, vectors = np.linalg.eig(np.linalg.solve(M, K))
    for w2_i, v in zip(w2, vectors.T):
        v = v / np.sqrt(v @ M @ v)
        assert v @ C @ v == pytest.approx(1.0 + 1e-3 * w2_i)


def test_envelope_decay_time_is_that_many_damped_periods_by_the_logarithmic_decrement():
    # omega_n = 10, zeta = 0.05, to a tenth: t = ln 10 / 0.5 = 4.60517 s
    t = vibrations.envelope_decay_time(10.0, 0.05, 0.1)
    assert t == pytest.approx(4.605170, rel=1e-6)
    # the same as n = ln 10 / delta damped periods T_d = 2 pi / omega_d
    delta = vibrations.logarithmic_decrement(0.05)
    periods = np.log(10) / delta
    assert t == pytest.approx(periods * 2 * np.pi / vibrations.damped_frequency(10.0, 0.05))


def test_u_tube_stiffness_is_the_curvature_of_the_liquids_potential_energy():
    rho, A, g = 1000.0, 1e-4, 9.81

    def V(x):
        # the two legs' columns of heights h + x and h - x, centres at half height
        h = 0.5
        return rho * g * A * ((h + x) ** 2 / 2 + (h - x) ** 2 / 2)

    d = 1e-3
    curvature = (V(d) - 2 * V(0.0) + V(-d)) / d**2
    assert vibrations.u_tube_stiffness(rho, A, g) == pytest.approx(curvature, rel=1e-6)
    # 2 * 1000 * 9.81 * 1e-4 = 1.962 N/m; the column of 2 m weighs 1000 * 1e-4 * 2 = 0.2 kg
    assert vibrations.u_tube_stiffness(rho, A, g) == pytest.approx(1.962)
    assert vibrations.liquid_column_mass(rho, A, 2.0) == pytest.approx(0.2)


# --- the exercises at fixed parameters ----------------------------------------------------

def test_trough_rolling_cylinder_at_R_1_r_quarter(bank):
    a = answers(bank, "trough-rolling-cylinder-lagrange", m=2.0, R=1.0, r=0.25, theta0=30.0)
    # R - r = 0.75 m: theta'' = -2 g sin 30 / (3 * 0.75) = -9.81 / 2.25 = -4.360 rad/s^2
    assert a["alpha0"] == pytest.approx(-4.36, rel=1e-4)
    # omega^2 = 2 * 9.81 / 2.25 = 8.72, omega = 2.9530 rad/s, T = 2 pi / omega = 2.1278 s
    assert a["omega"] == pytest.approx(2.95296, rel=1e-5)
    assert a["T_period"] == pytest.approx(2.12776, rel=1e-5)


@pytest.mark.parametrize("R, K, stability", [(0.3, 1.962, "stable"), (0.1, -1.962, "unstable")])
def test_block_on_cylinder_is_stable_exactly_when_R_exceeds_half_its_height(bank, R, K, stability):
    a = answers(bank, "block-rocking-on-cylinder", m=2.0, R=R, w=0.2, h=0.4)
    # K = m g (R - h/2) = 2 * 9.81 * (+-0.1) = +-1.962 N m
    assert a["K"] == pytest.approx(K, rel=1e-9)
    assert a["stability"] == stability
    # J_P = m (w^2 + 4 h^2) / 12 = 2 * 0.68 / 12 = 0.11333 kg m^2; s = sqrt(1.962 / J_P) = 4.1607 1/s
    assert a["s"] == pytest.approx(4.16073, rel=1e-5)


def test_block_on_cylinder_draws_both_stable_and_unstable_blocks(bank):
    exercise = bank.get("block-rocking-on-cylinder")
    stable = sum(exercise.variant(seed, with_statement=False).answers["stability"] == "stable"
                 for seed in range(100))
    assert 25 <= stable <= 75


def test_hinged_bar_with_tip_mass(bank):
    a = answers(bank, "hinged-bar-tip-mass", m=2.0, m_b=3.0, L=1.0, a=0.5, k=8000.0)
    # m_eq = m + m_b / 3 = 2 + 1 = 3 kg; k_eq = k (a/L)^2 = 8000 * 0.25 = 2000 N/m
    assert a["m_eq"] == pytest.approx(3.0)
    assert a["k_eq"] == pytest.approx(2000.0)
    # f = sqrt(2000 / 3) / (2 pi) = 25.8199 / 6.28319 = 4.10936 Hz
    assert a["f"] == pytest.approx(4.10936, rel=1e-5)
    # delta = (m + m_b/2) g / k_eq = 3.5 * 9.81 / 2000 = 0.0171675 m = 17.1675 mm
    assert a["delta"] == pytest.approx(17.1675, rel=1e-6)


def test_bounce_pitch_matrices_of_a_car(bank):
    a = answers(bank, "bounce-pitch-matrices", m=1200.0, J=2000.0, k1=30000.0, k2=25000.0,
                l1=1.2, l2=1.6, x0=20.0)
    # K12 = k1 l1 - k2 l2 = 36000 - 40000 = -4000 N
    assert a["K12"] == pytest.approx(-4000.0)
    # K22 = k1 l1^2 + k2 l2^2 = 30000 * 1.44 + 25000 * 2.56 = 43200 + 64000 = 107200 N m
    assert a["K22"] == pytest.approx(107200.0)
    # l1* = k2 (l1 + l2) / (k1 + k2) = 25000 * 2.8 / 55000 = 1.27273 m
    assert a["l1_star"] == pytest.approx(1.272727, rel=1e-6)
    # theta'' = -K12 x0 / J = 4000 * 0.02 / 2000 = 0.04 rad/s^2
    assert a["theta_ddot0"] == pytest.approx(0.04)


def test_bounce_pitch_modes_of_a_trailer(bank):
    a = answers(bank, "bounce-pitch-modes", m=1000.0, J=1500.0, k1=40000.0, k2=20000.0,
                l1=1.0, l2=1.5)
    # K11 = 60000, K12 = 40000 - 30000 = 10000, K22 = 40000 + 45000 = 85000;
    # 1.5e6 w^4 - (8.5e7 + 9e7) w^2 + (5.1e9 - 1e8) = 0, i.e. l^2 - 116.667 l + 3333.33 = 0:
    # w^2 = 50 and 66.667, f = sqrt(50)/(2 pi) = 1.12540 Hz and sqrt(66.667)/(2 pi) = 1.29949 Hz
    assert a["f1"] == pytest.approx(1.125395, rel=1e-5)
    assert a["f2"] == pytest.approx(1.299494, rel=1e-5)
    # s = K12 / (K11 - w^2 m): 10000 / (60000 - 50000) = 1 m (at the front spring) and
    # 10000 / (60000 - 66667) = -1.5 m (at the rear spring)
    assert a["s1"] == pytest.approx(1.0, rel=1e-6)
    assert a["s2"] == pytest.approx(-1.5, rel=1e-6)
    # the modes are M-orthogonal, m x1 x2 + J theta1 theta2 = 0: s1 s2 = -J/m = -1.5 m^2,
    # the relation the solution's check line uses
    assert a["s1"] * a["s2"] == pytest.approx(-1500.0 / 1000.0, rel=1e-6)


def test_two_mass_chain_forced_between_its_resonances(bank):
    a = answers(bank, "two-mass-forced-chain", m1=100.0, m2=50.0, k1=1e5, k2=5e4, F0=500.0, f=4.0)
    # resonances: 5000 w^4 - 1.25e7 w^2 + 5e9 = 0, w^2 = 500 and 2000 (22.36 and 44.72 rad/s);
    # Omega^2 = (8 pi)^2 = 631.65: a = 150000 - 63165.5 = 86834.5, d = 50000 - 31582.7 = 18417.3,
    # Delta = a d - k2^2 = 1.59926e9 - 2.5e9 = -9.0075e8
    # X1 = k2 F0 / Delta = 2.5e7 / -9.0075e8 = -0.027755 m; X2 = a F0 / Delta = -0.048201 m
    assert a["X1"] == pytest.approx(-27.755, rel=1e-4)
    assert a["X2"] == pytest.approx(-48.201, rel=1e-4)
    # f_a = sqrt((k1 + k2) / m1) / (2 pi) = sqrt(1500) / 6.28319 = 38.730 / 6.28319 = 6.1640 Hz
    assert a["f_a"] == pytest.approx(6.16404, rel=1e-5)


def test_struck_carts_split_into_rigid_and_vibration_modes(bank):
    a = answers(bank, "struck-carts-modal-decomposition", m1=2.0, m2=3.0, k=1920.0, v0=1.0, t1=0.1)
    # reduced mass 2*3/5 = 1.2 kg: omega = sqrt(1920/1.2) = sqrt(1600) = 40 rad/s
    assert a["omega"] == pytest.approx(40.0)
    # d_max = v0/omega = 1/40 m = 25 mm
    assert a["d_max"] == pytest.approx(25.0)
    # x2 = v_G t - m1/(m1+m2) v0/omega sin(omega t) = 0.4*0.1 - 0.4*0.025*sin(4)
    #    = 0.04 - 0.01*(-0.756802) = 0.0475680 m
    assert a["x2"] == pytest.approx(47.5680, rel=1e-5)


def test_damped_two_mass_system_at_omega_20(bank):
    a = answers(bank, "damped-two-mass-forced", m1=100.0, m2=20.0, k1=1e5, k2=2e4, c=1000.0,
                F0=1000.0, f=20 / (2 * np.pi))
    # Omega^2 = 400: k2 - Omega^2 m2 = 12000, k2^2/12000 = 33333.3, k1 + k2 - Omega^2 m1 = 80000;
    # dynamic stiffness of m1: 46666.7 + 20000 i, modulus sqrt(2.57778e9) = 50771.8 N/m
    # X1 = 1000 / 50771.8 = 0.019696 m; lag = atan(20000/46666.7) = atan(3/7) = 23.199 deg
    assert a["X1"] == pytest.approx(19.696, rel=1e-4)
    assert a["phi1"] == pytest.approx(23.1986, rel=1e-4)
    # X2 = k2/(k2 - Omega^2 m2) X1 = (20000/12000) * 19.696 = 32.827 mm
    assert a["X2"] == pytest.approx(32.827, rel=1e-4)


def test_rayleigh_damped_two_storey_model(bank):
    a = answers(bank, "rayleigh-damping-modes", m1=4000.0, m2=2000.0, k1=8e6, k2=4e6, alpha=1.0,
                beta=1e-3)
    # 8e6 w^4 - 4e10 w^2 + 3.2e13 = 0: w^2 = 1000 and 4000, w1 = 31.6228, w2 = 63.2456 rad/s
    # zeta1 = 1/(2*31.6228) + 1e-3*31.6228/2 = 0.0158114 + 0.0158114 = 0.0316228
    # zeta2 = 1/(2*63.2456) + 1e-3*63.2456/2 = 0.0079057 + 0.0316228 = 0.0395285
    assert a["zeta1"] == pytest.approx(0.0316228, rel=1e-5)
    assert a["zeta2"] == pytest.approx(0.0395285, rel=1e-5)
    # zeta1 w1 = 0.0316228 * 31.6228 = 1.0 1/s: t = ln 10 / 1.0 = 2.302585 s
    assert a["t_decay"] == pytest.approx(2.302585, rel=1e-5)


def test_u_tube_of_water_one_metre_long(bank):
    a = answers(bank, "u-tube-liquid-column", rho=1000.0, d=10.0, L=1.0, h0=100.0)
    # A = pi (0.01)^2 / 4 = 7.85398e-5 m^2: m_eq = 1000 * 7.85398e-5 * 1 = 0.0785398 kg = 78.5398 g
    assert a["m_eq"] == pytest.approx(78.5398, rel=1e-5)
    # k_eq = 2 * 1000 * 9.81 * 7.85398e-5 = 1.540951 N/m
    assert a["k_eq"] == pytest.approx(1.540951, rel=1e-5)
    # omega = sqrt(2 g / L) = sqrt(19.62) = 4.429447 rad/s, T = 2 pi / omega = 1.418512 s
    assert a["T_period"] == pytest.approx(1.418512, rel=1e-5)
    # v_max = omega h0 / 2 = 4.429447 * 0.05 = 0.221472 m/s
    assert a["v_max"] == pytest.approx(0.221472, rel=1e-5)


def test_spring_coupled_pendulums_released_from_four_degrees(bank):
    a = answers(bank, "spring-coupled-pendulums", m1=1.0, m2=2.0, L=1.0, a=0.5, k=40.0, theta0=4.0)
    # K11 = m1 g L + k a^2 = 9.81 + 40 * 0.25 = 19.81 N m; K12 = -k a^2 = -10 N m
    assert a["K11"] == pytest.approx(19.81)
    assert a["K12"] == pytest.approx(-10.0)
    # theta0 = 4 deg = 0.0698132 rad: theta1'' = -19.81 * 0.0698132 / (1 * 1^2) = -1.383000 rad/s^2
    assert a["theta1_ddot"] == pytest.approx(-1.383000, rel=1e-5)
    # theta2'' = k a^2 theta0 / (m2 L^2) = 10 * 0.0698132 / 2 = 0.349066 rad/s^2
    assert a["theta2_ddot"] == pytest.approx(0.349066, rel=1e-5)
