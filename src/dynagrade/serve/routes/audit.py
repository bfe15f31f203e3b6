"""The audit log: a page (``/i/{token}/audit``, filtered by action), ``audit.csv``, and
JSON under ``/api/v1/audit`` (:mod:`dynagrade.serve.audit`)."""

from __future__ import annotations

from fastapi import APIRouter
from fastapi.responses import HTMLResponse

from .. import audit, db, moments, pages
from ..deps import REFUSALS, RootPath, ServerDep, StaffBearer, StaffLink
from ..downloads import CsvResponse, csv_download
from ..models import AuditEntryModel, AuditLog
from ..state import Server

pages_router = APIRouter(prefix="/i/{token}", tags=["staff pages"], responses=REFUSALS)
api_router = APIRouter(prefix="/api/v1", tags=["api"], responses=REFUSALS)


@pages_router.get("/audit", response_class=HTMLResponse)
def audit_page(caller: StaffLink, server: ServerDep, base: RootPath,
               action: str | None = None) -> HTMLResponse:
    """Who changed what and when, newest first; ``action`` shows one kind of change."""
    data = server.data
    zone = moments.exam_zone(data.policy)
    known = sorted({e.action for e in db.changes(server.engine, data.exam_id)})
    chosen = action if action in known else None
    entries = db.changes(server.engine, data.exam_id, chosen, limit=audit.PAGE_ENTRIES)
    rows = [{"at": moments.moment(e.at, zone, seconds=True), "actor": e.actor,
             "action": e.action, "subject": e.subject, "change": audit.change_text(e)}
            for e in entries]
    return HTMLResponse(pages.render(
        "audit.html", title=data.title, token=caller.token, base=base,
        language=data.manifest.exam.language, rows=rows, actions=known, chosen=chosen,
        limit=audit.PAGE_ENTRIES))


@pages_router.get("/audit.csv", response_class=CsvResponse)
def audit_csv_page(caller: StaffLink, server: ServerDep) -> CsvResponse:
    """Every entry of the audit log, oldest first (CSV)."""
    return _audit_csv(server)


@api_router.get("/audit.csv", response_class=CsvResponse)
def audit_csv_api(caller: StaffBearer, server: ServerDep) -> CsvResponse:
    """Every entry of the audit log, oldest first (CSV)."""
    return _audit_csv(server)


@api_router.get("/audit")
def audit_json(caller: StaffBearer, server: ServerDep,
               action: str | None = None) -> AuditLog:
    """Every entry of the audit log (of ``action``, if given), newest first."""
    entries = db.changes(server.engine, server.data.exam_id, action)
    return AuditLog(entries=[AuditEntryModel.of(entry) for entry in entries])


def _audit_csv(server: Server) -> CsvResponse:
    entries = db.changes(server.engine, server.data.exam_id)
    text = audit.audit_csv(entries, moments.exam_zone(server.data.policy))
    return csv_download(text, "audit.csv")
