"""Statements that fix their conventions: a careful student who reads only the statement
gets the key's answer, and the figure agrees with the text.

Each test recomputes the reference answer by hand from the convention the statement now
states (not through the mechanics core the exercise calls), so a statement that drifts
from its key, or a key that drifts from the statement, fails here.
"""

from __future__ import annotations

import math
import re

import numpy as np
import pytest

from dynagrade.exercise import open_bank
from dynagrade.exercise.scoring import grade_variant

BANK = open_bank()
SEEDS = (0, 7, 11, 23, 42)


def _variants(exercise_id, seeds=SEEDS):
    exercise = BANK.get(exercise_id)
    return exercise, [exercise.variant(seed) for seed in seeds]


def _flat(text: str) -> str:
    """The statement on one line, so that a phrase split over lines still matches."""
    return " ".join(text.split())


# -- crank-slider-velocity ------------------------------------------------------------------


def test_crank_slider_statement_fixes_where_b_and_a_are_and_the_senses():
    exercise, variants = _variants("crank-slider-velocity")
    text = _flat(variants[0].statement)
    assert "B is to the right of O" in text
    assert "A is above that line" in text
    assert "measured counter-clockwise from OB" in text
    assert "the crank turns counter-clockwise" in text
    assert "positive to the right (away from O)" in text


@pytest.mark.parametrize("seed", SEEDS)
def test_crank_slider_key_is_the_derivative_of_the_stated_slider_position(seed):
    # With B right of O and A above it, x_B = r cos θ + sqrt(l² − r² sin² θ); the crank
    # turns counter-clockwise, so dθ/dt = +2π n, and
    # v_B = dx_B/dt = −r ω sin θ − r² ω sin θ cos θ / sqrt(l² − r² sin² θ).
    exercise = BANK.get("crank-slider-velocity")
    variant = exercise.variant(seed)
    p = exercise.si(variant.params)
    omega = 2 * math.pi * p.n
    root = math.sqrt(p.l**2 - (p.r * math.sin(p.theta)) ** 2)
    v_b = -p.r * omega * math.sin(p.theta) - p.r**2 * omega * math.sin(p.theta) * math.cos(
        p.theta) / root
    assert variant.answers["v_B"] == pytest.approx(v_b, rel=1e-9)


def _theta_label_distance_to_its_arc(exercise, variant):
    """How far the figure's θ label is from the nearest point of the arc drawn at O,
    in units of the figure's pin size (2.5 % of r + l)."""
    p = exercise.si(variant.params)
    figure = exercise.figure(p)
    axes = figure.axes[0]
    (label,) = [t for t in axes.texts if t.get_text() == "θ"]
    arcs = []
    for line in axes.lines:
        xy = np.column_stack(line.get_data()).astype(float)
        if len(xy) >= 20 and np.ptp(np.hypot(xy[:, 0], xy[:, 1])) < 1e-9 \
                and np.hypot(*xy[0]) > 0:
            arcs.append(xy)
    (arc,) = arcs
    distance = np.min(np.hypot(*(arc - np.asarray(label.get_position())).T))
    return distance / (0.025 * (p.r + p.l))


@pytest.mark.parametrize("overrides", [
    {"r": 145, "l": 420, "theta": 120, "n": 2800},   # the variant where θ sat by the rod
    {"r": 150, "l": 375, "theta": 15, "n": 1000},    # a narrow angle
    {"r": 150, "l": 375, "theta": 165, "n": 1000},   # the rod running just above O
    {"r": 60, "l": 300, "theta": 60, "n": 1000},
])
def test_crank_slider_theta_label_sits_at_its_arc(overrides):
    exercise = BANK.get("crank-slider-velocity")
    units = {"r": 1e-3, "l": 1e-3}
    values = {k: v * units.get(k, 1) for k, v in overrides.items()}
    variant = exercise.variant(0, values, strict=False)
    assert _theta_label_distance_to_its_arc(exercise, variant) <= 4.0


# -- dumbbell-angular-momentum --------------------------------------------------------------


def test_dumbbell_statement_fixes_the_directions_of_e1_e2_e3():
    exercise, variants = _variants("dumbbell-angular-momentum")
    text = _flat(variants[0].statement)
    assert "$e_2$ vertically up" in text
    assert "$e_1$ points horizontally to the right" in text
    assert r"$e_3 = e_1 \times e_2$ points out of the plane, toward the viewer" in text
    assert r"$r_{OC} = d\,e_2$" in text
    assert exercise.figure is not None


@pytest.mark.parametrize("seed", SEEDS)
def test_dumbbell_key_follows_from_the_stated_axes(seed):
    # H_C = μ L² ω along +e3 (counter-clockwise seen from +e3), μ = m1 m2 / (m1 + m2);
    # r_OC × M v_C = d e2 × M v e1 = −M d v e3 with e2 up and e3 = e1 × e2.
    exercise = BANK.get("dumbbell-angular-momentum")
    variant = exercise.variant(seed)
    p = exercise.si(variant.params)
    mass = p.m1 + p.m2
    h_c = p.m1 * p.m2 / mass * p.L**2 * p.omega
    assert variant.answers["H_C"] == pytest.approx(h_c, rel=1e-9)
    assert variant.answers["H_O"] == pytest.approx(h_c - mass * p.d * p.v, rel=1e-9)


def test_dumbbell_figure_puts_the_balls_as_the_statement_says():
    # the rod points from m1 to m2 at φ counter-clockwise from e1; C divides it so that
    # m1 r1 = m2 r2 (Section 2.2.1)
    exercise = BANK.get("dumbbell-angular-momentum")
    variant = exercise.variant(3)
    p = exercise.si(variant.params)
    axes = exercise.figure(p).axes[0]
    labels = {t.get_text(): np.asarray(t.get_position()) for t in axes.texts}
    direction = labels["m₂"] - labels["m₁"]
    assert math.atan2(direction[1], direction[0]) == pytest.approx(p.phi, abs=0.35)
    assert {"e₁", "e₂", "O", "C", "v", "ω", "φ", "d"} <= set(labels)


# -- cart-pendulum-matrices -----------------------------------------------------------------


@pytest.mark.parametrize("seed", SEEDS)
def test_cart_pendulum_coupling_has_the_sign_of_the_stated_angle(seed):
    # The bob at (x + L sin φ, −L cos φ) moves with (ẋ + L φ̇ cos φ, L φ̇ sin φ), so
    # T = ½ M ẋ² + ½ m (ẋ² + 2 L ẋ φ̇ cos φ + L² φ̇²) and, at φ = 0, M12 = +m L.
    exercise, (variant,) = _variants("cart-pendulum-matrices", (seed,))
    text = _flat(variant.statement)
    assert r"$(x + L\sin\varphi,\; -L\cos\varphi)$" in text
    assert "$\\varphi$ positive counter-clockwise" in text
    assert "(positive to the right)" in text
    p = exercise.si(variant.params)
    assert variant.answers["M12"] == pytest.approx(p.m * p.L, rel=1e-9)
    assert variant.answers["M12"] > 0


def test_cart_pendulum_figure_draws_the_positive_senses_the_statement_states():
    from dynagrade.exercise.figure import figure_notes

    exercise, (variant,) = _variants("cart-pendulum-matrices", (3,))
    drawn = figure_notes(exercise.figure(exercise.si(variant.params)))["drawn"]
    assert "an arrow x pointing to the right" in drawn
    assert ("an angle φ measured from the direction pointing down, turning "
            "counter-clockwise") in drawn


# -- beam-flexural-waves --------------------------------------------------------------------


@pytest.mark.parametrize("seed", SEEDS)
def test_flexural_waves_bend_in_the_plane_of_the_height(seed):
    # shaken along h, the beam bends about the axis along b: I = b h³/12, and
    # E I k⁴ = ρ A ω² gives λ = 2π / k
    exercise, (variant,) = _variants("beam-flexural-waves", (seed,))
    text = _flat(variant.statement)
    assert "in the direction of its height $h$" in text
    assert "bends about the axis along its width" in text
    p = exercise.si(variant.params)
    omega = 2 * math.pi * p.f

    def wavelength(second_moment):
        return 2 * math.pi / (p.rho * p.b * p.h * omega**2 / (p.E * second_moment)) ** 0.25

    upright, sideways = wavelength(p.b * p.h**3 / 12), wavelength(p.h * p.b**3 / 12)
    assert variant.answers["lam"] == pytest.approx(upright, rel=1e-9)
    # the plane matters: bending the other way would be a different, defensible answer
    assert abs(sideways / upright - 1) > 0.05


# -- elastic-slingshot ----------------------------------------------------------------------


def test_slingshot_is_guided_so_the_spring_cannot_lift_it():
    exercise, variants = _variants("elastic-slingshot")
    text = _flat(variants[0].statement)
    assert "slides without friction in the slot, which holds it down" in text
    assert "floor" not in text
    # why a guide is needed, by hand: k = 500 N/m, m = 0.1 kg, l0 = 10 cm, dx = 30 cm:
    # s = sqrt(0.3² + 0.1²) = 0.31623 m, stretch 0.21623 m, vertical pull
    # 500 · 0.21623 · 0.1/0.31623 = 34.19 N, far more than m g = 0.981 N
    variant = exercise.variant(0, {"k": 500, "m": 0.1, "l0": 10, "dx": 30})
    assert variant.answers["stretch"] == pytest.approx(21.623, rel=1e-4)
    assert variant.answers["v"] == pytest.approx(math.sqrt(500 / 0.1) * 0.21623, rel=1e-4)


@pytest.mark.parametrize("seed", SEEDS)
def test_slingshot_key_matches_the_guided_motion_integrated(seed):
    # in the slot only the spring's horizontal pull accelerates the particle:
    # m ẍ = −k (s − l0) x / s, s = sqrt(x² + l0²); integrate from rest at x = dx to x = 0
    from scipy.integrate import solve_ivp

    exercise, (variant,) = _variants("elastic-slingshot", (seed,))
    p = exercise.si(variant.params)

    def motion(_, y):
        x, v = y
        s = math.hypot(x, p.l0)
        return [v, -p.k * (s - p.l0) * x / (s * p.m)]

    def below_the_fixed_point(_, y):
        return y[0]

    below_the_fixed_point.terminal = True
    period = 2 * math.pi * math.sqrt(p.m / p.k)
    run = solve_ivp(motion, (0.0, 50 * period), [p.dx, 0.0], events=below_the_fixed_point,
                    rtol=1e-10, atol=1e-12)
    speed = abs(run.y_events[0][0][1])
    assert exercise.solve(p)["v"] == pytest.approx(speed, rel=1e-6)


# -- frictional-sliding-stop ----------------------------------------------------------------


@pytest.mark.parametrize("seed", SEEDS)
def test_friction_work_is_asked_with_its_sign_and_the_magnitude_is_wrong(seed):
    # the work-energy balance T2 − T1 = W (eq. (1.87)) with T2 = 0: W = −½ m v0²
    exercise, (variant,) = _variants("frictional-sliding-stop", (seed,))
    assert "with its sign" in _flat(variant.statement)
    p = exercise.si(variant.params)
    work = -0.5 * p.m * p.v0**2
    assert variant.answers["W"] == pytest.approx(work, rel=1e-9)
    signed = grade_variant(exercise, variant, {"W": repr(work)})
    magnitude = grade_variant(exercise, variant, {"W": repr(-work)})
    assert [r.correct for r in signed.parts if r.name == "W"] == [True]
    assert [r.correct for r in magnitude.parts if r.name == "W"] == [False]


def test_no_statement_prints_rpm_with_its_name_spelled_out():
    # "n = 180 rpm revolutions per minute" printed the unit twice
    for exercise_id in ("particle-on-a-string",):
        _, variants = _variants(exercise_id)
        assert not re.search(r"rpm\s+revolutions", _flat(variants[0].statement))


# -- the smaller wording --------------------------------------------------------------------


def test_spring_launch_particle_is_held_and_released_not_resting():
    # a spring compressed 6-20x its static compression m g / k cannot hold the particle
    # at rest: the statement has it held and released
    exercise, variants = _variants("spring-launch-height")
    for variant in variants:
        p = exercise.si(variant.params)
        assert p.dx > 3 * p.m * p.g / p.k
        text = _flat(variant.statement)
        assert "held with the spring compressed" in text and "released from rest" in text
        assert "rests" not in text


def test_rotating_particle_in_air_turns_through_a_finite_angle_as_time_grows():
    # φ(∞) − φ(0) = ∫₀^∞ φ̇0 e^(−k t/m) dt = m φ̇0 / k: reached only asymptotically
    exercise, variants = _variants("rotating-particle-in-air")
    for variant in variants:
        assert "never quite stops" in _flat(variant.statement)
        assert "before it stops" not in _flat(variant.statement)
        p = exercise.si(variant.params)
        assert variant.answers["phi_total"] == pytest.approx(p.m * p.omega0 / p.k, rel=1e-9)


def test_two_cart_figure_labels_a_left_arrow_with_a_speed():
    # v2 = −2 m/s: the arrow points left and says |v₂| = 2 m/s, not "v₂ = −2 m/s"
    from dynagrade.exercise.figure import figure_notes

    exercise = BANK.get("two-cart-collision")
    variant = exercise.variant(0, {"v2": -2.0}, strict=False)
    drawing = exercise.figure(exercise.si(variant.params))
    texts = [t.get_text() for t in drawing.axes[0].texts]
    assert "|v₂| = 2 m/s" in texts
    assert not [t for t in texts if re.search(r"[-−]\s*\d", t)]
    # cart 1's arrow and the + sense point right, cart 2's arrow left
    arrows = [d for d in figure_notes(drawing)["drawn"] if d.startswith("an arrow")]
    assert sorted(arrows) == ["an arrow pointing to the left",
                              "an arrow pointing to the right",
                              "an arrow pointing to the right"]


def test_no_two_cart_variant_has_an_answer_that_reads_as_a_cart_name_in_the_figure():
    # the carts are named 1 and 2 in the figure; a key of exactly 1 m/s (seed 54 before
    # the constraint: v_c = 1.0) made verify report the label "1" as a given-away answer
    from dynagrade.exercise.figure_checks import answer_numbers

    exercise = BANK.get("two-cart-collision")
    for seed in range(200):
        assert not answer_numbers(exercise, exercise.variant(seed)) & {"1", "2"}
    variant = exercise.variant(0, {"m1": 1.0, "m2": 1.0, "v1": 3.0, "v2": -1.0, "e": 0.5},
                               strict=False)
    # equal masses: v_c = (3 - 1)/2 = 1 m/s, which the constraint refuses
    assert any("cart's name" in c.description and not c.check(exercise.si(variant.params))
               for c in exercise.constraints)


def test_cantilever_is_not_called_steel_like_when_its_modulus_varies():
    _, variants = _variants("cantilever-spring-mass")
    assert all("steel" not in v.statement for v in variants)


def test_free_rod_asks_for_the_non_zero_frequencies():
    # a free-free rod also has the rigid-body mode at 0 Hz; the next two are
    # f_n = n c / (2 L), c = sqrt(E/ρ)
    exercise, variants = _variants("rod-struck-at-end")
    for variant in variants:
        assert "first two non-zero natural frequencies" in _flat(variant.statement)
        p = exercise.si(variant.params)
        c = math.sqrt(p.E / p.rho)
        assert variant.answers["f"] == pytest.approx([c / (2 * p.L), c / p.L], rel=1e-9)


def test_effective_mass_statement_defines_kappa_and_the_exact_frequency():
    # κ L tan(κ L) = m_s/m, ω_exact = c κ with c = L sqrt(k/m_s): ω_exact = κL sqrt(k/m_s);
    # Rayleigh's estimate sqrt(k/(m + m_s/3))
    from scipy.optimize import brentq

    exercise, variants = _variants("effective-mass-of-a-spring")
    for variant in variants:
        text = _flat(variant.statement)
        assert r"$c = L\sqrt{k/m_s}$" in text and r"$\omega_{\text{exact}} = c\,\kappa$" in text
        p = exercise.si(variant.params)
        kappa_l = brentq(lambda z: z * math.tan(z) - p.m_s / p.m, 1e-9, math.pi / 2 - 1e-9)
        exact = kappa_l * math.sqrt(p.k / p.m_s)
        estimate = math.sqrt(p.k / (p.m + p.m_s / 3))
        assert exercise.solve(p)["error"] == pytest.approx(estimate / exact - 1, rel=1e-6)


def test_logarithmic_decrement_asks_for_the_exact_damping_ratio():
    # δ = 2π ζ / sqrt(1 − ζ²) exactly, so ζ = δ / sqrt(4π² + δ²)
    exercise, variants = _variants("logarithmic-decrement-measurement")
    for variant in variants:
        assert "exactly, from $\\delta$" in _flat(variant.statement)
        p = exercise.si(variant.params)
        delta = math.log(p.x0 / p.xn) / p.n
        assert variant.answers["zeta"] == pytest.approx(
            delta / math.sqrt(4 * math.pi**2 + delta**2), rel=1e-9)


def test_turntable_walker_asks_for_the_magnitude_of_the_floor_force():
    exercise, variants = _variants("turntable-walker")
    for variant in variants:
        assert "magnitude of the horizontal force" in _flat(variant.statement)
        p = exercise.si(variant.params)
        assert variant.answers["F"] == pytest.approx(p.m * math.hypot(*variant.answers["a"]),
                                                     rel=1e-9)
