"""The staff page ``/i/{token}``: gradebook, progress, the policy form, and downloads
(the gradebook as class grading writes it and in Moodle's and Canvas's layouts, every
attempt, the class report).

The page refreshes its tables from ``/i/{token}/tables`` (JSON) with a small script
that the staff can pause; it never reloads itself. The policy form posts to
``/i/{token}/policy`` (with the page's CSRF field); a change is validated and recorded
as :mod:`dynagrade.serve.policy_changes` says.
"""

from __future__ import annotations

from typing import Any, Literal

from fastapi import APIRouter
from fastapi.responses import HTMLResponse, RedirectResponse
from starlette.concurrency import run_in_threadpool

from .. import downloads, pages
from ..deps import REFUSALS, Now, RootPath, ServerDep, StaffForm, StaffLink
from ..downloads import CsvResponse
from ..headers import STANDALONE_DOCUMENT_POLICY
from ..models import StaffTables, problem

router = APIRouter(prefix="/i/{token}", tags=["staff pages"], responses=REFUSALS)


@router.get("", response_class=HTMLResponse)
def staff_page(caller: StaffLink, server: ServerDep, now: Now, base: RootPath) -> HTMLResponse:
    """Progress, the gradebook, the policy and its changes, the downloads."""
    return HTMLResponse(pages.staff_html(server, caller.token, now, base))


@router.get("/tables")
def staff_tables(caller: StaffLink, server: ServerDep) -> StaffTables:
    """The counts, gradebook and progress as the page shows them (for its script)."""
    return StaffTables.model_validate(pages.staff_tables(server))


_CHANGED: dict[int | str, dict[str, Any]] = {
    303: {"description": "changed (or nothing to change): back to the page (`Location`)"},
    422: {"description": "refused: the page again, with the reason and what was typed",
          "content": {"text/html": {"schema": {"type": "string"}}}}}


@router.post("/policy", status_code=303, response_class=RedirectResponse,
             responses={**_CHANGED, 403: problem("a missing or wrong CSRF field")})
async def change_policy(form: StaffForm, server: ServerDep, now: Now, base: RootPath):
    """Change the policy (form fields: any of opens, closes, attempts, penalty, feedback,
    counts, solutions); recorded in the audit log with who and when."""
    from ...exam.policy import PolicyError
    from ..policy_changes import CHANGEABLE, PolicySource, change_policy as apply

    caller = form.caller
    typed = {key: str(form.fields[key]) for key in CHANGEABLE if key in form.fields}
    try:
        await run_in_threadpool(apply, server.engine, server.data.exam_id,
                                server.data.manifest_policy, caller.actor, typed)
    except PolicyError as error:
        page = await run_in_threadpool(pages.staff_html, server, caller.token, now, base,
                                       str(error), typed)
        return HTMLResponse(page, status_code=422)
    if isinstance(server.data.policy_source, PolicySource):
        server.data.policy_source.forget()  # this worker shows the change at once
    return RedirectResponse(f"{base}/i/{caller.token}#policy", status_code=303)


@router.get("/grades.csv", response_class=CsvResponse)
def grades_csv(caller: StaffLink, server: ServerDep) -> CsvResponse:
    """The gradebook, with the columns of class grading's ``grades.csv``."""
    return downloads.grades(server)


@router.get("/grades-{layout}.csv", response_class=CsvResponse)
def platform_grades_csv(caller: StaffLink, server: ServerDep,
                        layout: Literal["moodle", "canvas"]) -> CsvResponse:
    """The gradebook in Moodle's or Canvas's import layout."""
    return downloads.platform_grades(server, layout)


@router.get("/submissions.csv", response_class=CsvResponse)
def submissions_csv(caller: StaffLink, server: ServerDep) -> CsvResponse:
    """Every attempt, the one that counts flagged, as ``dynagrade grade --manifest``
    reads them."""
    return downloads.submissions(server)


@router.get("/report.html", response_class=HTMLResponse)
def class_report(caller: StaffLink, server: ServerDep) -> HTMLResponse:
    """Class grading's report (histogram, item statistics, wrong answers by what explains
    them, mistakes nobody declared, copied answers) of the counted verdicts and the
    points set by hand: the document ``dynagrade grade`` saves, with its own inline
    styles and no script."""
    from ...classgrade.report import report_html

    return HTMLResponse(report_html(server.data.manifest.exam,
                                    downloads.reported_outcome(server)),
                        headers={"Content-Security-Policy": STANDALONE_DOCUMENT_POLICY})


@router.get("/overrides.csv", response_class=CsvResponse)
def overrides_csv(caller: StaffLink, server: ServerDep) -> CsvResponse:
    """The points set by hand, as ``dynagrade grade --overrides`` reads them."""
    return downloads.overrides(server)
