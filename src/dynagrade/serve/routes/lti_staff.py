"""The staff's page of the course platform, ``/i/{token}/lti``: every score sent to
the platforms' gradebooks (or queued, or given up), when, and what the platform
answered (:mod:`dynagrade.serve.lti.grade_sync`)."""

from __future__ import annotations

from fastapi import APIRouter
from fastapi.responses import HTMLResponse

from ...i18n import N_, _
from .. import moments, pages
from ..deps import REFUSALS, RootPath, ServerDep, StaffLink
from ..lti import grades_store
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


@router.get("/lti", response_class=HTMLResponse)
def platform_page(caller: StaffLink, server: ServerDep, base: RootPath) -> HTMLResponse:
    """The scores sent to the course platforms, newest first."""
    data = server.data
    return HTMLResponse(pages.render(
        "lti_staff.html", title=data.title, token=caller.token, base=base,
        language=data.manifest.exam.language, rows=score_rows(server), limit=PAGE_SCORES,
        states={state: _(word) for state, word in STATE_WORDS.items()}))
