"""The staff page ``/i/{token}``: gradebook, progress, and its downloads."""

from __future__ import annotations

from fastapi import APIRouter
from fastapi.responses import HTMLResponse

from .. import db, downloads, gradebook, pages
from ..deps import REFUSALS, Now, RootPath, ServerDep, StaffLink
from ..downloads import CsvResponse

router = APIRouter(prefix="/i/{token}", tags=["staff pages"], responses=REFUSALS)


@router.get("", response_class=HTMLResponse)
def staff_page(caller: StaffLink, server: ServerDep, now: Now, base: RootPath) -> HTMLResponse:
    """Live progress, the gradebook and the downloads (reloads itself every minute)."""
    return HTMLResponse(pages.staff_html(server, caller.token, now, base))


@router.get("/grades.csv", response_class=CsvResponse)
def grades_csv(caller: StaffLink, server: ServerDep) -> CsvResponse:
    """The gradebook, with the columns of class grading's ``grades.csv``."""
    return downloads.grades(server)


@router.get("/submissions.csv", response_class=CsvResponse)
def submissions_csv(caller: StaffLink, server: ServerDep) -> CsvResponse:
    """The counted answer of every part, as ``dynagrade grade --manifest`` reads them."""
    return downloads.submissions(server)


@router.get("/report.html", response_class=HTMLResponse)
def class_report(caller: StaffLink, server: ServerDep) -> HTMLResponse:
    """Class grading's report of the counted answers."""
    stored = db.all_answers(server.engine, server.data.exam_id)
    return HTMLResponse(gradebook.class_report_html(server.data, stored))
