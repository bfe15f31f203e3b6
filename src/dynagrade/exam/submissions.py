"""Collecting a class's submissions for an exam, checking each against the manifest.

A submission is a filled-in fill-in file (read with :mod:`ast`, never run), a folder of
them (searched recursively for ``*.py`` and ``*.csv``) or a CSV file of responses with the header
``student_id,exercise_id,part,answer``. Arguments are taken in command-line order and a
folder's files in path order; when one student's exercise arrives twice, the later one
wins and a warning says which file replaced which.

Nothing here raises for a bad submission: corrupt files, sheets of another exam or
another student's variant, exercises not in the exam and students not on the roster are
reported as :class:`Problem` and skipped.
"""

from __future__ import annotations

import csv
import io
from dataclasses import dataclass, field
from pathlib import Path

from ..exercise.sheet import MAX_SHEET_BYTES, SheetError, read_sheet
from .manifest import Manifest

RESPONSE_HEADER = ("student_id", "exercise_id", "part", "answer")
MAX_CSV_BYTES = 50_000_000


@dataclass(frozen=True)
class Problem:
    """Something wrong with a submission; ``level`` is "error" (skipped) or "warning"."""

    level: str
    source: str
    message: str
    student_id: str = ""
    exercise_id: str = ""

    def to_row(self) -> list[str]:
        return [self.level, self.source, self.student_id, self.exercise_id, self.message]


@dataclass
class Submission:
    """One student's answers to one exercise of the exam."""

    source: str
    student_id: str
    exercise_id: str
    answers: dict[str, str | None]
    problems: dict[str, str] = field(default_factory=dict)


class _Exam:
    """What the checks need from the manifest."""

    def __init__(self, manifest: Manifest):
        self.students = {s.student_id: s for s in manifest.students}
        self.seeds = {(s.student_id, v.exercise): v.seed
                      for s in manifest.students for v in s.variants}
        self.parts = {e.id: [p.name for p in e.parts] for e in manifest.exercises}
        self.exam_id = manifest.exam.id


def expand(paths) -> list[Path]:
    """Files to read, in command-line order, each folder's ``*.py`` and ``*.csv`` files in
    path order."""
    files = []
    for path in paths:
        path = Path(path)
        if path.is_dir():
            files += sorted(p for p in path.rglob("*")
                            if p.suffix.lower() in (".py", ".csv") and p.is_file()
                            and "__pycache__" not in p.parts and not p.name.startswith("."))
        else:
            files.append(path)
    return files


def collect(paths, manifest: Manifest) -> tuple[dict[tuple[str, str], Submission], list[Problem]]:
    """The submission that counts for each (student, exercise), and every problem found."""
    exam = _Exam(manifest)
    problems: list[Problem] = []
    chosen: dict[tuple[str, str], Submission] = {}
    for path in expand(paths):
        if path.suffix.lower() == ".csv":
            found = _read_responses(path, exam, problems)
        else:
            found = _read_sheet(path, exam, problems)
        for submission in found:
            key = (submission.student_id, submission.exercise_id)
            if key in chosen:
                problems.append(Problem(
                    "warning", submission.source,
                    f"duplicate: replaces {chosen[key].source} for {submission.exercise_id} "
                    "(the later submission counts)", *key))
            chosen[key] = submission
    return chosen, problems


def _read_sheet(path: Path, exam: _Exam, problems: list[Problem]) -> list[Submission]:
    source = str(path)
    try:
        sheet = read_sheet(path)
    except SheetError as error:
        problems.append(Problem("error", source, f"corrupt, skipped: {error}"))
        return []
    if not sheet.student:
        problems.append(Problem("error", source, "skipped: the sheet names no STUDENT",
                                exercise_id=sheet.exercise_id))
        return []
    if sheet.student not in exam.students:
        problems.append(Problem("error", source, f"skipped: student {sheet.student!r} is not "
                                "on the exam's roster", sheet.student, sheet.exercise_id))
        return []
    if sheet.exercise_id not in exam.parts:
        problems.append(Problem("error", source, f"foreign, skipped: exercise "
                                f"{sheet.exercise_id!r} is not in exam {exam.exam_id!r}",
                                sheet.student, sheet.exercise_id))
        return []
    expected_seed = exam.seeds[(sheet.student, sheet.exercise_id)]
    if sheet.seed != expected_seed:
        problems.append(Problem("error", source, f"foreign, skipped: SEED {sheet.seed} is not "
                                f"the variant of {sheet.student} in exam {exam.exam_id!r} "
                                f"(that is SEED {expected_seed}); a sheet of another exam "
                                "or student?", sheet.student, sheet.exercise_id))
        return []
    unknown = [n for n in sheet.answers if n not in exam.parts[sheet.exercise_id]]
    for name in unknown:
        problems.append(Problem("warning", source, f"no part named {name!r} in "
                                f"{sheet.exercise_id}; ignored", sheet.student,
                                sheet.exercise_id))
    answers = {k: v for k, v in sheet.answers.items() if k not in unknown}
    return [Submission(source, sheet.student, sheet.exercise_id, answers,
                       {k: v for k, v in sheet.problems.items() if k not in unknown})]


def _read_responses(path: Path, exam: _Exam, problems: list[Problem]) -> list[Submission]:
    source = str(path)
    try:
        raw = path.read_bytes()
    except OSError as error:
        problems.append(Problem("error", source, f"cannot read, skipped: {error.strerror}"))
        return []
    if len(raw) > MAX_CSV_BYTES:
        problems.append(Problem("error", source, "corrupt, skipped: too large"))
        return []
    if raw.startswith(b"\xef\xbb\xbf"):
        raw = raw[3:]
        problems.append(Problem("warning", source, "starts with a byte-order mark; read "
                                "as UTF-8"))
    try:
        text = raw.decode("utf-8")
    except UnicodeDecodeError as error:
        row = raw[:error.start].count(b"\n") + 1
        problems.append(Problem("error", f"{source}, row {row}",
                                "corrupt, skipped: not UTF-8 text"))
        return []
    try:
        rows = list(csv.reader(io.StringIO(text, newline="")))
    except csv.Error as error:
        problems.append(Problem("error", source, f"corrupt, skipped: {error}"))
        return []
    if not rows or tuple(c.strip() for c in rows[0]) != RESPONSE_HEADER:
        got = ",".join(rows[0]) if rows else "nothing"
        problems.append(Problem("error", f"{source}, row 1", f"corrupt, skipped: the header "
                                f"is {got!r}, not {','.join(RESPONSE_HEADER)!r}"))
        return []
    grouped: dict[tuple[str, str], Submission] = {}
    seen_rows: dict[tuple[str, str, str], int] = {}
    for number, row in enumerate(rows[1:], 2):
        where = f"{source}, row {number}"
        if not any(cell.strip() for cell in row):
            continue
        if len(row) != 4:
            problems.append(Problem("error", where, f"skipped: {len(row)} columns, not 4"))
            continue
        student_id, exercise_id, part, answer = (cell.strip() for cell in row)
        if student_id not in exam.students:
            problems.append(Problem("error", where, f"skipped: student {student_id!r} is not "
                                    "on the exam's roster", student_id, exercise_id))
            continue
        if exercise_id not in exam.parts:
            problems.append(Problem("error", where, f"foreign, skipped: exercise "
                                    f"{exercise_id!r} is not in exam {exam.exam_id!r}",
                                    student_id, exercise_id))
            continue
        if part not in exam.parts[exercise_id]:
            problems.append(Problem("warning", where, f"no part named {part!r} in "
                                    f"{exercise_id}; ignored", student_id, exercise_id))
            continue
        if len(answer) > MAX_SHEET_BYTES:
            problems.append(Problem("error", where, "skipped: the answer is too long",
                                    student_id, exercise_id))
            continue
        key = (student_id, exercise_id, part)
        if key in seen_rows:
            problems.append(Problem("warning", where, f"duplicate: replaces row "
                                    f"{seen_rows[key]} for part {part!r} (the later row "
                                    "counts)", student_id, exercise_id))
        seen_rows[key] = number
        submission = grouped.setdefault((student_id, exercise_id),
                                        Submission(source, student_id, exercise_id, {}))
        submission.answers[part] = answer or None
    return list(grouped.values())
