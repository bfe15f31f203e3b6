"""The staff's downloads, the same from the staff page and the API: the gradebook (as
class grading writes it, and in Moodle's and Canvas's import layouts) and every attempt
(the responses CSV that ``dynagrade grade --manifest`` reads)."""

from __future__ import annotations

from starlette.responses import PlainTextResponse

from ..classgrade.gradebook import GRADEBOOK_FILES, platform_gradebook
from . import db, gradebook
from .state import Server


class CsvResponse(PlainTextResponse):
    """A CSV file to download (``text/csv; charset=utf-8``)."""

    media_type = "text/csv"


def csv_download(text: str, filename: str) -> CsvResponse:
    """``text`` as a file to save under ``filename``, never cached."""
    return CsvResponse(text, headers={"Content-Disposition": f'attachment; filename="{filename}"',
                                      "Cache-Control": "no-store"})


def grades(server: Server) -> CsvResponse:
    """``grades.csv``: the gradebook as class grading writes it."""
    return csv_download(gradebook.grades_csv(server.data, _stored(server)), "grades.csv")


def platform_grades(server: Server, layout: str) -> CsvResponse:
    """The gradebook in Moodle's or Canvas's import layout (``layout``: one of
    class grading's ``PLATFORM_FORMATS``), its grade column headed with the exam's
    title, as ``dynagrade grade --format`` writes it."""
    outcome = gradebook.outcome(server.data, _stored(server))
    return csv_download(platform_gradebook(outcome, layout, server.data.title),
                        GRADEBOOK_FILES[layout])


def submissions(server: Server) -> CsvResponse:
    """``submissions.csv``: every attempt, the one that counts flagged, as ``dynagrade
    grade --manifest`` reads it."""
    return csv_download(gradebook.responses_csv(server.data, _stored(server)),
                        "submissions.csv")


def _stored(server: Server) -> list[db.StoredAnswer]:
    return db.all_answers(server.engine, server.data.exam_id)
