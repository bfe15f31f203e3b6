"""Formulas right up to an additive constant: a potential energy whose zero level is a
convention (``up_to_constant``), worked by hand on the inverted pendulum on springs.

V(θ) = m g (L/2) cos θ + k a² sin²θ takes its zero at the pin's height. A student who puts
the zero at the upright rod writes V₀(θ) = m g (L/2)(cos θ − 1) + k a² sin²θ. By hand, with
m = 2 kg, g = 10 m/s², L = 1 m, k = 100 N/m, a = 0.5 m:

    θ = 0.5: V = 10 cos 0.5 + 25 sin²0.5 = 8.77583 + 5.74622 = 14.52205 J, V₀ = 4.52205 J
    θ = 1.0: V = 10 cos 1.0 + 25 sin²1.0 = 5.40302 + 17.70183 = 23.10485 J, V₀ = 13.10485 J

so V − V₀ = 10 J = m g L/2 at both angles: a constant in θ (though not in m, g, L).
"""

import pytest

from dynagrade.grading import evaluate_expression, grade
from dynagrade.grading.spec import SymbolicSpec, Variable

V = "m*g*L/2*cos(theta) + k*a^2*sin(theta)^2"
V_ZERO_UPRIGHT = "m g L/2 (cos(theta) - 1) + k a^2 sin(theta)^2"
VARIABLES = {"theta": Variable(-1.5, 1.5, "rad"), "m": Variable(0.5, 10, "kg"),
             "g": Variable(9, 10, "m/s^2"), "L": Variable(0.5, 2, "m"),
             "k": Variable(50, 2000, "N/m"), "a": Variable(0.1, 2, "m")}
HAND = {"m": 2.0, "g": 10.0, "L": 1.0, "k": 100.0, "a": 0.5}


@pytest.mark.parametrize("theta, v, v_zero", [(0.5, 14.52205, 4.52205), (1.0, 23.10485, 13.10485)])
def test_the_hand_worked_potentials_differ_by_m_g_L_over_2(theta, v, v_zero):
    values = {**HAND, "theta": theta}
    assert evaluate_expression(V, values) == pytest.approx(v, abs=1e-5)
    assert evaluate_expression(V_ZERO_UPRIGHT, values) == pytest.approx(v_zero, abs=1e-5)


def test_a_potential_with_another_zero_level_is_correct_and_told_the_constant_was_ignored():
    verdict = grade(SymbolicSpec(VARIABLES, up_to_constant=("theta",)), V, V_ZERO_UPRIGHT)
    assert verdict.correct and verdict.score == 1.0
    assert "additive constant (one independent of theta)" in verdict.feedback
    assert "ignores" in verdict.feedback


def test_the_same_zero_level_is_plainly_correct():
    verdict = grade(SymbolicSpec(VARIABLES, up_to_constant=("theta",)), V, V)
    assert verdict.feedback == "Correct."


def test_without_the_rule_another_zero_level_is_wrong():
    assert not grade(SymbolicSpec(VARIABLES), V, V_ZERO_UPRIGHT).correct


def test_a_constant_in_theta_must_not_depend_on_theta():
    """Adding k a² θ² changes V differently at every angle: no constant."""
    spec = SymbolicSpec(VARIABLES, up_to_constant=("theta",))
    assert not grade(spec, V, V + " + k*a^2*theta^2").correct


def test_a_constant_in_every_variable_may_not_depend_on_any():
    """m g L/2 is constant in θ but not in m, g and L."""
    spec = SymbolicSpec(VARIABLES, up_to_constant=True)
    assert not grade(spec, V, V_ZERO_UPRIGHT).correct


def test_a_position_from_another_origin_is_correct_when_every_variable_may_shift_it():
    spec = SymbolicSpec({"t": Variable(0, 3), "v": Variable(1, 5)}, up_to_constant=True)
    assert grade(spec, "v*t", "v*t + 2").correct
    assert not grade(spec, "v*t", "v*t + t").correct


def test_a_constant_of_the_wrong_unit_is_still_a_wrong_unit():
    spec = SymbolicSpec({"t": Variable(0, 3, "s"), "v": Variable(1, 5, "m/s")}, up_to_constant=True)
    assert grade(spec, "v*t", "v*t + 2").misconception == "dimensions"


def test_a_misconception_plus_a_constant_still_earns_its_feedback():
    from dynagrade.grading.spec import KnownWrong

    one_spring = KnownWrong("one spring only", "m*g*L/2*cos(theta) + k*a^2*sin(theta)^2/2",
                            "Both springs act.")
    spec = SymbolicSpec(VARIABLES, up_to_constant=("theta",), misconceptions=(one_spring,))
    verdict = grade(spec, V, "m g L/2 (cos(theta) - 1) + k a^2 sin(theta)^2/2")
    assert verdict.misconception == "one spring only" and not verdict.correct


def test_the_rule_names_only_declared_variables():
    with pytest.raises(ValueError, match=r"\['phi'\], which are no variables"):
        SymbolicSpec(VARIABLES, up_to_constant=("phi",))
