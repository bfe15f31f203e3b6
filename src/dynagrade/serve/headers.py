"""The headers of every answer, and ``HEAD`` wherever ``GET`` is allowed.

Tokens live in the path of the pages (``/s/<token>``, ``/i/<token>``), so every answer
is kept out of caches, referrers and frames (but a page launched from an LMS, which the
registered platforms alone may frame: :func:`framed_headers`), and the pages run only
this package's own scripts and styles (``/static/…``, :mod:`.routes.assets`), so that
text a student typed, were it ever let through unescaped, could not run. docs/serve.md ("Deployment") lists
the headers; tests/test_serve_headers.py checks them on every route.
"""

from __future__ import annotations

from starlette.concurrency import run_in_threadpool

from .lti import framing

#: the pages' policy: scripts, styles, fetches and form posts of this server only,
#: nothing in frames, nothing else at all
CONTENT_SECURITY_POLICY = (
    "default-src 'none'; script-src 'self'; style-src 'self'; img-src 'self'; "
    "connect-src 'self'; form-action 'self'; base-uri 'none'; frame-ancestors 'none'")

#: the policy of a standalone document served as it is also saved (the class report):
#: its own inline styles, matplotlib's style attributes included, and no script at all
STANDALONE_DOCUMENT_POLICY = (
    "default-src 'none'; style-src 'unsafe-inline'; img-src data:; base-uri 'none'; "
    "form-action 'none'; frame-ancestors 'none'")

#: every answer's headers, unless the route set its own (a static file's Cache-Control,
#: the class report's policy)
HEADERS = [(b"content-security-policy", CONTENT_SECURITY_POLICY.encode()),
           (b"referrer-policy", b"no-referrer"),
           (b"cache-control", b"no-store"),
           (b"x-content-type-options", b"nosniff"),
           (b"x-frame-options", b"DENY")]


def framed_headers(origins: tuple[str, ...]) -> list[tuple[bytes, bytes]]:
    """:data:`HEADERS` for a launched LTI page: framed by ``origins`` (the registered
    platforms', :mod:`.lti.framing`) and by nothing else; no ``X-Frame-Options``, whose
    ``DENY`` would forbid every frame (and which cannot name several origins)."""
    ancestors = " ".join(origins) or "'none'"
    policy = CONTENT_SECURITY_POLICY.replace("frame-ancestors 'none'",
                                             f"frame-ancestors {ancestors}")
    return [(b"content-security-policy", policy.encode())] + [
        h for h in HEADERS if h[0] not in (b"content-security-policy", b"x-frame-options")]


class SecurityHeaders:
    """ASGI middleware: :data:`HEADERS` on every answer that does not set them itself
    (pages and answers are private to their token's holder: never cached, never sent as
    a referrer, never framed, never sniffed as another type). A launched LTI page may be
    framed by the registered platforms (:func:`framed_headers`)."""

    def __init__(self, app):
        self.app = app

    async def __call__(self, scope, receive, send):
        if scope["type"] != "http":
            return await self.app(scope, receive, send)
        defaults = HEADERS
        path, root = scope["path"], scope.get("root_path", "")
        if framing.framed_path(path[len(root):] if root and path.startswith(root) else path):
            origins = scope["app"].state.server.platform_origins
            defaults = framed_headers(await run_in_threadpool(origins))

        async def with_headers(message):
            if message["type"] == "http.response.start":
                names = {name.lower() for name, _ in message.get("headers", [])}
                message["headers"] = list(message.get("headers", [])) + [
                    h for h in defaults if h[0] not in names]
            await send(message)

        await self.app(scope, receive, with_headers)


class HeadAsGet:
    """ASGI middleware: a ``HEAD`` request is answered as the ``GET`` of the same path,
    headers and status alike, without the body (RFC 9110, 9.3.2). A path without
    ``GET`` answers ``HEAD`` with 405, as it answers ``GET``."""

    def __init__(self, app):
        self.app = app

    async def __call__(self, scope, receive, send):
        if scope["type"] != "http" or scope["method"] != "HEAD":
            return await self.app(scope, receive, send)

        async def without_body(message):
            if message["type"] == "http.response.body":
                message = {**message, "body": b""}
            await send(message)

        await self.app({**scope, "method": "GET"}, receive, without_body)
