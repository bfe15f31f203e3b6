"""LTI 1.3: ``/lti/login`` (login initiation), ``/lti/launch`` (the id_token posted
back) and ``/lti/jwks`` (the tool's public keys). No token: the platform's signed
id_token, the state cookie and the stored state and nonce decide
(:mod:`dynagrade.serve.lti`). A launch ends in a redirect to the student's or staff page
of the new session's handle, the session's cookie set (at the exercise a practice
link names; a deep-linking request: at the teacher's page of what to place)."""

from __future__ import annotations

from typing import Any

from fastapi import APIRouter, Request
from fastapi.responses import HTMLResponse, JSONResponse, RedirectResponse, Response
from starlette.concurrency import run_in_threadpool

from ...i18n import _
from .. import pages
from ..deps import Now, RootPath, ServerDep
from ..lti import keys, login, sessions
from ..lti.launch import launch
from ..lti.refusals import LaunchRefused
from ..models import KeySet
from ..state import Server

router = APIRouter(prefix="/lti", tags=["LTI 1.3"])

_REFUSED: dict[int | str, dict[str, Any]] = {
    code: {"description": why, "content": {"text/html": {"schema": {"type": "string"}}}}
    for code, why in ((400, "an unknown platform or an incomplete request: a page"),
                      (401, "a token, state or nonce that does not verify: a page"),
                      (403, "a role without access, or a user not on the roster: a page"))}


def tool_url(server: Server, request: Request, path: str) -> str:
    """The public URL of the tool's ``path`` (``--base-url``'s, else the request's)."""
    base = server.settings.base_url.rstrip("/") or str(request.base_url).rstrip("/")
    return f"{base}{path}"


def _cookie_path(base: str) -> str:
    return f"{base}/" if base else "/"


def refused_page(server: Server, error: LaunchRefused, base: str) -> HTMLResponse:
    """The page of a refused login or launch (framable by the platforms: it is shown
    in their iframe)."""
    title = error.title or _("The course platform's sign-in was refused")
    return HTMLResponse(pages.render("lti_refused.html", title=title, message=error.message,
                                     language=server.data.manifest.exam.language,
                                     base=base), status_code=error.status)


async def _login(request: Request, server: Server, now, base: str,
                 params: dict[str, str]) -> Response:
    try:
        started = await run_in_threadpool(login.initiate, server.engine, params,
                                          tool_url(server, request, "/lti/launch"), now)
    except LaunchRefused as error:
        return refused_page(server, error, base)
    answer = RedirectResponse(started.redirect, status_code=303)
    answer.set_cookie(login.STATE_COOKIE, started.state, max_age=login.LOGIN_SECONDS,
                      path=f"{base}/lti/", secure=True, httponly=True, samesite="none")
    return answer


@router.get("/login", status_code=303, response_class=RedirectResponse,
            responses={303: {"description": "to the platform's authorization URL"},
                       **_REFUSED})
async def login_by_get(request: Request, server: ServerDep, now: Now, base: RootPath):
    """OIDC login initiation, its parameters in the query."""
    return await _login(request, server, now, base, dict(request.query_params))


@router.post("/login", status_code=303, response_class=RedirectResponse,
             responses={303: {"description": "to the platform's authorization URL"},
                        **_REFUSED})
async def login_by_post(request: Request, server: ServerDep, now: Now, base: RootPath):
    """OIDC login initiation, its parameters in a posted form."""
    form = await request.form()
    return await _login(request, server, now, base,
                        {k: str(v) for k, v in form.items() if isinstance(v, str)})


@router.post("/launch", status_code=303, response_class=RedirectResponse,
             responses={303: {"description": "to the launched user's page"}, **_REFUSED})
async def launch_posted(request: Request, server: ServerDep, now: Now, base: RootPath):
    """The platform's id_token and state (a form post): a session, then its page."""
    form = await request.form()
    id_token, state = str(form.get("id_token") or ""), str(form.get("state") or "")
    data = server.data
    try:
        launched = await run_in_threadpool(
            launch, server.engine, data.exam_id, data.students, id_token, state,
            request.cookies.get(login.STATE_COOKIE), now)
    except LaunchRefused as error:
        return refused_page(server, error, base)
    handle = sessions.handle(launched.session_id)
    if launched.placing:
        where = f"i/{handle}/lti/place"
    elif launched.session.role == "student":
        exercise = launched.exercise if launched.exercise in data.exercises_meta else None
        where = f"s/{handle}" + (f"#{exercise}" if exercise else "")
    else:
        where = f"i/{handle}"
    answer = RedirectResponse(f"{base}/{where}", status_code=303)
    answer.set_cookie(sessions.COOKIE, launched.session_id, max_age=sessions.SESSION_SECONDS,
                      path=_cookie_path(base), secure=True, httponly=True, samesite="none")
    answer.delete_cookie(login.STATE_COOKIE, path=f"{base}/lti/", secure=True,
                         httponly=True, samesite="none")
    return answer


@router.get("/jwks", response_model=KeySet)
async def tool_jwks(server: ServerDep) -> JSONResponse:
    """The tool's public key set, which platforms verify its signatures with."""
    return JSONResponse(await run_in_threadpool(keys.jwks, server.engine))
