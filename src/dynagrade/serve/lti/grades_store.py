"""The tables of LTI Assignment and Grade Services and of Names and Role Provisioning
Services, and every statement on them (migrations 0006 and 0007).

``lti_members``    a student launched from a platform: their ``sub`` there (the userId of
                   their scores), the resource link, and the AGS endpoint the launch
                   named (line items URL, line item URL, the scopes granted)
``lti_line_items`` the exam's line item (its gradebook column) on each platform
``lti_contexts``   where each platform lists the course's members (NRPS), from a launch
``lti_scores``     each score for the platform, queued (``pending``), ``sent`` or given up
                   (``failed``): its JSON body, attempts, when to try next, and the
                   platform's answer (status and the start of its text)

A score is only ever inserted, then updated with the outcome of sending it: the rows are
the log the staff page shows.
"""

from __future__ import annotations

import datetime as dt
import json
from dataclasses import dataclass

import sqlalchemy as sa

from .. import db
from . import store  # noqa: F401  (lti_platforms, which the foreign keys name)

members = sa.Table(
    "lti_members", db.metadata,
    sa.Column("exam_id", sa.String(200), primary_key=True),
    sa.Column("platform_id", sa.Integer, sa.ForeignKey("lti_platforms.id"), primary_key=True),
    sa.Column("student_id", sa.String(200), primary_key=True),
    sa.Column("sub", sa.String(400), nullable=False),
    sa.Column("resource_link_id", sa.String(400), nullable=True),
    sa.Column("lineitems_url", sa.Text, nullable=True),
    sa.Column("lineitem_url", sa.Text, nullable=True),
    sa.Column("scopes", sa.Text, nullable=False, server_default="[]"),  # JSON list
    sa.Column("launched_at", sa.DateTime(timezone=True), nullable=False),
)

line_items = sa.Table(
    "lti_line_items", db.metadata,
    sa.Column("exam_id", sa.String(200), primary_key=True),
    sa.Column("platform_id", sa.Integer, sa.ForeignKey("lti_platforms.id"), primary_key=True),
    sa.Column("lineitem_url", sa.Text, nullable=False),
)

contexts = sa.Table(
    "lti_contexts", db.metadata,
    sa.Column("exam_id", sa.String(200), primary_key=True),
    sa.Column("platform_id", sa.Integer, sa.ForeignKey("lti_platforms.id"), primary_key=True),
    sa.Column("memberships_url", sa.Text, nullable=False),
)

scores = sa.Table(
    "lti_scores", db.metadata,
    sa.Column("id", sa.Integer, primary_key=True, autoincrement=True),
    sa.Column("exam_id", sa.String(200), nullable=False),
    sa.Column("platform_id", sa.Integer, sa.ForeignKey("lti_platforms.id"), nullable=False),
    sa.Column("student_id", sa.String(200), nullable=False),
    sa.Column("body", sa.Text, nullable=False),  # JSON: the score as sent
    sa.Column("state", sa.String(16), nullable=False),  # pending | sent | failed
    sa.Column("attempts", sa.Integer, nullable=False, server_default="0"),
    sa.Column("created_at", sa.DateTime(timezone=True), nullable=False),
    sa.Column("next_try_at", sa.DateTime(timezone=True), nullable=False),
    sa.Column("sent_at", sa.DateTime(timezone=True), nullable=True),
    sa.Column("answer_status", sa.Integer, nullable=True),
    sa.Column("answer_text", sa.Text, nullable=True),
    sa.Index("ix_lti_scores_exam_student", "exam_id", "student_id"),
)

PENDING, SENT, FAILED = "pending", "sent", "failed"
#: the most of a platform's answer kept (characters)
ANSWER_CHARS = 500


@dataclass(frozen=True)
class Member:
    """A launched student and the AGS endpoint of their launch."""

    exam_id: str
    platform_id: int
    student_id: str
    sub: str
    resource_link_id: str | None
    lineitems_url: str | None
    lineitem_url: str | None
    scopes: tuple[str, ...]
    launched_at: dt.datetime | None = None


def version(engine: sa.Engine, exam_id: str) -> tuple:
    """What the scores of an exam depend on besides the clock, in one query: the newest
    submission and audit log entry (points by hand, regrades, exceptions, policy changes
    are logged), the launched and imported students, the timed starts. Equal versions:
    nothing changed."""
    s, log, m = db.submissions.c, db.audit_log.c, members.c
    query = sa.select(
        sa.select(sa.func.max(s.id)).where(s.exam_id == exam_id).scalar_subquery(),
        sa.select(sa.func.max(log.id)).where(log.exam_id == exam_id).scalar_subquery(),
        sa.select(sa.func.max(m.launched_at)).where(m.exam_id == exam_id).scalar_subquery(),
        sa.select(sa.func.count()).select_from(members).where(
            m.exam_id == exam_id).scalar_subquery(),
        sa.select(sa.func.count()).select_from(db.starts).where(
            db.starts.c.exam_id == exam_id).scalar_subquery())
    with engine.connect() as connection:
        return tuple(connection.execute(query).one())


def put_member(engine: sa.Engine, member: Member, now: dt.datetime) -> None:
    """Record (or renew) a launched student, and the line item their launch named."""
    key = {"exam_id": member.exam_id, "platform_id": member.platform_id,
           "student_id": member.student_id}
    values = {"sub": member.sub, "resource_link_id": member.resource_link_id,
              "lineitems_url": member.lineitems_url, "lineitem_url": member.lineitem_url,
              "scopes": json.dumps(list(member.scopes)), "launched_at": now}
    m = members.c
    with db.writing(engine), engine.begin() as connection:
        found = connection.execute(sa.update(members).where(
            m.exam_id == member.exam_id, m.platform_id == member.platform_id,
            m.student_id == member.student_id).values(**values)).rowcount
        if not found:
            connection.execute(members.insert().values(**key, **values))
        if member.lineitem_url:
            _bind(connection, member.exam_id, member.platform_id, member.lineitem_url)


def link_member(engine: sa.Engine, exam_id: str, platform_id: int, student_id: str,
                sub: str, now: dt.datetime) -> bool:
    """Record a student the platform lists (NRPS) unless they are recorded already (a
    launch's record, with its grade service, stays); whether they were new."""
    m = members.c
    with db.writing(engine), engine.begin() as connection:
        found = connection.execute(sa.select(m.sub).where(
            m.exam_id == exam_id, m.platform_id == platform_id,
            m.student_id == student_id)).first()
        if found is None:
            connection.execute(members.insert().values(
                exam_id=exam_id, platform_id=platform_id, student_id=student_id, sub=sub,
                scopes="[]", launched_at=now))
    return found is None


def put_memberships_url(engine: sa.Engine, exam_id: str, platform_id: int, url: str) -> None:
    """Where the platform lists the course's members (the newest launch's word)."""
    c = contexts.c
    with db.writing(engine), engine.begin() as connection:
        found = connection.execute(sa.update(contexts).where(
            c.exam_id == exam_id, c.platform_id == platform_id).values(
                memberships_url=url)).rowcount
        if not found:
            connection.execute(contexts.insert().values(
                exam_id=exam_id, platform_id=platform_id, memberships_url=url))


def memberships_urls(engine: sa.Engine, exam_id: str) -> dict[int, str]:
    """Where each platform lists the course's members, by platform id."""
    with engine.connect() as connection:
        return {r.platform_id: r.memberships_url for r in connection.execute(
            sa.select(contexts).where(contexts.c.exam_id == exam_id))}


def exam_members(engine: sa.Engine, exam_id: str) -> list[Member]:
    with engine.connect() as connection:
        rows = connection.execute(sa.select(members).where(members.c.exam_id == exam_id)
                                  .order_by(members.c.student_id)).all()
    return [Member(r.exam_id, r.platform_id, r.student_id, r.sub, r.resource_link_id,
                   r.lineitems_url, r.lineitem_url, tuple(json.loads(r.scopes)),
                   db.utc(r.launched_at)) for r in rows]


def _bind(connection, exam_id: str, platform_id: int, url: str) -> None:
    l = line_items.c
    found = connection.execute(sa.select(l.lineitem_url).where(
        l.exam_id == exam_id, l.platform_id == platform_id)).scalar()
    if found is None:
        connection.execute(line_items.insert().values(exam_id=exam_id,
                                                      platform_id=platform_id,
                                                      lineitem_url=url))


def bind_line_item(engine: sa.Engine, exam_id: str, platform_id: int, url: str) -> None:
    """The exam's line item on the platform is ``url`` (unless one is bound already)."""
    with db.writing(engine), engine.begin() as connection:
        _bind(connection, exam_id, platform_id, url)


def line_item(engine: sa.Engine, exam_id: str, platform_id: int) -> str | None:
    with engine.connect() as connection:
        return connection.execute(sa.select(line_items.c.lineitem_url).where(
            line_items.c.exam_id == exam_id,
            line_items.c.platform_id == platform_id)).scalar()


# -- scores -------------------------------------------------------------------------------


@dataclass(frozen=True)
class QueuedScore:
    """A score for the platform, as queued, sent or given up."""

    id: int
    platform_id: int
    student_id: str
    body: dict
    state: str
    attempts: int
    created_at: dt.datetime
    sent_at: dt.datetime | None
    answer_status: int | None
    answer_text: str | None


def _score(row) -> QueuedScore:
    return QueuedScore(row.id, row.platform_id, row.student_id, json.loads(row.body),
                       row.state, row.attempts, db.utc(row.created_at), db.utc(row.sent_at),
                       row.answer_status, row.answer_text)


def _newest_bodies(connection, exam_id: str) -> dict[tuple[int, str], dict]:
    """The body of the newest score queued for each (platform, student)."""
    s = scores.c
    newest = sa.select(sa.func.max(s.id)).where(s.exam_id == exam_id).group_by(
        s.platform_id, s.student_id)
    return {(r.platform_id, r.student_id): json.loads(r.body)
            for r in connection.execute(sa.select(s.platform_id, s.student_id, s.body)
                                        .where(s.id.in_(newest)))}


def queue(engine: sa.Engine, exam_id: str, wanted: dict[tuple[int, str], dict],
          now: dt.datetime) -> int:
    """Queue each body of ``wanted`` that differs from the newest queued for its
    (platform, student), in one transaction that holds out every other writer (so two
    server processes queue a change once); how many were queued."""
    with db.writing(engine), engine.begin() as connection:
        if engine.dialect.name == "postgresql":
            connection.execute(sa.text("SELECT pg_advisory_xact_lock(7414)"))
        last = _newest_bodies(connection, exam_id)
        changed = {key: body for key, body in wanted.items()
                   if not _same_score(last.get(key), body)}
        for (platform_id, student_id), body in changed.items():
            connection.execute(scores.insert().values(
                exam_id=exam_id, platform_id=platform_id, student_id=student_id,
                body=json.dumps(body), state=PENDING, attempts=0, created_at=now,
                next_try_at=now))
    return len(changed)


def _same_score(old: dict | None, new: dict) -> bool:
    """Whether two bodies give the same score (their timestamps aside)."""
    return old is not None and {k: v for k, v in old.items() if k != "timestamp"} == \
        {k: v for k, v in new.items() if k != "timestamp"}


def claim_due(engine: sa.Engine, exam_id: str, now: dt.datetime, lease: dt.timedelta,
              limit: int = 50) -> list[QueuedScore]:
    """The pending scores due at ``now``, each claimed by this process for ``lease``
    (their next try moved on, so another process leaves them alone meanwhile)."""
    s = scores.c
    with engine.connect() as connection:
        rows = connection.execute(sa.select(scores).where(
            s.exam_id == exam_id, s.state == PENDING, s.next_try_at <= now)
            .order_by(s.id).limit(limit)).all()
    claimed = []
    for row in rows:
        with db.writing(engine), engine.begin() as connection:
            taken = connection.execute(sa.update(scores).where(
                s.id == row.id, s.state == PENDING, s.next_try_at == row.next_try_at)
                .values(next_try_at=now + lease)).rowcount
        if taken == 1:
            claimed.append(_score(row))
    return claimed


def record_answer(engine: sa.Engine, score_id: int, state: str, attempts: int,
                  next_try_at: dt.datetime, status: int | None, text: str,
                  now: dt.datetime) -> None:
    """What sending a score came to: its state, the platform's answer."""
    with db.writing(engine), engine.begin() as connection:
        connection.execute(sa.update(scores).where(scores.c.id == score_id).values(
            state=state, attempts=attempts, next_try_at=next_try_at,
            sent_at=now if state == SENT else None, answer_status=status,
            answer_text=text[:ANSWER_CHARS]))


def recent_scores(engine: sa.Engine, exam_id: str, limit: int = 200) -> list[QueuedScore]:
    """The newest scores of the exam, newest first."""
    with engine.connect() as connection:
        rows = connection.execute(sa.select(scores).where(scores.c.exam_id == exam_id)
                                  .order_by(scores.c.id.desc()).limit(limit)).all()
    return [_score(r) for r in rows]
