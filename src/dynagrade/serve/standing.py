"""Where a student stands: the points that count per exercise and in total, the attempts
each part has used, and the moments the page shows.

The points are the gradebook's (:mod:`dynagrade.serve.gradebook`): the answer each part
counts by the exam's ``counts`` policy, rounded to the exam's step, an exercise the sum
of its rounded parts; so the page shows what the staff's gradebook will hold.
"""

from __future__ import annotations

import datetime as dt
from collections import Counter
from dataclasses import dataclass

from ..exercise.results import ExerciseResult
from . import gradebook
from .db import StoredAnswer
from .exam_data import ExamData


def results(data: ExamData, stored: list[StoredAnswer], student_id: str
            ) -> dict[str, ExerciseResult | None]:
    """The student's counted result of each exercise, rounded (None: nothing counted
    yet); ``stored``: the student's answers."""
    chosen = gradebook.counted_answers(data, stored)
    row = list(data.students).index(student_id)
    counted = gradebook.counted_results(data, chosen)[row]
    return {exercise_id: None if result is None else result.rounded(data.rounding)
            for exercise_id, result in counted.items()}


def total(data: ExamData, counted: dict[str, ExerciseResult | None]) -> float:
    """The sum of the exercises' counted points, as the gradebook adds them."""
    return data.rounding.total([r.score for r in counted.values() if r is not None])


def attempts_used(stored: list[StoredAnswer], exercise_id: str) -> Counter:
    """How many counted answers each part of an exercise has (its attempts spent)."""
    return Counter(a.part for a in stored if a.counted and a.exercise_id == exercise_id)


@dataclass(frozen=True)
class Moment:
    """A time as the page shows it: ISO 8601 for the browser to show in the reader's own
    zone, and a text in the exam's zone (naming it) for a page without JavaScript."""

    iso: str
    text: str


def exam_zone(policy) -> dt.tzinfo:
    """The zone the exam's times were written in (that of ``closes`` or ``opens``),
    else UTC."""
    for moment in (policy.closes, policy.opens):
        if moment is not None and moment.tzinfo is not None:
            return moment.tzinfo
    return dt.timezone.utc


def moment(value: dt.datetime, zone: dt.tzinfo, seconds: bool = False) -> Moment:
    """``value`` (SQLite's naive times are UTC) to the minute (or the second), in
    ``zone``."""
    aware = value if value.tzinfo else value.replace(tzinfo=dt.timezone.utc)
    local = aware.astimezone(zone)
    shown = f"{local:%Y-%m-%d %H:%M:%S}" if seconds else f"{local:%Y-%m-%d %H:%M}"
    return Moment(aware.isoformat(timespec="seconds"), f"{shown} {local.tzname() or 'UTC'}")
