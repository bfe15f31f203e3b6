"""LTI Deep Linking 2.0: a teacher places the exam, or one practice exercise, into the
course from the platform's activity chooser.

The platform launches the tool with an ``LtiDeepLinkingRequest`` (verified like any
launch, :mod:`.verify`; staff only). The request's settings (where to post the answer,
the platform's opaque ``data``) are kept with the teacher's session (``lti_deep_links``)
and the teacher chooses on a staff page what to place. The answer is an
``LtiDeepLinkingResponse``: a JWT the tool signs with its key (:mod:`.keys`), issuer its
client id, audience the platform's issuer, the deployment and the ``data`` echoed, and
one content item, an ``ltiResourceLink`` to the tool's launch URL: the whole exam (with
a ``lineItem`` of the exam's points, so the platform makes its gradebook column), or a
practice exercise (``custom.exercise`` names it; the launch opens the student's page at
it; no grade). The browser posts it to the platform (``JWT`` field of a form).
"""

from __future__ import annotations

import datetime as dt
import secrets
from dataclasses import dataclass

import sqlalchemy as sa

from .. import db
from . import claims, keys, store

deep_links = sa.Table(
    "lti_deep_links", db.metadata,
    sa.Column("session_hash", sa.String(64), primary_key=True),
    sa.Column("platform_id", sa.Integer, sa.ForeignKey("lti_platforms.id"), nullable=False),
    sa.Column("deployment_id", sa.String(400), nullable=False),
    sa.Column("return_url", sa.Text, nullable=False),
    sa.Column("data", sa.Text, nullable=True),
    sa.Column("accept_multiple", sa.Boolean, nullable=False),
)

RESPONSE_SECONDS = 300


@dataclass(frozen=True)
class Request:
    """A platform's deep-linking request, waiting for the teacher's choice."""

    platform_id: int
    deployment_id: str
    return_url: str
    data: str | None


def request_of(found: dict, platform_id: int) -> Request | None:
    """The request an id_token's deep-linking settings make (None: no return URL)."""
    settings = found.get(claims.DL_SETTINGS)
    settings = settings if isinstance(settings, dict) else {}
    url = settings.get("deep_link_return_url")
    accepts = settings.get("accept_types")
    if not isinstance(url, str) or not url or \
            (isinstance(accepts, list) and "ltiResourceLink" not in accepts):
        return None
    data = settings.get("data")
    return Request(platform_id, str(found.get(claims.DEPLOYMENT_ID)), url,
                   data if isinstance(data, str) else None)


def keep(engine: sa.Engine, session_id: str, request: Request) -> None:
    """Keep ``request`` with the teacher's session (until it ends)."""
    with db.writing(engine), engine.begin() as connection:
        # the requests of sessions that have ended go
        connection.execute(deep_links.delete().where(deep_links.c.session_hash.not_in(
            sa.select(store.sessions.c.session_hash))))
        connection.execute(deep_links.insert().values(
            session_hash=db.hash_token(session_id), platform_id=request.platform_id,
            deployment_id=request.deployment_id, return_url=request.return_url,
            data=request.data, accept_multiple=False))


def waiting(engine: sa.Engine, session_id: str | None) -> Request | None:
    """The request kept with the session of ``session_id``, if any."""
    if not session_id:
        return None
    with engine.connect() as connection:
        row = connection.execute(sa.select(deep_links).where(
            deep_links.c.session_hash == db.hash_token(session_id))).first()
    return Request(row.platform_id, row.deployment_id, row.return_url, row.data) \
        if row else None


@dataclass(frozen=True)
class Placement:
    """What the teacher chose to place: a title, and the exercise (None: the exam)."""

    title: str
    exercise: str | None = None
    max_points: float | None = None
    exam_id: str | None = None


def content_item(placement: Placement, launch_url: str) -> dict:
    """The ``ltiResourceLink`` content item of ``placement``."""
    item: dict = {"type": "ltiResourceLink", "title": placement.title, "url": launch_url}
    if placement.exercise is not None:
        item["custom"] = {"exercise": placement.exercise}
    if placement.max_points is not None:
        item["lineItem"] = {"scoreMaximum": placement.max_points, "label": placement.title,
                            "resourceId": placement.exam_id}
    return item


def response_jwt(engine: sa.Engine, platform: store.Platform, request: Request,
                 items: list[dict], now: dt.datetime) -> str:
    """The signed ``LtiDeepLinkingResponse`` carrying ``items``."""
    moment = int(now.timestamp())
    found: dict = {
        "iss": platform.client_id, "aud": platform.issuer, "iat": moment,
        "exp": moment + RESPONSE_SECONDS, "nonce": secrets.token_urlsafe(16),
        claims.MESSAGE_TYPE: claims.DEEP_LINKING_RESPONSE, claims.VERSION: claims.LTI_VERSION,
        claims.DEPLOYMENT_ID: request.deployment_id, claims.DL_CONTENT_ITEMS: items}
    if request.data is not None:
        found[claims.DL_DATA] = request.data
    return keys.sign(engine, found)
