"""Scoring a variant: points per part, partial credit, follow-through, unreadable answers."""

import pytest

from dynagrade.exercise import Constant, Exercise, Misconception, Numeric, Uniform
from dynagrade.exercise.scoring import grade_variant


def _exercise():
    # Part a is 2x metres; part b is a + 1 metres, graded with follow-through on a.
    return Exercise(
        id="two-step", title="Two steps", source="Example 1.1",
        params=(Uniform("x", 1, 9, step=1, unit="m"), Constant("one", 1.0, unit="m")),
        statement="x = {{ x }}",
        solve=lambda p: {"a": 2 * p.x, "b": 2 * p.x + p.one},
        parts=(
            Numeric("a", unit="m", points=2, misconceptions=(
                Misconception("forgot the factor", lambda p: p.x, "Twice x.", score=0.5),)),
            Numeric("b", unit="m", points=3, uses=("a",),
                    follow_through=lambda p, own: own["a"] + p.one),
        ),
    )


def _grade(answers, problems=None):
    exercise = _exercise()
    variant = exercise.variant(0, {"x": 4})  # a = 8 m, b = 9 m
    return grade_variant(exercise, variant, answers, problems)


def test_right_answers_earn_every_point():
    result = _grade({"a": "8", "b": "900 cm"})
    assert (result.score, result.max_score) == (5, 5)
    assert [p.status for p in result.parts] == ["correct", "correct"]


def test_a_declared_misconception_earns_its_partial_credit_and_feedback():
    part = _grade({"a": "4", "b": None}).parts[0]
    assert part.status == "partial" and part.score == 1.0  # half of 2 points
    assert part.misconception == "forgot the factor" and "Twice x." in part.feedback


def test_an_answer_consistent_with_a_wrong_earlier_answer_gets_follow_through():
    # a = 7 is wrong (8); b = 7 + 1 = 8 follows from it and earns b's points.
    result = _grade({"a": "7", "b": "8"})
    a, b = result.parts
    assert a.status == "wrong" and a.score == 0
    assert b.status == "follow-through" and b.score == 3
    assert "a" in b.feedback


def test_follow_through_does_not_rescue_an_answer_inconsistent_with_either():
    assert _grade({"a": "7", "b": "12"}).parts[1].score == 0


def test_follow_through_reads_the_earlier_answer_in_its_unit():
    # a = 700 cm = 7 m (wrong); b = 8 m is consistent with it.
    assert _grade({"a": "700 cm", "b": "8 m"}).parts[1].status == "follow-through"


def test_unanswered_and_unreadable_parts_get_a_verdict_each():
    result = _grade({"a": None}, problems={"b": "line 9: the answer is a function call"})
    assert [p.status for p in result.parts] == ["not answered", "wrong"]
    assert "function call" in result.parts[1].feedback
    assert result.score == 0


@pytest.mark.parametrize("hostile", ["__import__('os')", "9**9**9**9", "(" * 10_000,
                                     "x" * 100_000, "a.b", "\x00"])
def test_hostile_answers_are_wrong_with_a_message(hostile):
    part = _grade({"a": hostile}).parts[0]
    assert part.status == "wrong" and part.feedback


def test_a_part_can_require_the_unit_to_be_written():
    exercise = Exercise(
        id="with-unit", title="Unit", source="Example 1.1",
        params=(Uniform("x", 1, 9, step=1, unit="m"),), statement="x = {{ x }}",
        solve=lambda p: {"d": p.x},
        parts=(Numeric("d", unit="m", require_unit=True),))
    variant = exercise.variant(0, {"x": 4})
    bare, written = (grade_variant(exercise, variant, {"d": text}).parts[0]
                     for text in ("4", "400 cm"))
    assert not bare.correct and "unit" in bare.feedback.lower()
    assert written.correct


def test_a_form_test_gives_partial_credit_to_an_equivalent_answer_of_the_wrong_form():
    from dynagrade.exercise import Symbolic, Variable

    exercise = Exercise(
        id="half", title="Half", source="Example 1.1",
        params=(Uniform("x", 1, 9, step=1),), statement="x = {{ x }}",
        solve=lambda p: {},
        parts=(Symbolic("h", expected="x/2", variables={"x": Variable(1, 9)},
                        form=("no_decimals",), form_credit=0.5),))
    variant = exercise.variant(0)
    exact, decimal = (grade_variant(exercise, variant, {"h": text}).parts[0]
                      for text in ("x/2", "0.5 x"))
    assert exact.correct and exact.score == 1
    assert not decimal.correct and decimal.score == 0.5
