"""Exceptions to the policy per student: the staff page ``/i/{token}/exceptions`` and its
forms, and the API ``/api/v1/exceptions``.

The page lists every exception granted (student, what, who granted it, when, in the
course's zone), with a form that grants one exception to one student or a list of them
(ids separated by spaces, commas or new lines; ``?students=s1,s2`` fills it in) and a
button per student that removes theirs. A grant the rules refuse shows the page again
(422) with the reason and what was typed. What granting means, and how it is checked and
recorded: :mod:`dynagrade.serve.allowances`.
"""

from __future__ import annotations

from typing import Any

from fastapi import APIRouter, HTTPException
from fastapi.responses import HTMLResponse, RedirectResponse
from starlette.concurrency import run_in_threadpool

from .. import allowances, limits, moments, pages
from ..allowances import EVERY_PART, Allowance, AllowanceError
from ..deps import REFUSALS, RootPath, ServerDep, StaffBearer, StaffForm, StaffLink
from ..models import ExceptionBody, Exceptions, Removed, StudentException, problem
from ..state import Server

page_router = APIRouter(prefix="/i/{token}/exceptions", tags=["staff pages"],
                        responses=REFUSALS)
api_router = APIRouter(prefix="/api/v1/exceptions", tags=["api"], responses=REFUSALS)

_CHANGED: dict[int | str, dict[str, Any]] = {
    303: {"description": "done (or nothing to change): back to the page (`Location`)"},
    403: problem("a missing or wrong CSRF field"),
    422: {"description": "refused: the page again, with the reason and what was typed",
          "content": {"text/html": {"schema": {"type": "string"}}}}}


# -- the page ------------------------------------------------------------------------------


@page_router.get("", response_class=HTMLResponse)
def exceptions_page(caller: StaffLink, server: ServerDep, base: RootPath,
                    students: str = "") -> HTMLResponse:
    """Every exception granted and the form to grant one; ``students`` (ids separated
    by commas) fills in the form (with their exception, when one student is named)."""
    named = allowances.student_list(students)
    typed = {"students": "\n".join(named)}
    if len(named) == 1:
        mine = allowances.granted(server.engine, server.data.exam_id, named).get(named[0])
        typed.update(_typed_of(mine) if mine else {})
    return HTMLResponse(_page(server, caller.token, base, typed=typed))


@page_router.post("", status_code=303, response_class=RedirectResponse, responses=_CHANGED)
async def grant_exceptions(form: StaffForm, server: ServerDep, base: RootPath):
    """Grant the exception of the form (fields ``students``, ``opens``, ``closes``,
    ``extra_minutes``, ``attempts.*``, ``attempts.<exercise>``,
    ``attempts.<exercise>/<part>``) to each student listed; recorded in the audit log."""
    fields = form.fields
    typed = {key: str(value) for key, value in fields.items() if key != "csrf"}
    fields_given = {"opens": typed.get("opens", ""), "closes": typed.get("closes", ""),
                    "extra_minutes": typed.get("extra_minutes", ""),
                    "extra_attempts": {key[len("attempts."):]: value for key, value
                                       in typed.items() if key.startswith("attempts.")}}
    try:
        await run_in_threadpool(_grant, server, form.caller.actor,
                                allowances.student_list(typed.get("students", "")),
                                fields_given)
    except AllowanceError as error:
        page = await run_in_threadpool(_page, server, form.caller.token, base, str(error),
                                       typed)
        return HTMLResponse(page, status_code=422)
    return RedirectResponse(f"{base}/i/{form.caller.token}/exceptions#granted",
                            status_code=303)


@page_router.post("/remove", status_code=303, response_class=RedirectResponse,
                  responses=_CHANGED)
async def remove_exception(form: StaffForm, server: ServerDep, base: RootPath):
    """Remove one student's exceptions (field ``student``); the policy holds for them
    again. Recorded in the audit log; removing what is not there changes nothing."""
    student = str(form.fields.get("student", ""))
    try:
        await run_in_threadpool(_clear, server, form.caller.actor, student)
    except AllowanceError as error:
        page = await run_in_threadpool(_page, server, form.caller.token, base, str(error))
        return HTMLResponse(page, status_code=422)
    return RedirectResponse(f"{base}/i/{form.caller.token}/exceptions#granted",
                            status_code=303)


def _page(server: Server, token: str, base: str, error: str | None = None,
          typed: dict[str, str] | None = None) -> str:
    data = server.data
    zone = moments.exam_zone(data.policy)
    rows = [{"student_id": student_id, "name": _name(server, student_id),
             "what": allowances.describe(allowance, zone), "by": allowance.updated_by or "",
             "at": moments.moment(allowance.updated_at, zone, seconds=True)
             if allowance.updated_at else None}
            for student_id, allowance in allowances.granted(server.engine,
                                                            data.exam_id).items()]
    scopes = [(f"attempts.{exercise_id}", exercise_id, [
        (f"attempts.{exercise_id}/{part.name}", f"{exercise_id}/{part.name}")
        for part in data.manifest_parts[exercise_id]]) for exercise_id in data.exercise_ids]
    return pages.render(
        "exceptions.html", title=data.title, token=token, base=base,
        language=data.manifest.exam.language, csrf=limits.csrf_field(server.secret, token),
        rows=rows, error=error, typed=typed or {}, scopes=scopes,
        scoped=any(key.startswith("attempts.") and key != f"attempts.{EVERY_PART}" and value
                   for key, value in (typed or {}).items()),
        every=f"attempts.{EVERY_PART}", policy_text=pages.policy_text(data.policy,
                                                                     server.clock()),
        timed=bool(data.policy.time_limit), attempts=bool(data.policy.attempts))


def _typed_of(allowance: Allowance) -> dict[str, str]:
    """The form's fields holding ``allowance`` (to change one student's exceptions)."""
    typed = {key: value.isoformat() for key, value in (("opens", allowance.opens),
                                                       ("closes", allowance.closes)) if value}
    if allowance.extra_minutes:
        typed["extra_minutes"] = str(allowance.extra_minutes)
    typed.update({f"attempts.{scope}": str(n) for scope, n in allowance.extra_attempts.items()})
    return typed


def _name(server: Server, student_id: str) -> str:
    entry = server.data.students.get(student_id)
    return entry.name if entry is not None else ""


# -- what both the page and the API do ------------------------------------------------------


def _grant(server: Server, actor: str, students: object, fields: dict) -> dict[str, Allowance]:
    data = server.data
    student_ids = allowances.check_students(students, data.students)
    allowance = allowances.read_allowance(fields, data.policy, {
        exercise_id: tuple(p.name for p in parts)
        for exercise_id, parts in data.manifest_parts.items()})
    return allowances.grant(server.engine, data.exam_id, actor, student_ids, allowance)


def _clear(server: Server, actor: str, student_id: str) -> Allowance | None:
    allowances.check_students([student_id], server.data.students)
    return allowances.clear(server.engine, server.data.exam_id, actor, student_id)


# -- the API -------------------------------------------------------------------------------


def _record(server: Server, student_id: str, allowance: Allowance) -> StudentException:
    shown = allowance.to_json()
    return StudentException(
        student_id=student_id, name=_name(server, student_id), opens=shown["opens"],
        closes=shown["closes"], extra_minutes=allowance.extra_minutes,
        extra_attempts=dict(shown["extra_attempts"]), granted_by=allowance.updated_by,
        granted_at=allowance.updated_at.isoformat() if allowance.updated_at else None)


@api_router.get("")
def list_exceptions(caller: StaffBearer, server: ServerDep) -> Exceptions:
    """Every exception granted, by student id."""
    found = allowances.granted(server.engine, server.data.exam_id)
    return Exceptions(exceptions=[_record(server, s, a) for s, a in found.items()])


@api_router.put("", responses={422: problem(
    "a student not on the roster (every unknown id is named), a time without its offset, "
    "a close not after the opening, a number out of bounds, an exercise or part not in the "
    "exam, or nothing to grant")})
def set_exceptions(caller: StaffBearer, body: ExceptionBody,
                   server: ServerDep) -> Exceptions:
    """Give each student listed exactly this exception (repeating it changes nothing);
    each change is recorded in the audit log. The exceptions now in force for them."""
    try:
        found = _grant(server, caller.actor, body.students,
                       body.model_dump(exclude={"students"}))
    except AllowanceError as error:
        raise HTTPException(422, str(error)) from None
    return Exceptions(exceptions=[_record(server, s, a) for s, a in found.items()])


@api_router.delete("/{student_id}", responses={422: problem("a student not on the roster")})
def delete_exception(caller: StaffBearer, student_id: str, server: ServerDep) -> Removed:
    """Remove a student's exceptions (recorded; nothing to remove: nothing changes)."""
    try:
        removed = _clear(server, caller.actor, student_id)
    except AllowanceError as error:
        raise HTTPException(422, str(error)) from None
    return Removed(student_id=student_id,
                   removed=_record(server, student_id, removed) if removed else None)
