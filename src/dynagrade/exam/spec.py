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

    [[exercise]]
    id = "sliding-up-a-slope"
    [exercise.points]                # optional: every part's points instead of a total
    delta_x = 3
    a_up = 1
    t_stop = 1
    delta_x_formula = 1

Points are rounded as the top-level ``round = 0.5`` (multiples of a step) or ``decimals =
2`` (the default) says; :mod:`.points` splits an exercise's points over its parts.

The roster: a CSV with the header ``student_id,name`` or ``student_id,name,email``, one
student per row, or as Excel, Moodle and Canvas save it (:mod:`.roster`).

Every error names the file, and the line and field (or row and column) at fault.
"""

from __future__ import annotations

import contextlib
import datetime as dt
import math
import re
import tomllib
from dataclasses import dataclass, field
from pathlib import Path
from typing import Callable

from ..errors import DynagradeError
from . import roster
from .points import Rounding
from .policy import POLICY_KEYS, Policy, PolicyError, read_policy
from .roster import Student

_EXAM_ID = re.compile(r"[a-z0-9]+(-[a-z0-9]+)*")  # fullmatch: `$` would take "x\n"
MAX_POINTS = 1000.0  # more for one exercise is a typo, and sums must stay exact
_TOP_KEYS = ({"id", "title", "date", "instructions", "language", "exercise", "round",
              "decimals"} | POLICY_KEYS)
MAX_DECIMALS = 6
_LANGUAGE = re.compile(r"[a-z]{2,3}(-[A-Za-z0-9]{2,8})*")
_EXERCISE_KEYS = {"id", "points", "set"}


class ExamSpecError(DynagradeError, ValueError):
    """A malformed exam specification or roster; the message says where and why."""


@dataclass(frozen=True)
class ExamExercise:
    """One exercise of the exam: its id, the points it is worth, fixed parameters and,
    when the exam gives them (``[exercise.points]``), every part's points by name."""

    id: str
    points: float
    set: dict[str, float] = field(default_factory=dict)
    line: int = 0
    part_points: dict[str, float] = field(default_factory=dict)


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
    secret: str = ""  # set by the generation; never on a sheet (not in to_json)
    rounding: Rounding = Rounding()  # `round = 0.5` or `decimals = 2` (the default)

    @property
    def mode(self) -> str:
        """"exam" (the default: fill-in files carry variant tokens, the self-check only
        reads) or "homework"/"practice" (seeds, full verdicts)."""
        return self.policy.mode

    @property
    def total_points(self) -> float:
        return self.rounding.total([e.points for e in self.exercises])

    def to_json(self) -> dict:
        return {"id": self.id, "title": self.title, "date": self.date,
                "instructions": self.instructions, "language": self.language,
                "mode": self.mode}


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
    if not _EXAM_ID.fullmatch(exam_id):
        raise ExamSpecError(f"{where}, line {_key_line(text, 'id')}, field 'id': {exam_id!r} "
                            "is not kebab-case (a-z, 0-9 and '-')")
    title = _string(data, "title", where, text, required=True)
    instructions = _string(data, "instructions", where, text, required=False)
    date = _date(data.get("date"), where, _key_line(text, "date"))
    language = data.get("language", "en")
    if not isinstance(language, str) or not _LANGUAGE.fullmatch(language):
        raise ExamSpecError(f"{where}, line {_key_line(text, 'language')}, field 'language': "
                            f"{language!r} is not a language tag; give e.g. \"en\" or \"de\"")

    rounding = _rounding(data, where, text)
    tables = data.get("exercise")
    if not isinstance(tables, list) or not tables:
        raise ExamSpecError(f"{where}: no [[exercise]] tables; an exam needs at least one")
    exercises = []
    seen: dict[str, int] = {}
    for index, table in enumerate(tables):
        line = lines[index] if index < len(lines) else 0
        at = f"{where}, line {line}, [[exercise]] #{index + 1}"
        exercises.append(_exercise(table, at, line, seen, known, rounding))
    try:
        policy = read_policy(data, where, lambda key: _key_line(text, key))
    except PolicyError as error:
        raise ExamSpecError(str(error)) from None
    return ExamSpec(exam_id, title, date, instructions, tuple(exercises), str(path), policy,
                    language, rounding=rounding)


def _rounding(data: dict, where: str, text: str) -> Rounding:
    """The exam's rounding of points: ``round = STEP`` or ``decimals = N`` (not both);
    hundredths when neither is given."""
    if "round" in data and "decimals" in data:
        raise ExamSpecError(f"{where}, line {_key_line(text, 'decimals')}: give 'round' or "
                            "'decimals', not both")
    if "round" in data:
        step = data["round"]
        if isinstance(step, bool) or not isinstance(step, (int, float)) \
                or not math.isfinite(step) or not 0 < step <= MAX_POINTS:
            raise ExamSpecError(f"{where}, line {_key_line(text, 'round')}, field 'round': "
                                f"{step!r}; give the step points are rounded to, e.g. 0.5")
        return Rounding(float(step))
    decimals = data.get("decimals", 2)
    if isinstance(decimals, bool) or not isinstance(decimals, int) \
            or not 0 <= decimals <= MAX_DECIMALS:
        raise ExamSpecError(f"{where}, line {_key_line(text, 'decimals')}, field 'decimals': "
                            f"{decimals!r}; give a whole number from 0 to {MAX_DECIMALS}")
    return Rounding.to_decimals(decimals)


def _exercise(table, at: str, line: int, seen: dict[str, int], known,
              rounding: Rounding = Rounding()) -> ExamExercise:
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
    part_points = {}
    if isinstance(points, dict):
        part_points = _part_points(points, f"{at} ({exercise_id})", exercise, rounding)
        points = rounding.total(list(part_points.values()))
    if isinstance(points, bool) or not isinstance(points, (int, float)) \
            or not math.isfinite(points) or not 0 < points <= MAX_POINTS:
        raise ExamSpecError(f"{at} ({exercise_id}), field 'points': "
                            f"{'missing' if points is None else repr(points)}; "
                            f"give a positive number up to {MAX_POINTS:g}, or a table "
                            "[exercise.points] of every part's points")
    if not rounding.is_multiple(points):
        raise ExamSpecError(f"{at} ({exercise_id}), field 'points': {points:g} cannot be split "
                            f"into the exam's rounding ({rounding.describe()}); give a "
                            "multiple of it or change 'round'/'decimals'")
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
                parameter = exercise.parameter(name)
            except DynagradeError as error:
                raise ExamSpecError(f"{at} ({exercise_id}), field 'set.{name}': "
                                    f"{error}") from None
            outside = domain_problem(parameter, float(value))
            if outside:
                raise ExamSpecError(f"{at} ({exercise_id}), field 'set.{name}': {outside}")
        values[name] = float(value)
    return ExamExercise(exercise_id, float(points), values, line, part_points)


def _part_points(table: dict, at: str, exercise, rounding: Rounding) -> dict[str, float]:
    """``[exercise.points]``: every part of the exercise (when known) with its points, a
    non-negative multiple of the exam's rounding step."""
    given = {}
    for name, value in table.items():
        if isinstance(value, bool) or not isinstance(value, (int, float)) \
                or not math.isfinite(value) or not 0 <= value <= MAX_POINTS:
            raise ExamSpecError(f"{at}, field 'points.{name}': {value!r}; give the part's "
                                f"points, a number from 0 to {MAX_POINTS:g}")
        if not rounding.is_multiple(value):
            raise ExamSpecError(f"{at}, field 'points.{name}': {value:g} is not one of the "
                                f"exam's {rounding.describe()}")
        given[name] = float(value)
    if exercise is not None:
        names = [part.name for part in exercise.parts]
        unknown = [name for name in given if name not in names]
        if unknown:
            raise ExamSpecError(f"{at}, field 'points.{unknown[0]}': the exercise has no "
                                f"part {unknown[0]!r}; its parts are {', '.join(names)}")
        missing = [name for name in names if name not in given]
        if missing:
            raise ExamSpecError(f"{at}, field 'points': give every part's points; missing "
                                f"{', '.join(missing)}")
        given = {name: given[name] for name in names}
    return given


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


def domain_problem(parameter, value: float) -> str:
    """Why ``value`` (in the parameter's unit) cannot be set for ``parameter`` ("" when it
    can): outside the parameter's physical domain (``g > 0``, ``0 ≤ e ≤ 1``, ...)."""
    domain = getattr(parameter, "allowed", None)
    if domain is None or value in domain:
        return ""
    return (f"{value:g} is outside the parameter's physical domain "
            f"({domain.describe(parameter.name)})")


# -- roster.csv ---------------------------------------------------------------------------


def read_roster(path: str | Path, notices: list[str] | None = None) -> tuple[Student, ...]:
    """The students of the roster at ``path`` (:mod:`.roster` says what is accepted);
    notices about ignored columns are appended to ``notices``."""
    return roster.read_roster(path, notices, ExamSpecError)


def parse_roster(raw: bytes, where: str = "<roster>",
                 notices: list[str] | None = None) -> tuple[Student, ...]:
    """The students of a roster given as bytes; ``where`` names it in errors."""
    return roster.parse_roster(raw, where, notices, ExamSpecError)
