"""Statements whose printed names, numbering or conventions a careful student read another
defensible way and was graded wrong: each answer written as the statement prints it is
now accepted, and each convention is stated. Every formula below is the statement's own
result typed by hand, not the key's text."""

import pytest

from dynagrade.exercise import open_bank
from dynagrade.exercise.asked import numbered_questions, question_problems, unshown_variables
from dynagrade.grading import grade

from bank_ids import bank_ids

BANK = open_bank()


def _verdict(exercise_id, part_name, answer, seed=11):
    exercise = BANK.get(exercise_id)
    variant = exercise.variant(seed)
    part = exercise.part(part_name)
    return grade(part.spec(exercise.si(variant.params)), variant.answers[part_name], answer)


@pytest.mark.parametrize("latitude", ["lat", "lambda", "λ"])
def test_coriolis_deflection_accepts_the_latitude_as_the_statement_writes_it(latitude):
    """Section 3.4.3: d = Ω_E g cos λ (2h/g)^{3/2} / 3; the statement asks for it in λ."""
    answer = f"Ω_E g cos({latitude}) (2h/g)^(3/2)/3"
    assert _verdict("coriolis-falling-body", "d_formula", answer).correct


@pytest.mark.parametrize("inertia", ["I", "I_0", "I0", "I₀"])
def test_rotating_chair_accepts_the_chairs_inertia_as_printed(inertia):
    """Example 1.19: ω₁ = ω₀ (I₀ + m r₀²)/(I₀ + m r₁²)."""
    answer = f"ω_0 ({inertia} + m r_0^2)/({inertia} + m r_1^2)"
    assert _verdict("rotating-chair", "omega_formula", answer).correct


@pytest.mark.parametrize("velocity", ["v02", "v_2(0)", "v₂(0)", "v_{2}(0)", "v2(0)", "v_{02}"])
def test_release_under_gravity_accepts_the_initial_velocity_as_printed(velocity):
    """Example 1.1: x₂(t) = h₀ + v₂(0) t − g t²/2."""
    assert _verdict("release-under-gravity", "x2_formula", f"h_0 + {velocity} t - g t^2/2").correct


def test_release_under_gravity_names_the_initial_velocity_one_way():
    """v_2 alone is the velocity at time t (question 2), so it is not v_2(0)."""
    statement = BANK.get("release-under-gravity").statement
    assert "v_{02}" not in statement and "$v_2(0)$ (the initial upward velocity)" in statement
    verdict = _verdict("release-under-gravity", "x2_formula", "h0 + v2 t - g t^2/2")
    assert not verdict.correct and "unknown name 'v2'" in verdict.feedback


@pytest.mark.parametrize("answer", ["2, 3", "b, c", "ground, link", "2 and 3",
                                    "particle sliding on a flat ground, particle on a rigid "
                                    "link about a fixed point"])
def test_degrees_of_freedom_takes_the_cases_by_their_numbers(answer):
    """Example 1.4: the ground and the rigid link are the constraints needing reactions."""
    assert _verdict("degrees-of-freedom", "reaction", answer).correct


def test_degrees_of_freedom_refuses_the_spring_case():
    assert not _verdict("degrees-of-freedom", "reaction", "2, 4").correct


def test_pendulum_with_torsion_spring_asks_for_the_formula_it_grades():
    exercise = BANK.get("pendulum-torsion-spring-lagrange")
    assert numbered_questions(exercise.statement) == [1, 2, 3, 4]
    assert exercise.part("omega_formula").question == 4
    assert "4. Give $\\omega$ of question 2 as a formula" in exercise.statement
    assert _verdict(exercise.id, "omega_formula", "sqrt(g/L + k_t/(m L^2))").correct


def test_inverted_pendulum_states_the_zero_level_and_ignores_the_constant():
    """V(θ) = m g (L/2) cos θ + 2 · k (a sin θ)²/2, zero at the pin; with the zero at the
    upright rod the student's V differs by m g L/2, a constant in θ."""
    exercise = BANK.get("inverted-pendulum-springs")
    assert "zero level of gravity's potential at the pin" in exercise.statement
    at_pin = _verdict(exercise.id, "V", "m g L/2 cos(θ) + k a^2 sin(θ)^2")
    upright = _verdict(exercise.id, "V", "m g L/2 (cos(θ) - 1) + k a^2 sin(θ)^2")
    assert at_pin.correct and at_pin.feedback == "Correct."
    assert upright.correct and "additive constant" in upright.feedback


def test_oblique_wall_impact_says_the_rebound_angle_formula_is_in_radians():
    statement = BANK.get("oblique-wall-impact").statement
    assert "rebound angle, in radians, as a formula" in statement


@pytest.mark.parametrize("exercise_id", bank_ids())
def test_every_part_answers_a_question_and_every_variable_is_shown(exercise_id):
    exercise = BANK.get(exercise_id)
    assert question_problems(exercise) == [] and unshown_variables(exercise) == []
    assert all(part.question is not None for part in exercise.parts)


def test_the_fill_in_line_names_the_question_and_the_printed_symbols():
    part = BANK.get("release-under-gravity").part("x2_formula")
    assert part.describe(1) == ("question 4, height as a formula: a formula in h0 (h₀), "
                                "v02 (v₂(0)), g, t (1 point)")
