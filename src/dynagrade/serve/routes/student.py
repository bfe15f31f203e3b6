"""The student's page ``/s/{token}`` and the forms it posts (each with its CSRF field).

The page works without JavaScript: a form posts, the server stores the submit and
redirects back to the page (303, ``?done=<exercise>#status``), which then says what was
saved and lists the attempt. A form sends every box of its exercise; only the parts whose
text changed since their last counted answer are submitted. A refused submit, or one with
answers that could not be read, shows the page again with the text typed and the reason
beside each part it concerns (under the refusal's status; 200 when something was saved).
"""

from __future__ import annotations

from typing import Any

from fastapi import APIRouter, HTTPException
from fastapi.responses import HTMLResponse, RedirectResponse
from starlette.concurrency import run_in_threadpool

from ...i18n import _
from .. import pages, timed
from ..deps import REFUSALS, Now, RootPath, ServerDep, StudentForm, StudentLink
from ..models import problem
from ..practice import practice_seed, practice_value
from ..submit import Refused, submit

router = APIRouter(prefix="/s/{token}", tags=["student pages"], responses=REFUSALS)

_BACK: dict[int | str, dict[str, Any]] = {
    303: {"description": "done: back to the page (`Location`)"}}


@router.get("", response_class=HTMLResponse)
def student_page(caller: StudentLink, server: ServerDep, now: Now, base: RootPath,
                 practice: str | None = None, done: str | None = None) -> HTMLResponse:
    """The student's sheet, answer boxes and attempts; ``practice`` shows a signed
    practice draw (``<exercise>:<seed>.<signature>``) of one exercise; ``done`` names the
    exercise just submitted (the page says what was saved)."""
    return HTMLResponse(pages.student_html(server, caller.token, caller.student_id,
                                           practice, now, base,
                                           typed=pages.Typed.done(done)))


@router.post("/submit", status_code=303, response_class=RedirectResponse, responses={
    **_BACK, 422: {"description": "refused: the page again, with the reason",
                   "content": {"text/html": {"schema": {"type": "string"}}}}})
async def submit_answers(form: StudentForm, server: ServerDep, now: Now, base: RootPath):
    """Store the answers of one exercise (fields ``answer.<part>``, ``key``, optionally
    ``practice``), by the rules of :mod:`dynagrade.serve.submit`."""
    caller, fields, exercise_id = form.caller, form.fields, form.exercise_id
    answers = posted_answers(fields)
    posted = fields.get("practice")
    practice = posted if isinstance(posted, str) and posted else None
    typed = pages.Typed(exercise_id, answers)
    try:
        seed = practice_seed(server.secret, caller.student_id, exercise_id, practice)
        result = await submit(server, caller.student_id, exercise_id, answers,
                              str(fields.get("key") or "") or None, seed, now,
                              only_changed=True)
    except Refused as error:
        page = await run_in_threadpool(pages.student_html, server, caller.token,
                                       caller.student_id, practice_of(exercise_id, practice),
                                       now, base, error.message,
                                       typed.with_reasons(error.parts))
        return HTMLResponse(page, status_code=error.status)
    unread = {p["name"]: p["message"] for p in result["parts"] if not p["readable"]}
    if unread:  # saved in part: the page again, the unreadable answers beside their reason
        page = await run_in_threadpool(pages.student_html, server, caller.token,
                                       caller.student_id, practice_of(exercise_id, practice),
                                       now, base, None, typed.with_reasons(unread, saved=True))
        return HTMLResponse(page)
    query = f"?practice={exercise_id}:{practice}&done={exercise_id}" if practice \
        else f"?done={exercise_id}"
    return RedirectResponse(f"{base}/s/{caller.token}{query}#status", status_code=303)


def posted_answers(fields) -> dict[str, str]:
    """The answers of a posted form, part -> text; the ticked boxes of a choice part of
    several options (fields of the same name) joined as the typed form, ``A, B``."""
    answers: dict[str, str] = {}
    for name in dict.fromkeys(k for k in fields.keys() if k.startswith("answer.")):
        values = [str(v) for v in fields.getlist(name) if str(v).strip()]
        answers[name[len("answer."):]] = ", ".join(values)
    return answers


def practice_of(exercise_id: str, practice: str | None) -> str | None:
    """The page's ``practice`` query for a practice draw's form (None: no draw)."""
    return f"{exercise_id}:{practice}" if practice else None


@router.post("/start", status_code=303, response_class=RedirectResponse, responses={
    **_BACK, 403: {"description": "before the student's opening or from their close on: "
                                  "the page again, with the reason",
                   "content": {"text/html": {"schema": {"type": "string"}}}}})
async def start_timed(form: StudentForm, server: ServerDep, now: Now, base: RootPath):
    """Start the student's time on a timed exam (the first start counts); the page then
    shows the exercises and the time left."""
    caller = form.caller
    try:
        await run_in_threadpool(timed.start, server, caller.student_id, now)
    except Refused as error:
        page = await run_in_threadpool(pages.student_html, server, caller.token,
                                       caller.student_id, None, now, base, error.message)
        return HTMLResponse(page, status_code=error.status)
    return RedirectResponse(f"{base}/s/{caller.token}#main", status_code=303)


@router.post("/practice", status_code=303, response_class=RedirectResponse, responses={
    **_BACK, 422: problem("not practice mode, or no such exercise")})
async def new_practice_draw(form: StudentForm, server: ServerDep, base: RootPath):
    """Practice mode: a fresh draw of one exercise, shown on the page that follows."""
    data, exercise_id = server.data, form.exercise_id
    if data.policy.mode != "practice" or exercise_id not in data.exercises_meta:
        raise HTTPException(422, _("new variants are offered in practice mode only"))
    seed = await run_in_threadpool(data.new_practice_seed, exercise_id)
    value = practice_value(server.secret, form.caller.student_id, exercise_id, seed)
    return RedirectResponse(f"{base}/s/{form.caller.token}?practice={exercise_id}:{value}"
                            f"#{exercise_id}", status_code=303)
