"""The teacher's page of a deep-linking request, ``/i/{token}/lti/place``: what to place
in the course (the exam; in practice mode, also one exercise), then the signed answer
posted back to the platform (:mod:`dynagrade.serve.lti.deep_linking`)."""

from __future__ import annotations

from fastapi import APIRouter, Request
from fastapi.responses import HTMLResponse
from starlette.concurrency import run_in_threadpool

from ...i18n import _
from .. import headers, limits, pages
from ..deps import REFUSALS, Now, RootPath, ServerDep, SessionCookie, StaffForm, StaffLink
from ..lti import deep_linking, sessions, store
from ..lti.framing import origin
from ..state import Server
from .lti import tool_url

router = APIRouter(prefix="/i/{token}", tags=["staff pages"], responses=REFUSALS)

EXAM = "exam"


def choices(server: Server) -> list[tuple[str, str]]:
    """(value, label) of what may be placed: the exam, and in practice mode each
    exercise on its own."""
    data = server.data
    found = [(EXAM, _("{title} (all exercises, graded)").format(title=data.title))]
    if data.policy.mode == "practice":
        found += [(f"exercise:{e.id}", _("{title} (practice exercise)").format(title=e.title))
                  for e in data.exercises_meta.values()]
    return found


def placement(server: Server, choice: str) -> deep_linking.Placement | None:
    """The placement a posted ``choice`` names (None: none offered)."""
    data = server.data
    if choice == EXAM:
        return deep_linking.Placement(data.title, None, sum(
            float(m.points) for m in data.exercises_meta.values()), data.exam_id)
    exercise = choice.removeprefix("exercise:")
    if choice.startswith("exercise:") and data.policy.mode == "practice" \
            and exercise in data.exercises_meta:
        return deep_linking.Placement(data.exercises_meta[exercise].title, exercise)
    return None


def _page(server: Server, token: str, base: str, waiting: bool) -> str:
    data = server.data
    return pages.render("lti_place.html", title=data.title, token=token, base=base,
                        language=data.manifest.exam.language, waiting=waiting,
                        choices=choices(server), csrf=limits.csrf_field(server.secret, token))


@router.get("/lti/place", response_class=HTMLResponse)
def place_page(caller: StaffLink, server: ServerDep, base: RootPath,
               cookie: SessionCookie) -> HTMLResponse:
    """What the teacher may place in the course (a deep-linking request waits in their
    session), or a page saying there is no request to answer."""
    request = deep_linking.waiting(server.engine, cookie) \
        if sessions.is_handle(caller.token) else None
    return HTMLResponse(_page(server, caller.token, base, request is not None))


@router.post("/lti/place", response_class=HTMLResponse)
async def place(form: StaffForm, server: ServerDep, now: Now, base: RootPath,
                cookie: SessionCookie, http_request: Request) -> HTMLResponse:
    """The signed deep-linking answer for the chosen content, in a form the page posts
    to the platform at once (a button, without JavaScript)."""
    token = form.caller.token
    request = deep_linking.waiting(server.engine, cookie) if sessions.is_handle(token) else None
    chosen = placement(server, str(form.fields.get("choice") or ""))
    platform = store.platform_by_id(server.engine, request.platform_id) if request else None
    if request is None or platform is None or chosen is None:
        return HTMLResponse(await run_in_threadpool(_page, server, token, base,
                                                    request is not None),
                            status_code=200 if request is None else 422)
    item = deep_linking.content_item(chosen, tool_url(server, http_request, "/lti/launch"))
    signed = await run_in_threadpool(deep_linking.response_jwt, server.engine, platform,
                                     request, [item], now)
    page = pages.render("lti_placed.html", title=server.data.title, base=base,
                        language=server.data.manifest.exam.language,
                        return_url=request.return_url, jwt=signed, placed=chosen.title)
    policy = headers.CONTENT_SECURITY_POLICY.replace(
        "form-action 'self'", f"form-action 'self' {origin(request.return_url) or ''}".rstrip())
    framers = " ".join(server.platform_origins()) or "'none'"
    policy = policy.replace("frame-ancestors 'none'", f"frame-ancestors {framers}")
    return HTMLResponse(page, headers={"content-security-policy": policy})
