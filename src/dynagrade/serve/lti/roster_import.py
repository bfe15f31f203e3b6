"""The course's members imported from the platform (NRPS 2.0) and merged with the
exam's roster by the registration's claim (:mod:`.roster_match`).

The roster is the exam's: every student on it has variants generated for them
(``dynagrade exam``), so the server cannot add a student while it runs. Importing
therefore merges the other way round: each learner the platform lists is looked up on
the roster by the claim; one who is found is linked (recorded for the grade service,
so their score reaches the platform even before they open the activity), one who is not
is listed (the staff add them to roster.csv, and ``dynagrade lti roster -o`` writes the
rows to add); the roster's students the platform does not list are listed too.

The members are read page by page (``Link: <…>; rel="next"``), with an access token for
the membership scope (:mod:`.access`).
"""

from __future__ import annotations

import datetime as dt
import re
from dataclasses import dataclass, field
from typing import Mapping

import sqlalchemy as sa

from ...errors import DynagradeError
from ...i18n import _
from . import access, claims, grades_store, http, store
from .roster_match import roster_student

#: the most pages of members read (a course of 100 000 members in pages of 100)
MAX_PAGES = 1000


class ImportFailed(DynagradeError):
    """No members imported; the message says why. ``status``: 502 when the platform
    failed to list them, 200 when no platform has told where it lists them yet
    (nothing failed: there is nothing to import from)."""

    def __init__(self, message: str, status: int = 502):
        super().__init__(message)
        self.status = status


@dataclass(frozen=True)
class Learner:
    """A learner the platform lists: their user id there, name, email, ID number."""

    sub: str
    name: str
    email: str
    sourcedid: str

    def as_claims(self) -> dict:
        """The learner as an id_token would name them (for :mod:`.roster_match`)."""
        return {"sub": self.sub, "email": self.email,
                claims.LIS: {"person_sourcedid": self.sourcedid}}


@dataclass
class RosterImport:
    """What an import found: learners linked to roster students (newly or before),
    learners the roster lacks, roster students the platform does not list."""

    linked: list[tuple[str, Learner]] = field(default_factory=list)
    new_links: int = 0
    unknown: list[Learner] = field(default_factory=list)
    unlisted: list[str] = field(default_factory=list)


def _next_page(answer: http.Answer) -> str | None:
    link = next((v for k, v in answer.headers.items() if k.lower() == "link"), "")
    found = re.search(r'<([^>]+)>\s*;\s*rel="?next"?', link)
    return found.group(1) if found else None


def fetch_learners(engine: sa.Engine, platform: store.Platform, url: str) -> list[Learner]:
    """The active learners the platform lists at ``url``."""
    try:
        token = access.access_token(engine, platform, (claims.NRPS_SCOPE,))
    except access.NoAccess as error:
        raise ImportFailed(str(error)) from None
    learners: list[Learner] = []
    next_url: str | None = url
    for _page in range(MAX_PAGES):
        if next_url is None:
            break
        answer = http.request("GET", next_url, {"Authorization": f"Bearer {token}",
                                                "Accept": claims.MEMBERSHIPS_MEDIA})
        try:
            members = answer.json().get("members") if answer.ok else None
        except (ValueError, AttributeError):
            members = None
        if not isinstance(members, list):
            raise ImportFailed(_("the course platform did not list its members: {status} "
                                 "{text}").format(status=answer.status, text=answer.text[:200]))
        for member in members:
            if not isinstance(member, dict) or member.get("status", "Active") != "Active" \
                    or claims.role_of(member.get("roles")) != claims.STUDENT:
                continue
            learners.append(Learner(str(member.get("user_id", "")), str(member.get("name", "")),
                                    str(member.get("email", "")),
                                    str(member.get("lis_person_sourcedid", ""))))
        next_url = _next_page(answer)
    return learners


def merge(engine: sa.Engine, exam_id: str, students: Mapping[str, object],
          platform: store.Platform, learners: list[Learner], now: dt.datetime) -> RosterImport:
    """Link each learner the roster holds (by the platform's claim); list the rest."""
    found = RosterImport()
    listed = set()
    for learner in learners:
        student_id = roster_student(students, learner.as_claims(), platform.user_claim)
        if student_id is None or not learner.sub:
            found.unknown.append(learner)
            continue
        listed.add(student_id)
        found.linked.append((student_id, learner))
        found.new_links += grades_store.link_member(engine, exam_id, platform.id, student_id,
                                                    learner.sub, now)
    found.unlisted = [s for s in students if s not in listed]
    return found


def import_roster(engine: sa.Engine, exam_id: str, students: Mapping[str, object],
                  now: dt.datetime) -> RosterImport:
    """Import from every platform a launch told the members' address of (one, as a
    rule); :class:`ImportFailed` when there is none or one fails."""
    urls = grades_store.memberships_urls(engine, exam_id)
    if not urls:
        raise ImportFailed(_("no course platform has told where it lists its members "
                             "yet; open the activity from the course once, as a teacher"),
                           200)
    learners: list[tuple[store.Platform, list[Learner]]] = []
    for platform_id, url in urls.items():
        platform = store.platform_by_id(engine, platform_id)
        if platform is not None:
            learners.append((platform, fetch_learners(engine, platform, url)))
    result = RosterImport(unlisted=list(students))
    for platform, listed in learners:
        merged = merge(engine, exam_id, students, platform, listed, now)
        result.linked += merged.linked
        result.new_links += merged.new_links
        result.unknown += merged.unknown
        result.unlisted = [s for s in result.unlisted if s in merged.unlisted]
    return result
