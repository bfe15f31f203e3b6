"""The gradebook of a graded class: its rows, and the files a learning platform imports.

A row holds the student's id, name and email (from the roster), the points earned in each
exercise, the total, the exam's maximum, the percentage and a status. Points are
multiples of the exam's rounding step (:mod:`.points`): each part's score is rounded,
an exercise's points are the sum of its rounded parts and the total the sum of the
exercises, so every column adds up exactly. An absent student (nothing handed in) has
empty exercise, total and percentage cells: no grade, not a zero.

Three layouts (``docs/exams.md`` describes each with the platform documentation it
follows):

``csv`` (``grades.csv``)
    student_id, name, email, one column per exercise id, total, max_total, percent,
    status.
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

import csv
import io
from typing import Mapping, Sequence

from ..exercise.numbers import percent_text
from ..exam.points import Rounding

#: the layouts a gradebook can be written in, and the file each is written to
GRADEBOOK_FILES = {"csv": "grades.csv", "moodle": "grades-moodle.csv",
                   "canvas": "grades-canvas.csv"}
#: the platform formats ``dynagrade grade --format`` offers
PLATFORM_FORMATS = ("moodle", "canvas")

MOODLE_ID_COLUMNS = ("ID number", "Email address", "Full name")
CANVAS_ID_COLUMNS = ("Student", "ID", "SIS User ID", "SIS Login ID", "Section")
CANVAS_POINTS_ROW = "Points Possible"


def round_results(results: Mapping[str, dict | None], rounding: Rounding) -> None:
    """Round every part's score of one student's ``results`` to the exam's step (in
    place) and make each exercise's score the sum of its rounded parts."""
    for result in results.values():
        if result is None:
            continue
        for part in result["parts"]:
            part["score"] = rounding.round(part["score"])
        result["score"] = rounding.total([p["score"] for p in result["parts"]])


def gradebook_row(student_id: str, results: Mapping[str, dict | None],
                  exercise_ids: Sequence[str], max_total: float, handed_in: bool = False,
                  *, name: str = "", email: str = "",
                  rounding: Rounding = Rounding()) -> dict:
    """A student's row: points per exercise (0 when not submitted), total, percent and
    status (absent: nothing submitted, and no points at all, not zeros; rejected: files
    handed in but none could be graded; incomplete: some exercises missing)."""
    submitted = [e for e in exercise_ids if results[e] is not None]
    status = ("rejected" if not submitted and handed_in else
              "absent" if not submitted else
              "graded" if len(submitted) == len(exercise_ids) else "incomplete")
    row = {"student_id": student_id, "name": name, "email": email}
    if status == "absent":
        row.update(dict.fromkeys(exercise_ids), total=None, max_total=max_total,
                   percent=None, status=status)
        return row
    for exercise_id in exercise_ids:
        result = results[exercise_id]
        row[exercise_id] = rounding.round(result["score"]) if result else 0.0
    total = rounding.total([row[e] for e in exercise_ids])
    row.update(total=total, max_total=max_total,
               percent=round(100.0 * total / max_total, 2) if max_total else 0.0,
               status=status)
    return row


def _points(value: float | None, rounding: Rounding) -> str:
    """A gradebook cell: the points with the step's decimals, empty for no grade."""
    return "" if value is None else rounding.text(value)


def _csv(rows: list[list[str]]) -> str:
    buffer = io.StringIO()
    csv.writer(buffer, lineterminator="\n").writerows(rows)
    return buffer.getvalue()


def gradebook_csv(outcome) -> str:
    """``grades.csv``: one row per roster student, in roster order."""
    rounding = outcome.rounding
    header = ["student_id", "name", "email", *outcome.exercise_ids, "total", "max_total",
              "percent", "status"]
    return _csv([header] + [
        [row["student_id"], row.get("name", ""), row.get("email", ""),
         *(_points(row[e], rounding) for e in outcome.exercise_ids),
         _points(row["total"], rounding), _points(row["max_total"], rounding),
         percent_text(row["percent"], ""), row["status"]]
        for row in outcome.rows])


def feedback_line(row: dict, exercise_ids: Sequence[str], rounding: Rounding,
                  comments: Sequence[str] = ()) -> str:
    """The short feedback a platform's gradebook shows beside the grade: the points of
    every exercise, the total and the staff's comments on overridden parts."""
    if row["status"] == "absent":
        return "absent: nothing handed in"
    points = ", ".join(f"{e} {_points(row[e], rounding)}" for e in exercise_ids)
    text = (f"{_points(row['total'], rounding)} / {_points(row['max_total'], rounding)} "
            f"points ({points}); {row['status']}")
    return text + "".join(f". {comment}" for comment in comments)


def moodle_csv(outcome, title: str) -> str:
    """``grades-moodle.csv`` for Moodle's CSV grade import: a row per roster student with
    both identifiers Moodle can map users from (ID number, email address), the grade item
    column headed ``title`` and the feedback column headed ``Feedback: <title>``. An absent
    student's grade is empty, which Moodle imports as "no grade"."""
    rounding = outcome.rounding
    header = [*MOODLE_ID_COLUMNS, title, f"Feedback: {title}"]
    rows = [[row["student_id"], row.get("email", ""), row.get("name", ""),
             _points(row["total"], rounding),
             feedback_line(row, outcome.exercise_ids, rounding,
                           outcome.comments.get(row["student_id"], ()))]
            for row in outcome.rows]
    return _csv([header, *rows])


def canvas_csv(outcome, title: str) -> str:
    """``grades-canvas.csv`` for Canvas's gradebook import: the five student columns
    Canvas's export starts with (the roster's id as ``SIS User ID``; Canvas's own ``ID``
    and the login, section left empty for Canvas to match on the SIS User ID), the
    assignment column headed ``title`` and the ``Points Possible`` row."""
    rounding = outcome.rounding
    header = [*CANVAS_ID_COLUMNS, title]
    possible = [CANVAS_POINTS_ROW, "", "", "", "", _points(outcome.max_total, rounding)]
    rows = [[row.get("name", ""), "", row["student_id"], "", "",
             _points(row["total"], rounding)] for row in outcome.rows]
    return _csv([header, possible, *rows])


def platform_gradebook(outcome, layout: str, title: str) -> str:
    """The gradebook in a platform's ``layout`` (:data:`PLATFORM_FORMATS`), its grade
    column headed ``title``."""
    if layout == "moodle":
        return moodle_csv(outcome, title)
    if layout == "canvas":
        return canvas_csv(outcome, title)
    raise ValueError(f"unknown gradebook format {layout!r}; known: "
                     f"{', '.join(PLATFORM_FORMATS)}")
