"""The student's page ``/s/{token}`` and the forms it posts (each with its CSRF field).

The page works without JavaScript: a form posts, the server stores the submit and
redirects back to the page (303), which then lists the attempt. A refused submit shows
the page again with the reason, under the status of the refusal.
"""

from __future__ import annotations

from typing import Any

from fastapi import APIRouter, HTTPException
from fastapi.responses import HTMLResponse, RedirectResponse
from starlette.concurrency import run_in_threadpool

from .. import pages
from ..deps import REFUSALS, Now, RootPath, ServerDep, StudentForm, StudentLink
from ..models import problem
from ..practice import practice_seed, practice_value
from ..submit import Refused, submit

router = APIRouter(prefix="/s/{token}", tags=["student pages"], responses=REFUSALS)

_BACK: dict[int | str, dict[str, Any]] = {
    303: {"description": "done: back to the page (`Location`)"}}


@router.get("", response_class=HTMLResponse)
def student_page(caller: StudentLink, server: ServerDep, now: Now, base: RootPath,
                 practice: str | None = None) -> HTMLResponse:
    """The student's sheet, answer boxes and attempts; ``practice`` shows a signed
    practice draw (``<exercise>:<seed>.<signature>``) of one exercise."""
    return HTMLResponse(pages.student_html(server, caller.token, caller.student_id,
                                           practice, now, base))


@router.post("/submit", status_code=303, response_class=RedirectResponse, responses={
    **_BACK, 422: {"description": "refused: the page again, with the reason",
                   "content": {"text/html": {"schema": {"type": "string"}}}}})
async def submit_answers(form: StudentForm, server: ServerDep, now: Now, base: RootPath):
    """Store the answers of one exercise (fields ``answer.<part>``, ``key``, optionally
    ``practice``), by the rules of :mod:`dynagrade.serve.submit`."""
    caller, fields, exercise_id = form.caller, form.fields, form.exercise_id
    answers = {k[len("answer."):]: str(v) for k, v in fields.items() if k.startswith("answer.")}
    posted = fields.get("practice")
    practice = posted if isinstance(posted, str) and posted else None
    try:
        seed = practice_seed(server.secret, caller.student_id, exercise_id, practice)
        await submit(server, caller.student_id, exercise_id, answers,
                     str(fields.get("key") or "") or None, seed, now)
    except Refused as error:
        page = await run_in_threadpool(pages.student_html, server, caller.token,
                                       caller.student_id, None, now, base, error.message)
        return HTMLResponse(page, status_code=error.status)
    query = f"?practice={exercise_id}:{practice}" if practice else ""
    return RedirectResponse(f"{base}/s/{caller.token}{query}#{exercise_id}", status_code=303)


@router.post("/practice", status_code=303, response_class=RedirectResponse, responses={
    **_BACK, 422: problem("not practice mode, or no such exercise")})
async def new_practice_draw(form: StudentForm, server: ServerDep, base: RootPath):
    """Practice mode: a fresh draw of one exercise, shown on the page that follows."""
    data, exercise_id = server.data, form.exercise_id
    if data.policy.mode != "practice" or exercise_id not in data.exercises_meta:
        raise HTTPException(422, "new variants are offered in practice mode only")
    seed = await run_in_threadpool(data.new_practice_seed, exercise_id)
    value = practice_value(server.secret, form.caller.student_id, exercise_id, seed)
    return RedirectResponse(f"{base}/s/{form.caller.token}?practice={exercise_id}:{value}"
                            f"#{exercise_id}", status_code=303)
