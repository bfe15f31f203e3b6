"""Scores sent to the platforms: queued when they change, sent with retries, by a task
of every server process (started with the app; the queue is in the database, so what
was queued survives a restart and is sent by whichever process comes first).

Every :data:`SYNC_SECONDS` the task

1. computes, when anything that decides a score changed (a submission, an entry of the
   audit log: points by hand, a regrade, an exception, the policy; a launch or an
   import; a timed start) and at least every :data:`RECOMPUTE_SECONDS` (a close passing
   changes no row), the score each launched student's platform should hold now
   (:mod:`.scores`; the gradebook's totals and each student's rules) and queues those
   that differ from the last one queued for them: so a submit, points set by hand, a
   regrade, an exception and the close each send a score once, and nothing is sent
   before the close where feedback waits for it;
2. sends the queued scores that are due, each claimed for :data:`LEASE` so that no
   other process sends it meanwhile: to the exam's line item (bound or made,
   :mod:`.line_items`), with an access token for the score scope (:mod:`.access`). A
   refusal or no answer is tried again after 10 s, 20 s, 40 s, … (at most an hour
   apart), :data:`MAX_ATTEMPTS` times in all, then given up (``failed``); the staff
   page lists every score with its outcome.
"""

from __future__ import annotations

import asyncio
import datetime as dt
import json
import logging

from starlette.concurrency import run_in_threadpool

from .. import allowances, db, gradebook
from ..state import Server
from . import access, claims, grades_store, http, store
from .line_items import line_item_url, scores_url
from .scores import score_body

SYNC_SECONDS = 5.0
#: the longest a process goes without computing the scores although no row changed, so
#: that a close or a timed deadline passing sends its scores within this time
RECOMPUTE_SECONDS = 60.0
LEASE = dt.timedelta(seconds=60)
FIRST_RETRY_SECONDS = 10
LONGEST_WAIT_SECONDS = 3600
MAX_ATTEMPTS = 10

log = logging.getLogger("dynagrade.serve.lti")


def retry_delay(attempts: int) -> dt.timedelta:
    """How long to wait after the ``attempts``-th failed try (1, 2, …)."""
    return dt.timedelta(seconds=min(FIRST_RETRY_SECONDS * 2 ** (attempts - 1),
                                    LONGEST_WAIT_SECONDS))


def wanted_scores(server: Server, now: dt.datetime) -> dict[tuple[int, str], dict]:
    """The score each launched (or imported) student's platform should hold now, where
    there is one: students of a platform that named no grade service are left out."""
    data, engine = server.data, server.engine
    everyone = grades_store.exam_members(engine, data.exam_id)
    served = set(endpoints(everyone))  # the platforms with a grade service to send to
    members = [m for m in everyone if m.student_id in data.students and m.platform_id in served]
    if not members:
        return {}
    outcome = gradebook.outcome(data, db.all_answers(engine, data.exam_id),
                                db.stored_overrides(engine, data.exam_id))
    rows = {row.student_id: row for row in outcome.rows}
    granted = allowances.granted(engine, data.exam_id)
    started = db.started_times(engine, data.exam_id)
    wanted = {}
    for member in members:
        row = rows[member.student_id]
        rules = allowances.Rules(data.policy, granted.get(member.student_id),
                                 started.get(member.student_id))
        body = score_body(member.sub, row.total, row.max_total, rules, now)
        if body is not None:
            wanted[(member.platform_id, member.student_id)] = body
    return wanted


def endpoints(members: list[grades_store.Member]) -> dict[int, grades_store.Member]:
    """For each platform, the newest launch that named its grade service (the line item
    or where to make it): a student the staff imported (:mod:`.roster_import`) never
    launched, and is sent to through another's launch."""
    found: dict[int, grades_store.Member] = {}
    for member in sorted(members, key=lambda m: (m.launched_at is not None,
                                                 m.launched_at or dt.datetime.min)):
        if member.lineitem_url or member.lineitems_url:
            found[member.platform_id] = member
    return found


def queue_changes(server: Server, now: dt.datetime) -> int:
    """Queue every score that changed; how many."""
    wanted = wanted_scores(server, now)
    return grades_store.queue(server.engine, server.data.exam_id, wanted, now) if wanted else 0


def send_due(server: Server, now: dt.datetime) -> int:
    """Send the queued scores due at ``now``; how many the platforms accepted."""
    engine, data = server.engine, server.data
    accepted = 0
    service = endpoints(grades_store.exam_members(engine, data.exam_id))
    max_points = sum(float(m.points) for m in data.exercises_meta.values())
    for score in grades_store.claim_due(engine, data.exam_id, now, LEASE):
        platform = store.platform_by_id(engine, score.platform_id)
        member = service.get(score.platform_id)
        answer = _send(engine, platform, member, score.body, data.title, max_points) \
            if platform is not None and member is not None \
            else http.Answer(0, "the platform or its grade service is gone", {})
        attempts = score.attempts + 1
        if answer.ok:
            state, accepted = grades_store.SENT, accepted + 1
        else:
            state = grades_store.FAILED if attempts >= MAX_ATTEMPTS else grades_store.PENDING
            if answer.status == 401 and platform is not None:
                access.forget(platform)
        grades_store.record_answer(engine, score.id, state, attempts,
                                   now + retry_delay(attempts), answer.status or None,
                                   answer.text, now)
    return accepted


def _send(engine, platform: store.Platform, member: grades_store.Member, body: dict,
          title: str, max_points: float) -> http.Answer:
    try:
        url, refusal = line_item_url(engine, platform, member, title, max_points)
        if url is None:
            return refusal or http.Answer(0, "the launch named no line item to post to", {})
        token = access.access_token(engine, platform, (claims.AGS_SCORE_SCOPE,))
    except access.NoAccess as error:
        return error.answer
    return http.request("POST", scores_url(url),
                        {"Authorization": f"Bearer {token}",
                         "Content-Type": claims.SCORE_MEDIA}, json.dumps(body).encode())


class RecomputeGate:
    """Whether a process must compute the scores again: the whole gradebook is computed
    for it (the answers of every student), which a class of a thousand would pay every
    :data:`SYNC_SECONDS` in every process; one cheap query (:func:`grades_store.version`)
    says whether anything it depends on changed since the last time."""

    def __init__(self) -> None:
        self.version: tuple | None = None
        self.computed_at: dt.datetime | None = None

    def due(self, server: Server, now: dt.datetime) -> bool:
        """Whether the scores are to be computed at ``now`` (and note that they are)."""
        version = grades_store.version(server.engine, server.data.exam_id)
        if version == self.version and self.computed_at is not None and \
                (now - self.computed_at).total_seconds() < RECOMPUTE_SECONDS:
            return False
        self.version, self.computed_at = version, now
        return True


def sync_once(server: Server, gate: RecomputeGate | None = None) -> None:
    """One round: queue what changed (computed only when ``gate`` says so, if given),
    send what is due."""
    now = server.clock()
    if gate is None or gate.due(server, now):
        queue_changes(server, now)
    send_due(server, now)


async def run(server: Server) -> None:
    """:func:`sync_once` every :data:`SYNC_SECONDS` while the app runs; a round that
    fails (the database away) is logged and the next one tries again."""
    gate = RecomputeGate()
    while True:
        await asyncio.sleep(SYNC_SECONDS)
        try:
            await run_in_threadpool(sync_once, server, gate)
        except Exception:  # noqa: BLE001  (the task must outlive one bad round)
            log.exception("sending LTI scores failed; trying again in %s s", SYNC_SECONDS)
