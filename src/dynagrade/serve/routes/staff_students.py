"""The staff's page of one student, ``/i/{token}/students/{student_id}``, and its forms:
points set by hand on a part, and their removal.

The page lists every attempt of every part with the one that counts marked
(:mod:`dynagrade.serve.student_record`). Its forms post with the page's CSRF field; a
change goes through :mod:`dynagrade.serve.overrides` (checked as the offline overrides
file is, recorded in the audit log) and comes back to the page (303) at the part; a
refused one shows the page again (422) with the reason beside the part and what was typed.
"""

from __future__ import annotations

from typing import Any
from urllib.parse import quote

from fastapi import APIRouter, HTTPException
from fastapi.responses import HTMLResponse, RedirectResponse
from starlette.concurrency import run_in_threadpool

from ...i18n import _
from .. import overrides
from ..deps import REFUSALS, RootPath, ServerDep, StaffForm, StaffLink
from ..models import problem
from ..student_record import staff_student_html
from ..submit import Refused

router = APIRouter(prefix="/i/{token}/students", tags=["staff pages"], responses=REFUSALS)

_CHANGED: dict[int | str, dict[str, Any]] = {
    303: {"description": "changed (or nothing to change): back to the student's page at "
                         "the part (`Location`)"},
    403: problem("a missing or wrong CSRF field"),
    404: problem("a student not on the roster"),
    422: {"description": "refused: the page again, with the reason beside the part and "
                         "what was typed",
          "content": {"text/html": {"schema": {"type": "string"}}}}}


def on_roster(server, student_id: str) -> str:
    """``student_id`` when the exam's roster has it; 404 otherwise."""
    if student_id not in server.data.students:
        raise HTTPException(404, _("no student {student!r} on this exam's roster").format(
            student=student_id))
    return student_id


@router.get("/{student_id}", response_class=HTMLResponse,
            responses={404: problem("a student not on the roster")})
def student_page(caller: StaffLink, server: ServerDep, base: RootPath,
                 student_id: str) -> HTMLResponse:
    """One student's attempts (which counts and why), drafts and points set by hand."""
    on_roster(server, student_id)
    return HTMLResponse(staff_student_html(server, caller.token, student_id, base))


@router.post("/{student_id}/overrides", status_code=303, response_class=RedirectResponse,
             responses=_CHANGED)
async def set_points(form: StaffForm, server: ServerDep, base: RootPath, student_id: str):
    """Set the points of a part by hand (form fields: ``exercise``, ``part``, ``points``,
    ``comment``)."""
    fields = {key: str(form.fields.get(key, "")) for key in
              ("exercise", "part", "points", "comment")}
    return await _change(form, server, base, on_roster(server, student_id), fields,
                         overrides.set_points, fields["points"], fields["comment"])


@router.post("/{student_id}/overrides/remove", status_code=303,
             response_class=RedirectResponse, responses=_CHANGED)
async def remove_points(form: StaffForm, server: ServerDep, base: RootPath,
                        student_id: str):
    """Remove the points set by hand on a part (form fields: ``exercise``, ``part``): the
    automatic score counts again."""
    fields = {key: str(form.fields.get(key, "")) for key in ("exercise", "part")}
    return await _change(form, server, base, on_roster(server, student_id), fields,
                         overrides.remove_points)


async def _change(form, server, base: str, student_id: str, fields: dict[str, str],
                  change, *values: str):
    """Make ``change`` and go back to the part, or show the page again with the refusal."""
    caller = form.caller
    try:
        await run_in_threadpool(change, server.engine, server.data, caller.actor,
                                student_id, fields["exercise"], fields["part"], *values)
    except Refused as refusal:
        page = await run_in_threadpool(staff_student_html, server, caller.token,
                                       student_id, base,
                                       {**fields, "reason": refusal.message})
        return HTMLResponse(page, status_code=refusal.status)
    return RedirectResponse(f"{base}/i/{caller.token}/students/{quote(student_id, safe='')}"
                            f"#{fields['exercise']}--{fields['part']}", status_code=303)
