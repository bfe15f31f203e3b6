"""Staff links: listed, made and revoked from the staff pages (``/i/{token}/links``) and
the API (``/api/v1/staff-links``), as :mod:`dynagrade.serve.links` says.

A new link's address is shown once, on the page that answers the form (never in a URL the
browser keeps). The link in use cannot revoke itself: another staff link, or ``dynagrade
links --revoke-staff``, can. Every change is in the audit log.
"""

from __future__ import annotations

import datetime as dt

from fastapi import APIRouter, HTTPException, Request
from fastapi.responses import HTMLResponse
from starlette.concurrency import run_in_threadpool

from ...i18n import _
from .. import db, limits, links, moments, pages
from ..deps import REFUSALS, Caller, Now, RootPath, ServerDep, StaffBearer, StaffForm, \
    StaffLink
from ..models import NewStaffLink, NewStaffLinkBody, StaffLinkInfo, StaffLinks, problem
from ..state import Server

pages_router = APIRouter(prefix="/i/{token}/links", tags=["staff pages"], responses=REFUSALS)
api_router = APIRouter(prefix="/api/v1/staff-links", tags=["api"], responses=REFUSALS)

_REFUSED = {"description": "refused: the page again, with the reason",
            "content": {"text/html": {"schema": {"type": "string"}}}}


@pages_router.get("", response_class=HTMLResponse)
def links_page(caller: StaffLink, server: ServerDep, now: Now, base: RootPath) -> HTMLResponse:
    """Every staff link (id, name, when made, revoked or not), a form to make one, and a
    button to revoke each other one."""
    return HTMLResponse(_page(server, caller, now, base))


@pages_router.post("", response_class=HTMLResponse, responses={
    403: problem("a missing or wrong CSRF field"), 422: _REFUSED})
async def make_link(request: Request, form: StaffForm, server: ServerDep, now: Now,
                    base: RootPath) -> HTMLResponse:
    """Make a staff link named by the field ``name``; the answer shows its address once."""
    name = str(form.fields.get("name", ""))
    try:
        token = await run_in_threadpool(links.add_staff_link, server.engine,
                                        server.data.exam_id, name, form.caller.actor)
    except links.LinkError as error:
        return HTMLResponse(_page(server, form.caller, now, base, error=str(error),
                                  typed=name), status_code=422)
    made = links.staff_url(_public_base(request, server), token)
    return HTMLResponse(_page(server, form.caller, now, base, made=made))


@pages_router.post("/revoke", response_class=HTMLResponse, responses={
    403: problem("a missing or wrong CSRF field"), 422: _REFUSED})
async def revoke_link(form: StaffForm, server: ServerDep, now: Now,
                      base: RootPath) -> HTMLResponse:
    """Revoke the staff link with the id in the field ``link``: refused here at once, by
    every server within 30 seconds."""
    try:
        revoked = await _revoke(server, form.caller, str(form.fields.get("link", "")))
    except links.LinkError as error:
        return HTMLResponse(_page(server, form.caller, now, base, error=str(error)),
                            status_code=422)
    done = _("Revoked {link}.").format(link=_named(revoked)) if revoked else \
        _("That link was revoked already.")
    return HTMLResponse(_page(server, form.caller, now, base, done=done))


@api_router.get("")
def list_links(caller: StaffBearer, server: ServerDep) -> StaffLinks:
    """Every staff link of the exam, oldest first (never a token)."""
    return StaffLinks(links=[StaffLinkInfo.of(link) for link in db.staff_links(
        server.engine, server.data.exam_id)])


@api_router.post("", status_code=201, responses={422: problem("a name that is too long")})
async def add_link(request: Request, caller: StaffBearer, body: NewStaffLinkBody,
                   server: ServerDep) -> NewStaffLink:
    """Make a staff link; the answer holds its token and address, shown only this once."""
    try:
        token = await run_in_threadpool(links.add_staff_link, server.engine,
                                        server.data.exam_id, body.name, caller.actor)
    except links.LinkError as error:
        raise HTTPException(422, str(error)) from None
    return NewStaffLink(id=db.link_id(token), name=(body.name or "").strip() or None,
                        token=token, url=links.staff_url(_public_base(request, server), token))


@api_router.delete("/{link_id}", responses={
    404: problem("no staff link has this id"),
    409: problem("the link that asks cannot revoke itself")})
async def delete_link(link_id: str, caller: StaffBearer, server: ServerDep) -> StaffLinkInfo:
    """Revoke a staff link (a link revoked before stays as it was)."""
    try:
        await _revoke(server, caller, link_id)
    except links.LinkError as error:
        status = 409 if link_id == db.link_id(caller.token) else 404
        raise HTTPException(status, str(error)) from None
    found = next(link for link in db.staff_links(server.engine, server.data.exam_id)
                 if link.id == link_id)
    return StaffLinkInfo.of(found)


async def _revoke(server: Server, caller: Caller, link_id: str) -> list[db.StaffLinkRecord]:
    """Revoke ``link_id`` for ``caller`` and forget every token this process knew, so
    that the link is refused here at once."""
    if link_id == db.link_id(caller.token):
        raise links.LinkError(_("this is the link you are using; revoke it with another "
                                "staff link or with dynagrade links --revoke-staff"))
    revoked = await run_in_threadpool(links.revoke_staff_links, server.engine,
                                      server.data.exam_id, [link_id], caller.actor)
    server.identities.forget_all()
    return revoked


def _named(revoked: list[db.StaffLinkRecord]) -> str:
    return ", ".join(f"{link.id} ({link.label})" if link.label else link.id
                     for link in revoked)


def _public_base(request: Request, server: Server) -> str:
    """The address links start with: ``--base-url``, or the one this request came to."""
    return server.settings.base_url or str(request.base_url)


def _page(server: Server, caller: Caller, now: dt.datetime, base: str, *,
          made: str | None = None, done: str | None = None, error: str | None = None,
          typed: str = "") -> str:
    zone = moments.exam_zone(server.data.policy)
    rows = [{"id": link.id, "name": link.label or "", "mine": link.id == db.link_id(caller.token),
             "made": moments.moment(link.created_at, zone, seconds=True),
             "revoked": moments.moment(link.revoked_at, zone, seconds=True)
             if link.revoked_at else None}
            for link in db.staff_links(server.engine, server.data.exam_id)]
    return pages.render(
        "staff_links.html", title=server.data.title, token=caller.token, base=base,
        language=server.data.manifest.exam.language, links=rows, made=made, done=done,
        error=error, typed=typed, within=round(links.REVOKED_WITHIN),
        csrf=limits.csrf_field(server.secret, caller.token))
