"""Answer keys from an exam manifest: a CSV for machines and a PDF for people.

Beside each variant's answers the keys show its given values, the parameters the
statement prints, as it prints them (``v0 = 12 m/s; alpha = 40°; g = 9.81 m/s²``), so
that a written solution can be checked by hand against the numbers the student had.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Mapping

from ..exam.csvcells import csv_text
from ..exercise.numbers import answer_text, points_text
from ..exercise.statement import ShownValue, referenced_names
from ..exercise.units import pretty_unit

if TYPE_CHECKING:
    from ..exam.manifest import Manifest
    from ..exercise.model import Exercise
    from ..exercise.params import Parameter

KEY_COLUMNS = ("student_id", "name", "exercise_id", "seed", "given", "part", "answer", "unit",
               "points")


def shown_parameters(exercise: Exercise | None) -> tuple[Parameter, ...]:
    """The parameters ``exercise``'s statement shows, in declaration order (none when the
    exercise is not at hand)."""
    if exercise is None:
        return ()
    shown = referenced_names(exercise.statement)
    return tuple(p for p in exercise.params if p.name in shown)


def given_values(shown: tuple[Parameter, ...], params: Mapping[str, float]) -> str:
    """A variant's given values as its statement prints them, ``name = value unit``
    separated by ``; ``: the ``shown`` parameters (:func:`shown_parameters`) at
    ``params``."""
    return "; ".join(f"{p.name} = {ShownValue(p, params[p.name])}"
                     for p in shown if p.name in params)


def key_rows(manifest: Manifest, exercises: Mapping[str, Exercise] | None = None):
    """One row per student, exercise and part (the columns of :data:`KEY_COLUMNS`); the
    given values need the exercises (by id). Each statement is read once, not once per
    variant."""
    parts = {e.id: e.parts for e in manifest.exercises}
    exercises = exercises or {}
    shown = {e.id: shown_parameters(exercises.get(e.id)) for e in manifest.exercises}
    for student in manifest.students:
        for variant in student.variants:
            given = given_values(shown[variant.exercise], variant.params)
            for part in parts[variant.exercise]:
                yield {"student_id": student.student_id, "name": student.name,
                       "exercise_id": variant.exercise, "seed": variant.seed,
                       "given": given, "part": part.name,
                       "value": variant.answers[part.name], "unit": part.unit or "",
                       "points": part.points}


def key_csv(manifest: Manifest, exercises: Mapping[str, Exercise] | None = None) -> str:
    """The answer key as CSV, answers to 10 significant figures, each row with its
    variant's given values."""
    return csv_text([KEY_COLUMNS, *(
        [row["student_id"], row["name"], row["exercise_id"], row["seed"], row["given"],
         row["part"], answer_text(row["value"], 10), row["unit"], points_text(row["points"])]
        for row in key_rows(manifest, exercises))])


def key_typst(manifest: Manifest, exercises: Mapping[str, Exercise] | None = None) -> str:
    """The body of the answer key PDF: per student a line per exercise with its seed, its
    given values and every part's answer, unit and points (compact: a class of 500
    compiles in seconds)."""
    from .sheets import render_template

    students = []
    titles = {e.id: e.title for e in manifest.exercises}
    rows_by_student: dict[str, list] = {}
    for row in key_rows(manifest, exercises):
        shown = answer_text(row["value"])
        unit = pretty_unit(row["unit"]) if row["unit"] else ""
        rows_by_student.setdefault(row["student_id"], []).append(
            {**row, "shown": shown, "shown_unit": unit,
             "title": titles[row["exercise_id"]]})
    for student in manifest.students:
        lines: dict[str, dict] = {}
        for row in rows_by_student.get(student.student_id, []):
            lines.setdefault(row["exercise_id"], {"id": row["exercise_id"],
                                                  "seed": row["seed"], "given": row["given"],
                                                  "rows": []})
            lines[row["exercise_id"]]["rows"].append(row)
        students.append({"id": student.student_id, "name": student.name,
                         "exercises": list(lines.values())})
    return render_template("key.typ", exam=manifest.exam, students=students)
