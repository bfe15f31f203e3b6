"""Points set by the staff after grading: ``dynagrade grade … --overrides overrides.csv``.

The file has the header ``student_id,exercise,part,points,comment`` (``comment`` may be
left out) and one row per part whose points the staff set by hand, e.g. after reading a
student's working::

    student_id,exercise,part,points,comment
    s1,car-in-a-looping,N_max,1,"sign slip only, method right"

The points replace what the grader gave that part (which is kept beside them, as the
:class:`~dynagrade.exercise.results.StaffOverride` of the part's record); the comment
follows the part's feedback. The file is read as people save it (UTF-8 with or without a byte-order mark,
``,``, ``;`` or a tab as separator, CRLF or LF; a decimal comma such as ``1,5`` is read as 1.5).

Every row is checked before anything is graded or written: a student not on the roster,
an exercise not in the exam, a part the exercise does not have, points that are not a
number, negative, above the part's points or not a multiple of the exam's rounding, a row
with too few columns or a part given twice. All bad rows are listed in one
:class:`OverrideError` and the run stops before it writes anything, so the previous
grading stays as it was. A part of an exercise the student handed nothing in for cannot
be overridden (there is no graded part to replace); that too is refused with the row.

The checks of one override (:class:`OverrideRules`, :func:`not_handed_in`) are the same
for the server's points by hand (:mod:`dynagrade.serve.overrides`), whose stored
overrides class grading applies here too (:func:`apply_overrides`, with their author and
time), so both refuse the same and give the same marks.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path
from typing import Mapping

from ..errors import DynagradeError
from ..exercise.datafile import DataFileError, read_data_file
from ..exercise.results import ExerciseResult, StaffOverride
from ..exam.manifest import Manifest
from ..exam.points import Rounding
from ..exam.roster import csv_rows
from ..i18n import _

OVERRIDE_COLUMNS = ("student_id", "exercise", "part", "points", "comment")
MAX_OVERRIDES_BYTES = 5_000_000


class OverrideError(DynagradeError, ValueError):
    """Overrides that cannot be applied; the message lists every bad row."""


@dataclass(frozen=True)
class Override:
    """One row of the overrides file: the points the staff give a student's part."""

    row: int
    student_id: str
    exercise: str
    part: str
    points: float
    comment: str
    #: who set them (the server's staff link; "": the file they came from)
    author: str = ""
    #: when, as ISO 8601 text ("": not recorded)
    at: str = ""


def read_overrides(path: str | Path, manifest: Manifest,
                   rounding: Rounding) -> tuple[Override, ...]:
    """The overrides in ``path``, every row checked against the exam; an
    :class:`OverrideError` lists every bad row."""
    path = Path(path)
    try:
        raw = read_data_file(path, MAX_OVERRIDES_BYTES)
    except DataFileError as problem:
        raise OverrideError(f"{path}: cannot read the overrides ({problem})") from None
    return parse_overrides(raw, str(path), manifest, rounding)


def parse_overrides(raw: bytes, where: str, manifest: Manifest,
                    rounding: Rounding) -> tuple[Override, ...]:
    """The overrides in ``raw`` (the file's bytes); ``where`` names it in errors."""
    rows = csv_rows(raw, where, OverrideError)
    header = [cell.strip().lower() for cell in rows[0]] if rows else []
    if header[:4] != list(OVERRIDE_COLUMNS[:4]) or len(header) > 5 \
            or header[4:] not in ([], ["comment"]):
        raise OverrideError(f"{where}, row 1: the header must be "
                            f"{','.join(OVERRIDE_COLUMNS)} (comment may be left out)")
    checker = _RowChecker(manifest, rounding)
    overrides, problems = [], []
    for number, row in enumerate(rows[1:], 2):
        if not any(cell.strip() for cell in row):
            continue
        try:
            overrides.append(checker.check(number, row, len(header)))
        except ValueError as problem:
            problems.append(f"{where}, row {number}: {problem}")
    if problems:
        raise OverrideError(f"{len(problems)} bad override row(s); nothing was graded or "
                            "written:\n  " + "\n  ".join(problems))
    return tuple(overrides)


class OverrideRules:
    """What an override must satisfy against the exam, whoever sets it (a row of the
    overrides file, the server's staff): the student is on the roster, the exercise is in
    the exam and has the part, and the points are a number from 0 to the part's points
    and a multiple of the exam's rounding."""

    def __init__(self, manifest: Manifest, rounding: Rounding):
        self.students = {s.student_id for s in manifest.students}
        self.exercises = {e.id: {p.name: p.points for p in e.parts} for e in manifest.exercises}
        self.rounding = rounding

    def points(self, student_id: str, exercise: str, part: str,
               given: str | float) -> float:
        """The points ``given`` (text as people type it, or a number), rounded to the
        exam's step; a :class:`ValueError` naming what is wrong otherwise."""
        most = self.part_points(student_id, exercise, part)
        points = _number(given) if isinstance(given, str) else \
            (float(given) if math.isfinite(given) else None)
        if points is None:
            raise ValueError(_("points {given!r} is not a number").format(given=given))
        given = given if isinstance(given, str) else f"{given:g}"
        if not 0 <= points <= most + 1e-9:
            raise ValueError(_("points {given} is outside 0 to {most}, the points of part "
                               "{part!r}").format(given=given, part=part,
                                                  most=self.rounding.text(most)))
        if not self.rounding.is_multiple(points):
            raise ValueError(_("points {given} is not one of the exam's multiples of "
                               "{step}").format(given=given,
                                                step=self.rounding.text(self.rounding.step)))
        return self.rounding.round(points)

    def part_points(self, student_id: str, exercise: str, part: str) -> float:
        """What ``part`` of ``exercise`` is worth, once the student, the exercise and
        the part are checked (a :class:`ValueError` naming the one not in the exam)."""
        if student_id not in self.students:
            raise ValueError(_("student {student!r} is not on the exam's roster").format(
                student=student_id))
        if exercise not in self.exercises:
            raise ValueError(_("exercise {exercise!r} is not in the exam (its exercises: "
                               "{exercises})").format(exercise=exercise,
                                                      exercises=", ".join(self.exercises)))
        parts = self.exercises[exercise]
        if part not in parts:
            raise ValueError(_("exercise {exercise!r} has no part {part!r} (its parts: "
                               "{parts})").format(exercise=exercise, part=part,
                                                  parts=", ".join(parts)))
        return float(parts[part])


def not_handed_in(student_id: str, exercise: str) -> str:
    """Why an override of an exercise the student handed nothing in for is refused."""
    return _("{student} handed in nothing gradable for {exercise!r}; an override replaces "
             "the points of a graded part").format(student=student_id, exercise=exercise)


class _RowChecker:
    """Checks one row after another against the exam (:class:`OverrideRules`) and
    against the rows before (a part given twice)."""

    def __init__(self, manifest: Manifest, rounding: Rounding):
        self.rules = OverrideRules(manifest, rounding)
        self.seen: dict[tuple[str, str, str], int] = {}

    def check(self, number: int, row: list[str], width: int) -> Override:
        if len(row) not in (4, width):
            raise ValueError(f"{len(row)} columns, the header has {width}")
        student_id, exercise, part, given = (cell.strip() for cell in row[:4])
        comment = row[4].strip() if len(row) > 4 else ""
        points = self.rules.points(student_id, exercise, part, given)
        key = (student_id, exercise, part)
        if key in self.seen:
            raise ValueError(f"{student_id}'s part {part!r} of {exercise!r} is already "
                             f"overridden on row {self.seen[key]}")
        self.seen[key] = number
        return Override(number, student_id, exercise, part, points, comment)


def _number(text: str) -> float | None:
    """A number as people type it (``1.5``, ``1,5``); None when it is not one."""
    try:
        value = float(text.replace(",", ".") if text.count(",") == 1 and "." not in text
                      else text)
    except ValueError:
        return None
    return value if math.isfinite(value) else None


def apply_overrides(overrides: tuple[Override, ...], where: str,
                    results_by_student: Mapping[str, Mapping[str, ExerciseResult | None]],
                    rounding: Rounding
                    ) -> tuple[dict[str, dict[str, ExerciseResult | None]], dict[str, list[str]]]:
    """The graded results with every overridden part's points set by the staff (the
    automatic score kept beside them, the comment and the file as the override's author
    recorded), and the staff's notes by student for the platform feedback. An override
    of an exercise the student handed nothing in for is an :class:`OverrideError`,
    listing every such row."""
    results = {student: dict(by_exercise) for student, by_exercise in results_by_student.items()}
    problems: list[str] = []
    comments: dict[str, list[str]] = {}
    for override in overrides:
        result = results[override.student_id][override.exercise]
        if result is None:
            problems.append(f"{where}, row {override.row}: "
                            + not_handed_in(override.student_id, override.exercise))
            continue
        part = result.part(override.part).with_override(
            StaffOverride(override.points, override.comment,
                          author=override.author or where, at=override.at))
        results[override.student_id][override.exercise] = result.with_part(part)
        comments.setdefault(override.student_id, []).append(
            f"{override.exercise} {override.part}: {part.override_note(rounding)}")
    if problems:
        raise OverrideError(f"{len(problems)} bad override row(s); nothing was written:\n  "
                            + "\n  ".join(problems))
    return results, comments
