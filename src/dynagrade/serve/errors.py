"""Every error the server answers, for the one who asked: a page for a browser, JSON for
the API.

A request wants a page when it is not under ``/api/`` and its ``Accept`` header prefers
``text/html`` to JSON (a browser's does); then the answer is ``templates/error.html``: the
exam's language, a title, the reason and a sentence of help (a link is personal: ask the
course staff). Everyone else gets ``{"detail": ...}`` as before.

A database or disk failure is 503 with ``Retry-After``: the server is fine, the store is
not, and the request may be repeated. When it was a student's form post (the page
without JavaScript), the 503 page carries what they typed in a form that sends it again
(:class:`KeepForm` keeps the posted body for this, as the route has read it already).
"""

from __future__ import annotations

import math
from typing import Any
from urllib.parse import parse_qsl

import sqlalchemy as sa
from fastapi import FastAPI, Request
from fastapi.exceptions import RequestValidationError
from fastapi.responses import HTMLResponse, JSONResponse, Response
from starlette.exceptions import HTTPException

from ..i18n import _
from .grading_pool import Busy
from .submit import Refused

#: seconds a client should wait before repeating a request the store could not serve
RETRY_AFTER = "5"

#: where :class:`KeepForm` leaves a form post's body in the request's scope
_KEPT = "dynagrade.form_body"


def _help(status: int) -> tuple[str, str]:
    """The title and the sentence of help of an error page."""
    if status == 401:
        return _("This link is not known"), _(
            "Links are personal: open the whole link you were sent, without changes. If "
            "it still does not work, ask the course staff for your link.")
    if status == 403:
        return _("Not allowed"), _(
            "This page or action is not open to this link now. If you think it should "
            "be, ask the course staff.")
    if status == 404:
        return _("Page not found"), _(
            "Check the address, or open the link you were sent.")
    if status == 413:
        return _("Too much text"), _("Shorten what you typed and send it again.")
    if status == 422:
        return _("This could not be read"), _(
            "Go back to the page, reload it and try again.")
    if status == 429:
        return _("Too many requests"), _("Wait a few seconds, then try again.")
    if status == 503:
        return _("Please try again shortly"), _(
            "The server cannot save or read your work just now. Nothing is lost: wait a "
            "minute and send it again.")
    return _("Something went wrong"), _(
        "Try again in a minute; if it happens again, tell the course staff.")


def wants_page(request: Request) -> bool:
    """Whether the caller is a browser asking for a page (not the API)."""
    path = request.scope.get("path", "")
    if path.startswith(f"{request.scope.get('root_path', '')}/api/") or \
            path.startswith("/api/"):
        return False
    accept = request.headers.get("accept", "").lower()
    html, json = accept.find("text/html"), accept.find("application/json")
    return html >= 0 and (json < 0 or html < json)


def error_page(request: Request, status: int, detail: str | None = None,
               retry: dict[str, Any] | None = None) -> str:
    """The HTML of an error page (``retry``: a form that sends typed text again)."""
    from .pages import render

    server = getattr(request.app.state, "server", None)
    language = server.data.manifest.exam.language if server is not None else "en"
    title, help_text = _help(status)
    return render("error.html", title=title, help=help_text, detail=detail,
                  status=status, language=language, retry=retry,
                  base=request.scope.get("root_path", ""))


def encodable(detail: Any) -> Any:
    """``detail`` with what a JSON answer cannot hold written as text: a character UTF-8
    cannot hold (a lone surrogate the request sent, echoed in a message) as its escape,
    ``\\ud800``, and a number JSON has no word for (a body ``Infinity``, echoed as the
    input a check refused) as ``"inf"``: an answer that quotes the request cannot fail to
    be sent."""
    if isinstance(detail, str):
        return detail.encode("utf-8", "backslashreplace").decode("utf-8")
    if isinstance(detail, float) and not math.isfinite(detail):
        return str(detail)
    if isinstance(detail, dict):
        return {encodable(key): encodable(value) for key, value in detail.items()}
    if isinstance(detail, (list, tuple)):
        return [encodable(item) for item in detail]
    return detail


def answer(request: Request, status: int, detail: Any,
           headers: dict[str, str] | None = None) -> Response:
    """The error as a page or as JSON, as the caller wants."""
    detail = encodable(detail)
    if wants_page(request):
        shown = detail if isinstance(detail, str) else None
        retry = _retry_form(request) if status == 503 else None
        return HTMLResponse(error_page(request, status, shown, retry), status_code=status,
                            headers=headers)
    return JSONResponse({"detail": detail}, status_code=status, headers=headers)


def _retry_form(request: Request) -> dict[str, Any] | None:
    """A student's form post, to send again: its action, hidden fields and answers."""
    body = request.scope.get(_KEPT)
    if not body:
        return None
    fields = parse_qsl(body.decode("utf-8", "replace"), keep_blank_values=True)
    answers = [(name, value) for name, value in fields if name.startswith("answer.")]
    if not answers:
        return None
    labels: dict[str, str] = {}
    server = getattr(request.app.state, "server", None)
    exercise = dict(fields).get("exercise", "")
    if server is not None and exercise in server.data.exercises_meta:
        labels = {f"answer.{p.name}": p.label or p.name for p in server.data.parts(exercise)}
    return {"action": request.scope.get("root_path", "") + request.url.path,
            "hidden": [(n, v) for n, v in fields if not n.startswith("answer.")],
            "answers": [(n, labels.get(n, n[len("answer."):]), v) for n, v in answers]}


class KeepForm:
    """ASGI middleware: keep the body of a form post to a student's page (at most the
    size limit's 64 KiB) in the scope, so that a failure can give back what was typed."""

    def __init__(self, app):
        self.app = app

    async def __call__(self, scope, receive, send):
        if scope["type"] != "http" or scope["method"] != "POST" or "/s/" not in scope["path"]:
            return await self.app(scope, receive, send)
        chunks: list[bytes] = []

        async def keeping():
            message = await receive()
            if message["type"] == "http.request":
                chunks.append(message.get("body", b""))
                scope[_KEPT] = b"".join(chunks)
            return message

        await self.app(scope, keeping, send)


# -- the handlers ---------------------------------------------------------------------------


async def _http_error(request: Request, error: Exception) -> Response:
    assert isinstance(error, HTTPException)
    if isinstance(error.__cause__, UnicodeDecodeError):  # FastAPI's 400 for a body not UTF-8
        return answer(request, 422, _("the body is not UTF-8 text (byte {position} cannot be "
                                      "read); send the text as UTF-8").format(
            position=error.__cause__.start))
    return answer(request, error.status_code, error.detail, dict(error.headers or {}))


async def _invalid(request: Request, error: Exception) -> Response:
    assert isinstance(error, RequestValidationError)
    from fastapi.encoders import jsonable_encoder

    return answer(request, 422, jsonable_encoder(error.errors()))


async def _refused(request: Request, error: Exception) -> Response:
    """A refusal of the exam's rules: its status and message."""
    assert isinstance(error, Refused)
    return answer(request, error.status, error.message)


async def _busy(request: Request, error: Exception) -> Response:
    """The grading queue is full: 503, try again shortly."""
    return answer(request, 503, _("the server is busy grading; try again shortly"),
                  {"Retry-After": "2"})


async def _store_failed(request: Request, error: Exception) -> Response:
    """The database or the disk failed: 503, the request may be repeated."""
    return answer(request, 503, _("the database cannot be reached or is full; try again "
                                  "shortly"), {"Retry-After": RETRY_AFTER})


def install(app: FastAPI) -> None:
    """Answer every error of ``app`` as this module says."""
    app.add_middleware(KeepForm)
    app.add_exception_handler(HTTPException, _http_error)
    app.add_exception_handler(RequestValidationError, _invalid)
    app.add_exception_handler(Refused, _refused)
    app.add_exception_handler(Busy, _busy)
    for failure in (sa.exc.DBAPIError, sa.exc.TimeoutError, OSError):
        app.add_exception_handler(failure, _store_failed)
