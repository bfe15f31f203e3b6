"""The gradebook and the counted answers as CSV downloads (staff page and API alike)."""

from __future__ import annotations

from starlette.responses import PlainTextResponse

from . import db, gradebook
from .state import Server


class CsvResponse(PlainTextResponse):
    """A CSV file to download (``text/csv; charset=utf-8``)."""

    media_type = "text/csv"


def grades(server: Server) -> CsvResponse:
    """``grades.csv``: the gradebook as class grading writes it."""
    return _download(server, gradebook.grades_csv, "grades.csv")


def submissions(server: Server) -> CsvResponse:
    """``submissions.csv``: the counted answers as ``dynagrade grade --manifest`` reads."""
    return _download(server, gradebook.responses_csv, "submissions.csv")


def _download(server: Server, render, filename: str) -> CsvResponse:
    text = render(server.data, db.all_answers(server.engine, server.data.exam_id))
    return CsvResponse(text, headers={"Content-Disposition": f'attachment; filename="{filename}"',
                                      "Cache-Control": "no-store"})
