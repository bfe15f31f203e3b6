"""What grading a class produces: the gradebook rows, each student's feedback, the item
statistics and the problems found, as class grading and the server's gradebook build them
(:func:`dynagrade.classgrade.grade.class_outcome`) and the report renders them
(:mod:`.report`)."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Mapping

from ..exam.manifest import StudentEntry
from ..exam.points import Rounding
from ..exercise.results import ExerciseResult
from .answered import Answered, from_results
from .findings import Findings
from .gradebook import GradebookRow
from .stats import PartStats
from .submissions import Problem


@dataclass
class StudentFeedback:
    """What one student's feedback page shows: their results, their gradebook row, why
    files they handed in were not graded, and their worked solutions where the policy
    shows them."""

    student: StudentEntry
    results: dict[str, ExerciseResult | None]
    row: GradebookRow
    #: per exercise, why the files handed in for it were not graded
    rejected: dict[str, list[str]] = field(default_factory=dict)
    #: per exercise, the worked solution (None: it could not be rendered)
    solutions: dict[str, str | None] = field(default_factory=dict)


@dataclass
class ClassOutcome:
    """The gradebook and everything the report shows."""

    exam_title: str
    exercise_ids: list[str]
    rows: list[GradebookRow]
    problems: list[Problem]
    stats: list[PartStats] = field(default_factory=list)
    feedback: dict[str, StudentFeedback] = field(default_factory=dict)
    timings: dict[str, float] = field(default_factory=dict)
    rounding: Rounding = Rounding()
    max_total: float = 0.0
    #: the staff's comments on overridden parts, by student (for the platform feedback)
    comments: dict[str, list[str]] = field(default_factory=dict)
    #: how many parts the overrides replaced
    overridden: int = 0
    #: discovered misconceptions and copied answers (:mod:`.findings`; None: not searched)
    findings: Findings | None = None

    def records(self, times: Mapping[tuple[str, str], str] | None = None) -> list[Answered]:
        """Every graded part (the points that count, overrides included); ``times`` maps
        ``(student_id, exercise_id)`` to when it was handed in."""
        return from_results({student_id: feedback.results
                             for student_id, feedback in self.feedback.items()}, times)

    def summary(self) -> dict:
        """The gradebook and the problems as ``dynagrade grade --json`` prints them."""
        return {"exam": self.exam_title, "rows": [_row_json(r) for r in self.rows],
                "problems": [p.__dict__ for p in self.problems]}


def _row_json(row: GradebookRow) -> dict:
    """A gradebook row as JSON: the fixed columns, and the exercises' points under
    ``exercises``."""
    return {"student_id": row.student_id, "name": row.name, "email": row.email,
            "exercises": dict(row.cells), "total": row.total, "max_total": row.max_total,
            "percent": row.percent, "status": str(row.status)}
