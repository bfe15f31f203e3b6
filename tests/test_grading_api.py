"""The public grading API: names, signatures and the basic verdicts others rely on."""

import dataclasses

import pytest

from dynagrade.grading import AnswerError, Verdict, grade
from dynagrade.grading.dispatch import accepts
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


# -- one tolerance rule for numbers and vector components -----------------------------------
from hypothesis import given, settings  # noqa: E402
from hypothesis import strategies as st  # noqa: E402


def test_a_vector_component_at_the_boundary_is_right_like_a_number():
    # [2.02, 0] for (2, 0) at 1 % was wrong while 2.02 for 2 was right.
    assert grade(NumericSpec(), 2.0, "2.02").correct
    assert grade(VectorSpec(2), (2.0, 0.0), "[2.02, 0]").correct
    assert grade(VectorSpec(2), (2.0, 0.0), "[1.98, 0]").correct
    assert grade(VectorSpec(2), (2.0, 0.0), "[2, 0.0002]").correct  # 1 % of 1 % of the length
    assert not grade(VectorSpec(2), (2.0, 0.0), "[2, 0.00021]").correct


@settings(max_examples=200, deadline=None)
@given(st.floats(min_value=1e-3, max_value=1e6), st.floats(min_value=-0.0102, max_value=0.0102),
       st.sampled_from([1, -1]))
def test_a_vector_component_is_right_exactly_when_the_same_number_would_be(e, offset, sign):
    e *= sign
    answer = repr(e * (1 + offset))
    as_number = grade(NumericSpec(), e, answer).correct
    verdict = grade(VectorSpec(2), (e, e), f"[{answer}, {e!r}]")
    assert ("1: ✓" in verdict.feedback or verdict.correct) is as_number


@settings(max_examples=200, deadline=None)
@given(st.floats(min_value=1e-3, max_value=1e6), st.floats(min_value=-0.06, max_value=0.06),
       st.sampled_from(["", " m/s", " km/h", " m", " 1/s"]), st.booleans())
def test_a_number_is_accepted_exactly_when_its_verdict_is_correct(e, offset, unit, strict):
    """Near the tolerance, in other units and with misconceptions declared: ``accepts``
    says what ``grade`` says, without the feedback."""
    spec = NumericSpec(unit="m/s", require_unit=strict, unit_credit=0.5 if strict else None,
                       misconceptions=(KnownWrong("half", e / 2, "Half."),))
    answer = repr(e * (1 + offset)) + unit
    assert accepts(spec, e, answer) is grade(spec, e, answer).correct


@settings(max_examples=200, deadline=None)
@given(st.floats(min_value=-1e4, max_value=1e4), st.floats(min_value=-0.03, max_value=0.03),
       st.sampled_from(["", " m", " cm", " s"]), st.sampled_from([2, 3]))
def test_a_vector_is_accepted_exactly_when_its_verdict_is_correct(x, offset, unit, size):
    """A component near the tolerance, zero components, other units, a wrong count."""
    e = (x, 0.0, -2.0 * x)[:size]
    spec = VectorSpec(2, unit="m", misconceptions=(KnownWrong("flipped", (-x, 0.0), "Flip."),))
    answer = "[" + ", ".join(repr(c * (1 + offset)) for c in e) + "]" + unit
    assert accepts(spec, e[:2], answer) is grade(spec, e[:2], answer).correct


def test_an_unreadable_or_infinite_number_is_not_accepted():
    for answer in ("2 +* 3", "1e999", "", "((((", "2 kg"):
        assert not accepts(NumericSpec(unit="m"), 2.0, answer)
    assert accepts(NumericSpec(unit="m"), 2.0, "200 cm")


# -- choice labels in every documented form -------------------------------------------------
@pytest.mark.parametrize("answer", ["(a), (c)", "(a) (c)", "(a)(c)", "a), c)", "[a]; [c]", "{a} and {c}",
                                    "a. c.", "(A), c", "(a, c)", "c) a"])
def test_bracketed_labels_in_a_list_are_each_an_option(answer):
    assert grade(ChoiceSpec(("a", "b", "c", "d"), multiple=True), ("a", "c"), answer).correct


def test_an_unknown_label_among_bracketed_ones_is_named():
    verdict = grade(ChoiceSpec(("a", "b", "c", "d"), multiple=True), ("a", "c"), "(a), (e)")
    assert verdict.error and "unknown option" in verdict.error and "'(e)'" in verdict.error


def test_a_choice_answer_is_length_limited_before_any_work():
    verdict = grade(ChoiceSpec(("a", "b"), multiple=True), ("a",), "a, " * 1000)
    assert not verdict.correct and "too long" in verdict.error
