"""Every graded part of a class, one flat record each: what copy detection
(:mod:`.copies`) and misconception discovery (:mod:`.discover`) read.

Class grading writes them as ``answers.csv`` (one row per student, exercise and part,
through :func:`dynagrade.exam.csvcells.csv_text`), so that ``dynagrade discover
MANIFEST GRADED_DIR`` can run again on a graded folder without grading anything::

    student_id,exercise_id,part,status,answer,misconception,time
    s001,projectile-range,x_max,wrong,41.2 m,,
"""

from __future__ import annotations

import csv
import io
from dataclasses import dataclass
from pathlib import Path
from typing import Iterable, Mapping

from ..exam.csvcells import csv_text, restored_rows
from ..exercise.results import ExerciseResult, Status

HEADER = ("student_id", "exercise_id", "part", "status", "answer", "misconception", "time")


@dataclass(frozen=True)
class Answered:
    """One student's graded part: the status, the answer as typed (None: none), the
    mistake the grader named for it and, when known, when it was handed in (ISO 8601)."""

    student_id: str
    exercise_id: str
    part: str
    status: Status
    answer: str | None
    misconception: str | None = None
    time: str = ""

    @property
    def unexplained_wrong(self) -> bool:
        """Wrong, answered, and nothing the grader tried explains it."""
        return self.status in (Status.WRONG, Status.PARTIAL) and not self.misconception \
            and bool((self.answer or "").strip())

    @property
    def wrong(self) -> bool:
        """Answered and wrong or partly right (follow-through is right for its student)."""
        return self.status in (Status.WRONG, Status.PARTIAL) and bool((self.answer or "").strip())


def from_results(results: Mapping[str, Mapping[str, ExerciseResult | None]],
                 times: Mapping[tuple[str, str], str] | None = None) -> list[Answered]:
    """The records of each student's results (``results[student_id][exercise_id]``);
    ``times`` maps ``(student_id, exercise_id)`` to when it was handed in."""
    times = times or {}
    return [Answered(student_id, exercise_id, part.name, part.status, part.answer,
                     part.misconception, times.get((student_id, exercise_id), ""))
            for student_id, by_exercise in results.items()
            for exercise_id, result in by_exercise.items() if result is not None
            for part in result.parts]


def answered_csv(records: Iterable[Answered]) -> str:
    """``answers.csv``: one row per record."""
    return csv_text([HEADER, *((r.student_id, r.exercise_id, r.part, str(r.status), r.answer,
                                r.misconception, r.time) for r in records)])


def read_answered(path: str | Path) -> list[Answered]:
    """The records of an ``answers.csv`` that class grading wrote."""
    rows = restored_rows(csv.reader(io.StringIO(Path(path).read_text(encoding="utf-8"))))
    if not rows or tuple(rows[0]) != HEADER:
        raise ValueError(f"{path}: not an answers.csv of dynagrade grade (its header must be "
                         f"{','.join(HEADER)})")
    return [Answered(r[0], r[1], r[2], Status(r[3]), r[4] or None, r[5] or None, r[6])
            for r in rows[1:] if len(r) == len(HEADER)]
