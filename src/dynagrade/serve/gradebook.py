"""What the staff page shows and lets download, from the stored submissions.

The attempt that counts for a part is the exam's ``counts`` policy: the ``last`` answer
or the ``best`` score (penalties included; the earlier attempt wins a tie). The gradebook
has the columns of class grading's ``grades.csv``; the submissions download is the
responses CSV that ``dynagrade grade --manifest`` reads, holding each counted answer, so
an offline regrade gives the same points (when ``penalty`` is 0: the offline grader knows
nothing of attempts).
"""

from __future__ import annotations

import csv
import io
import tempfile
from pathlib import Path

from ..classgrade.grade import ClassOutcome, grade_class, gradebook_csv, gradebook_row
from ..exam.points import Rounding
from ..classgrade.submissions import RESPONSE_HEADER
from .db import StoredAnswer
from .exam_data import ExamData


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


def gradebook_rows(data: ExamData, chosen: dict) -> list[dict]:
    """One row per roster student, as class grading's grades.csv has them."""
    max_total = sum(float(data.exercises_meta[e].points) for e in data.exercise_ids)
    rows = []
    for student_id in data.students:
        results = {}
        for exercise_id in data.exercise_ids:
            scores = [chosen[(student_id, exercise_id, p.name)].score
                      for p in data.parts(exercise_id)
                      if (student_id, exercise_id, p.name) in chosen]
            results[exercise_id] = {"score": round(sum(scores), 6)} if scores else None
        student = data.students[student_id]
        rows.append(gradebook_row(student_id, results, data.exercise_ids, max_total,
                                  name=student.name, email=student.email,
                                  rounding=_rounding(data)))
    return rows


def grades_csv(data: ExamData, stored: list[StoredAnswer]) -> str:
    """The gradebook as class grading writes it."""
    rows = gradebook_rows(data, counted_answers(data, stored))
    return gradebook_csv(ClassOutcome(data.title, data.exercise_ids, rows, [],
                                      rounding=_rounding(data)))


def _rounding(data: ExamData) -> Rounding:
    """The exam's rounding of points, as class grading rounds them."""
    return Rounding(data.manifest.exam.rounding)


def responses_csv(data: ExamData, stored: list[StoredAnswer]) -> str:
    """Every counted answer, in roster and exam order, as ``dynagrade grade`` reads them."""
    chosen = counted_answers(data, stored)
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    writer.writerow(RESPONSE_HEADER)
    for student_id in data.students:
        for exercise_id in data.exercise_ids:
            for part in data.parts(exercise_id):
                answer = chosen.get((student_id, exercise_id, part.name))
                if answer is not None:
                    writer.writerow([student_id, exercise_id, part.name, answer.raw])
    return buffer.getvalue()


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


def class_report_html(data: ExamData, stored: list[StoredAnswer], folders=()) -> str:
    """Class grading's report (histogram, item statistics, wrong answers by what explains
    them) of the counted answers."""
    from ..exercise.loader import open_bank
    from ..classgrade.report import report_html

    with tempfile.TemporaryDirectory() as folder:
        path = Path(folder) / "responses.csv"
        path.write_text(responses_csv(data, stored), encoding="utf-8")
        outcome = grade_class(data.path, [path], bank=open_bank(folders), jobs=1)
    return report_html(data.manifest.exam, outcome)
