"""Reading an exam: its specification (``exam.toml``) and its roster (a CSV file).

``exam.toml``::

    id = "dyn-midterm-2025"          # kebab-case; it seeds every student's variants
    title = "Dynamics, midterm"
    date = 2025-04-14                # a TOML date or "YYYY-MM-DD"
    instructions = "Answer every part. Give numbers to three significant figures."
    language = "de"                  # optional, default "en": the sheets' declared language

    [[exercise]]
    id = "projectile-range"
    points = 6

    [[exercise]]
    id = "car-in-a-looping"
    points = 8
    [exercise.set]                   # optional: fixed values, in the parameter's unit
    R = 5.0

The roster: a UTF-8 CSV (no byte-order mark) with the header ``student_id,name`` or
``student_id,name,email``, one student per row.

Every error names the file, and the line and field (or row and column) at fault.
"""

from __future__ import annotations

import contextlib
import csv
import datetime as dt
import io
import math
import re
import tomllib
from dataclasses import dataclass, field
from pathlib import Path
from typing import Callable

from ..errors import DynagradeError
from .policy import POLICY_KEYS, Policy, PolicyError, read_policy

_EXAM_ID = re.compile(r"^[a-z0-9]+(-[a-z0-9]+)*$")
_STUDENT_ID = re.compile(r"^[A-Za-z0-9][A-Za-z0-9._-]*$")
_TOP_KEYS = {"id", "title", "date", "instructions", "language", "exercise"} | POLICY_KEYS
_LANGUAGE = re.compile(r"^[a-z]{2,3}(-[A-Za-z0-9]{2,8})*$")
_EXERCISE_KEYS = {"id", "points", "set"}
ROSTER_HEADERS = (("student_id", "name"), ("student_id", "name", "email"))


class ExamSpecError(DynagradeError, ValueError):
    """A malformed exam specification or roster; the message says where and why."""


@dataclass(frozen=True)
class ExamExercise:
    """One exercise of the exam: its id, the points it is worth and fixed parameters."""

    id: str
    points: float
    set: dict[str, float] = field(default_factory=dict)
    line: int = 0


@dataclass(frozen=True)
class ExamSpec:
    """The exam as ``exam.toml`` declares it."""

    id: str
    title: str
    date: str  # ISO date, YYYY-MM-DD
    instructions: str
    exercises: tuple[ExamExercise, ...]
    path: str = ""
    policy: Policy = Policy()  # delivery by `dynagrade serve` (exam/policy.py)
    language: str = "en"  # a BCP 47 tag: HTML lang and the PDFs' language

    @property
    def total_points(self) -> float:
        return sum(e.points for e in self.exercises)

    def to_json(self) -> dict:
        return {"id": self.id, "title": self.title, "date": self.date,
                "instructions": self.instructions, "language": self.language}


@dataclass(frozen=True)
class Student:
    """A row of the roster."""

    student_id: str
    name: str
    email: str = ""

    def to_json(self) -> dict:
        return {"student_id": self.student_id, "name": self.name, "email": self.email}


# -- exam.toml ----------------------------------------------------------------------------


def read_exam_spec(path: str | Path, known: Callable[[str], object] | None = None) -> ExamSpec:
    """The exam in ``path``.

    ``known(exercise_id)`` returns the exercise (an object with ``parameter(name)``) or
    raises a :class:`~dynagrade.errors.DynagradeError` saying why; with it, exercise ids and the names in ``[exercise.set]`` are
    checked too.
    """
    path = Path(path)
    try:
        raw = path.read_bytes()
    except OSError as error:
        raise ExamSpecError(f"{path}: cannot read the exam ({error.strerror})") from None
    if raw.startswith(b"\xef\xbb\xbf"):
        raise ExamSpecError(f"{path}, line 1: the file starts with a byte-order mark; "
                            "save it as UTF-8 without BOM")
    try:
        text = raw.decode("utf-8")
    except UnicodeDecodeError as error:
        raise ExamSpecError(f"{path}: not UTF-8 text (byte {error.start})") from None
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as error:
        raise ExamSpecError(f"{path}: not valid TOML: {error}") from None
    lines = _exercise_lines(text)
    where = f"{path}"

    unknown = sorted(set(data) - _TOP_KEYS)
    if unknown:
        raise ExamSpecError(f"{where}, line {_key_line(text, unknown[0])}: unknown key "
                            f"{unknown[0]!r}; an exam has {sorted(_TOP_KEYS)}")
    exam_id = data.get("id")
    if not isinstance(exam_id, str) or not exam_id:
        raise ExamSpecError(f"{where}: the top-level key 'id' (a kebab-case string) is "
                            "missing")
    if not _EXAM_ID.match(exam_id):
        raise ExamSpecError(f"{where}, line {_key_line(text, 'id')}, field 'id': {exam_id!r} "
                            "is not kebab-case (a-z, 0-9 and '-')")
    title = _string(data, "title", where, text, required=True)
    instructions = _string(data, "instructions", where, text, required=False)
    date = _date(data.get("date"), where, _key_line(text, "date"))
    language = data.get("language", "en")
    if not isinstance(language, str) or not _LANGUAGE.match(language):
        raise ExamSpecError(f"{where}, line {_key_line(text, 'language')}, field 'language': "
                            f"{language!r} is not a language tag; give e.g. \"en\" or \"de\"")

    tables = data.get("exercise")
    if not isinstance(tables, list) or not tables:
        raise ExamSpecError(f"{where}: no [[exercise]] tables; an exam needs at least one")
    exercises = []
    seen: dict[str, int] = {}
    for index, table in enumerate(tables):
        line = lines[index] if index < len(lines) else 0
        at = f"{where}, line {line}, [[exercise]] #{index + 1}"
        exercises.append(_exercise(table, at, line, seen, known))
    try:
        policy = read_policy(data, where, lambda key: _key_line(text, key))
    except PolicyError as error:
        raise ExamSpecError(str(error)) from None
    return ExamSpec(exam_id, title, date, instructions, tuple(exercises), str(path), policy,
                    language)


def _exercise(table, at: str, line: int, seen: dict[str, int], known) -> ExamExercise:
    if not isinstance(table, dict):
        raise ExamSpecError(f"{at}: not a table")
    unknown = sorted(set(table) - _EXERCISE_KEYS)
    if unknown:
        raise ExamSpecError(f"{at}: unknown key {unknown[0]!r}; an exercise has "
                            f"{sorted(_EXERCISE_KEYS)}")
    exercise_id = table.get("id")
    if not isinstance(exercise_id, str) or not exercise_id.strip():
        raise ExamSpecError(f"{at}, field 'id': missing (the id of an exercise in the bank)")
    if exercise_id in seen:
        raise ExamSpecError(f"{at}, field 'id': {exercise_id!r} is already exercise "
                            f"#{seen[exercise_id]}; use an exercise once per exam")
    seen[exercise_id] = len(seen) + 1
    exercise = None
    if known is not None:
        try:
            exercise = known(exercise_id)
        except DynagradeError as error:
            raise ExamSpecError(f"{at}, field 'id': {error}") from None
    points = table.get("points")
    if isinstance(points, bool) or not isinstance(points, (int, float)) \
            or not math.isfinite(points) or points <= 0:
        raise ExamSpecError(f"{at} ({exercise_id}), field 'points': "
                            f"{'missing' if points is None else repr(points)}; "
                            "give a positive number")
    overrides = table.get("set", {})
    if not isinstance(overrides, dict):
        raise ExamSpecError(f"{at} ({exercise_id}), field 'set': must be a table "
                            "[exercise.set] of name = value")
    values = {}
    for name, value in overrides.items():
        if isinstance(value, bool) or not isinstance(value, (int, float)) \
                or not math.isfinite(value):
            raise ExamSpecError(f"{at} ({exercise_id}), field 'set.{name}': {value!r} is not "
                                "a number (give it in the parameter's unit)")
        if exercise is not None:
            try:
                exercise.parameter(name)
            except DynagradeError as error:
                raise ExamSpecError(f"{at} ({exercise_id}), field 'set.{name}': "
                                    f"{error}") from None
        values[name] = float(value)
    return ExamExercise(exercise_id, float(points), values, line)


def _string(data, key, where, text, required) -> str:
    value = data.get(key)
    if value is None and not required:
        return ""
    if not isinstance(value, str) or (required and not value.strip()):
        raise ExamSpecError(f"{where}, line {_key_line(text, key)}, field {key!r}: "
                            f"{'missing' if value is None else repr(value)}; give a string")
    return value.strip()


def _date(value, where, line) -> str:
    if isinstance(value, dt.datetime):
        return value.date().isoformat()
    if isinstance(value, dt.date):
        return value.isoformat()
    if isinstance(value, str):
        with contextlib.suppress(ValueError):  # not ISO: reported below like any bad date
            return dt.date.fromisoformat(value.strip()).isoformat()
    raise ExamSpecError(f"{where}, line {line}, field 'date': "
                        f"{'missing' if value is None else repr(value)}; give a date "
                        "YYYY-MM-DD (it is printed on the sheets and dates the PDFs)")


def _exercise_lines(text: str) -> list[int]:
    """The line number of each ``[[exercise]]`` header, in order."""
    return [n for n, line in enumerate(text.splitlines(), 1)
            if re.match(r"^\s*\[\[\s*exercise\s*\]\]", line)]


def _key_line(text: str, key: str) -> str:
    """The line of the first top-level ``key = ...``, or '?'."""
    for n, line in enumerate(text.splitlines(), 1):
        if re.match(r"^\s*\[", line):
            break
        if re.match(rf"^\s*{re.escape(key)}\s*=", line):
            return str(n)
    return "?"


# -- roster.csv ---------------------------------------------------------------------------


def read_roster(path: str | Path) -> tuple[Student, ...]:
    """The students of the roster at ``path``, in file order."""
    path = Path(path)
    try:
        raw = path.read_bytes()
    except OSError as error:
        raise ExamSpecError(f"{path}: cannot read the roster ({error.strerror})") from None
    return parse_roster(raw, str(path))


def parse_roster(raw: bytes, where: str = "<roster>") -> tuple[Student, ...]:
    """The students of a roster given as bytes; ``where`` names it in errors."""
    if raw.startswith(b"\xef\xbb\xbf"):
        raise ExamSpecError(f"{where}, row 1: the file starts with a byte-order mark (as "
                            "Excel's 'CSV UTF-8' writes); save it as plain UTF-8 CSV")
    try:
        text = raw.decode("utf-8")
    except UnicodeDecodeError as error:
        line = raw[:error.start].count(b"\n") + 1
        raise ExamSpecError(f"{where}, row {line}: not UTF-8 text") from None
    rows = list(csv.reader(io.StringIO(text, newline="")))
    if not rows or not any(cell.strip() for cell in rows[0]):
        raise ExamSpecError(f"{where}: the roster is empty; it needs the header "
                            "student_id,name[,email] and one row per student")
    header = tuple(cell.strip() for cell in rows[0])
    if header not in ROSTER_HEADERS:
        wrong = next((i for i, (got, want) in enumerate(zip(header, ROSTER_HEADERS[1]))
                      if got != want), min(len(header), 3))
        raise ExamSpecError(f"{where}, row 1, column {wrong + 1}: the header is "
                            f"{','.join(header)!r}; it must be 'student_id,name' or "
                            "'student_id,name,email'")
    students: list[Student] = []
    seen: dict[str, int] = {}
    for number, row in enumerate(rows[1:], 2):
        if not any(cell.strip() for cell in row):
            continue
        if len(row) != len(header):
            raise ExamSpecError(f"{where}, row {number}: {len(row)} columns, the header has "
                                f"{len(header)}")
        cells = dict(zip(header, (cell.strip() for cell in row)))
        student_id = cells["student_id"]
        if not student_id:
            raise ExamSpecError(f"{where}, row {number}, column 1 (student_id): missing")
        if not _STUDENT_ID.match(student_id):
            raise ExamSpecError(f"{where}, row {number}, column 1 (student_id): "
                                f"{student_id!r} may hold only letters, digits, '.', '_' "
                                "and '-' (it names the student's files)")
        if student_id in seen:
            raise ExamSpecError(f"{where}, row {number}, column 1 (student_id): "
                                f"{student_id!r} is already on row {seen[student_id]}")
        seen[student_id] = number
        if not cells["name"]:
            raise ExamSpecError(f"{where}, row {number}, column 2 (name): missing")
        students.append(Student(student_id, cells["name"], cells.get("email", "")))
    if not students:
        raise ExamSpecError(f"{where}: the roster is empty (a header and no students)")
    return tuple(students)
