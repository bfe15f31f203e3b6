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


class _RowChecker:
    """Checks one row after another against the exam (and against the rows before)."""

    def __init__(self, manifest: Manifest, rounding: Rounding):
        self.students = {s.student_id for s in manifest.students}
        self.exercises = {e.id: {p.name: p.points for p in e.parts} for e in manifest.exercises}
        self.rounding = rounding
        self.seen: dict[tuple[str, str, str], int] = {}

    def check(self, number: int, row: list[str], width: int) -> Override:
        if len(row) not in (4, width):
            raise ValueError(f"{len(row)} columns, the header has {width}")
        student_id, exercise, part, given = (cell.strip() for cell in row[:4])
        comment = row[4].strip() if len(row) > 4 else ""
        if student_id not in self.students:
            raise ValueError(f"student {student_id!r} is not on the exam's roster")
        if exercise not in self.exercises:
            raise ValueError(f"exercise {exercise!r} is not in the exam (its exercises: "
                             f"{', '.join(self.exercises)})")
        parts = self.exercises[exercise]
        if part not in parts:
            raise ValueError(f"exercise {exercise!r} has no part {part!r} (its parts: "
                             f"{', '.join(parts)})")
        points = _number(given)
        if points is None:
            raise ValueError(f"points {given!r} is not a number")
        if not 0 <= points <= parts[part] + 1e-9:
            raise ValueError(f"points {given} is outside 0 to "
                             f"{self.rounding.text(parts[part])}, the points of part {part!r}")
        if not self.rounding.is_multiple(points):
            raise ValueError(f"points {given} is not one of the exam's "
                             f"{self.rounding.describe()}")
        key = (student_id, exercise, part)
        if key in self.seen:
            raise ValueError(f"{student_id}'s part {part!r} of {exercise!r} is already "
                             f"overridden on row {self.seen[key]}")
        self.seen[key] = number
        return Override(number, student_id, exercise, part, self.rounding.round(points),
                        comment)


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
            problems.append(f"{where}, row {override.row}: {override.student_id} handed in "
                            f"nothing gradable for {override.exercise!r}; an override "
                            "replaces the points of a graded part")
            continue
        part = result.part(override.part).with_override(
            StaffOverride(override.points, override.comment, author=where))
        results[override.student_id][override.exercise] = result.with_part(part)
        comments.setdefault(override.student_id, []).append(
            f"{override.exercise} {override.part}: {part.override_note(rounding)}")
    if problems:
        raise OverrideError(f"{len(problems)} bad override row(s); nothing was written:\n  "
                            + "\n  ".join(problems))
    return results, comments
