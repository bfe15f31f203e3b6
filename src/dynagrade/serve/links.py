"""Secret links: one per roster student, and staff links.

The database keeps only each token's sha256, so a link can be shown once, when it is
made. ``write_links`` therefore keeps the rows of an existing ``links.csv`` whose tokens
are still valid, makes tokens for students who have none, and with ``rotate`` revokes
every student token and makes new ones. A student whose token is valid but whose row is
missing from the old file cannot get their link again without ``--rotate``: they are
listed in the returned notices.

Staff links have a name ("Anna (TA)"), which the audit log shows as who made a change,
and an id (the start of the token's hash) by which lists show them and commands and the
staff page revoke them (:func:`add_staff_link`, :func:`revoke_staff_links`; both recorded
in the audit log). A revoked link is refused by every server process within
:data:`REVOKED_WITHIN` seconds: each process remembers a token it has seen for at most
that long (:class:`~dynagrade.serve.limits.RecentlySeen`), and the process that revokes
forgets at once.
"""

from __future__ import annotations

import csv
import io
from pathlib import Path

from ..errors import DynagradeError
from ..exam.csvcells import csv_text, restored_rows
from ..i18n import _
from ..runs.files import refuse_unless_replaceable, write_atomic
from . import db, limits
from .exam_data import ExamData

LINK_HEADER = ("student_id", "name", "email", "url")
#: the audit log's action for a staff link made or revoked (subject: the link's id)
STAFF_LINK_CHANGE = "staff-link"
#: the longest a revoked link keeps opening pages in another server process (seconds)
REVOKED_WITHIN = limits.REMEMBER_SECONDS
#: the longest name a staff link may have
MAX_LABEL = 100


def student_url(base_url: str, token: str) -> str:
    return f"{base_url.rstrip('/')}/s/{token}"


def staff_url(base_url: str, token: str) -> str:
    return f"{base_url.rstrip('/')}/i/{token}"


def write_links(data: ExamData, engine, out: Path, base_url: str,
                rotate: bool = False) -> list[str]:
    """Write ``out`` (student_id,name,email,url per roster student), readable by its
    owner only (the links are the students' passwords); returns notices. A target that
    is no regular file is refused before any token is issued or revoked."""
    refuse_unless_replaceable(out)
    previous = {} if rotate else _previous_urls(out)
    issued = db.issue_tokens(engine, data.exam_id, list(data.students), rotate=rotate)
    rows: list[tuple[str, str, str, str]] = []
    unknown: list[str] = []
    for student_id, student in data.students.items():
        token = issued[student_id]
        kept = None if token is not None else \
            _still_valid(engine, data.exam_id, student_id, previous.get(student_id))
        if token is not None:
            url = student_url(base_url, token)
        elif kept is not None:
            url = kept
        else:
            unknown.append(student_id)
            url = ""
        rows.append((student_id, student.name, student.email, url))
    write_atomic(out, csv_text([LINK_HEADER, *rows]), private=True)
    if not unknown:
        return []
    return [f"{len(unknown)} students ({', '.join(unknown[:5])}{', ...' if len(unknown) > 5 else ''})"
            f" have links that are not in the earlier {out.name}, so their url is empty; "
            "run with --rotate to make new links for everyone"]


def _previous_urls(path: Path) -> dict[str, str]:
    try:
        rows = restored_rows(csv.reader(io.StringIO(path.read_text(encoding="utf-8"),
                                                    newline="")))
    except (OSError, UnicodeDecodeError, csv.Error):
        return {}
    records = [dict(zip(rows[0], row)) for row in rows[1:]] if rows else []
    return {r.get("student_id", ""): r.get("url", "") for r in records if r.get("url")}


def _still_valid(engine, exam_id: str, student_id: str, url: str | None) -> str | None:
    if not url or "/s/" not in url:
        return None
    token = url.rsplit("/s/", 1)[1]
    identity = db.identify(engine, exam_id, token)
    if identity is None or identity.student_id != student_id:
        return None
    return url


class LinkError(DynagradeError, ValueError):
    """A staff link that cannot be made or revoked as asked; the message says why."""


def add_staff_link(engine, exam_id: str, label: str | None, actor: str) -> str:
    """A new staff link's token, named ``label``; recorded in the audit log."""
    name = (label or "").strip() or None
    if name is not None and (len(name) > MAX_LABEL or not name.isprintable()):
        raise LinkError(_("a staff link's name is at most {n} printable characters")
                        .format(n=MAX_LABEL))
    token = db.issue_staff_token(engine, exam_id, name)
    db.record_change(engine, exam_id, actor, STAFF_LINK_CHANGE, db.link_id(token), None,
                     {"name": name, "revoked": False})
    return token


def revoke_staff_links(engine, exam_id: str, ids: list[str] | None, actor: str,
                       keep: str | None = None) -> list[db.StaffLinkRecord]:
    """Revoke the staff links named by ``ids`` (``None``: all but ``keep``, a token
    whose link stays); each recorded in the audit log. Revoking a link revoked before
    changes nothing. :class:`LinkError` for an id no staff link has."""
    known = {link.id: link for link in db.staff_links(engine, exam_id)}
    if ids is not None:
        unknown = [i for i in ids if i not in known]
        if unknown:
            raise LinkError(_("no staff link {ids}; the links are {known}").format(
                ids=", ".join(unknown), known=", ".join(known) or _("none")))
    else:
        ids = [i for i in known if keep is None or i != db.link_id(keep)]
    revoked = db.revoke_staff_links(engine, exam_id, ids)
    for link in revoked:
        db.record_change(engine, exam_id, actor, STAFF_LINK_CHANGE, link.id,
                         {"name": link.label, "revoked": False},
                         {"name": link.label, "revoked": True})
    return revoked
