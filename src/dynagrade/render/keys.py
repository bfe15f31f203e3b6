"""Answer keys from an exam manifest: a CSV for machines and a PDF for people."""

from __future__ import annotations

import csv
import io
from typing import TYPE_CHECKING

from ..exercise.numbers import answer_text, points_text
from ..exercise.units import pretty_unit

if TYPE_CHECKING:
    from ..exam.manifest import Manifest

KEY_COLUMNS = ("student_id", "name", "exercise_id", "seed", "part", "answer", "unit", "points")


def key_rows(manifest: Manifest):
    """One row per student, exercise and part (the columns of :data:`KEY_COLUMNS`)."""
    parts = {e.id: e.parts for e in manifest.exercises}
    for student in manifest.students:
        for variant in student.variants:
            for part in parts[variant.exercise]:
                yield {"student_id": student.student_id, "name": student.name,
                       "exercise_id": variant.exercise, "seed": variant.seed,
                       "part": part.name, "value": variant.answers[part.name],
                       "unit": part.unit or "", "points": part.points}


def key_csv(manifest: Manifest) -> str:
    """The answer key as CSV, answers to 10 significant figures."""
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    writer.writerow(KEY_COLUMNS)
    for row in key_rows(manifest):
        writer.writerow([row["student_id"], row["name"], row["exercise_id"], row["seed"],
                         row["part"], answer_text(row["value"], 10), row["unit"],
                         points_text(row["points"])])
    return buffer.getvalue()


def key_typst(manifest: Manifest) -> str:
    """The body of the answer key PDF: per student a line per exercise with its seed and
    every part's answer, unit and points (compact: a class of 500 compiles in seconds)."""
    from .sheets import render_template

    students = []
    titles = {e.id: e.title for e in manifest.exercises}
    rows_by_student: dict[str, list] = {}
    for row in key_rows(manifest):
        shown = answer_text(row["value"])
        unit = pretty_unit(row["unit"]) if row["unit"] else ""
        rows_by_student.setdefault(row["student_id"], []).append(
            {**row, "shown": shown, "shown_unit": unit,
             "title": titles[row["exercise_id"]]})
    for student in manifest.students:
        exercises: dict[str, dict] = {}
        for row in rows_by_student.get(student.student_id, []):
            exercises.setdefault(row["exercise_id"], {"id": row["exercise_id"],
                                                      "seed": row["seed"], "rows": []})
            exercises[row["exercise_id"]]["rows"].append(row)
        students.append({"id": student.student_id, "name": student.name,
                         "exercises": list(exercises.values())})
    return render_template("key.typ", exam=manifest.exam, students=students)
