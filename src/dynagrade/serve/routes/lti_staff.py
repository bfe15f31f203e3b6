"""The staff's page of the course platform, ``/i/{token}/lti``: every score sent to
the platforms' gradebooks (or queued, or given up), when, and what the platform
answered (:mod:`dynagrade.serve.lti.grade_sync`); and the button that imports the
course's members and merges them with the roster (``POST /i/{token}/lti/roster``,
:mod:`dynagrade.serve.lti.roster_import`)."""

from __future__ import annotations

from fastapi import APIRouter
from fastapi.responses import HTMLResponse
from starlette.concurrency import run_in_threadpool

from ...i18n import N_, _
from .. import limits, moments, pages
from ..deps import REFUSALS, Now, RootPath, ServerDep, StaffForm, StaffLink
from ..lti import grades_store, roster_import
from ..state import Server

router = APIRouter(prefix="/i/{token}", tags=["staff pages"], responses=REFUSALS)

#: the scores the page lists, newest first
PAGE_SCORES = 200

#: a score's state as the page words it (translated when the page is made)
STATE_WORDS = {grades_store.PENDING: N_("queued"), grades_store.SENT: N_("sent"),
               grades_store.FAILED: N_("given up")}


def score_rows(server: Server) -> list[dict]:
    """The newest scores as the page lists them."""
    data = server.data
    zone = moments.exam_zone(data.policy)
    rows = []
    for score in grades_store.recent_scores(server.engine, data.exam_id, PAGE_SCORES):
        body = score.body
        student = data.students.get(score.student_id)
        rows.append({
            "queued": moments.moment(score.created_at, zone, seconds=True),
            "student": f"{student.name} ({score.student_id})" if student else score.student_id,
            "score": f"{body.get('scoreGiven', '')} / {body.get('scoreMaximum', '')}",
            "progress": f"{body.get('activityProgress', '')}, {body.get('gradingProgress', '')}",
            "state": score.state, "attempts": score.attempts,
            "sent": moments.moment(score.sent_at, zone, seconds=True) if score.sent_at else None,
            "answer": (f"{score.answer_status or _('no answer')} {score.answer_text or ''}"
                       .strip() if score.attempts else "")})
    return rows


def page(server: Server, token: str, base: str,
         imported: roster_import.RosterImport | None = None, failure: str | None = None) -> str:
    """The page, with an import's outcome (or why it failed) when there was one."""
    data = server.data
    return pages.render(
        "lti_staff.html", title=data.title, token=token, base=base,
        language=data.manifest.exam.language, rows=score_rows(server), limit=PAGE_SCORES,
        states={state: _(word) for state, word in STATE_WORDS.items()},
        csrf=limits.csrf_field(server.secret, token), imported=imported, failure=failure,
        names={sid: s.name for sid, s in data.students.items()})


@router.get("/lti", response_class=HTMLResponse)
def platform_page(caller: StaffLink, server: ServerDep, base: RootPath) -> HTMLResponse:
    """The scores sent to the course platforms, newest first; the import button."""
    return HTMLResponse(page(server, caller.token, base))


@router.post("/lti/roster", response_class=HTMLResponse, responses={
    502: {"description": "the platform did not list its members: the page, saying why",
          "content": {"text/html": {"schema": {"type": "string"}}}}})
async def import_members(form: StaffForm, server: ServerDep, now: Now,
                         base: RootPath) -> HTMLResponse:
    """Import the course's members from the platform and merge them with the roster:
    the page then lists who was linked, who the roster lacks, who the platform lacks."""
    data, token = server.data, form.caller.token
    try:
        imported = await run_in_threadpool(roster_import.import_roster, server.engine,
                                           data.exam_id, data.students, now)
    except roster_import.ImportFailed as error:
        return HTMLResponse(await run_in_threadpool(page, server, token, base, None,
                                                    str(error)), status_code=error.status)
    return HTMLResponse(await run_in_threadpool(page, server, token, base, imported))
