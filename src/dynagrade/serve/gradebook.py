"""What the staff page shows and lets download, built from the stored verdicts.

The attempt that counts for a part is the exam's ``counts`` policy: the ``last`` answer
or the ``best`` score (penalties included; the earlier attempt wins a tie). The counted
verdicts of each student become the same records class grading makes
(:class:`~dynagrade.exercise.results.ExerciseResult`), and the gradebook, the report and
the statistics are built from them by class grading's own code
(:func:`dynagrade.classgrade.grade.class_outcome`): each part rounded to the exam's step,
an exercise the sum of its rounded parts. Nothing is graded again.

The submissions download is the responses CSV that ``dynagrade grade --manifest`` reads,
holding every attempt with the one that counts flagged, so an offline regrade gives the
same ``grades.csv`` byte for byte when ``penalty`` is 0 (the offline grader knows nothing of attempts; with a penalty,
each part's points here are the grader's points times the attempt's factor, rounded).
"""

from __future__ import annotations

from ..i18n import N_, _
from typing import Iterable, Sequence

from ..classgrade.grade import class_outcome
from ..classgrade.outcome import ClassOutcome
from ..classgrade.gradebook import exercise_columns, gradebook_csv
from ..classgrade.stats import declared_names
from ..classgrade.submissions import ATTEMPT_COLUMNS, RESPONSE_HEADER
from ..exercise.numbers import percent_text
from ..exam.csvcells import csv_text
from ..exam.manifest import PartEntry
from ..exercise.results import ExerciseResult, GradedPart
from . import db
from .db import StoredAnswer, StoredOverride
from .exam_data import ExamData
from .overrides import as_class_overrides
from .verdicts import SubmittedPart, not_answered


def counted_answers(data: ExamData, stored: list[StoredAnswer]
                    ) -> dict[tuple[str, str, str], StoredAnswer]:
    """The answer that counts for each (student, exercise, part); practice draws never."""
    chosen: dict[tuple[str, str, str], StoredAnswer] = {}
    best = data.policy.counts == "best"
    for answer in stored:  # oldest first
        if not answer.counted:
            continue
        key = (answer.student_id, answer.exercise_id, answer.part)
        if key not in chosen or not best or answer.score > chosen[key].score:
            chosen[key] = answer
    return chosen


def counted_results(data: ExamData, chosen: dict[tuple[str, str, str], StoredAnswer],
                    students: Iterable[str] | None = None
                    ) -> list[dict[str, ExerciseResult | None]]:
    """Each roster student's results (or those of ``students``), in that order, from their
    counted verdicts: an exercise with no counted answer is not handed in (None); a part
    of a handed-in exercise without one is not answered, as class grading records an
    empty part."""
    graded = []
    for student_id in data.students if students is None else students:
        results: dict[str, ExerciseResult | None] = {}
        for exercise_id in data.exercise_ids:
            entries = data.manifest_parts[exercise_id]
            answers = {p.name: chosen.get((student_id, exercise_id, p.name)) for p in entries}
            if not any(answers.values()):
                results[exercise_id] = None
                continue
            parts = tuple(_counted_part(answers[p.name], p) for p in entries)
            source = f"server, {exercise_id}"
            results[exercise_id] = ExerciseResult(exercise_id, None, parts, source)
        graded.append(results)
    return graded


def _counted_part(answer: StoredAnswer | None, part: PartEntry) -> GradedPart:
    """The verdict on ``part`` that counts: its stored answer's, or not answered."""
    if answer is None:
        return not_answered(part)
    return SubmittedPart.stored(answer, part.label).verdict


def outcome(data: ExamData, stored: list[StoredAnswer],
            overrides: Sequence[StoredOverride]) -> ClassOutcome:
    """The class's gradebook, feedback and statistics from the stored verdicts, with the
    points the staff set by hand (:mod:`.overrides`; every export passes the stored
    ones, :func:`dynagrade.serve.db.stored_overrides`)."""
    graded = counted_results(data, counted_answers(data, stored))
    return class_outcome(data.manifest, graded, [], {}, declared_names(data.exercises),
                         as_class_overrides(overrides), _("the staff"))


def grades_csv(data: ExamData, stored: list[StoredAnswer],
               overrides: Sequence[StoredOverride]) -> str:
    """The gradebook as class grading writes it."""
    return gradebook_csv(outcome(data, stored, overrides))


#: the headers of grades.csv's own columns, as the staff page shows them
COLUMN_WORDS = (N_("student_id"), N_("name"), N_("email"), N_("total"), N_("max_total"),
                N_("percent"), N_("status"))
#: a row's status (classgrade's RowStatus) as the staff page shows it
_STATUS_WORDS = (N_("graded"), N_("incomplete"), N_("rejected"), N_("absent"))


def staff_table(data: ExamData, stored: list[StoredAnswer],
                overrides: Sequence[StoredOverride]) -> tuple[list[str], list[dict]]:
    """The gradebook as the staff page shows it: the columns of ``grades.csv`` and one
    row of cell texts per roster student."""
    graded = outcome(data, stored, overrides)
    rounding = graded.rounding
    columns = ["student_id", "name", "email", *exercise_columns(data.exercise_ids), "total",
               "max_total", "percent", "status"]
    rows = []
    for row in graded.rows:
        points = [*(row.cells[e] for e in data.exercise_ids), row.total, row.max_total]
        shown = [None if value is None else rounding.text(value) for value in points]
        percent = None if row.percent is None else percent_text(row.percent)
        rows.append(dict(zip(columns, [row.student_id, row.name, row.email, *shown, percent,
                                       _(str(row.status))])))
    return columns, rows


def responses_csv(data: ExamData, stored: list[StoredAnswer]) -> str:
    """Every attempt (practice draws are not the exam's), in roster, exam, part and
    attempt order, with its time in the course's zone and whether it is the one that
    counts, as ``dynagrade grade`` reads them (it grades the rows that count)."""
    chosen = {id(answer) for answer in counted_answers(data, stored).values()}
    attempts: dict[tuple[str, str, str], list[StoredAnswer]] = {}
    for answer in stored:  # oldest first
        if answer.counted:
            attempts.setdefault((answer.student_id, answer.exercise_id, answer.part),
                                []).append(answer)
    zone = data.policy.zone
    rows: list[Sequence[object]] = [RESPONSE_HEADER + ATTEMPT_COLUMNS]
    for student_id in data.students:
        for exercise_id in data.exercise_ids:
            for part in data.parts(exercise_id):
                for number, answer in enumerate(
                        attempts.get((student_id, exercise_id, part.name), []), 1):
                    at = db.utc(answer.created_at).astimezone(zone)
                    rows.append([student_id, exercise_id, part.name, answer.raw, number,
                                 at.isoformat(timespec="seconds"),
                                 "yes" if id(answer) in chosen else "no"])
    return csv_text(rows)


def progress(data: ExamData, stored: list[StoredAnswer]) -> list[dict]:
    """Per student: submissions per exercise and the time of the latest."""
    seen: dict[str, dict] = {s: {"student_id": s, "name": data.students[s].name,
                                 "attempts": {}, "last": None} for s in data.students}
    for answer in stored:
        if not answer.counted or answer.student_id not in seen:
            continue
        entry = seen[answer.student_id]
        entry["attempts"][answer.exercise_id] = max(
            entry["attempts"].get(answer.exercise_id, 0), answer.attempt)
        entry["last"] = answer.created_at
    return list(seen.values())
