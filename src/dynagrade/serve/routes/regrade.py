"""Regrading online: the staff page ``/i/{token}/regrade`` with its forms, and the API
``/api/v1/regrades`` (:mod:`dynagrade.serve.regrade` does the work).

A preview grades every counted answer again in processes of its own (seconds to half a
minute for a large class), so it runs off the event loop; applying reloads this server
process's exam at once (the others follow within seconds, :mod:`dynagrade.serve.reload`).
"""

from __future__ import annotations

from typing import Annotated, Any

from fastapi import APIRouter, Path
from fastapi.responses import HTMLResponse, RedirectResponse
from starlette.concurrency import run_in_threadpool

from .. import regrade, regrade_page
from ..deps import REFUSALS, Now, RootPath, ServerDep, StaffBearer, StaffForm, StaffLink
from ..models import RegradePlan, problem
from ..state import Server
from ..submit import Refused

pages = APIRouter(prefix="/i/{token}/regrade", tags=["staff pages"], responses=REFUSALS)
api = APIRouter(prefix="/api/v1/regrades", tags=["api"], responses=REFUSALS)

RegradeId = Annotated[int, Path(ge=1, description="the regrade's id (from the preview)")]

_REFUSED: dict[int | str, dict[str, Any]] = {
    404: problem("no such regrade in this exam"),
    409: problem("the regrade was discarded (apply) or applied (discard), the manifest or "
                 "an exercise file changed since the preview, or an answer no longer holds "
                 "the plan's old verdict: preview again")}
_PREVIEW_REFUSED: dict[int | str, dict[str, Any]] = {
    422: problem("the manifest or an exercise file on disk cannot be loaded or graded")}


async def _apply(server: Server, regrade_id: int, actor: str):
    found, done = await run_in_threadpool(regrade.apply, server, regrade_id, actor)
    if server.catch_up is not None:  # this process grades new submits by the plan at once
        await server.catch_up()
    return found, done


# -- the staff page -----------------------------------------------------------------------


@pages.get("", response_class=HTMLResponse)
def regrade_page_view(caller: StaffLink, server: ServerDep, now: Now, base: RootPath,
                      applied: int | None = None) -> HTMLResponse:
    """The regrade page: "Preview regrade", the open plan's table with "Apply" and
    "Discard", the earlier regrades; ``applied``: the plan just applied, said in a
    sentence."""
    return HTMLResponse(regrade_page.regrade_html(server, caller.token, now, base,
                                                  applied=applied))


async def _page_again(server: Server, token: str, now, base: str, error: Refused):
    page = await run_in_threadpool(regrade_page.regrade_html, server, token, now, base,
                                   error.message)
    return HTMLResponse(page, status_code=error.status)


_FORM: dict[int | str, dict[str, Any]] = {
    303: {"description": "done: back to the regrade page (`Location`)"},
    403: problem("a missing or wrong CSRF field")}


@pages.post("/preview", status_code=303, response_class=RedirectResponse, responses={
    **_FORM, 422: {"description": "refused: the page again with the reason",
                   "content": {"text/html": {"schema": {"type": "string"}}}}})
async def preview_form(form: StaffForm, server: ServerDep, now: Now, base: RootPath):
    """Grade every counted answer again against the files on disk; back to the page with
    the plan."""
    try:
        await run_in_threadpool(regrade.preview, server, form.caller.actor)
    except Refused as error:
        return await _page_again(server, form.caller.token, now, base, error)
    return RedirectResponse(f"{base}/i/{form.caller.token}/regrade#plan", status_code=303)


@pages.post("/{regrade_id}/apply", status_code=303, response_class=RedirectResponse,
            responses={**_FORM, 404: _REFUSED[404], 409: _REFUSED[409]})
async def apply_form(form: StaffForm, regrade_id: RegradeId, server: ServerDep, now: Now,
                     base: RootPath):
    """Apply the plan (one transaction; repeating it does nothing); back to the page,
    which says what changed."""
    try:
        await _apply(server, regrade_id, form.caller.actor)
    except Refused as error:
        return await _page_again(server, form.caller.token, now, base, error)
    return RedirectResponse(f"{base}/i/{form.caller.token}/regrade?applied={regrade_id}"
                            "#result", status_code=303)


@pages.post("/{regrade_id}/discard", status_code=303, response_class=RedirectResponse,
            responses={**_FORM, 404: _REFUSED[404], 409: _REFUSED[409]})
async def discard_form(form: StaffForm, regrade_id: RegradeId, server: ServerDep, now: Now,
                       base: RootPath):
    """Discard the plan; back to the page."""
    try:
        await run_in_threadpool(regrade.discard, server, regrade_id, form.caller.actor)
    except Refused as error:
        return await _page_again(server, form.caller.token, now, base, error)
    return RedirectResponse(f"{base}/i/{form.caller.token}/regrade", status_code=303)


# -- the API ------------------------------------------------------------------------------


@api.post("", responses=_PREVIEW_REFUSED)
async def preview_regrade(caller: StaffBearer, server: ServerDep) -> RegradePlan:
    """Preview a regrade: every counted answer graded again against the manifest and the
    exercise files as they are on disk; the plan of the verdicts that would change is
    kept (state "previewed") and returned. Nothing changes until it is applied."""
    found = await run_in_threadpool(regrade.preview, server, caller.actor)
    return RegradePlan.of(found)


@api.get("/{regrade_id}", responses={404: _REFUSED[404]})
def get_regrade(caller: StaffBearer, regrade_id: RegradeId, server: ServerDep) -> RegradePlan:
    """A regrade, its state and its plan."""
    found = regrade.find(server, regrade_id)
    return RegradePlan.of(found, answers_since=regrade.answers_since(server, found))


@api.post("/{regrade_id}/apply", responses=_REFUSED)
async def apply_regrade(caller: StaffBearer, regrade_id: RegradeId,
                        server: ServerDep) -> RegradePlan:
    """Apply a previewed regrade in one transaction (the old verdicts are kept in the
    verdict history; recorded in the audit log); applying it again does nothing
    (``done``: false)."""
    found, done = await _apply(server, regrade_id, caller.actor)
    return RegradePlan.of(found, done=done, answers_since=regrade.answers_since(server, found))


@api.post("/{regrade_id}/discard", responses={404: _REFUSED[404],
                                              409: problem("the regrade was applied")})
async def discard_regrade(caller: StaffBearer, regrade_id: RegradeId,
                          server: ServerDep) -> RegradePlan:
    """Discard a previewed regrade (recorded in the audit log); again: nothing."""
    found, done = await run_in_threadpool(regrade.discard, server, regrade_id, caller.actor)
    return RegradePlan.of(found, done=done)


#: the routers of this module (:data:`dynagrade.serve.routes.ROUTERS`)
ROUTERS = (pages, api)
