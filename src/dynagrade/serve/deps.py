"""The dependencies routes declare: the server's state, and who is calling.

A route says in its signature what it needs and who may call it, e.g.::

    @router.get("/s/{token}")
    def student_page(caller: StudentLink, server: ServerDep) -> HTMLResponse: ...

State (the one :class:`~dynagrade.serve.state.Server` of this worker process):
``ServerDep``, ``Data`` (the exam), ``Pool`` (the grading pool), ``Now`` (the server's
clock), ``RootPath`` (the path the app is served under).

Callers. A token is either in a page's path (``/s/{token}``, ``/i/{token}``:
``LinkToken``) or in the header ``Authorization: Bearer <token>`` (the JSON API:
``BearerToken``). ``StudentLink``, ``StaffLink``, ``StudentBearer`` and ``StaffBearer``
are the :class:`Caller` holding a token of that role, taken from that place, after the
guards, in this order: the token's rate limit (429 with ``Retry-After``), an unknown or
missing token (401), a token of the other role (403). A user launched from an LMS holds
no link: their token is the handle of their LTI session, which counts only together
with the session's cookie (:mod:`dynagrade.serve.lti.sessions`). ``StudentForm``
(``StaffForm``) is a form posted from a student's (a staff) page, after those and the
form's CSRF field (403).
"""

from __future__ import annotations

import datetime as dt
from dataclasses import dataclass, field
from typing import Annotated, Any, Awaitable, Callable

from fastapi import Depends, HTTPException, Path, Request
from fastapi.security import HTTPAuthorizationCredentials, HTTPBearer
from starlette.concurrency import run_in_threadpool
from starlette.datastructures import FormData

from ..i18n import _
from . import db, limits
from .exam_data import ExamData
from .grading_pool import GradingPool
from .lti import sessions as lti_sessions
from .models import problem
from .state import Server

STUDENT, STAFF = "student", "staff"


# -- the server's state -------------------------------------------------------------------


# The dependencies below read the request themselves rather than depend on each other:
# FastAPI solves every dependency of every request again, cached or not, and a class's
# submits and previews pay for each one.


def _server_of(request: Request) -> Server:
    return request.app.state.server


async def server(request: Request) -> Server:
    """This worker's server (set by ``create_app``)."""
    return _server_of(request)


ServerDep = Annotated[Server, Depends(server)]


async def exam_data(request: Request) -> ExamData:
    """The exam this worker serves."""
    return _server_of(request).data


async def grading_pool(request: Request) -> GradingPool:
    """This worker's grading processes."""
    pool = _server_of(request).pool
    if pool is None:  # only between create_app and the app's start
        raise RuntimeError("the grading pool starts with the app")
    return pool


async def now(request: Request) -> dt.datetime:
    """The server's clock (the policy's opening and closing are read against it)."""
    return _server_of(request).clock()


async def root_path(request: Request) -> str:
    """The path the app is served under (``--base-url``'s path; ``""`` at the root)."""
    return request.scope.get("root_path", "")


Data = Annotated[ExamData, Depends(exam_data)]
Pool = Annotated[GradingPool, Depends(grading_pool)]
Now = Annotated[dt.datetime, Depends(now)]
RootPath = Annotated[str, Depends(root_path)]


# -- tokens -------------------------------------------------------------------------------

LinkToken = Annotated[str, Path(description="the secret token of the link")]

_bearer_scheme = HTTPBearer(auto_error=False, description="a student or staff link's token")


async def bearer_token(credentials: Annotated[HTTPAuthorizationCredentials | None,
                                              Depends(_bearer_scheme)]) -> str:
    """The token of ``Authorization: Bearer <token>``; 401 without one."""
    if credentials is None:
        raise HTTPException(401, _("send the token as 'Authorization: Bearer <token>'"),
                            headers={"WWW-Authenticate": "Bearer"})
    return credentials.credentials


BearerToken = Annotated[str, Depends(bearer_token)]


def _address_of(request: Request) -> str:
    return request.client.host if request.client else ""


async def client_address(request: Request) -> str:
    """The address the request came from (behind a trusted proxy, the one it names)."""
    return _address_of(request)


ClientAddress = Annotated[str, Depends(client_address)]


# -- callers ------------------------------------------------------------------------------


@dataclass(frozen=True)
class Caller:
    """Who is asking: the token they hold, its role and (a staff link) its name."""

    token: str
    role: str
    label: str | None = field(default=None, kw_only=True)

    @property
    def actor(self) -> str:
        """Who the audit log says made a change: the staff link's name, or else the
        first characters of its token's hash (never the token itself)."""
        return self.label or f"staff link {db.hash_token(self.token)[:8]}"


@dataclass(frozen=True)
class StudentCaller(Caller):
    """A student asking: their token, and whose it is."""

    student_id: str


def _cookie_of(request: Request) -> str | None:
    return request.cookies.get(lti_sessions.COOKIE)


async def session_cookie(request: Request) -> str | None:
    """The LTI session's cookie the request carries, if any."""
    return _cookie_of(request)


SessionCookie = Annotated[str | None, Depends(session_cookie)]


async def identify(server: Server, token: str, role: str, client: str = "",
                   cookie: str | None = None) -> db.Identity:
    """The holder of ``token``, who must have ``role``; refuses as the module says.

    A token seen in the last seconds is known without leaving the event loop; an unseen
    one is looked up in the database in a thread, off the loop. An LTI session's handle
    is looked up with ``cookie`` each time (it is not remembered without it)."""
    if len(token) > limits.MAX_TOKEN_CHARS:  # no token of ours: nothing to look up
        raise HTTPException(401, _("unknown link"))
    if not server.limiter.allow(limits.limiter_key(client, token)):
        raise HTTPException(429, _("too many requests; slow down"), headers={"Retry-After": "1"})
    if lti_sessions.is_handle(token):
        identity = await run_in_threadpool(lti_sessions.identity, server.engine,
                                           server.data.exam_id, token, cookie,
                                           server.clock())
    elif (identity := server.identities.get(token)) is None:
        identity = await run_in_threadpool(db.identify, server.engine, server.data.exam_id,
                                           token)
        server.identities.put(token, identity)
    if identity is None:
        raise HTTPException(401, _("unknown link"))
    if identity.role != role:
        raise HTTPException(403, _("not a link for this page"))
    return identity


async def _student(server: Server, token: str, client: str,
                   cookie: str | None) -> StudentCaller:
    identity = await identify(server, token, STUDENT, client, cookie)
    if identity.student_id is None:  # a student's token always names its student
        raise HTTPException(401, _("unknown link"))
    return StudentCaller(token, STUDENT, identity.student_id)


async def _staff(server: Server, token: str, client: str, cookie: str | None) -> Caller:
    identity = await identify(server, token, STAFF, client, cookie)
    return Caller(token, STAFF, label=identity.label)


async def student_by_link(request: Request, token: LinkToken) -> StudentCaller:
    """The student whose link this page is."""
    return await _student(_server_of(request), token, _address_of(request),
                          _cookie_of(request))


async def staff_by_link(request: Request, token: LinkToken) -> Caller:
    """The staff member whose link this page is."""
    return await _staff(_server_of(request), token, _address_of(request), _cookie_of(request))


async def student_by_bearer(request: Request, token: BearerToken) -> StudentCaller:
    """The student whose token the request carries."""
    return await _student(_server_of(request), token, _address_of(request),
                          _cookie_of(request))


async def staff_by_bearer(request: Request, token: BearerToken) -> Caller:
    """The staff member whose token the request carries."""
    return await _staff(_server_of(request), token, _address_of(request), _cookie_of(request))


StudentLink = Annotated[StudentCaller, Depends(student_by_link)]
StaffLink = Annotated[Caller, Depends(staff_by_link)]
StudentBearer = Annotated[StudentCaller, Depends(student_by_bearer)]
StaffBearer = Annotated[Caller, Depends(staff_by_bearer)]

#: how the OpenAPI document describes the refusals of a caller dependency
REFUSALS: dict[int | str, dict[str, Any]] = {401: problem("no token, or an unknown one"),
            403: problem("a token of the other role, or a refusal of the exam's rules"),
            429: problem("beyond the token's rate limit (`Retry-After`)")}

#: every caller dependency: the role it admits and where it takes the token from
CALLERS: dict[Callable[..., Awaitable[Caller]], tuple[str, str]] = {
    student_by_link: (STUDENT, "path"), staff_by_link: (STAFF, "path"),
    student_by_bearer: (STUDENT, "bearer"), staff_by_bearer: (STAFF, "bearer")}


# -- forms --------------------------------------------------------------------------------


@dataclass(frozen=True)
class PostedForm:
    """A form posted from a student's page: its caller, its fields, its exercise."""

    caller: StudentCaller
    fields: FormData
    exercise_id: str


async def _checked_fields(request: Request, caller: Caller, server: Server) -> FormData:
    """The fields of a form posted from ``caller``'s page; 403 unless its CSRF field is
    the one that page was given."""
    form = await request.form()
    if not limits.csrf_ok(server.secret, caller.token, form.get("csrf")):
        raise HTTPException(403, _("the form is stale or not from this page; reload it"))
    return form


async def student_form(request: Request, caller: StudentLink, server: ServerDep) -> PostedForm:
    """The form a student posted from their page, once its CSRF field is checked."""
    form = await _checked_fields(request, caller, server)
    return PostedForm(caller, form, str(form.get("exercise", "")))


StudentForm = Annotated[PostedForm, Depends(student_form)]


@dataclass(frozen=True)
class StaffPostedForm:
    """A form posted from a staff page: its caller and its fields."""

    caller: Caller
    fields: FormData


async def staff_form(request: Request, caller: StaffLink, server: ServerDep) -> StaffPostedForm:
    """The form a staff member posted from a staff page, once its CSRF field is checked."""
    return StaffPostedForm(caller, await _checked_fields(request, caller, server))


StaffForm = Annotated[StaffPostedForm, Depends(staff_form)]
