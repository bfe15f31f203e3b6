"""Timed exams: the Start a student presses, from which their time runs.

With a ``time_limit`` in the policy, a student's page shows the rules and a Start button
instead of the exercises; pressing it (``POST /s/{token}/start``, ``POST
/api/v1/start``) stores the moment in the database's ``starts``. From then on they may
answer until their deadline, the earlier of their close and the start plus
``time_limit`` and their ``extra_minutes`` (:class:`~dynagrade.serve.allowances.Rules`).
The first start counts: pressing Start again, on another device too, changes nothing.
A start is accepted only while the exam is open for the student; an untimed exam has
nothing to start (the answer then says so and stores nothing).
"""

from __future__ import annotations

import dataclasses
import datetime as dt

from . import allowances, db
from .allowances import Rules
from .submit import Refused


def start(server, student_id: str, now: dt.datetime) -> Rules:
    """Start the student's time at ``now`` unless it started before (or the exam is
    untimed); the rules in force for them after it. :class:`Refused` (403) before their
    opening and from their close on."""
    data = server.data
    rules = allowances.rules_for(server.engine, data.exam_id, data.policy, student_id)
    if not rules.timed or rules.started_at is not None:
        return rules
    if rules.before_opens(now) or rules.closed(now):
        raise Refused(403, rules.refusal(now) or "")
    first = db.record_start(server.engine, data.exam_id, student_id,
                            now.astimezone(dt.timezone.utc))
    return dataclasses.replace(rules, started_at=db.utc(first))
