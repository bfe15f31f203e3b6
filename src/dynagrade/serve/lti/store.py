"""The LTI tables and every statement on them (created by migration 0005).

``lti_platforms``  each registered platform: issuer, client id, deployment ids (JSON),
                   its login, token and JWKS URLs, and the claim that finds a launching
                   user on the roster (``email``, ``sub`` or ``sourcedid``)
``lti_keys``       the tool's RSA key pairs (PEM); the newest unretired one signs, every
                   unretired one is published (:mod:`.keys`)
``lti_logins``     a login initiation waiting for its id_token: sha256 of its state, its
                   nonce, its platform, until when it may be used (single use)
``lti_sessions``   a launched user: sha256 of the session cookie's value, the exam, the
                   role, the roster student (students) or a name (staff), until when

Nothing here is secret in the database but the tool's private keys: states and session
ids are stored only as their sha256, like the links' tokens.
"""

from __future__ import annotations

import datetime as dt
import json
from dataclasses import dataclass

import sqlalchemy as sa

from .. import db

platforms = sa.Table(
    "lti_platforms", db.metadata,
    sa.Column("id", sa.Integer, primary_key=True, autoincrement=True),
    sa.Column("issuer", sa.String(400), nullable=False),
    sa.Column("client_id", sa.String(400), nullable=False),
    sa.Column("deployment_ids", sa.Text, nullable=False),  # JSON list
    sa.Column("auth_login_url", sa.Text, nullable=False),
    sa.Column("token_url", sa.Text, nullable=False),
    sa.Column("jwks_url", sa.Text, nullable=False),
    sa.Column("user_claim", sa.String(16), nullable=False),
    sa.Column("created_at", sa.DateTime(timezone=True), nullable=False),
    sa.UniqueConstraint("issuer", "client_id", name="uq_lti_platforms_issuer_client"),
)

keys = sa.Table(
    "lti_keys", db.metadata,
    sa.Column("kid", sa.String(64), primary_key=True),
    sa.Column("private_pem", sa.Text, nullable=False),
    sa.Column("created_at", sa.DateTime(timezone=True), nullable=False),
    sa.Column("retired_at", sa.DateTime(timezone=True), nullable=True),
)

logins = sa.Table(
    "lti_logins", db.metadata,
    sa.Column("state_hash", sa.String(64), primary_key=True),
    sa.Column("nonce", sa.String(64), nullable=False),
    sa.Column("platform_id", sa.Integer, sa.ForeignKey("lti_platforms.id"), nullable=False),
    sa.Column("expires_at", sa.DateTime(timezone=True), nullable=False),
)

sessions = sa.Table(
    "lti_sessions", db.metadata,
    sa.Column("session_hash", sa.String(64), primary_key=True),
    sa.Column("exam_id", sa.String(200), nullable=False),
    sa.Column("platform_id", sa.Integer, sa.ForeignKey("lti_platforms.id"), nullable=False),
    sa.Column("role", sa.String(16), nullable=False),
    sa.Column("student_id", sa.String(200), nullable=True),
    sa.Column("label", sa.String(200), nullable=True),
    sa.Column("sub", sa.String(400), nullable=False),
    sa.Column("expires_at", sa.DateTime(timezone=True), nullable=False),
)

#: the claims that may find a launching user on the roster
USER_CLAIMS = ("email", "sub", "sourcedid")


@dataclass(frozen=True)
class Platform:
    """A registered platform (an LMS): who it is and where it answers."""

    id: int
    issuer: str
    client_id: str
    deployment_ids: tuple[str, ...]
    auth_login_url: str
    token_url: str
    jwks_url: str
    user_claim: str


def _platform(row) -> Platform:
    return Platform(row.id, row.issuer, row.client_id, tuple(json.loads(row.deployment_ids)),
                    row.auth_login_url, row.token_url, row.jwks_url, row.user_claim)


def register(engine: sa.Engine, issuer: str, client_id: str, deployment_ids: list[str],
             auth_login_url: str, token_url: str, jwks_url: str, user_claim: str) -> Platform:
    """Register a platform, or replace the registration of the same issuer and client."""
    values = {"deployment_ids": json.dumps(list(deployment_ids)),
              "auth_login_url": auth_login_url, "token_url": token_url,
              "jwks_url": jwks_url, "user_claim": user_claim}
    with engine.begin() as connection:
        found = connection.execute(sa.select(platforms.c.id).where(
            platforms.c.issuer == issuer, platforms.c.client_id == client_id)).scalar()
        if found is None:
            connection.execute(platforms.insert().values(
                issuer=issuer, client_id=client_id, created_at=db.now(), **values))
        else:
            connection.execute(platforms.update().where(platforms.c.id == found)
                               .values(**values))
    found_platform = find_platform(engine, issuer, client_id)
    assert found_platform is not None
    return found_platform


def find_platform(engine: sa.Engine, issuer: str, client_id: str | None) -> Platform | None:
    """The platform of ``issuer`` (and ``client_id``; None: the issuer's only one)."""
    query = sa.select(platforms).where(platforms.c.issuer == issuer)
    if client_id is not None:
        query = query.where(platforms.c.client_id == client_id)
    with engine.connect() as connection:
        rows = connection.execute(query).all()
    return _platform(rows[0]) if len(rows) == 1 else None


def platform_by_id(engine: sa.Engine, platform_id: int) -> Platform | None:
    with engine.connect() as connection:
        row = connection.execute(sa.select(platforms).where(
            platforms.c.id == platform_id)).first()
    return _platform(row) if row else None


def all_platforms(engine: sa.Engine) -> list[Platform]:
    with engine.connect() as connection:
        return [_platform(row) for row in connection.execute(
            sa.select(platforms).order_by(platforms.c.id))]


# -- the tool's keys ----------------------------------------------------------------------


@dataclass(frozen=True)
class StoredKey:
    kid: str
    private_pem: str
    created_at: dt.datetime


def add_key(engine: sa.Engine, kid: str, private_pem: str) -> None:
    with engine.begin() as connection:
        connection.execute(keys.insert().values(kid=kid, private_pem=private_pem,
                                                created_at=db.now()))


def live_keys(engine: sa.Engine) -> list[StoredKey]:
    """The unretired keys, oldest first (the last one signs)."""
    with engine.connect() as connection:
        rows = connection.execute(sa.select(keys).where(keys.c.retired_at.is_(None))
                                  .order_by(keys.c.created_at, keys.c.kid)).all()
    return [StoredKey(r.kid, r.private_pem, db.utc(r.created_at)) for r in rows]


def retire_keys(engine: sa.Engine, kids: list[str]) -> int:
    """Retire the keys ``kids``; how many were live."""
    with engine.begin() as connection:
        return connection.execute(keys.update().where(
            keys.c.kid.in_(kids), keys.c.retired_at.is_(None)).values(
                retired_at=db.now())).rowcount


# -- logins -------------------------------------------------------------------------------


def add_login(engine: sa.Engine, state: str, nonce: str, platform_id: int,
              expires_at: dt.datetime) -> None:
    with engine.begin() as connection:
        connection.execute(logins.delete().where(logins.c.expires_at < db.now()))
        connection.execute(logins.insert().values(
            state_hash=db.hash_token(state), nonce=nonce, platform_id=platform_id,
            expires_at=expires_at))


def take_login(engine: sa.Engine, state: str, now: dt.datetime) -> tuple[str, int] | None:
    """The nonce and platform of the login ``state`` began, which is used up: a state is
    taken once. None for an unknown, used or expired state."""
    with engine.begin() as connection:
        row = connection.execute(sa.select(logins).where(
            logins.c.state_hash == db.hash_token(state))).first()
        if row is None:
            return None
        taken = connection.execute(logins.delete().where(
            logins.c.state_hash == row.state_hash)).rowcount
    if taken != 1 or db.utc(row.expires_at) < now:
        return None
    return row.nonce, row.platform_id


# -- sessions -----------------------------------------------------------------------------


@dataclass(frozen=True)
class Session:
    """A launched user of one exam."""

    exam_id: str
    platform_id: int
    role: str
    student_id: str | None
    label: str | None
    sub: str


def add_session(engine: sa.Engine, session_id: str, session: Session,
                expires_at: dt.datetime) -> None:
    with engine.begin() as connection:
        connection.execute(sessions.delete().where(sessions.c.expires_at < db.now()))
        connection.execute(sessions.insert().values(
            session_hash=db.hash_token(session_id), exam_id=session.exam_id,
            platform_id=session.platform_id, role=session.role,
            student_id=session.student_id, label=session.label, sub=session.sub,
            expires_at=expires_at))


def find_session(engine: sa.Engine, exam_id: str, session_id: str,
                 now: dt.datetime) -> Session | None:
    """The unexpired session of ``session_id`` in exam ``exam_id``, or None."""
    with engine.connect() as connection:
        row = connection.execute(sa.select(sessions).where(
            sessions.c.session_hash == db.hash_token(session_id),
            sessions.c.exam_id == exam_id)).first()
    if row is None or db.utc(row.expires_at) < now:
        return None
    return Session(row.exam_id, row.platform_id, row.role, row.student_id, row.label,
                   row.sub)
