"""The JSON API under ``/api/v1``: the token in ``Authorization: Bearer <token>``.

Students submit answers and preview how an answer reads; staff download the gradebook
(as JSON or CSV) and the counted answers. Every JSON body has its model in
:mod:`dynagrade.serve.models`.
"""

from __future__ import annotations

from typing import Annotated, Any, Literal

from fastapi import APIRouter, Header
from starlette.concurrency import run_in_threadpool

from .. import allowances, db, downloads, drafts, overrides, timed
from ..deps import REFUSALS, Data, Now, Pool, ServerDep, StaffBearer, StudentBearer
from ..downloads import CsvResponse
from ...i18n import _
from ..models import (AnswersBody, DraftsBody, DraftsResponse, Gradebook, OverrideBody,
                      OverrideChange, OverrideEntry, Overrides, PreviewBody,
                      PolicyBody, PolicyInForce, PreviewResponse, StartResponse, StudentRecord,
                      SubmitResponse, problem)
from ..student_record import student_record as record_of
from .staff_students import on_roster
from ..practice import practice_seed
from ..submit import Refused, check_open, submit

router = APIRouter(prefix="/api/v1", tags=["api"], responses=REFUSALS)


def _unreadable_in_time() -> dict:
    return {"readable": False, "message": _("could not be read in time"), "formula": None}


@router.post("/answers", response_model_exclude_unset=True, responses={
    413: problem("a body over 64 KiB"),
    422: problem("an exercise, part or answer the exam's rules refuse (a malformed body: "
                 "`detail` is a list of errors)"),
    503: problem("the grading queue is full (`Retry-After`)")})
async def submit_answers(caller: StudentBearer, body: AnswersBody, server: ServerDep,
                         now: Now, idempotency_key: Annotated[str | None, Header(
                             description="8-100 of A-Z a-z 0-9 . _ : -; a retry with the "
                                         "same key stores nothing twice")] = None
                         ) -> SubmitResponse:
    """Grade and store one exercise's answers; the answer shows what the policy allows."""
    result = await submit(server, caller.student_id, body.exercise, body.answers,
                          idempotency_key, None, now)
    return SubmitResponse.model_validate(result)


@router.put("/drafts", responses={
    403: problem("before the student's opening, from their close on, before the Start of a "
                 "timed exam, or once their time ran out"),
    422: problem("an exercise or part not in the exam, or a text over 2000 characters")})
async def save_drafts(caller: StudentBearer, body: DraftsBody, server: ServerDep,
                      now: Now) -> DraftsResponse:
    """Keep what the student typed as drafts (never graded, never counted)."""
    saved = await drafts.save(server, caller.student_id, body.exercise, body.answers, now)
    return DraftsResponse(exercise=body.exercise, saved=saved)


@router.post("/preview", responses={403: problem("before the student's opening, or before "
                                                  "the Start of a timed exam")})
async def preview(caller: StudentBearer, body: PreviewBody, server: ServerDep,
                  pool: Pool, now: Now) -> PreviewResponse:
    """How an answer reads (never whether it is right); nothing before the exam opens
    for the student (or, timed, before their Start)."""
    data = server.data
    rules = await run_in_threadpool(allowances.rules_for, server.engine, data.exam_id,
                                    data.policy, caller.student_id)
    if rules.before_opens(now) or rules.waiting_to_start(now):
        check_open(rules, now)
    if body.exercise not in data.exercises_meta or \
            body.part not in {p.name for p in data.parts(body.exercise)}:
        raise Refused(422, _("no such exercise or part in this exam"))
    seed = practice_seed(server.secret, caller.student_id, body.exercise, body.practice)
    read = await pool.read(caller.student_id, body.exercise, body.part, body.answer, seed)
    return PreviewResponse.model_validate(read or _unreadable_in_time())


@router.post("/start", responses={403: problem("before the student's opening or from their "
                                               "close on")})
async def start(caller: StudentBearer, server: ServerDep, now: Now) -> StartResponse:
    """Start the student's time on a timed exam (the first start counts; again: the same
    answer). On an untimed exam nothing is started."""
    rules = await run_in_threadpool(timed.start, server, caller.student_id, now)
    return StartResponse(timed=rules.timed, started_at=_iso(rules.started_at),
                         minutes=rules.minutes, deadline=_iso(rules.deadline))


def _iso(moment) -> str | None:
    return moment.isoformat() if moment is not None else None


@router.get("/gradebook")
def gradebook_json(caller: StaffBearer, server: ServerDep, data: Data) -> Gradebook:
    """The gradebook as JSON: every roster student's row, in roster order."""
    return Gradebook.from_rows(data.exercise_ids, downloads.class_outcome(server).rows)


@router.get("/grades.csv", response_class=CsvResponse)
def grades_csv(caller: StaffBearer, server: ServerDep) -> CsvResponse:
    """The gradebook as class grading's ``grades.csv``."""
    return downloads.grades(server)


@router.get("/grades-{layout}.csv", response_class=CsvResponse)
def platform_grades_csv(caller: StaffBearer, server: ServerDep,
                        layout: Literal["moodle", "canvas"]) -> CsvResponse:
    """The gradebook in Moodle's or Canvas's import layout."""
    return downloads.platform_grades(server, layout)


@router.get("/submissions.csv", response_class=CsvResponse)
def submissions_csv(caller: StaffBearer, server: ServerDep) -> CsvResponse:
    """Every attempt, the one that counts flagged, as the responses CSV ``dynagrade grade
    --manifest`` reads."""
    return downloads.submissions(server)


# -- points by hand and a student's record ------------------------------------------------

_OVERRIDE_REFUSALS: dict[int | str, dict[str, Any]] = {422: problem(
    "a student, exercise or part not in the exam, points outside 0 to the part's points "
    "or not a multiple of the exam's rounding, or an exercise the student handed nothing "
    "in for")}


@router.put("/overrides", responses=_OVERRIDE_REFUSALS)
def put_override(caller: StaffBearer, body: OverrideBody, server: ServerDep,
                 data: Data) -> OverrideChange:
    """Set the points of one part of one student by hand, with a comment (the grader's
    points are kept beside them); recorded in the audit log unless nothing changed."""
    return OverrideChange(changed=overrides.set_points(
        server.engine, data, caller.actor, body.student, body.exercise, body.part,
        body.points, body.comment))


@router.delete("/overrides/{student_id}/{exercise}/{part}", responses=_OVERRIDE_REFUSALS)
def delete_override(caller: StaffBearer, student_id: str, exercise: str, part: str,
                    server: ServerDep, data: Data) -> OverrideChange:
    """Remove the points set by hand on a part: the grader's points count again."""
    return OverrideChange(changed=overrides.remove_points(
        server.engine, data, caller.actor, student_id, exercise, part))


@router.get("/overrides")
def list_overrides(caller: StaffBearer, server: ServerDep, data: Data) -> Overrides:
    """Every part whose points were set by hand."""
    return Overrides(overrides=[
        OverrideEntry(student=o.student_id, exercise=o.exercise_id, part=o.part,
                            points=o.points, comment=o.comment, author=o.author,
                            at=db.iso(o.at))
        for o in db.stored_overrides(server.engine, data.exam_id)])


@router.get("/overrides.csv", response_class=CsvResponse)
def overrides_csv(caller: StaffBearer, server: ServerDep) -> CsvResponse:
    """The points set by hand, as ``dynagrade grade --overrides`` reads them."""
    return downloads.overrides(server)


@router.get("/students/{student_id}", responses={404: problem("a student not on the roster")})
def student_record(caller: StaffBearer, student_id: str, server: ServerDep) -> StudentRecord:
    """One student's attempts (which counts), drafts and points set by hand."""
    on_roster(server, student_id)
    return StudentRecord.model_validate(
        record_of(server.engine, server.data, student_id))


@router.get("/policy")
def policy_in_force(caller: StaffBearer, data: Data) -> PolicyInForce:
    """The policy in force: the manifest's, or the staff's latest change."""
    return PolicyInForce(policy=data.policy.to_json())


@router.put("/policy", responses={422: problem("a value the policy's rules refuse (the "
                                               "reason names the setting)")})
async def change_policy(caller: StaffBearer, body: PolicyBody, server: ServerDep
                        ) -> PolicyInForce:
    """Change the settings given, checked as exam.toml's policy is and recorded in the
    audit log (the same change as the staff page's policy form); a change that changes
    nothing records nothing."""
    from ...exam.policy import PolicyError
    from ..policy_changes import PolicySource, change_policy as apply

    data = server.data
    given = body.model_dump(exclude_unset=True)
    try:
        before, after = await run_in_threadpool(apply, server.engine, data.exam_id,
                                                data.manifest_policy, caller.actor, given)
    except PolicyError as error:
        raise Refused(422, str(error)) from None
    if isinstance(data.policy_source, PolicySource):
        data.policy_source.forget()  # this worker holds the change at once
    return PolicyInForce(policy=after.to_json(), changed=after != before)
