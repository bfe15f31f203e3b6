"""One submit, from the request to the committed row and the answer the student sees.

The rules, the same for the student page's form and ``POST /api/v1/answers``:

1. The exercise and part names must be the exam's, each answer at most
   :data:`~dynagrade.serve.exam_data.MAX_ANSWER_CHARS` long, at least one answer given
   (otherwise 422). The student page sends every box of the exercise; of those only the
   parts whose text differs from the part's last counted answer are submitted
   (``only_changed``), so a part already answered spends no attempt by being sent again.
2. Counted answers are accepted only while the exam is open for the student (server
   clock; their own opening, close and timed deadline, :mod:`.allowances`) and while
   every submitted part has attempts left (the policy's and the student's extra ones;
   otherwise 403, naming the parts). Practice draws (practice mode, "new variant") are
   graded the same way but never counted.
3. An answer the grader cannot read (:meth:`ExamData.read
   <dynagrade.serve.exam_data.ExamData.read>`: syntax, an unknown name, a unit of the
   wrong dimension, the wrong kind) is not graded, not stored and spends no attempt; the
   response names it, unreadable, with the reason. When no answer of a submit can be
   read, nothing is stored (422, the reason per part).
4. A submit with an idempotency key that is already stored returns the stored result
   instead of storing it again; a retry after a lost response is therefore safe.
5. The answers are graded in the pool; the submission (attempt number = the exercise's
   next one, penalties applied per part) is inserted in one transaction; only then is the
   response built. Two workers racing for the same attempt number: the loser retries.
6. What the response shows follows the policy: always how each answer was read; right or
   wrong, points and feedback only where the policy shows verdicts at that moment.
"""

from __future__ import annotations

import datetime as dt
import re
import uuid
from dataclasses import dataclass, field

from starlette.concurrency import run_in_threadpool

from ..errors import DynagradeError
from ..exercise.results import ExerciseResult, GradedPart, Status
from ..i18n import _
from . import allowances, db
from .allowances import Rules
from .exam_data import MAX_ANSWER_CHARS, ExamData
from .verdicts import SubmittedPart

_KEY = re.compile(r"^[A-Za-z0-9._:-]{8,100}$")


@dataclass
class Refused(DynagradeError):
    """A submit the rules refuse: the HTTP status and a message for the student, and the
    reason beside each part it concerns (part name -> message; the page shows it there)."""

    status: int
    message: str
    parts: dict[str, str] = field(default_factory=dict)


def check_texts(data: ExamData, exercise_id, texts) -> list[str]:
    """Check that ``texts`` (a submit's answers, or drafts) name an exercise of the exam
    and parts of it, each at most :data:`MAX_ANSWER_CHARS` long; :class:`Refused` (422)
    otherwise. Returns the exercise's part names, in order."""
    if not isinstance(exercise_id, str) or exercise_id not in data.exercises_meta:
        raise Refused(422, _("no exercise {exercise!r} in this exam").format(
            exercise=exercise_id))
    if not isinstance(texts, dict) or not all(
            isinstance(k, str) and isinstance(v, str) for k, v in texts.items()):
        raise Refused(422, _("'answers' must map part names to answer texts"))
    names = [p.name for p in data.parts(exercise_id)]
    unknown = [name for name in texts if name not in names]
    if unknown:
        raise Refused(422, _("no part {part!r} in {exercise}; the parts are {parts}").format(
            part=unknown[0], exercise=exercise_id, parts=", ".join(names)))
    long = [name for name, text in texts.items() if len(text) > MAX_ANSWER_CHARS]
    if long:
        raise Refused(422, _("the answer to {part!r} is longer than {n} characters").format(
            part=long[0], n=MAX_ANSWER_CHARS), {long[0]: _("longer than {n} characters")
                                                .format(n=MAX_ANSWER_CHARS)})
    return names


def check_request(data: ExamData, exercise_id, answers) -> dict[str, str]:
    """The non-empty answers of a well-formed request; :class:`Refused` (422) otherwise."""
    names = check_texts(data, exercise_id, answers)
    given = {name: text for name, text in answers.items() if text.strip()}
    if not given:
        raise Refused(422, _("no answer given"))
    return {name: given[name] for name in names if name in given}


def changed(given: dict[str, str], last: dict[str, str]) -> dict[str, str]:
    """The answers whose text differs (but for spaces around it) from the part's last
    counted answer ``last``; :class:`Refused` (422) when none does."""
    fresh = {name: text for name, text in given.items()
             if text.strip() != last.get(name, "").strip()}
    if not fresh:
        raise Refused(422, _("nothing changed since your last saved answers"))
    return fresh


async def submit(state, student_id: str, exercise_id, answers, key: str | None,
                 practice_seed: int | None, now: dt.datetime,
                 only_changed: bool = False) -> dict:
    """Grade, store and describe one submit (see the module's rules); ``only_changed``:
    submit only the parts whose text changed since their last counted answer."""
    data: ExamData = state.data
    policy = data.policy
    given = check_request(data, exercise_id, answers)
    counted = practice_seed is None
    if not counted and policy.mode != "practice":
        raise Refused(422, _("new variants are offered in practice mode only"))
    if key is not None and not _KEY.match(key):
        raise Refused(422, _("the idempotency key must be 8-100 letters, digits or ._:-"))
    reads = await run_in_threadpool(db.submit_reads, state.engine, data.exam_id, student_id,
                                    exercise_id, key, counted, counted and only_changed)
    rules = allowances.rules_from(policy, reads.terms, reads.started)
    if key is not None and reads.stored is not None:  # a retry: the stored submit
        return _replay(data, rules, student_id, reads.stored, now, key)
    key = key or uuid.uuid4().hex
    if counted:
        check_open(rules, now)
    if reads.last_texts is not None:
        given = changed(given, reads.last_texts)
    if counted and policy.attempts:  # refuse before grading; checked again when storing
        _check_attempts(rules, exercise_id, reads.per_part, given)
    graded = await state.pool.grade(student_id, exercise_id, given, practice_seed)
    if graded is None:
        graded = [_not_in_time(data, exercise_id, name, text) for name, text in given.items()]
    unread = [part for part in graded if part.invalid]
    graded = [part for part in graded if not part.invalid]
    if not graded:
        reasons = {part.name: part.message for part in unread}
        raise Refused(422, _("nothing was saved: no answer could be read ({reasons}); an "
                             "answer that cannot be read costs no attempt").format(
            reasons="; ".join(f"{name}: {message}" for name, message in reasons.items())),
            reasons)
    seed = practice_seed if practice_seed is not None else \
        data.entry(student_id, exercise_id).seed
    last, per_part = reads.last_attempt, reads.per_part
    for retry in range(20):
        if retry:  # another submit took the attempt number meanwhile: read them again
            last, per_part = await run_in_threadpool(
                db.part_attempts, state.engine, data.exam_id, student_id, exercise_id,
                counted)
        if counted:
            _check_attempts(rules, exercise_id, per_part, given)
        rows = [_with_penalty(policy, part, per_part.get(part.name, 0) + 1, counted)
                for part in graded]
        attempt = last + 1
        try:
            await run_in_threadpool(db.record_submission, state.engine, data.exam_id,
                                    student_id, exercise_id, attempt, seed, counted, key,
                                    [part.row() for part in rows])
        except db.DuplicateAttempt:
            continue
        except db.DuplicateSubmission:  # the same key arrived twice at once: the other was stored
            stored = await run_in_threadpool(db.find_submission, state.engine,
                                             data.exam_id, key)
            if stored is None:  # the other submit's transaction was rolled back: retry
                continue
            return _replay(data, rules, student_id, stored, now, key)
        return describe(data, exercise_id, attempt, rows, rules.shows_verdicts(now), key,
                        unread)
    raise Refused(503, _("too many submits at once; try again"))


def describe(data: ExamData, exercise_id: str, attempt: int, rows: list[SubmittedPart],
             verdicts: bool, key: str, unread: list[SubmittedPart] | None = None) -> dict:
    """The response body of a submit: points rounded as the gradebook rounds them; the
    ``unread`` parts (not stored) follow, unreadable, with the reason."""
    result = ExerciseResult(exercise_id, None, tuple(r.verdict for r in rows)
                            ).rounded(data.rounding)
    parts = []
    for row, verdict in zip(rows, result.parts):
        shown = {"name": row.name, "readable": row.readable, "message": row.message}
        if verdicts:
            shown.update(correct=verdict.correct, score=verdict.score,
                         feedback=verdict.feedback)
        parts.append(shown)
    parts += [{"name": row.name, "readable": False, "message": row.message}
              for row in unread or ()]
    body = {"exercise": exercise_id, "attempt": attempt, "idempotency_key": key,
            "parts": parts}
    if verdicts:
        body["score"] = result.score
        body["max_score"] = round(result.max_score, 6)
    return body


def _replay(data: ExamData, rules: Rules, student_id: str, stored: list[db.StoredAnswer],
            now: dt.datetime, key: str) -> dict:
    if stored[0].student_id != student_id:
        raise Refused(422, _("this idempotency key was used by another submission; send a "
                             "fresh key with each new submit"))
    rows = [SubmittedPart.stored(a) for a in stored]
    return describe(data, stored[0].exercise_id, stored[0].attempt, rows,
                    rules.shows_verdicts(now), key) | {"replayed": True}


def check_open(rules: Rules, now: dt.datetime) -> None:
    """:class:`Refused` (403) unless the student's answers are accepted at ``now``: before
    their opening, from their close on, before the Start of a timed exam and once their
    time ran out (the message says which, and when)."""
    reason = rules.refusal(now)
    if reason is not None:
        raise Refused(403, reason)


def _check_attempts(rules: Rules, exercise_id: str, per_part: dict[str, int],
                    given: dict[str, str]) -> None:
    allowed = {name: rules.attempts(exercise_id, name) for name in given}
    spent = [name for name in given if allowed[name] and per_part.get(name, 0) >= allowed[name]]
    if spent:
        limits = {allowed[name] for name in spent}  # extra attempts may differ by part
        message = _("no attempts left for {parts} (each part allows {n})").format(
            parts=", ".join(spent), n=limits.pop()) if len(limits) == 1 else \
            _("no attempts left for {parts}").format(parts=", ".join(spent))
        raise Refused(403, message, {name: _("no attempts left") for name in spent})


def _with_penalty(policy, part: SubmittedPart, attempt: int, counted: bool) -> SubmittedPart:
    return part.penalised(policy.attempt_factor(attempt) if counted else 1.0, attempt)


def _not_in_time(data: ExamData, exercise_id: str, name: str, text: str) -> SubmittedPart:
    part = next(p for p in data.parts(exercise_id) if p.name == name)
    message = _("could not be graded in time; the staff will grade it")
    return SubmittedPart(text, False, message, GradedPart(
        name, part.label, Status.ERROR, 0.0, part.points, text, message))
