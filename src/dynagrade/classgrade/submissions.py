"""Collecting a class's submissions for an exam, checking each against the manifest.

A submission is a filled-in fill-in file (read with :mod:`ast`, never run) or a CSV file
of responses with the header ``student_id,exercise_id,part,answer``, found in the folders
and files given (folders are searched recursively for ``*.py`` and ``*.csv``). A
responses file may carry every attempt, as the server's ``submissions.csv`` does: then
its header goes on with ``attempt,submitted_at,counts`` and only the rows whose
``counts`` is ``yes`` are graded (the others are the history of earlier attempts).

Whose it is comes from **where it was found**, never from what it says (see
:mod:`.layouts`): a fill-in file belongs to the student whose folder holds it, and one
whose ``STUDENT`` line names somebody else is rejected as impersonating and credited to
nobody. A CSV in a student's folder may hold only that student's rows; a CSV outside any
student's folder is the staff's own export and its ``student_id`` column is trusted.

A platform's bulk download (a Moodle or Canvas ``.zip``, :mod:`.downloads`) may stand in
for a folder: each file belongs to the roster student whose platform id is in its name.

When one student's exercise arrives twice, the one modified last counts (path order
breaks ties) and a warning names both files; in a platform's download, where times say
nothing, neither counts and both are reported.

Files are data: links are not followed out of the folder given, only regular files are
read (size checked first), devices and FIFOs are reported, and a message never quotes a
file's content beyond the fields dynagrade itself writes.

Nothing here raises for a bad submission: corrupt files, sheets of another exam or
another student's variant, exercises not in the exam and students not on the roster are
reported as :class:`Problem` (naming the student and exercise wherever known) and skipped.
"""

from __future__ import annotations

import csv
import io
import os
import stat
from dataclasses import dataclass, field
from pathlib import Path

from ..exercise.datafile import DataFileError, file_kind, read_data_file
from ..exercise.seeds import token_matches, variant_token
from ..exercise.sheet import MAX_SHEET_BYTES, Sheet, SheetError, read_sheet, sheet_from_bytes
from .downloads import MAX_CSV_BYTES, Identities, identities, read_download
from .layouts import owner
from ..exam.csvcells import restored_rows
from ..exam.manifest import Manifest

RESPONSE_HEADER = ("student_id", "exercise_id", "part", "answer")
#: the columns a responses file of every attempt adds (the server's ``submissions.csv``)
ATTEMPT_COLUMNS = ("attempt", "submitted_at", "counts")


@dataclass(frozen=True)
class Problem:
    """Something wrong with a submission; ``level`` is "error" (skipped) or "warning"."""

    level: str
    source: str
    message: str
    student_id: str = ""
    exercise_id: str = ""
    handed_in_by: bool = True  # False: student_id is only what the file claims


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
        self.secret = manifest.exam.secret

    def is_variant(self, sheet: Sheet, student_id: str) -> bool:
        """Whether ``sheet`` is the variant the exam gave ``student_id``: its token
        authenticates it (exam sheets), or its seed is the student's (others)."""
        seed = self.seeds[(student_id, sheet.exercise_id)]
        if sheet.token is not None:
            return self.secret is not None and token_matches(sheet.token, variant_token(
                self.secret, self.exam_id, student_id, sheet.exercise_id, seed))
        return sheet.seed == seed


@dataclass(frozen=True)
class Found:
    """A file among the submissions: where, whose folder it was in, and its order; a
    file of a platform's download also carries its bytes (it is never written out)."""

    path: Path
    owner: str | None
    modified: int  # st_mtime_ns
    order: int
    content: bytes | None = None

    @property
    def downloaded(self) -> bool:
        """Whether the file came out of a platform's download."""
        return self.content is not None


SUFFIXES = (".py", ".csv")


def walk(paths, roster, problems: list[Problem], people: Identities | None = None,
         platform: str | None = None, exercise_ids=()) -> list[Found]:
    """Every submission file in ``paths`` with its owner (:mod:`.layouts`, or for a
    platform's ``.zip`` download the roster's platform ids in ``people``); what cannot be
    a submission (a link out of the folder, a device, a FIFO) is reported."""
    found: list[Found] = []
    for argument in paths:
        argument = Path(argument)
        if argument.suffix.lower() == ".zip" and not argument.is_dir():
            found += _download_files(argument, people, platform, problems, len(found),
                                     exercise_ids)
        elif argument.is_dir() and not argument.is_symlink():
            for path in _folder_files(argument, problems):
                parts = (argument.resolve().name, *path.relative_to(argument).parts)
                found.append(_found(path, owner(parts, roster), len(found)))
        else:
            parts = (argument.absolute().parent.name, argument.name)
            found.append(_found(argument, owner(parts, roster), len(found)))
    return found


def _download_files(archive: Path, people: Identities | None, platform: str | None,
                    problems: list[Problem], start: int, exercise_ids=()) -> list[Found]:
    """The files of a platform's download, each with its student; every entry refused or
    unmatched is reported, with the exercise its file name points to (so that a student's
    feedback says what was handed in and not graded)."""
    found: list[Found] = []
    for entry in read_download(archive, people, platform):
        source = archive / entry.name
        if entry.problem:
            named = next((e for e in exercise_ids if e in source.name), "")
            problems.append(Problem(entry.level, str(source), entry.problem,
                                    entry.student_id or "", named))
        else:
            found.append(Found(source, entry.student_id, 0, start + len(found), entry.content))
    return found


def _found(path: Path, whose: str | None, order: int) -> Found:
    try:
        modified = os.stat(path).st_mtime_ns
    except OSError:
        modified = 0
    return Found(path, whose, modified, order)


def _folder_files(folder: Path, problems: list[Problem]) -> list[Path]:
    """The regular ``*.py``/``*.csv`` files under ``folder`` in path order, and links that
    stay inside it; every other kind of entry is reported."""
    root = folder.resolve()
    files = []
    for directory, folders, names in os.walk(folder, followlinks=False):
        folders[:] = sorted(f for f in folders if not f.startswith(".") and f != "__pycache__")
        for name in folders:
            if os.path.islink(os.path.join(directory, name)):
                problems.append(Problem("error", os.path.join(directory, name),
                                        "skipped: a link to a folder is not followed"))
        for name in sorted(names):
            path = Path(directory) / name
            if name.startswith("."):
                continue
            mode = os.lstat(path).st_mode
            if stat.S_ISLNK(mode):
                target = path.resolve()
                if not target.is_relative_to(root) or not target.is_file():
                    problems.append(Problem("error", str(path), "skipped: a link to a file "
                                            "outside the submissions folder is not followed"))
                    continue
            elif not stat.S_ISREG(mode):
                problems.append(Problem("error", str(path), f"skipped: {file_kind(mode)} is "
                                        "not a submission"))
                continue
            if path.suffix.lower() in SUFFIXES:
                files.append(path)
    return files


def collect(paths, manifest: Manifest, roster=None,
            platform: str | None = None) -> tuple[dict[tuple[str, str], Submission], list[Problem]]:
    """The submission that counts for each (student, exercise), and every problem found.
    ``roster`` (a roster file with platform id columns) maps the students of a
    platform's download; ``platform`` says which platform made it (default: detected)."""
    exam = _Exam(manifest)
    problems: list[Problem] = []
    accepted: dict[tuple[str, str], list[tuple[Found, Submission]]] = {}
    people = identities(roster, exam.students) if roster is not None else None
    for found in walk(paths, exam.students, problems, people, platform, list(exam.parts)):
        if found.path.suffix.lower() == ".csv":
            submissions = _read_responses(found, exam, problems)
        else:
            submissions = _read_sheet(found, exam, problems)
        for submission in submissions:
            accepted.setdefault((submission.student_id, submission.exercise_id),
                                []).append((found, submission))
    chosen = {}
    for key, candidates in accepted.items():
        if len(candidates) > 1 and any(found.downloaded for found, _ in candidates):
            problems += _two_in_a_download(key, [s for _, s in candidates])
            continue
        candidates.sort(key=lambda pair: (pair[0].modified, pair[0].order))
        for (_, earlier), (_, later) in zip(candidates, candidates[1:]):
            problems.append(Problem(
                "warning", later.source,
                f"duplicate: replaces {earlier.source} for {key[1]} (the one modified "
                "last counts; path order breaks a tie)", *key))
        chosen[key] = candidates[-1][1]
    return chosen, problems


def _two_in_a_download(key: tuple[str, str], submissions: list[Submission]) -> list[Problem]:
    """A student's exercise handed in more than once in a platform's download: which one
    counts cannot be told (the download's times are not the hand-in times), so none does
    and each is reported."""
    sources = [s.source for s in submissions]
    return [Problem("error", source, f"two files for {key[1]}, not graded: "
                    f"{', '.join(Path(other).name for other in sources if other != source)} "
                    "also answers it; keep the one that counts and grade again", *key)
            for source in sources]


def _guess_exercise(path: Path, exam: _Exam) -> str:
    """The exam exercise a file's name points to (``projectile-range.py``), or ""."""
    return next((e for e in exam.parts if path.stem.endswith(e)), "")


def _read_sheet(found: Found, exam: _Exam, problems: list[Problem]) -> list[Submission]:
    path, whose = found.path, found.owner or ""
    source = str(path)
    try:
        sheet = (sheet_from_bytes(found.content, source) if found.content is not None
                 else read_sheet(path))
    except SheetError as error:
        problems.append(Problem("error", source, "corrupt, skipped: "
                                + _without_path(error, path), whose,
                                _guess_exercise(path, exam)))
        return []
    named = sheet.student or ""
    exercise_id = sheet.exercise_id if sheet.exercise_id in exam.parts else ""
    if not whose:
        problems.append(Problem("error", source, "skipped: not in the folder of a student on "
                                "the roster, so whose it is cannot be told (put each "
                                "student's files in a folder named by their id)"
                                + (f"; it names STUDENT {named!r}" if named else ""),
                                named, exercise_id, handed_in_by=False))
        return []
    if named and named != whose:
        problems.append(Problem("error", source, f"impersonating, skipped: found in the "
                                f"folder of {whose} but names STUDENT {named!r}; credited "
                                "to nobody", whose, exercise_id))
        return []
    if not exercise_id:
        problems.append(Problem("error", source, "foreign, skipped: its exercise is not in "
                                f"exam {exam.exam_id!r}", whose))
        return []
    if not exam.is_variant(sheet, whose):
        problems.append(Problem("error", source, f"foreign, skipped: not the variant of "
                                f"{whose} in exam {exam.exam_id!r}; a sheet of another "
                                "exam or student?", whose, exercise_id))
        return []
    for note in sheet.notes:
        problems.append(Problem("warning", source, note, whose, exercise_id))
    unknown = [n for n in sheet.answers if n not in exam.parts[exercise_id]]
    for name in unknown:
        problems.append(Problem("warning", source, f"no part named {name!r} in "
                                f"{exercise_id}; ignored", whose, exercise_id))
    answers = {k: v for k, v in sheet.answers.items() if k not in unknown}
    return [Submission(source, whose, exercise_id, answers,
                       {k: v for k, v in sheet.problems.items() if k not in unknown})]


def _without_path(error: Exception, path: Path) -> str:
    """An error's message without the path it starts with (the source column has it)."""
    return str(error).removeprefix(f"{path}: ").removeprefix(f"{path}")


def _read_responses(found: Found, exam: _Exam, problems: list[Problem]) -> list[Submission]:
    source, whose = str(found.path), found.owner or ""
    try:
        raw = (found.content if found.content is not None
               else read_data_file(found.path, MAX_CSV_BYTES))
    except DataFileError as error:
        problems.append(Problem("error", source, f"corrupt, skipped: {error}", whose))
        return []
    try:
        text = raw.decode("utf-8-sig")
    except UnicodeDecodeError as error:
        row = raw[:error.start].count(b"\n") + 1
        problems.append(Problem("error", f"{source}, row {row}",
                                "corrupt, skipped: not UTF-8 text", whose))
        return []
    try:
        rows = restored_rows(csv.reader(io.StringIO(text, newline="")))
    except csv.Error:
        problems.append(Problem("error", source, "corrupt, skipped: not a CSV file", whose))
        return []
    header = tuple(c.strip() for c in rows[0]) if rows else ()
    if header not in (RESPONSE_HEADER, RESPONSE_HEADER + ATTEMPT_COLUMNS):
        problems.append(Problem("error", f"{source}, row 1", "corrupt, skipped: not a "
                                "responses file (its first row is not the header "
                                f"{','.join(RESPONSE_HEADER)})", whose))
        return []
    return _response_rows(source, rows, found.owner, exam, problems)


def _response_rows(source: str, rows: list[list[str]], whose: str | None, exam: _Exam,
                   problems: list[Problem]) -> list[Submission]:
    """The submissions in a responses CSV's rows (of a file of every attempt, the rows
    that count); in a student's folder, only theirs."""
    grouped: dict[tuple[str, str], Submission] = {}
    seen_rows: dict[tuple[str, str, str], int] = {}
    width = len(rows[0])
    for number, row in enumerate(rows[1:], 2):
        where = f"{source}, row {number}"
        if not any(cell.strip() for cell in row):
            continue
        if len(row) != width:
            problems.append(Problem("error", where, f"skipped: {len(row)} columns, not "
                                    f"{width}", whose or ""))
            continue
        counts = row[width - 1].strip().lower() if width > len(RESPONSE_HEADER) else "yes"
        if counts == "no":
            continue  # an attempt that does not count: history, not graded
        if counts != "yes":
            problems.append(Problem("error", where, "skipped: 'counts' must be yes or no",
                                    whose or ""))
            continue
        student_id, exercise_id, part, answer = (cell.strip() for cell in row[:4])
        if whose and student_id != whose:
            problems.append(Problem("error", where, f"impersonating, skipped: found in the "
                                    f"folder of {whose} but names student {student_id!r}; "
                                    "credited to nobody", whose, exercise_id))
            continue
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
