"""A launch (the id_token the platform posts to ``/lti/launch``) turned into a session.

The state posted must be the state cookie of this browser and a login of this tool not
used before and not expired; it names the platform and the nonce the id_token must
carry (:mod:`.verify`). The roles then decide: staff get a session of their own (named
by the token's ``name``, for the audit log); a learner gets the session of the roster
student the platform's ``user_claim`` finds (:mod:`.roster_match`), and one the roster
does not hold is refused with a page saying so (403). A student's launch also records
them for the grade service, with the AGS endpoint it names (:mod:`.grade_sync`); any
launch records where the platform lists the course's members (:mod:`.roster_import`).
A deep-linking request (staff only) keeps its settings with the teacher's session for
the page where they choose what to place (:mod:`.deep_linking`). What the user opens next is the
student or staff page of the session's handle (:mod:`.sessions`).
"""

from __future__ import annotations

import datetime as dt
import hmac
from dataclasses import dataclass
from typing import Mapping

import sqlalchemy as sa

from ...i18n import _
from . import claims, deep_linking, grades_store, sessions, store
from .refusals import LaunchRefused
from .roster_match import claimed_value, roster_student
from .verify import verified_claims


@dataclass(frozen=True)
class Launched:
    """A started session: its id (the cookie), who it is, whether it came to place
    content (deep linking), and the exercise the resource link names (``custom``
    ``exercise``: a practice exercise placed by deep linking)."""

    session_id: str
    session: store.Session
    placing: bool = False
    exercise: str | None = None


def platform_and_nonce(engine: sa.Engine, state: str, state_cookie: str | None,
                       now: dt.datetime) -> tuple[store.Platform, str]:
    """The platform and nonce of the login ``state`` began in this browser (used up)."""
    stale = LaunchRefused(_("the sign-in has expired or was begun in another browser "
                            "window; open the activity from the course again"))
    if not state or not state_cookie or not hmac.compare_digest(state, state_cookie):
        raise stale
    taken = store.take_login(engine, state, now)
    platform = store.platform_by_id(engine, taken[1]) if taken else None
    if taken is None or platform is None:
        raise stale
    return platform, taken[0]


def launch(engine: sa.Engine, exam_id: str, students: Mapping[str, object], id_token: str,
           state: str, state_cookie: str | None, now: dt.datetime) -> Launched:
    """The session a launch starts; :class:`LaunchRefused` as the module says."""
    platform, nonce = platform_and_nonce(engine, state, state_cookie, now)
    found = verified_claims(id_token, platform, nonce)
    role = claims.role_of(found.get(claims.ROLES))
    if role is None:
        raise LaunchRefused(_("your role in this course gives no access to the exam "
                              "server"), 403, _("No access"))
    service = found.get(claims.NRPS_CLAIM)
    if isinstance(service, dict) and isinstance(service.get("context_memberships_url"), str):
        grades_store.put_memberships_url(engine, exam_id, platform.id,
                                         service["context_memberships_url"])
    placing = found.get(claims.MESSAGE_TYPE) == claims.DEEP_LINKING_REQUEST
    request = deep_linking.request_of(found, platform.id) if placing else None
    if placing and (role != claims.STAFF or request is None):
        raise LaunchRefused(_("only the course's teachers place the exam server's content, "
                              "as a link to it"), 403, _("No access"))
    session = staff_session(exam_id, platform, found) if role == claims.STAFF \
        else student_session(engine, exam_id, students, platform, found, now)
    session_id = sessions.start(engine, session, now)
    if request is not None:
        deep_linking.keep(engine, session_id, request)
    custom = found.get(claims.CUSTOM)
    exercise = custom.get("exercise") if isinstance(custom, dict) else None
    return Launched(session_id, session, placing,
                    exercise if isinstance(exercise, str) else None)


def staff_session(exam_id: str, platform: store.Platform, found: dict) -> store.Session:
    """A teacher's session, named for the audit log by the name the platform sends."""
    sub = str(found["sub"])
    name = found.get("name") or found.get("email") or sub
    return store.Session(exam_id, platform.id, claims.STAFF, None,
                         f"{str(name)[:180]} (LTI)", sub)


def student_session(engine: sa.Engine, exam_id: str, students: Mapping[str, object],
                    platform: store.Platform, found: dict, now: dt.datetime) -> store.Session:
    """The session of the roster student the launch names (recorded for the grade
    service); :class:`LaunchRefused` (403) for one the roster does not hold."""
    student_id = roster_student(students, found, platform.user_claim)
    if student_id is None:
        raise LaunchRefused(
            _("you are not on this exam's roster (looked up by {claim}: {value}); "
              "ask the course staff to add you").format(
                claim=platform.user_claim,
                value=claimed_value(found, platform.user_claim) or _("none sent")),
            403, _("Not on the roster"))
    grades_store.put_member(engine, member(exam_id, platform.id, student_id, found), now)
    return store.Session(exam_id, platform.id, claims.STUDENT, student_id, None,
                         str(found["sub"]))


def member(exam_id: str, platform_id: int, student_id: str, found: dict
           ) -> grades_store.Member:
    """A launched student as the grade service needs them: their ``sub``, the resource
    link, and the AGS endpoint the launch named (URLs and scopes; none without it)."""
    link = found.get(claims.RESOURCE_LINK)
    endpoint = found.get(claims.AGS_ENDPOINT)
    endpoint = endpoint if isinstance(endpoint, dict) else {}
    scopes = endpoint.get("scope")

    def text(value: object) -> str | None:
        return value if isinstance(value, str) and value else None

    return grades_store.Member(
        exam_id, platform_id, student_id, str(found["sub"]),
        text(link.get("id")) if isinstance(link, dict) else None,
        text(endpoint.get("lineitems")), text(endpoint.get("lineitem")),
        tuple(s for s in scopes if isinstance(s, str)) if isinstance(scopes, list) else ())
