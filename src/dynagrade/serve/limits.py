"""Guards in front of the routes: request size, requests per token, CSRF fields.

- Bodies over :data:`MAX_BODY_BYTES` are refused with 413 before they are read whole.
- Each token may make :data:`BURST` requests at once and :data:`RATE` per second after
  that (a token bucket per token, kept by each worker process; put a per-address limit
  in the reverse proxy as well). Beyond it: 429 with ``Retry-After``.
- Every form carries a CSRF field: an HMAC of the page's token under the server's secret
  (stored in the database, so every worker checks what any worker signed).
"""

from __future__ import annotations

import hashlib
import hmac
import threading
import time

from ..errors import DynagradeError
from ..i18n import language

MAX_BODY_BYTES = 64 * 1024
RATE = 5.0    # requests per second, sustained, per token
BURST = 60    # requests at once, per token


class RateLimiter:
    """A token bucket per key; thread-safe."""

    def __init__(self, rate: float = RATE, burst: int = BURST):
        self.rate, self.burst = rate, burst
        self._buckets: dict[str, tuple[float, float]] = {}
        self._lock = threading.Lock()

    def allow(self, key: str) -> bool:
        now = time.monotonic()
        with self._lock:
            level, then = self._buckets.get(key, (float(self.burst), now))
            level = min(float(self.burst), level + (now - then) * self.rate)
            if level < 1.0:
                self._buckets[key] = (level, now)
                return False
            self._buckets[key] = (level - 1.0, now)
            if len(self._buckets) > 100_000:  # forget idle tokens now and then
                self._buckets = {k: v for k, v in self._buckets.items() if now - v[1] < 60}
            return True


def csrf_field(secret: str, token: str) -> str:
    """The CSRF value of forms on ``token``'s pages."""
    return hmac.new(secret.encode(), b"csrf:" + token.encode(), hashlib.sha256).hexdigest()


def csrf_ok(secret: str, token: str, value: object) -> bool:
    """Whether ``value`` (a posted field: text, a file or nothing) is the CSRF value of
    ``token``'s pages."""
    return isinstance(value, str) and bool(value) and \
        hmac.compare_digest(csrf_field(secret, token), value)


def sign(secret: str, text: str) -> str:
    """A short signature of ``text`` (practice variants travel signed in the page)."""
    return hmac.new(secret.encode(), b"sign:" + text.encode(), hashlib.sha256).hexdigest()[:32]


def signed_ok(secret: str, text: str, signature: str) -> bool:
    return hmac.compare_digest(sign(secret, text), signature or "")


#: how long a server process trusts what it learnt of a token (seconds)
REMEMBER_SECONDS = 30.0


class RecentlySeen:
    """Who recently seen tokens belong to, for ``seconds`` (a submit then needs one
    database query less). A revoked link keeps working in a worker for at most that
    long; unknown tokens are not remembered, so a new link works at once."""

    def __init__(self, seconds: float = REMEMBER_SECONDS, size: int = 50_000):
        self.seconds, self.size = seconds, size
        self._seen: dict[str, tuple[float, object]] = {}
        self._lock = threading.Lock()

    def get(self, token: str):
        with self._lock:
            found = self._seen.get(token)
        if found is None or time.monotonic() - found[0] > self.seconds:
            return None
        return found[1]

    def forget_all(self) -> None:
        """Forget every token (after a link was revoked here: it is refused at once)."""
        with self._lock:
            self._seen.clear()

    def put(self, token: str, identity) -> None:
        if identity is None:
            return
        with self._lock:
            if len(self._seen) >= self.size:
                self._seen.clear()
            self._seen[token] = (time.monotonic(), identity)


class PrivateHeaders:
    """ASGI middleware: pages and answers are private to their token's holder: never
    cached, never sent as a referrer, never sniffed as another type."""

    HEADERS = [(b"referrer-policy", b"no-referrer"), (b"cache-control", b"no-store"),
               (b"x-content-type-options", b"nosniff"), (b"x-frame-options", b"DENY")]

    def __init__(self, app):
        self.app = app

    async def __call__(self, scope, receive, send):
        if scope["type"] != "http":
            return await self.app(scope, receive, send)

        async def with_headers(message):
            if message["type"] == "http.response.start":
                names = {name.lower() for name, _ in message.get("headers", [])}
                message["headers"] = list(message.get("headers", [])) + [
                    h for h in self.HEADERS if h[0] not in names]
            await send(message)

        await self.app(scope, receive, with_headers)


class ExamLanguage:
    """Answer every request in the exam's language (``language`` of exam.toml; docs/serve.md,
    "Languages"): the active language of :mod:`dynagrade.i18n` for the request's work."""

    def __init__(self, app, code: str):
        self.app, self.code = app, code

    async def __call__(self, scope, receive, send):
        with language(self.code):
            await self.app(scope, receive, send)


class BodySizeLimit:
    """ASGI middleware: 413 for a body over ``limit`` bytes (declared or streamed)."""

    def __init__(self, app, limit: int = MAX_BODY_BYTES):
        self.app, self.limit = app, limit

    async def __call__(self, scope, receive, send):
        if scope["type"] != "http":
            return await self.app(scope, receive, send)
        declared = dict(scope.get("headers") or []).get(b"content-length")
        if declared is not None and (not declared.isdigit() or int(declared) > self.limit):
            return await _too_large(send)
        seen = 0

        async def limited_receive():
            nonlocal seen
            message = await receive()
            if message["type"] == "http.request":
                seen += len(message.get("body", b""))
                if seen > self.limit:
                    raise _TooLarge()
            return message

        try:
            await self.app(scope, limited_receive, send)
        except _TooLarge:
            await _too_large(send)


class _TooLarge(DynagradeError):
    """A request body over MAX_BODY_BYTES, stopping the read before the rest arrives."""


async def _too_large(send) -> None:
    body = b'{"detail": "the request is too large"}'
    await send({"type": "http.response.start", "status": 413,
                "headers": [(b"content-type", b"application/json"),
                            (b"content-length", str(len(body)).encode())]})
    await send({"type": "http.response.body", "body": body})
