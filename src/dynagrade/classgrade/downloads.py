"""A learning platform's bulk download of an assignment's submissions, read as it comes.

Two downloads are read, each a zip whose entry names say whose a file is:

- **Moodle**, an assignment's "Download all submissions": ``<full name>_<participant
  id>_assignsubmission_file/<file>`` (with "Download submissions in folders", the
  default; Moodle before 4.1 ends the folder with ``_``) or, without folders,
  ``<full name>_<participant id>_assignsubmission_file_<file>``. The participant id is
  the assignment's own number for the student (the ``Identifier`` column of its grading
  worksheet, ``Participant 1234``); with blind marking the name is ``Participant``.
- **Canvas**, an assignment's "Download Submissions": ``<lastfirst>_<user id>_<submission
  id>_<original name>``, with ``late`` after the name for a late submission
  (``smithanna_late_1234_5678_projectile-range.py``) and ``-1``, ``-2`` ... at the end of
  the original name of a resubmitted file.

A file belongs to the roster student whose platform id (:mod:`dynagrade.exam.roster`: ``moodle_id``,
``canvas_id``) is the one in its name, never to a name written in it or a name that
merely looks alike. A file whose name is not the platform's pattern or whose id is on no
roster row is *unmatched*: reported, credited to nobody.

The zip is data, like a submissions folder: it is never extracted to disk (entries are
read into memory, only ``*.py`` and ``*.csv``, the same size limits as files in a folder),
links and encrypted entries are refused, a name that climbs out (``..``, an absolute path)
is refused, and the archive as a whole is bounded (:data:`MAX_ENTRIES` entries,
:data:`MAX_TOTAL_BYTES` read, no entry expanding more than :data:`MAX_RATIO` times), so a
zip bomb costs a message, not the machine.
"""

from __future__ import annotations

import os
import re
import stat
import zipfile
import zlib
from dataclasses import dataclass
from pathlib import Path, PurePosixPath
from typing import Callable

from ..errors import DynagradeError
from ..exercise.datafile import file_kind
from ..exercise.sheet import MAX_SHEET_BYTES
from ..exam.roster import read_roster

PLATFORMS = ("moodle", "canvas")
#: an archive with more entries than this is refused whole
MAX_ENTRIES = 20_000
#: the most bytes read out of one archive, all entries together
MAX_TOTAL_BYTES = 500_000_000
#: an entry that expands more than this many times (and beyond 1 MB) is a zip bomb
MAX_RATIO = 200
#: the largest responses CSV read, in a submissions folder or a download
MAX_CSV_BYTES = 50_000_000
#: the limit of one entry, by suffix: as for a file in a submissions folder
ENTRY_LIMITS = {".py": MAX_SHEET_BYTES, ".csv": MAX_CSV_BYTES}
#: the largest zip file read at all
MAX_ARCHIVE_BYTES = 2_000_000_000

_MOODLE = re.compile(r"(?P<name>[^/]*)_(?P<id>\d+)_assignsubmission_[a-z0-9]+"
                     r"(?:_?/(?P<inner>.+)|_(?P<flat>[^/]+))")
_CANVAS = re.compile(r"(?P<name>[^/_]*?)(?:_(?P<late>late))?_(?P<id>\d+)_\d+_(?P<file>[^/]+)",
                     re.IGNORECASE)


class DownloadError(DynagradeError, ValueError):
    """A download that cannot be read at all; the message names the file and why."""


@dataclass(frozen=True)
class EntryName:
    """What a platform's entry name says: the student's platform id, the name shown with
    it, and the handed-in file's own name."""

    identifier: str
    name: str
    file: str
    late: bool = False


def moodle_entry(name: str) -> EntryName | None:
    """The parts of a Moodle "Download all submissions" entry name, or None."""
    match = _MOODLE.fullmatch(name)
    if match is None:
        return None
    inner = match["inner"] or match["flat"]
    return EntryName(str(int(match["id"])), match["name"], PurePosixPath(inner).name)


def canvas_entry(name: str) -> EntryName | None:
    """The parts of a Canvas "Download Submissions" entry name, or None."""
    match = _CANVAS.fullmatch(name)
    if match is None:
        return None
    return EntryName(str(int(match["id"])), match["name"], match["file"],
                     late=match["late"] is not None)


READERS: dict[str, Callable[[str], EntryName | None]] = {
    "moodle": moodle_entry, "canvas": canvas_entry}


def detect_platform(names: list[str], where: str) -> str:
    """The platform whose naming the entries follow; an error when none or both do."""
    counts = {p: sum(READERS[p](n) is not None for n in names) for p in PLATFORMS}
    matching = [p for p in PLATFORMS if counts[p]]
    if len(matching) == 1:
        return matching[0]
    if not matching:
        raise DownloadError(f"{where}: no entry is named as Moodle's or Canvas's submission "
                            "downloads name them; is it a platform's download?")
    raise DownloadError(f"{where}: entries are named both as Moodle ({counts['moodle']}) "
                        f"and as Canvas ({counts['canvas']}) name them; say which with "
                        "--platform moodle or --platform canvas")


@dataclass(frozen=True)
class Identities:
    """Per platform, which roster student each platform id belongs to, and each
    student's name (to point out a download whose name differs from the roster's)."""

    students: dict[str, dict[str, str]]
    names: dict[str, str]
    roster: str = "the roster"

    def student(self, platform: str, identifier: str) -> str | None:
        return self.students.get(platform, {}).get(identifier)


def identities(roster_path, student_ids) -> Identities:
    """The platform ids of the roster at ``roster_path`` for the students in
    ``student_ids`` (the exam's; a roster row of anybody else maps to nobody)."""
    roster = read_roster(roster_path, error=DownloadError)
    wanted = set(student_ids)
    students: dict[str, dict[str, str]] = {p: {} for p in PLATFORMS}
    for student in roster:
        if student.student_id in wanted:
            for platform, identifier in student.platform_ids:
                students[platform][identifier] = student.student_id
    return Identities(students, {s.student_id: s.name for s in roster}, str(roster_path))


@dataclass(frozen=True)
class Entry:
    """A file of the download: its entry name, the roster student it belongs to, its
    bytes; or, when it cannot be taken, why (``problem``, with ``level``)."""

    name: str
    student_id: str | None = None
    content: bytes | None = None
    problem: str = ""
    level: str = "error"


def read_download(path, people: Identities | None, platform: str | None) -> list[Entry]:
    """The ``*.py``/``*.csv`` files of the download at ``path``, each with its student,
    and every entry refused or unmatched with the reason. A file that is not a readable
    zip, or one past the archive's bounds, is a :class:`DownloadError`."""
    path = Path(path)
    where = str(path)
    try:
        with _open_regular(path) as handle, zipfile.ZipFile(handle) as archive:
            infos = archive.infolist()
            if len(infos) > MAX_ENTRIES:
                raise DownloadError(f"{where}: {len(infos)} entries, more than the "
                                    f"{MAX_ENTRIES} a download is read with")
            files = [i for i in infos if not i.is_dir() and not _hidden(i.filename)]
            if people is None:
                raise DownloadError(f"{where}: a platform's download names students by "
                                    "the platform's id; give --roster with a moodle_id or "
                                    "canvas_id column (docs/exams.md, Platform downloads)")
            platform = platform or detect_platform([i.filename for i in files], where)
            if not people.students[platform]:
                column = "moodle_id" if platform == "moodle" else "canvas_id"
                raise DownloadError(f"{where}: a {platform.capitalize()} download, but "
                                    f"{people.roster} gives no exam student a "
                                    f"{platform.capitalize()} id; add a {column} column "
                                    "(docs/exams.md, Platform downloads)")
            return _entries(archive, files, people, platform, where)
    except (zipfile.BadZipFile, zipfile.LargeZipFile, OSError, EOFError) as error:
        raise DownloadError(f"{where}: not a readable zip file ({error})") from None


def _open_regular(path: Path):
    """The zip opened for reading, when it is a regular file of bounded size (not a FIFO
    or a device, which a zip reader would wait on or read forever)."""
    flags = os.O_RDONLY | getattr(os, "O_NONBLOCK", 0) | getattr(os, "O_NOCTTY", 0)
    try:
        descriptor = os.open(path, flags)
    except OSError as error:
        raise DownloadError(f"{path}: cannot read the download ({error.strerror})") from None
    handle = os.fdopen(descriptor, "rb")
    status = os.fstat(descriptor)
    problem = (f"it is {file_kind(status.st_mode)}, not a regular file"
               if not stat.S_ISREG(status.st_mode) else
               f"{status.st_size} bytes is too large (the limit is {MAX_ARCHIVE_BYTES})"
               if status.st_size > MAX_ARCHIVE_BYTES else "")
    if problem:
        handle.close()
        raise DownloadError(f"{path}: cannot read the download ({problem})")
    return handle


def _hidden(name: str) -> bool:
    """Entries that are an archiver's own, not a submission (``__MACOSX/``, dot files)."""
    return any(part == "__MACOSX" or (part.startswith(".") and part not in (".", ".."))
               for part in PurePosixPath(name).parts)


def _entries(archive: zipfile.ZipFile, infos, people: Identities, platform: str,
             where: str) -> list[Entry]:
    read = READERS[platform]
    label = platform.capitalize()
    total = 0
    entries = []
    for info in infos:
        name = info.filename
        refused = _refusal(info)
        if refused:
            entries.append(Entry(name, problem=f"refused: {refused}"))
            continue
        limit = ENTRY_LIMITS.get(PurePosixPath(name).suffix.lower())
        if limit is None:
            continue  # not a fill-in file or responses CSV: nothing to grade
        said = read(name)
        if said is None:
            entries.append(Entry(name, problem=f"unmatched, not credited: not named as "
                                 f"{label} names a student's file"))
            continue
        student_id = people.student(platform, said.identifier)
        if student_id is None:
            entries.append(Entry(name, problem=f"unmatched, not credited: no student on the "
                                 f"roster has {label} id {said.identifier}"))
            continue
        unreadable = _unreadable(info, limit)
        if unreadable:
            entries.append(Entry(name, student_id, problem=f"refused: {unreadable}"))
            continue
        if total + info.file_size > MAX_TOTAL_BYTES:
            raise DownloadError(f"{where}: more than {MAX_TOTAL_BYTES} bytes to read; "
                                "split the download")
        content = _read_bounded(archive, info, limit)
        if isinstance(content, str):
            entries.append(Entry(name, student_id, problem=f"refused: {content}"))
            continue
        total += len(content)
        entries.append(Entry(name, student_id, content))
        note = _name_note(platform, said, people.names.get(student_id, ""))
        if note:
            entries.append(Entry(name, student_id, problem=note, level="warning"))
        if said.late:
            entries.append(Entry(name, student_id, problem=f"{label} marks this submission "
                                 "late; graded all the same", level="warning"))
    return entries


def _name_note(platform: str, said: EntryName, roster_name: str) -> str:
    """A warning when Moodle shows another name than the roster's for the id (a stale
    roster, or a team's folder); "" when the names agree or cannot be compared: Canvas
    runs names together, and blind marking shows one word ("Participant") in the site's
    language."""
    if platform != "moodle" or not roster_name or len(said.name.split()) < 2:
        return ""
    if _same_name(said.name, roster_name):
        return ""
    return (f"the download names {said.name!r}, the roster {roster_name!r} for Moodle id "
            f"{said.identifier}; credited by the id (check the roster's moodle_id column)")


def _refusal(info: zipfile.ZipInfo) -> str:
    """Why an entry is not read at all ("" when it may be)."""
    name = info.filename
    parts = PurePosixPath(name.replace("\\", "/")).parts
    if name.startswith(("/", "\\")) or re.match(r"[A-Za-z]:", name) or ".." in parts:
        return "its name points outside the download"
    if stat.S_ISLNK(info.external_attr >> 16):
        return "a link is not followed"
    return ""


def _unreadable(info: zipfile.ZipInfo, limit: int) -> str:
    """Why a file to grade is not read ("" when it is read)."""
    if info.flag_bits & 0x1:
        return "the entry is encrypted"
    if info.file_size > limit:
        return f"{info.file_size} bytes is too large (the limit is {limit})"
    if info.file_size > 1_000_000 and info.file_size > MAX_RATIO * max(info.compress_size, 1):
        return (f"it expands {info.file_size // max(info.compress_size, 1)} times "
                "(a zip bomb?)")
    return ""


def _read_bounded(archive: zipfile.ZipFile, info: zipfile.ZipInfo, limit: int) -> bytes | str:
    """The entry's bytes, reading no more than ``limit`` + 1 whatever its header says; or
    why they cannot be taken (more than the limit, a damaged or unsupported entry)."""
    try:
        with archive.open(info) as handle:
            data = handle.read(limit + 1)
    except (zipfile.BadZipFile, EOFError, NotImplementedError, zlib.error) as error:
        return f"the entry cannot be read ({error})"
    if len(data) > limit:
        return "it expands beyond what its header says (a zip bomb?)"
    return data


def _same_name(shown: str, roster: str) -> bool:
    """Whether two names have the same words, in any order, ignoring case and marks that
    a file name cannot hold."""
    def words(text: str) -> list[str]:
        return sorted(re.findall(r"\w+", text.casefold()))

    return words(shown) == words(roster) or "".join(words(shown)) == "".join(words(roster))
