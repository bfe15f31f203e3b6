"""The gradebook, the counted answers and the points set by hand as CSV downloads (staff
page and API alike)."""

from __future__ import annotations

from starlette.responses import PlainTextResponse

from . import db, gradebook
from .overrides import overrides_csv
from .state import Server


class CsvResponse(PlainTextResponse):
    """A CSV file to download (``text/csv; charset=utf-8``)."""

    media_type = "text/csv"


def grades(server: Server) -> CsvResponse:
    """``grades.csv``: the gradebook as class grading writes it, points set by hand
    included."""
    data, engine = server.data, server.engine
    return _download(gradebook.grades_csv(data, db.all_answers(engine, data.exam_id),
                                          db.stored_overrides(engine, data.exam_id)),
                     "grades.csv")


def submissions(server: Server) -> CsvResponse:
    """``submissions.csv``: the counted answers as ``dynagrade grade --manifest`` reads."""
    data = server.data
    return _download(gradebook.responses_csv(data, db.all_answers(server.engine,
                                                                  data.exam_id)),
                     "submissions.csv")


def overrides(server: Server) -> CsvResponse:
    """``overrides.csv``: the points set by hand as ``dynagrade grade --overrides`` reads."""
    data = server.data
    return _download(overrides_csv(data, db.stored_overrides(server.engine, data.exam_id)),
                     "overrides.csv")


def _download(text: str, filename: str) -> CsvResponse:
    return CsvResponse(text, headers={"Content-Disposition": f'attachment; filename="{filename}"',
                                      "Cache-Control": "no-store"})
