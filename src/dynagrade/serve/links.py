"""Secret links: one per roster student, and staff links.

The database keeps only each token's sha256, so a link can be shown once, when it is
made. ``write_links`` therefore keeps the rows of an existing ``links.csv`` whose tokens
are still valid, makes tokens for students who have none, and with ``rotate`` revokes
every student token and makes new ones. A student whose token is valid but whose row is
missing from the old file cannot get their link again without ``--rotate``: they are
listed in the returned notices.
"""

from __future__ import annotations

import csv
import io
from pathlib import Path

from . import db
from .exam_data import ExamData

LINK_HEADER = ("student_id", "name", "email", "url")


def student_url(base_url: str, token: str) -> str:
    return f"{base_url.rstrip('/')}/s/{token}"


def staff_url(base_url: str, token: str) -> str:
    return f"{base_url.rstrip('/')}/i/{token}"


def write_links(data: ExamData, engine, out: Path, base_url: str,
                rotate: bool = False) -> list[str]:
    """Write ``out`` (student_id,name,email,url per roster student); returns notices."""
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
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    writer.writerow(LINK_HEADER)
    writer.writerows(rows)
    out.parent.mkdir(parents=True, exist_ok=True)
    temporary = out.with_name(out.name + ".tmp")
    temporary.write_text(buffer.getvalue(), encoding="utf-8")
    temporary.chmod(0o600)  # the links are the students' passwords
    temporary.replace(out)
    if not unknown:
        return []
    return [f"{len(unknown)} students ({', '.join(unknown[:5])}{', ...' if len(unknown) > 5 else ''})"
            f" have links that are not in the earlier {out.name}, so their url is empty; "
            "run with --rotate to make new links for everyone"]


def _previous_urls(path: Path) -> dict[str, str]:
    try:
        rows = list(csv.DictReader(io.StringIO(path.read_text(encoding="utf-8"))))
    except (OSError, UnicodeDecodeError, csv.Error):
        return {}
    return {r.get("student_id", ""): r.get("url", "") for r in rows if r.get("url")}


def _still_valid(engine, exam_id: str, student_id: str, url: str | None) -> str | None:
    if not url or "/s/" not in url:
        return None
    token = url.rsplit("/s/", 1)[1]
    identity = db.identify(engine, exam_id, token)
    if identity is None or identity.student_id != student_id:
        return None
    return url
