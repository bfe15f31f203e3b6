"""Chapter 5's new exercises (issue 31): each key at fixed parameters against a hand
calculation, written out in the comments, and every exercise's draws able to tell its
parts apart (no two answers of different meaning within 10 % of each other, every option
of a choice part the answer of a fair share of students)."""

import itertools
import math

import pytest

from dynagrade.exercise import open_bank

BANK = open_bank()
NEW = ("motor-on-simply-supported-beam", "heavy-beam-midspan-mass",
       "colliding-rods", "suddenly-loaded-rod",
       "shaft-with-end-disk", "shaft-suddenly-driven",
       "tuned-free-free-bar")


def _answers(exercise_id, **values):
    """The exercise's answers, in its parts' units, at the given declared values."""
    return BANK.get(exercise_id).variant_set(0, values).answers


@pytest.mark.parametrize("exercise_id", NEW)
def test_no_two_numeric_answers_of_a_variant_lie_within_ten_percent_of_each_other(exercise_id):
    exercise = BANK.get(exercise_id)
    for seed in range(30):
        variant = exercise.variant(seed)
        solved = exercise.solve(exercise.si(variant.params))
        numbers = {}
        for part in exercise.parts:
            shown = variant.answers[part.name]
            if isinstance(shown, str):
                continue
            si = solved[part.name]
            pairs = zip(shown, si) if isinstance(shown, (tuple, list)) else [(shown, si)]
            for i, (a, b) in enumerate(pairs):
                numbers[(part.name, i)] = (abs(float(a)), abs(float(b)))
        for (p1, (a1, s1)), (p2, (a2, s2)) in itertools.combinations(numbers.items(), 2):
            assert abs(math.log(a1 / a2)) > math.log(1.1), (seed, p1, p2, a1, a2)
            assert abs(math.log(s1 / s2)) > math.log(1.1), (seed, p1, p2, s1, s2)


@pytest.mark.parametrize("exercise_id", ("motor-on-simply-supported-beam",))
def test_every_option_of_a_choice_part_is_the_answer_for_a_fifth_of_the_seeds_or_more(exercise_id):
    exercise = BANK.get(exercise_id)
    choices = [part for part in exercise.parts if hasattr(part, "options")]
    assert choices
    answers = [exercise.variant(seed).answers for seed in range(100)]
    for part in choices:
        for option in part.options:
            assert sum(a[part.name] == option for a in answers) >= 20, (part.name, option)


def test_motor_on_beam_sags_and_vibrates_as_a_mass_on_48_E_I_over_L_cubed():
    # I = 0.05 * 0.02^3 / 12 = 3.3333e-8 m^4; k = 48 * 200e9 * 3.3333e-8 / 2^3 = 40000 N/m
    # delta = 10 * 9.81 / 40000 = 2.4525e-3 m = 2.4525 mm
    # f = sqrt(40000 / 10) / (2 pi) = 63.2456 / 6.28319 = 10.0658 Hz
    # 300 rpm = 31.416 rad/s < 63.246 rad/s: below; 1200 rpm = 125.66 rad/s: above
    below = _answers("motor-on-simply-supported-beam", E=200, b=50, h=20, L=2.0, m=10, n=300)
    assert below["delta"] == pytest.approx(2.4525, rel=1e-4)
    assert below["f"] == pytest.approx(10.0658, rel=1e-4)
    assert below["regime"] == "below resonance"
    above = _answers("motor-on-simply-supported-beam", E=200, b=50, h=20, L=2.0, m=10, n=1200)
    assert above["regime"] == "above resonance"


def test_heavy_beam_adds_seventeen_thirty_fifths_of_its_mass_at_midspan():
    # m_b = 7800 * 0.1 * 0.02 * 2 = 31.2 kg; m_eff = 17/35 * 31.2 = 15.1543 kg
    # k = 48 * 200e9 * (0.1 * 0.02^3 / 12) / 2^3 = 80000 N/m
    # f = sqrt(80000 / (30 + 15.1543)) / (2 pi) = 42.0916 / 6.28319 = 6.6991 Hz
    # (the massless beam would give sqrt(80000 / 30) / (2 pi) = 8.2187 Hz)
    answers = _answers("heavy-beam-midspan-mass", E=200, rho=7800, b=100, h=20, L=2.0, m=30)
    assert answers["m_eff"] == pytest.approx(15.1543, rel=1e-4)
    assert answers["f"] == pytest.approx(6.6991, rel=1e-4)


def test_colliding_rods_meet_at_half_speed_for_two_striker_transit_times():
    # c = sqrt(200e9 / 8000) = 5000 m/s; the face moves at v/2 = 1.5 m/s
    # sigma = 8000 * 5000 * 1.5 = 60e6 Pa = 60 MPa; t_c = 2 * 0.2 / 5000 = 80e-6 s = 0.08 ms
    # v2 = 3 * 0.2 / 0.5 = 1.2 m/s (rod 1's momentum over rod 2's mass)
    answers = _answers("colliding-rods", E=200, rho=8000, L1=0.2, L2=0.5, v=3.0)
    assert answers["sigma"] == pytest.approx(60.0, rel=1e-9)
    assert answers["t_c"] == pytest.approx(0.08, rel=1e-9)
    assert answers["v2"] == pytest.approx(1.2, rel=1e-9)


def test_a_suddenly_pulled_rod_doubles_stress_at_the_clamp_and_overshoots_twice_static():
    # A = pi 0.02^2 / 4 = 3.14159e-4 m^2; F/A = 20000 / 3.14159e-4 = 63.662 MPa; c = 5000 m/s
    # v = 63.662e6 / (8000 * 5000) = 1.59155 m/s; sigma_max = 2 F/A = 127.324 MPa
    # t = L / c = 2 / 5000 = 0.4 ms; u_max = 2 * 20000 * 2 / (200e9 * 3.14159e-4) = 1.27324 mm
    answers = _answers("suddenly-loaded-rod", E=200, rho=8000, d=20, L=2.0, F=20)
    assert answers["v_end"] == pytest.approx(1.59155, rel=1e-5)
    assert answers["sigma_max"] == pytest.approx(127.324, rel=1e-5)
    assert answers["t_max"] == pytest.approx(0.4, rel=1e-9)
    assert answers["u_max"] == pytest.approx(1.27324, rel=1e-5)


def test_a_disk_on_a_heavy_shaft_vibrates_at_the_roots_of_kl_tan_kl_equal_to_the_inertia_ratio():
    # I_p = pi 0.04^4 / 32 = 2.51327e-7 m^4; J_s = 8000 * 2.51327e-7 * 1.0 = 2.01062e-3 kg m^2
    # J_d = 0.5 * 0.5 * 0.08^2 = 1.6e-3 kg m^2; x tan x = 1.256637; c_T = sqrt(80e9 / 8000) = 3162.28 m/s
    # bisection: x1 = 0.932431 (0.932431 tan 0.932431 = 1.25664), x2 = 3.487442
    # f1 = 3162.28 * 0.932431 / (2 pi) = 469.285 Hz; f2 = 3162.28 * 3.487442 / (2 pi) = 1755.20 Hz
    answers = _answers("shaft-with-end-disk", G=80, rho=8000, d=40, L=1.0, m=0.5, R=80)
    assert answers["J_s"] == pytest.approx(2.01062e-3, rel=1e-5)
    assert answers["f1"] == pytest.approx(469.285, rel=1e-5)
    assert answers["f2"] == pytest.approx(1755.20, rel=1e-5)


def test_a_suddenly_driven_shaft_needs_rho_c_ip_omega_and_its_free_end_turns_at_twice_omega_for_l_over_c():
    # c_T = sqrt(80e9 / 8000) = 3162.28 m/s; I_p = pi 0.04^4 / 32 = 2.51327e-7 m^4
    # Omega = 300 rpm = 31.4159 rad/s; T = 8000 * 3162.28 * 2.51327e-7 * 31.4159 = 199.746 N m
    # tau = rho c Omega d/2 = 8000 * 3162.28 * 31.4159 * 0.02 = 15.8953 MPa
    # t = 10 / 3162.28 = 3.16228 ms; the free end turns at 2 * 31.4159 = 62.8319 rad/s until
    # the reflection is back at the motor, another 3.16228 ms: 62.8319 * 3.16228e-3 = 0.198692 rad
    answers = _answers("shaft-suddenly-driven", G=80, rho=8000, d=40, L=10.0, Omega=300)
    assert answers["T"] == pytest.approx(199.746, rel=1e-5)
    assert answers["tau"] == pytest.approx(15.8953, rel=1e-5)
    assert answers["t_end"] == pytest.approx(3.16228, rel=1e-5)
    assert answers["phi_end"] == pytest.approx(0.198692, rel=1e-5)


def test_a_glockenspiel_bar_for_1000_hz_is_227_mm_long_with_nodes_at_0_224_of_it():
    # E h^2 / (12 rho) = 200e9 * 0.01^2 / 96000 = 208.333 m^4/s^2, its fourth root 3.79918
    # L = 4.730041 * 3.79918 / sqrt(2 pi 1000) = 4.730041 * 3.79918 / 79.2665 = 226.707 mm
    # node of the first free-free mode at 0.22416 L = 50.819 mm
    # f2 = 1000 * (7.853205 / 4.730041)^2 = 2756.54 Hz
    answers = _answers("tuned-free-free-bar", E=200, rho=8000, h=10, f1=1000)
    assert answers["L"] == pytest.approx(226.707, rel=1e-5)
    assert answers["x_n"] == pytest.approx(50.819, rel=1e-4)
    assert answers["f2"] == pytest.approx(2756.54, rel=1e-5)


# --- plausible draws: materials that exist, beams that stay elastic, disks that are disks ---

#: sqrt(E/rho) of real structural metals and materials: aluminium 5.1, steel 5.1, brass 3.5,
#: copper 3.7, titanium 4.9, oak 4.2, concrete 3.5 km/s
_BAR_SPEED = (3.0e3, 5.5e3)
#: sqrt(G/rho): aluminium 3.1, steel 3.2, copper 2.3, brass 2.1, titanium 3.1 km/s
_SHEAR_SPEED = (2.0e3, 3.4e3)


def _drawn(exercise_id, seeds=40):
    """The parameters (SI) of the first ``seeds`` variants."""
    exercise = BANK.get(exercise_id)
    return [exercise.si(exercise.variant(seed).params) for seed in range(seeds)]


@pytest.mark.parametrize("exercise_id", ("colliding-rods", "suddenly-loaded-rod",
                                         "tuned-free-free-bar", "heavy-beam-midspan-mass"))
def test_every_drawn_rod_or_beam_is_of_a_material_that_exists(exercise_id):
    # E = 210 GPa with rho = 2700 kg/m^3 (c = 8.8 km/s) was drawn before; no metal has it
    for p in _drawn(exercise_id):
        assert _BAR_SPEED[0] <= math.sqrt(p.E / p.rho) <= _BAR_SPEED[1], (p.E, p.rho)


@pytest.mark.parametrize("exercise_id", ("shaft-suddenly-driven", "shaft-with-end-disk"))
def test_every_drawn_shaft_is_of_a_metal_that_exists(exercise_id):
    for p in _drawn(exercise_id):
        assert _SHEAR_SPEED[0] <= math.sqrt(p.G / p.rho) <= _SHEAR_SPEED[1], (p.G, p.rho)


def test_every_drawn_heavy_beam_stays_far_below_yield_under_its_static_load():
    # midspan moment m g L/4 + m_b g L/8 over b h^2/6; draws reached 166 MPa (0.37 % strain)
    for p in _drawn("heavy-beam-midspan-mass"):
        m_b = p.rho * p.b * p.h * p.L
        stress = (p.m * 9.81 * p.L / 4 + m_b * 9.81 * p.L / 8) / (p.b * p.h**2 / 6)
        assert stress / p.E <= 5e-4, (stress, p.E)


def test_every_drawn_end_disk_is_wider_than_the_shaft_and_thinner_than_its_radius():
    # R = 30 mm on a 80 mm shaft, or a 5 kg "disk" 0.2 m thick, were drawn before
    for p in _drawn("shaft-with-end-disk"):
        thickness = p.m / (p.rho * math.pi * p.R**2)
        assert p.R >= p.d and p.R / 50 <= thickness <= p.R, (p.R, p.d, thickness)
