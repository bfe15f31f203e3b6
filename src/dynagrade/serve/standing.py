"""Where a student stands: the points that count per exercise and in total, and the
attempts each part has used.

The points are the gradebook's (:mod:`dynagrade.serve.gradebook`): the answer each part
counts by the exam's ``counts`` policy, rounded to the exam's step, the points the staff
set by hand in place of the grader's (:mod:`.overrides`), an exercise the sum of its
parts; so the page shows what the staff's gradebook will hold.
"""

from __future__ import annotations

from collections import Counter
from typing import Sequence

from ..classgrade.overrides import apply_overrides
from ..exercise.results import ExerciseResult
from ..i18n import _
from . import gradebook
from .db import StoredAnswer, StoredOverride
from .overrides import as_class_overrides
from .exam_data import ExamData


def results(data: ExamData, stored: list[StoredAnswer], student_id: str,
            overrides: Sequence[StoredOverride]) -> dict[str, ExerciseResult | None]:
    """The student's counted result of each exercise, rounded, with the points the staff
    set by hand (None: nothing counted yet); ``stored``: the student's answers,
    ``overrides``: theirs (:func:`dynagrade.serve.db.stored_overrides`)."""
    chosen = gradebook.counted_answers(data, stored)
    (counted,) = gradebook.counted_results(data, chosen, [student_id])
    rounded = {exercise_id: None if result is None else result.rounded(data.rounding)
               for exercise_id, result in counted.items()}
    mine = [o for o in overrides if o.student_id == student_id]
    final, _notes = apply_overrides(as_class_overrides(mine), _("the staff"),
                                    {student_id: rounded}, data.rounding)
    return final[student_id]


def total(data: ExamData, counted: dict[str, ExerciseResult | None]) -> float:
    """The sum of the exercises' counted points, as the gradebook adds them."""
    return data.rounding.total([r.score for r in counted.values() if r is not None])


def attempts_used(stored: list[StoredAnswer], exercise_id: str) -> Counter:
    """How many counted answers each part of an exercise has (its attempts spent)."""
    return Counter(a.part for a in stored if a.counted and a.exercise_id == exercise_id)
