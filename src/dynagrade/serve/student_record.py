"""One student's record as the staff look it up: every attempt of every part, which one
counts and why, the drafts, the points set by hand, the exceptions to the policy they
were granted (with their close and, on a timed exam, when they started), and the
verdicts regrades changed.

:func:`student_record` builds it as plain values (a dict), which the staff's student
page renders (``templates/staff_student.html``) and the API returns
(:class:`dynagrade.serve.models.StudentRecord`).

The attempt that counts is the gradebook's (:func:`dynagrade.serve.gradebook.
counted_answers`, by the policy's ``counts``), the points those of
:func:`dynagrade.serve.standing.results` (rounded, points set by hand applied), so the
page shows what the gradebook holds. Times are in the course's zone, to the second
("I submitted at 10:02": the staff can check when).
"""

from __future__ import annotations

from ..i18n import N_, _
from . import allowances, db, gradebook, moments, standing
from .exam_data import ExamData

#: why an attempt counts, by the policy's ``counts``
WHY_COUNTED = {"best": N_("The best score counts (the earlier attempt on a tie)"),
               "last": N_("The last saved answer counts")}


def student_record(engine, data: ExamData, student_id: str) -> dict:
    """The record of a student on the roster (a :class:`KeyError` otherwise)."""
    student = data.students[student_id]
    zone = moments.exam_zone(data.policy)
    stored = db.student_answers(engine, data.exam_id, student_id)
    overrides = db.stored_overrides(engine, data.exam_id, student_id)
    drafts = {(d.exercise_id, d.part): d
              for d in db.student_drafts(engine, data.exam_id, student_id)}
    chosen = gradebook.counted_answers(data, stored)
    results = standing.results(data, stored, student_id, overrides)
    by_part = {(o.exercise_id, o.part): o for o in overrides}
    exercises = []
    for exercise_id in data.exercise_ids:
        result = results[exercise_id]
        parts = []
        for info in data.parts(exercise_id):
            key = (exercise_id, info.name)
            counted = chosen.get((student_id, *key))
            verdict = result.part(info.name) if result is not None else None
            override, draft = by_part.get(key), drafts.get(key)
            parts.append({
                "part": info.name, "label": info.label or info.name, "points": info.points,
                "attempts": [_attempt(a, counted, zone) for a in stored
                             if (a.exercise_id, a.part) == key],
                "counted_attempt": counted.attempt if counted is not None else None,
                "status": str(verdict.status) if verdict else None,
                "status_text": verdict.status.shown if verdict else None,
                "auto_score": verdict.auto_score if verdict else None,
                "score": verdict.score if verdict else None,
                "override": _override(override, zone) if override else None,
                "draft": {"text": draft.text,
                          "saved_at": moments.moment(draft.saved_at, zone, True).iso,
                          "saved_text": moments.moment(draft.saved_at, zone, True).text}
                if draft else None})
        exercises.append({
            "exercise": exercise_id, "title": data.exercises_meta[exercise_id].title,
            "handed_in": result is not None,
            "score": result.score if result is not None else None,
            "max_score": float(data.exercises_meta[exercise_id].points), "parts": parts})
    return {"student_id": student_id, "name": student.name, "email": student.email,
            "counts": data.policy.counts, "why_counted": _(WHY_COUNTED[data.policy.counts]),
            "total": standing.total(data, results)
            if any(r is not None for r in results.values()) else None,
            "exercises": exercises,
            "terms": _terms(allowances.rules_for(engine, data.exam_id, data.policy,
                                                 student_id), zone),
            "regrades": _regrades(data, db.replaced_verdicts(engine, data.exam_id,
                                                             student_id), zone)}


def _terms(rules: allowances.Rules, zone) -> dict:
    """The policy as it holds for the student: the exceptions granted (one phrase each,
    who granted them and when), their close, and on a timed exam their start and end."""
    granted = rules.allowance

    def shown(moment):
        return moments.moment(moment, zone, seconds=True).text if moment else None

    return {"exceptions": allowances.describe(granted, zone) if granted else [],
            "granted_by": granted.updated_by if granted else None,
            "granted_at": shown(granted.updated_at) if granted else None,
            "closes": shown(rules.closes), "extended": rules.extended,
            "timed": rules.timed, "minutes": rules.minutes,
            "started_at": shown(rules.started_at), "time_ends": shown(rules.time_ends)}


def _regrades(data: ExamData, replaced: list[db.ReplacedVerdict], zone) -> list[dict]:
    """The verdicts of the student's answers that applied regrades changed, oldest first."""
    labels = {(e, p.name): p.label or p.name for e, parts in data.manifest_parts.items()
              for p in parts}
    return [{"at": moments.moment(r.applied_at, zone, seconds=True).text,
             "exercise": r.exercise_id, "part": labels.get((r.exercise_id, r.part), r.part),
             "attempt": r.attempt, "before": r.before, "after": r.after} for r in replaced]


def _attempt(answer: db.StoredAnswer, counted: db.StoredAnswer | None, zone) -> dict:
    """One stored answer as the record lists it."""
    when = moments.moment(answer.created_at, zone, seconds=True)
    return {"attempt": answer.attempt, "practice": not answer.counted,
            "answer": answer.raw, "read_as": answer.message, "readable": answer.readable,
            "status": answer.status, "status_text": _(answer.status),
            "score": answer.score, "max_score": answer.max_score,
            "feedback": answer.feedback, "at": when.iso, "at_text": when.text,
            "counts": counted is not None and counted.submission_id == answer.submission_id}


def _override(override: db.StoredOverride, zone) -> dict:
    """Points set by hand as the record shows them."""
    when = moments.moment(override.at, zone, seconds=True)
    return {"points": override.points, "comment": override.comment,
            "author": override.author, "at": when.iso, "at_text": when.text}


def staff_student_html(server, token: str, student_id: str, base: str,
                       refused: dict | None = None) -> str:
    """The staff's page of one student (``refused``: a form the rules refused, as
    ``{"exercise", "part", "reason", "points", "comment"}``, shown again beside its
    part with what was typed)."""
    from . import limits
    from .pages import render

    data = server.data
    record = student_record(server.engine, data, student_id)
    return render("staff_student.html", title=data.title, token=token, base=base,
                  language=data.manifest.exam.language, record=record,
                  csrf=limits.csrf_field(server.secret, token), refused=refused or {},
                  rounding=data.rounding)
