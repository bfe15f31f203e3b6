"""The gradebook of a graded class: its rows, and the files a learning platform imports.

A row (:class:`GradebookRow`) holds the student's id, name and email (from the roster),
the points earned in each exercise (kept apart from the fixed columns), the total, the
exam's maximum, the percentage and a status. Points are multiples of the exam's
rounding step (:mod:`dynagrade.exam.points`): each part's score is rounded, an
exercise's points are the sum of its rounded parts
(:meth:`~dynagrade.exercise.results.ExerciseResult.rounded`) and the total the sum of
the exercises, so every column adds up exactly. Class grading and the server build
their rows with the same :func:`gradebook_row`. An absent student (nothing handed in) has
empty exercise, total and percentage cells: no grade, not a zero.

Three layouts (``docs/exams.md`` describes each with the platform documentation it
follows):

``csv`` (``grades.csv``)
    student_id, name, email, one column per exercise id, total, max_total, percent,
    status (an exercise whose id is a fixed column's name is headed ``exercise:<id>``).
``moodle`` (``grades-moodle.csv``)
    what Moodle's grade import (Grades → Import → CSV file) reads: the identifier
    columns ``ID number`` and ``Email address`` (map users from either), ``Full name``,
    the grade item column (the exam's points) and its feedback column.
``canvas`` (``grades-canvas.csv``)
    what Canvas's gradebook import reads: ``Student``, ``ID``, ``SIS User ID``, ``SIS
    Login ID``, ``Section``, then the assignment column, with the ``Points Possible``
    row under the header as in Canvas's own export.
"""

from __future__ import annotations

from dataclasses import dataclass
from enum import StrEnum
from typing import Mapping, Sequence

from ..exam.csvcells import csv_text
from ..exam.points import Rounding
from ..exercise.numbers import percent_text
from ..exercise.results import ExerciseResult

#: the layouts a gradebook can be written in, and the file each is written to
GRADEBOOK_FILES = {"csv": "grades.csv", "moodle": "grades-moodle.csv",
                   "canvas": "grades-canvas.csv"}
#: the platform formats ``dynagrade grade --format`` offers
PLATFORM_FORMATS = ("moodle", "canvas")

MOODLE_ID_COLUMNS = ("ID number", "Email address", "Full name")
CANVAS_ID_COLUMNS = ("Student", "ID", "SIS User ID", "SIS Login ID", "Section")
CANVAS_POINTS_ROW = "Points Possible"
#: the columns of ``grades.csv`` besides the exercises' (which stand after ``email``)
FIXED_COLUMNS = ("student_id", "name", "email", "total", "max_total", "percent", "status")


class RowStatus(StrEnum):
    """Where a roster student stands in a graded class."""

    #: every exercise handed in and graded
    GRADED = "graded"
    #: some exercises missing
    INCOMPLETE = "incomplete"
    #: files handed in, but none could be graded (corrupt, foreign, impersonating)
    REJECTED = "rejected"
    #: nothing handed in: no grade, not a zero
    ABSENT = "absent"


@dataclass(frozen=True)
class GradebookRow:
    """One roster student's row: the fixed columns, and the points of each exercise kept
    apart in ``cells`` (so that no exercise id, ``total`` included, can stand in for a
    fixed column). A cell is None where the student has no grade at all (absent)."""

    student_id: str
    name: str
    email: str
    cells: Mapping[str, float | None]
    total: float | None
    max_total: float
    status: RowStatus

    @property
    def percent(self) -> float | None:
        """The total as a percentage of the maximum, to hundredths (None: no grade)."""
        if self.total is None:
            return None
        return round(100.0 * self.total / self.max_total, 2) if self.max_total else 0.0


def gradebook_row(student_id: str, results: Mapping[str, ExerciseResult | None],
                  exercise_ids: Sequence[str], max_total: float, handed_in: bool = False,
                  *, name: str = "", email: str = "",
                  rounding: Rounding = Rounding()) -> GradebookRow:
    """A student's row from their rounded results (:meth:`ExerciseResult.rounded`):
    points per exercise (0 when not submitted), the total in exact steps and the status
    (absent: nothing submitted, and no points at all, not zeros; rejected: files handed
    in but none could be graded; incomplete: some exercises missing)."""
    submitted = [e for e in exercise_ids if results[e] is not None]
    status = (RowStatus.REJECTED if not submitted and handed_in else
              RowStatus.ABSENT if not submitted else
              RowStatus.GRADED if len(submitted) == len(exercise_ids) else
              RowStatus.INCOMPLETE)
    if status is RowStatus.ABSENT:
        return GradebookRow(student_id, name, email, dict.fromkeys(exercise_ids), None,
                            max_total, status)
    cells = {}
    for exercise_id in exercise_ids:
        result = results[exercise_id]
        cells[exercise_id] = result.rounded(rounding).score if result else 0.0
    return GradebookRow(student_id, name, email, cells, rounding.total(list(cells.values())),
                        max_total, status)


def _points(value: float | None, rounding: Rounding) -> str:
    """A gradebook cell: the points with the step's decimals, empty for no grade."""
    return "" if value is None else rounding.text(value)


def exercise_columns(exercise_ids: Sequence[str]) -> list[str]:
    """The headers of the exercise columns: each exercise's id, and ``exercise:<id>`` for
    an id that is also the name of a fixed column (an exercise called ``total``), so that
    no header stands twice and a spreadsheet or an import finds the real total."""
    return [f"exercise:{e}" if e in FIXED_COLUMNS else e for e in exercise_ids]


def gradebook_csv(outcome) -> str:
    """``grades.csv``: one row per roster student, in roster order."""
    rounding = outcome.rounding
    header = [*FIXED_COLUMNS[:3], *exercise_columns(outcome.exercise_ids),
              *FIXED_COLUMNS[3:]]
    return csv_text([header] + [
        [row.student_id, row.name, row.email,
         *(_points(row.cells[e], rounding) for e in outcome.exercise_ids),
         _points(row.total, rounding), _points(row.max_total, rounding),
         percent_text(row.percent, ""), row.status]
        for row in outcome.rows])


def feedback_line(row: GradebookRow, exercise_ids: Sequence[str], rounding: Rounding,
                  comments: Sequence[str] = ()) -> str:
    """The short feedback a platform's gradebook shows beside the grade: the points of
    every exercise, the total and the staff's comments on overridden parts."""
    if row.status is RowStatus.ABSENT:
        return "absent: nothing handed in"
    points = ", ".join(f"{e} {_points(row.cells[e], rounding)}" for e in exercise_ids)
    text = (f"{_points(row.total, rounding)} / {_points(row.max_total, rounding)} "
            f"points ({points}); {row.status}")
    return text + "".join(f". {comment}" for comment in comments)


def moodle_csv(outcome, title: str) -> str:
    """``grades-moodle.csv`` for Moodle's CSV grade import: a row per roster student with
    both identifiers Moodle can map users from (ID number, email address), the grade item
    column headed ``title`` and the feedback column headed ``Feedback: <title>``. An absent
    student's grade is empty, which Moodle imports as "no grade"."""
    rounding = outcome.rounding
    header = [*MOODLE_ID_COLUMNS, title, f"Feedback: {title}"]
    rows = [[row.student_id, row.email, row.name, _points(row.total, rounding),
             feedback_line(row, outcome.exercise_ids, rounding,
                           outcome.comments.get(row.student_id, ()))]
            for row in outcome.rows]
    return csv_text([header, *rows])


def canvas_csv(outcome, title: str) -> str:
    """``grades-canvas.csv`` for Canvas's gradebook import: the five student columns
    Canvas's export starts with (the roster's id as ``SIS User ID``; Canvas's own ``ID``
    and the login, section left empty for Canvas to match on the SIS User ID), the
    assignment column headed ``title`` and the ``Points Possible`` row."""
    rounding = outcome.rounding
    header = [*CANVAS_ID_COLUMNS, title]
    possible = [CANVAS_POINTS_ROW, "", "", "", "", _points(outcome.max_total, rounding)]
    rows = [[row.name, "", row.student_id, "", "", _points(row.total, rounding)]
            for row in outcome.rows]
    return csv_text([header, possible, *rows])


def platform_gradebook(outcome, layout: str, title: str) -> str:
    """The gradebook in a platform's ``layout`` (:data:`PLATFORM_FORMATS`), its grade
    column headed ``title``."""
    if layout == "moodle":
        return moodle_csv(outcome, title)
    if layout == "canvas":
        return canvas_csv(outcome, title)
    raise ValueError(f"unknown gradebook format {layout!r}; known: "
                     f"{', '.join(PLATFORM_FORMATS)}")
