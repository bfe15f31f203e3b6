"""The public grading API: names, signatures and the basic verdicts others rely on."""

import dataclasses

import pytest

from dynagrade.grading import AnswerError, Verdict, grade
from dynagrade.grading.spec import ChoiceSpec, KnownWrong, NumericSpec, SymbolicSpec, Variable, VectorSpec


def test_answer_error_is_a_value_error_with_a_caret_under_the_position():
    error = AnswerError("unexpected ')'", 7, "2*(a+b))")
    assert isinstance(error, ValueError)
    assert error.message == "unexpected ')'" and error.position == 7 and error.text == "2*(a+b))"
    lines = str(error).splitlines()
    assert lines[0] == "unexpected ')'"
    assert lines[2].index("^") - lines[1].index("2") == 7


def test_answer_error_without_position_is_just_the_message():
    assert str(AnswerError("the answer is empty")) == "the answer is empty"


def test_verdict_is_frozen_with_the_agreed_fields():
    verdict = Verdict(True, 1.0, "Correct.")
    assert verdict.error is None and verdict.misconception is None
    with pytest.raises(dataclasses.FrozenInstanceError):
        verdict.score = 0.5  # type: ignore[misc]
    assert [f.name for f in dataclasses.fields(Verdict)] == ["correct", "score", "feedback", "error", "misconception"]


def test_spec_defaults_match_the_design():
    assert NumericSpec().rtol == 1e-2 and NumericSpec().atol is None and NumericSpec().sigfigs is None
    assert SymbolicSpec({"x": Variable(0, 1)}).rtol == 1e-6
    assert VectorSpec(3).rtol == 1e-2
    assert ChoiceSpec(("a", "b")).multiple is False
    assert KnownWrong("sign", -1.0, "sign!").score == 0.0


def test_numeric_within_one_percent_is_correct_and_outside_is_not():
    spec = NumericSpec(unit="m")
    assert grade(spec, 100.0, "100.9").correct
    assert not grade(spec, 100.0, "101.1").correct


def test_units_are_converted_into_the_part_unit():
    assert grade(NumericSpec(unit="m/s"), 12.5, "45 km/h").correct
    verdict = grade(NumericSpec(unit="m/s"), 12.5, "12.5 m")
    assert not verdict.correct and "length (m)" in verdict.feedback and "velocity (m/s)" in verdict.feedback


def test_angles_are_their_own_dimension():
    assert grade(NumericSpec(unit="rad"), 0.5236, "30 deg").correct
    assert not grade(NumericSpec(unit="rad"), 0.5236, "30 m").correct


def test_symbolic_equivalence_with_positive_domains():
    spec = SymbolicSpec({"k": Variable(1, 100), "m": Variable(0.1, 10)})
    assert grade(spec, "sqrt(k/m)", "sqrt(k)/sqrt(m)").correct
    assert not grade(spec, "sqrt(k/m)", "1.001*sqrt(k/m)").correct


def test_vector_and_choice_dispatch():
    assert grade(VectorSpec(2, unit="m/s"), (1.2, -3.4), "(1.2, -3.4) m/s").correct
    assert grade(ChoiceSpec(("a", "b", "c"), multiple=True), ("a", "c"), "C, a").correct


def test_unreadable_answer_gives_an_error_verdict_not_an_exception():
    verdict = grade(NumericSpec(), 1.0, "2 +* 3")
    assert not verdict.correct and verdict.score == 0 and verdict.error
