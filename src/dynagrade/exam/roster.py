"""Reading a roster as people save it: from Excel, Moodle, Canvas or by hand.

Accepted: UTF-8 with or without a byte-order mark (Excel's "CSV UTF-8"), ``,``, ``;``
(Excel in many European locales) or a tab as separator (the one the header row uses),
CRLF or LF line ends, and these column names (any case; ``docs/exams.md`` has the table):

============  ==========================================================================
field         column names, the first found wins
============  ==========================================================================
student id    ``student_id``, ``SIS User ID`` (Canvas), ``ID number`` (Moodle),
              ``Student number``, ``Matriculation number``, ``Matrikelnummer``
name          ``name``, ``Full name``, ``Student`` (Canvas), ``Student name``; or
              ``First name`` with ``Last name`` / ``Surname`` (Moodle)
email         ``email``, ``Email address`` (Moodle), ``E-mail``, ``Mail``
Moodle id     ``moodle_id``, ``Participant id``, ``Identifier`` (Moodle's grading
              worksheet: ``Participant 1234``); the number Moodle puts in the file names
              of an assignment's "Download all submissions"
Canvas id     ``canvas_id``, ``Canvas user id``; or ``ID`` beside ``SIS User ID`` (Canvas's
              gradebook export); the user id in Canvas's "Download Submissions" names
============  ==========================================================================

A platform id is optional for every student (empty: the student has none); where given it
is a whole number, and no two students share one.

Any other column is ignored and named in a notice. Refused, with file, row and column:
duplicate ids, an id that cannot be a folder name (only letters, digits, ``.``, ``_``,
``-``, starting with a letter or digit, not a Windows device name such as ``CON``), and
ids longer than :data:`MAX_ID_LENGTH` characters. A bare ``ID`` column is *not* taken as
the student id: in a Canvas export it is Canvas's internal number.
"""

from __future__ import annotations

import csv
import io
import re
from dataclasses import dataclass
from pathlib import Path

from ..errors import DynagradeError
from .csvcells import restored_rows
from ..exercise.datafile import DataFileError, read_data_file

MAX_ROSTER_BYTES = 20_000_000
MAX_ID_LENGTH = 64
_STUDENT_ID = re.compile(r"[A-Za-z0-9][A-Za-z0-9._-]*")
_DEVICE_NAMES = {"con", "prn", "aux", "nul", *(f"com{i}" for i in range(1, 10)),
                 *(f"lpt{i}" for i in range(1, 10))}

ID_COLUMNS = ("student_id", "sis user id", "id number", "student number",
              "matriculation number", "matrikelnummer")
NAME_COLUMNS = ("name", "full name", "student", "student name")
FIRST_NAME_COLUMNS = ("first name", "firstname", "given name")
LAST_NAME_COLUMNS = ("last name", "surname", "lastname", "family name")
EMAIL_COLUMNS = ("email", "email address", "e-mail", "mail")
SEPARATORS = (",", ";", "\t")
#: per learning platform, the columns of the id it names students by in its downloads
PLATFORM_COLUMNS = {"moodle": ("moodle_id", "participant id", "identifier"),
                    "canvas": ("canvas_id", "canvas user id")}
#: Canvas's gradebook export calls its user id just ``ID``, beside ``SIS User ID``
CANVAS_EXPORT_ID = ("id", "sis user id")
_PLATFORM_ID = re.compile(r"(?:[^\W\d_]\D*?)?(\d{1,18})")


class RosterError(DynagradeError, ValueError):
    """A roster that cannot be read; the message names file, row and column."""


@dataclass(frozen=True)
class Student:
    """A row of the roster."""

    student_id: str
    name: str
    email: str = ""
    #: ``(platform, id)`` pairs: the ids a learning platform names the student by
    platform_ids: tuple[tuple[str, str], ...] = ()

    def to_json(self) -> dict:
        return {"student_id": self.student_id, "name": self.name, "email": self.email}


@dataclass(frozen=True)
class Columns:
    """Which column (0-based) holds each field; ``extra`` are the ignored columns' names."""

    student_id: int
    name: tuple[int, ...]
    email: int | None
    extra: tuple[str, ...]
    platforms: tuple[tuple[str, int], ...] = ()


def read_roster(path: str | Path, notices: list[str] | None = None,
                error: type[Exception] = RosterError) -> tuple[Student, ...]:
    """The students of the roster at ``path``, in file order; notices (ignored columns)
    are appended to ``notices``."""
    path = Path(path)
    try:
        raw = read_data_file(path, MAX_ROSTER_BYTES)
    except DataFileError as problem:
        raise error(f"{path}: cannot read the roster ({problem})") from None
    return parse_roster(raw, str(path), notices, error)


def parse_roster(raw: bytes, where: str = "<roster>", notices: list[str] | None = None,
                 error: type[Exception] = RosterError) -> tuple[Student, ...]:
    """The students of a roster given as bytes; ``where`` names it in errors."""
    rows = csv_rows(raw, where, error)
    if not rows or not any(cell.strip() for cell in rows[0]):
        raise error(f"{where}: the roster is empty; it needs the header "
                    "student_id,name[,email] and one row per student")
    header = [cell.strip() for cell in rows[0]]
    columns = header_columns(header, where, error)
    if columns.extra and notices is not None:
        notices.append(f"{where}: the columns {', '.join(repr(c) for c in columns.extra)} "
                       "are not used")
    students = _students(rows, header, columns, where, error)
    if not students:
        raise error(f"{where}: the roster is empty (a header and no students)")
    return students


def csv_rows(raw: bytes, where: str, error: type[Exception] = RosterError) -> list[list[str]]:
    """The rows of a CSV file as people save it: UTF-8 with or without a byte-order mark,
    the separator its header row uses (``,``, ``;`` or a tab), CRLF or LF, each cell with
    the apostrophe that keeps a spreadsheet from running it dropped as dynagrade's own
    CSVs add it (:func:`~dynagrade.exam.csvcells.restored`); ``error`` (with ``where`` and
    the row) when it is not UTF-8 or not CSV."""
    try:
        text = raw.decode("utf-8-sig")
    except UnicodeDecodeError as problem:
        line = raw[:problem.start].count(b"\n") + 1
        raise error(f"{where}, row {line}: not UTF-8 text") from None
    first_line = text.split("\n", 1)[0]
    separator = max(SEPARATORS, key=first_line.count)
    try:
        return restored_rows(csv.reader(io.StringIO(text, newline=""), delimiter=separator))
    except csv.Error as problem:
        raise error(f"{where}: not a CSV file ({problem})") from None


def header_columns(header: list[str], where: str, error=RosterError) -> Columns:
    """Where the id, name and email are in ``header``."""
    lowered = [cell.lower() for cell in header]

    def first(names) -> int | None:
        return next((lowered.index(n) for n in names if n in lowered), None)

    student_id = first(ID_COLUMNS)
    name = first(NAME_COLUMNS)
    names = (name,) if name is not None else tuple(
        i for i in (first(FIRST_NAME_COLUMNS), first(LAST_NAME_COLUMNS)) if i is not None)
    if student_id is None or len(names) == 0:
        wanted = ID_COLUMNS if student_id is None else NAME_COLUMNS
        missing = next((i for i, cell in enumerate(lowered) if cell not in ID_COLUMNS
                        and cell not in NAME_COLUMNS), len(header))
        raise error(f"{where}, row 1, column {missing + 1}: the header is "
                    f"{','.join(header)!r}; it needs a column "
                    f"{'of student ids' if student_id is None else 'of names'} "
                    f"({', '.join(wanted)}), e.g. the header 'student_id,name' or "
                    "'student_id,name,email'")
    email = first(EMAIL_COLUMNS)
    platforms = tuple((platform, column) for platform, column in (
        (platform, first(names)) for platform, names in PLATFORM_COLUMNS.items())
        if column is not None)
    if "canvas" not in dict(platforms) and all(c in lowered for c in CANVAS_EXPORT_ID):
        platforms += (("canvas", lowered.index(CANVAS_EXPORT_ID[0])),)
    used = {student_id, *names, email, *(column for _, column in platforms)}
    extra = tuple(cell for i, cell in enumerate(header) if i not in used)
    return Columns(student_id, names, email, extra, platforms)


def _students(rows, header, columns: Columns, where: str, error) -> tuple[Student, ...]:
    students: list[Student] = []
    seen: dict[str, int] = {}
    taken: dict[tuple[str, str], int] = {}
    id_column = f"column {columns.student_id + 1} ({header[columns.student_id]})"
    for number, row in enumerate(rows[1:], 2):
        if not any(cell.strip() for cell in row):
            continue
        if len(row) != len(header):
            raise error(f"{where}, row {number}: {len(row)} columns, the header has "
                        f"{len(header)}")
        student_id = row[columns.student_id].strip()
        problem = id_problem(student_id)
        if problem:
            raise error(f"{where}, row {number}, {id_column}: {problem}")
        if student_id in seen:
            raise error(f"{where}, row {number}, {id_column}: {student_id!r} is already on "
                        f"row {seen[student_id]}")
        seen[student_id] = number
        name = " ".join(row[i].strip() for i in columns.name if row[i].strip())
        if not name:
            raise error(f"{where}, row {number}, column {columns.name[0] + 1} "
                        f"({header[columns.name[0]]}): missing")
        email = row[columns.email].strip() if columns.email is not None else ""
        platform_ids = tuple(_platform_ids(row, header, columns, number, where, error,
                                           taken))
        students.append(Student(student_id, name, email, platform_ids))
    return tuple(students)


def _platform_ids(row, header, columns: Columns, number: int, where: str, error,
                  taken: dict[tuple[str, str], int]):
    """The row's ``(platform, id)`` pairs; an id that is not a number, or that an earlier
    row already has, is an error naming row and column."""
    for platform, column in columns.platforms:
        cell = row[column].strip()
        if not cell:
            continue
        where_cell = f"{where}, row {number}, column {column + 1} ({header[column]})"
        match = _PLATFORM_ID.fullmatch(cell)
        if match is None:
            raise error(f"{where_cell}: {cell!r} is not a {platform.capitalize()} id (a "
                        "whole number, e.g. 1234 or 'Participant 1234')")
        key = (platform, str(int(match.group(1))))
        if key in taken:
            raise error(f"{where_cell}: {platform.capitalize()} id {key[1]} is already on "
                        f"row {taken[key]}")
        taken[key] = number
        yield key


def id_problem(student_id: str) -> str:
    """Why ``student_id`` cannot name a student's folder and files ("" when it can)."""
    if not student_id:
        return "missing"
    if len(student_id) > MAX_ID_LENGTH:
        return (f"{len(student_id)} characters is longer than the {MAX_ID_LENGTH} an id "
                "may have")
    if not _STUDENT_ID.fullmatch(student_id):
        return (f"{student_id!r} may hold only letters, digits, '.', '_' and '-', starting "
                "with a letter or digit (it names the student's folder and files)")
    if student_id.split(".")[0].lower() in _DEVICE_NAMES:
        return f"{student_id!r} cannot be a folder name on Windows"
    return ""
