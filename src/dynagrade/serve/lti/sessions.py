"""The session of a launched user, and what the pages accept in place of a link token.

A launch ends with a session: a random id, stored as its sha256 (``lti_sessions``), set
as the cookie :data:`COOKIE` (``SameSite=None; Secure; HttpOnly``: LTI pages live in the
platform's iframe, a cross-site context). The pages of a launched user are then the
pages of a link whose token is the session's *handle*, ``lti-`` and a digest of the id
(``/s/lti-…``, ``/i/lti-…``): the handle alone opens nothing, the cookie alone names no
page; only together do they (:func:`identity`). Every page, form and CSRF field works
as for a secret link; the handle, which no one else can compute, keys the CSRF fields.
The API accepts the handle as its bearer token together with the cookie, which the
page's script sends along (same origin).
"""

from __future__ import annotations

import datetime as dt
import hashlib
import hmac

import sqlalchemy as sa

from .. import db
from . import store

COOKIE = "dynagrade_lti"
PREFIX = "lti-"
#: how long a launch's session lasts (seconds): a long exam and then some
SESSION_SECONDS = 12 * 3600


def handle(session_id: str) -> str:
    """The token the pages of session ``session_id`` carry in their path."""
    return PREFIX + hashlib.sha256(b"lti-handle:" + session_id.encode()).hexdigest()[:40]


def is_handle(token: str) -> bool:
    return token.startswith(PREFIX)


def identity(engine: sa.Engine, exam_id: str, token: str, cookie: str | None,
             now: dt.datetime) -> db.Identity | None:
    """Who holds the session of ``cookie`` when ``token`` is its handle; None otherwise
    (no cookie, another session's handle, an expired session, another exam)."""
    if not cookie or not hmac.compare_digest(handle(cookie), token):
        return None
    session = store.find_session(engine, exam_id, cookie, now)
    if session is None:
        return None
    return db.Identity(session.role, session.student_id, session.label)


def start(engine: sa.Engine, session: store.Session, now: dt.datetime) -> str:
    """A new session's id (the cookie's value)."""
    session_id = db.new_token()
    store.add_session(engine, session_id, session,
                      now + dt.timedelta(seconds=SESSION_SECONDS))
    return session_id
