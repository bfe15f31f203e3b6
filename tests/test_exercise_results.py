"""The record of graded work: an override wins and the automatic score is kept; an
exercise is rounded one way, each part first and the exercise the exact sum."""

from __future__ import annotations

from hypothesis import given, strategies as st

from dynagrade.exam.points import Rounding
from dynagrade.exercise.results import ExerciseResult, GradedPart, StaffOverride, Status


def _part(name: str, score: float, points: float = 2.0,
          status: Status = Status.PARTIAL) -> GradedPart:
    return GradedPart(name, name, status, score, points, "1", "half right")


def test_an_override_sets_the_score_and_keeps_what_the_grader_gave():
    part = _part("v", 0.4).with_override(StaffOverride(1.5, "method right", "ta@example",
                                                       "2025-04-20T10:00:00+00:00"))
    assert (part.score, part.auto_score, part.fraction) == (1.5, 0.4, 0.75)
    assert part.status is Status.PARTIAL  # what the grader decided stays on record
    assert part.shown_feedback(Rounding(0.1)) == (
        "half right Points set by the staff: 1.5 (graded 0.4): method right")
    assert part.to_json()["score"] == 1.5


def test_an_override_of_zero_points_counts():
    part = _part("v", 2.0, status=Status.CORRECT).with_override(StaffOverride(0.0))
    assert part.score == 0.0 and part.auto_score == 2.0


def test_the_statuses_are_spelled_as_the_files_print_them():
    assert [str(s) for s in Status] == ["correct", "follow-through", "partial", "wrong",
                                        "not answered", "error"]
    assert {s for s in Status if s.answered_wrong} == {
        Status.WRONG, Status.PARTIAL, Status.FOLLOW_THROUGH}


def test_a_part_scaled_to_the_exams_points_keeps_its_fraction():
    scaled = _part("v", 0.5, points=2.0).scaled(3.0)
    assert (scaled.auto_score, scaled.points) == (0.75, 3.0)


def test_rounding_rounds_each_part_then_adds_them_exactly():
    """Two parts at a fifth of their point with half points: each rounds to 0, so the
    exercise earns 0 (rounding the sum, 0.4, would give 0.5)."""
    result = ExerciseResult("e", 1, (_part("a", 0.2, 1.0), _part("b", 0.2, 1.0)))
    assert result.score == 0.4
    assert result.rounded(Rounding(0.5)).score == 0.0


@given(step=st.sampled_from([0.01, 0.1, 0.25, 0.5, 1.0]),
       scores=st.lists(st.floats(0, 5), min_size=1, max_size=6))
def test_rounding_twice_changes_nothing_and_the_score_is_a_whole_number_of_steps(step, scores):
    rule = Rounding(step)
    once = ExerciseResult("e", 1, tuple(_part(f"p{i}", s, 5.0) for i, s in enumerate(scores))
                          ).rounded(rule)
    assert once.rounded(rule) == once and once.rounded(rule).score == once.score
    assert rule.is_multiple(once.score)
    assert rule.steps(once.score) == sum(rule.steps(s) for s in scores)
