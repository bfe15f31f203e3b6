"""The staff's downloads, the same from the staff page and the API: the gradebook (as
class grading writes it, and in Moodle's and Canvas's import layouts), every attempt (the
responses CSV that ``dynagrade grade --manifest`` reads) and the points set by hand (the
overrides file that ``dynagrade grade --overrides`` reads). Every gradebook holds the
points set by hand."""

from __future__ import annotations

from starlette.responses import PlainTextResponse

from ..classgrade.gradebook import GRADEBOOK_FILES, gradebook_csv, platform_gradebook
from ..classgrade.grade import with_findings
from ..classgrade.outcome import ClassOutcome
from . import db, gradebook
from .overrides import overrides_csv
from .state import Server


class CsvResponse(PlainTextResponse):
    """A CSV file to download (``text/csv; charset=utf-8``)."""

    media_type = "text/csv"


def csv_download(text: str, filename: str) -> CsvResponse:
    """``text`` as a file to save under ``filename``, never cached."""
    return CsvResponse(text, headers={"Content-Disposition": f'attachment; filename="{filename}"',
                                      "Cache-Control": "no-store"})


def class_outcome(server: Server) -> ClassOutcome:
    """The class's outcome from the stored verdicts and the points set by hand."""
    data, engine = server.data, server.engine
    return gradebook.outcome(data, db.all_answers(engine, data.exam_id),
                             db.stored_overrides(engine, data.exam_id))


def reported_outcome(server: Server) -> ClassOutcome:
    """The class's outcome with the mistakes nobody declared and the copied answers
    (class grading's :func:`~dynagrade.classgrade.grade.with_findings`), each exercise
    timed by its latest counted answer."""
    data = server.data
    stored = db.all_answers(server.engine, data.exam_id)
    outcome = gradebook.outcome(data, stored, db.stored_overrides(server.engine, data.exam_id))
    times: dict[tuple[str, str], str] = {}
    for answer in gradebook.counted_answers(data, stored).values():
        key = (answer.student_id, answer.exercise_id)
        times[key] = max(times.get(key, ""), answer.created_at.isoformat(timespec="seconds"))
    return with_findings(outcome, data.manifest, data.exercises, times)


def grades(server: Server) -> CsvResponse:
    """``grades.csv``: the gradebook as class grading writes it."""
    return csv_download(gradebook_csv(class_outcome(server)), GRADEBOOK_FILES["csv"])


def platform_grades(server: Server, layout: str) -> CsvResponse:
    """The gradebook in Moodle's or Canvas's import layout (``layout``: one of
    class grading's ``PLATFORM_FORMATS``), its grade column headed with the exam's
    title, as ``dynagrade grade --format`` writes it."""
    return csv_download(platform_gradebook(class_outcome(server), layout, server.data.title),
                        GRADEBOOK_FILES[layout])


def submissions(server: Server) -> CsvResponse:
    """``submissions.csv``: every attempt, the one that counts flagged, as ``dynagrade
    grade --manifest`` reads it."""
    data = server.data
    return csv_download(gradebook.responses_csv(data, db.all_answers(server.engine,
                                                                     data.exam_id)),
                        "submissions.csv")


def overrides(server: Server) -> CsvResponse:
    """``overrides.csv``: the points set by hand as ``dynagrade grade --overrides`` reads."""
    data = server.data
    return csv_download(overrides_csv(data, db.stored_overrides(server.engine, data.exam_id)),
                        "overrides.csv")
