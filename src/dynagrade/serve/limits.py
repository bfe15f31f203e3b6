"""Guards in front of the routes: request size, requests per token, CSRF fields.

- Bodies over :data:`MAX_BODY_BYTES` are refused with 413 before they are read whole.
- Each client (its address) may make :data:`BURST` requests at once with one token and
  :data:`RATE` per second after that (a token bucket per address and token, kept by each
  worker process in a table of at most :data:`MAX_BUCKETS` entries, the longest idle
  forgotten first, so that no stream of requests can grow it; put a per-address limit for
  the whole class in the reverse proxy as well). Beyond it: 429 with ``Retry-After``. A
  token longer than :data:`MAX_TOKEN_CHARS` is no token of ours and is refused before any
  of this.
- The access log shows a link's token as the start of its hash (:class:`TokenlessAccessLog`).
- Every form carries a CSRF field: an HMAC of the page's token under the server's secret
  (stored in the database, so every worker checks what any worker signed).
"""

from __future__ import annotations

import hashlib
import hmac
import logging
import re
import threading
import time
from collections import OrderedDict

from ..i18n import language

MAX_BODY_BYTES = 64 * 1024
RATE = 5.0    # requests per second, sustained, per address and token
BURST = 60    # requests at once, per address and token
#: the most buckets a worker keeps (about 100 bytes each)
MAX_BUCKETS = 20_000
#: the longest token worth looking up (ours are 43 characters)
MAX_TOKEN_CHARS = 100


def limiter_key(client: str, token: str) -> str:
    """The rate limiter's key of a request: the client's address and a digest of the
    token (of fixed size, however long the token sent)."""
    return f"{client} {hashlib.sha256(token.encode('utf-8', 'replace')).hexdigest()[:16]}"


class RateLimiter:
    """A token bucket per key in a table of at most ``size`` keys, the longest idle
    forgotten first; thread-safe."""

    def __init__(self, rate: float = RATE, burst: int = BURST, size: int = MAX_BUCKETS):
        self.rate, self.burst, self.size = rate, burst, size
        self._buckets: OrderedDict[str, tuple[float, float]] = OrderedDict()
        self._lock = threading.Lock()

    def allow(self, key: str) -> bool:
        now = time.monotonic()
        with self._lock:
            level, then = self._buckets.pop(key, (float(self.burst), now))
            level = min(float(self.burst), level + (now - then) * self.rate)
            allowed = level >= 1.0
            self._buckets[key] = (level - 1.0 if allowed else level, now)  # newest last
            while len(self._buckets) > self.size:
                self._buckets.popitem(last=False)
            return allowed

    def __len__(self) -> int:
        return len(self._buckets)


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


class ExamLanguage:
    """Answer every request in the exam's language (``language`` of exam.toml; docs/serve.md,
    "Languages"): the active language of :mod:`dynagrade.i18n` for the request's work."""

    def __init__(self, app, code: str):
        self.app, self.code = app, code

    async def __call__(self, scope, receive, send):
        with language(self.code):
            await self.app(scope, receive, send)


class BodySizeLimit:
    """ASGI middleware: 413 for a body over ``limit`` bytes, declared or streamed.

    A body of declared length is refused on its ``Content-Length`` before it is read; a
    streamed one (``Transfer-Encoding: chunked``) is read here, at most ``limit`` bytes,
    and handed on whole, so that no route's parser ever meets the limit halfway (it would
    answer 400)."""

    def __init__(self, app, limit: int = MAX_BODY_BYTES):
        self.app, self.limit = app, limit

    async def __call__(self, scope, receive, send):
        if scope["type"] != "http":
            return await self.app(scope, receive, send)
        declared = dict(scope.get("headers") or []).get(b"content-length")
        if declared is not None:
            if not declared.isdigit() or int(declared) > self.limit:
                return await _too_large(send)
            return await self.app(scope, receive, send)
        body, more = b"", True
        while more:
            message = await receive()
            if message["type"] != "http.request":  # the client left: nothing to answer
                return
            body += message.get("body", b"")
            more = message.get("more_body", False)
            if len(body) > self.limit:
                return await _too_large(send)
        read = False

        async def replayed():
            nonlocal read
            if read:
                return await receive()
            read = True
            return {"type": "http.request", "body": body, "more_body": False}

        await self.app(scope, replayed, send)


async def _too_large(send) -> None:
    body = b'{"detail": "the request is too large"}'
    await send({"type": "http.response.start", "status": 413,
                "headers": [(b"content-type", b"application/json"),
                            (b"content-length", str(len(body)).encode())]})
    await send({"type": "http.response.body", "body": body})


class TokenlessAccessLog(logging.Filter):
    """The server's access log (uvicorn's ``uvicorn.access``) without secrets: the token
    in a page's path (``/s/<token>``, ``/i/<token>``) is replaced by the start of its hash,
    as the audit log and ``dynagrade links --list-staff`` name links."""

    _TOKEN = re.compile(r"(/[si]/)([^/?#\s]+)")

    def filter(self, record: logging.LogRecord) -> bool:
        if isinstance(record.args, tuple):
            record.args = tuple(self._TOKEN.sub(self._hidden, arg) if isinstance(arg, str)
                                else arg for arg in record.args)
        return True

    @staticmethod
    def _hidden(match: re.Match) -> str:
        digest = hashlib.sha256(match.group(2).encode("utf-8", "replace")).hexdigest()
        return f"{match.group(1)}{digest[:8]}…"


def hide_tokens_in_access_log() -> None:
    """Install :class:`TokenlessAccessLog` on uvicorn's access log (once)."""
    access = logging.getLogger("uvicorn.access")
    if not any(isinstance(f, TokenlessAccessLog) for f in access.filters):
        access.addFilter(TokenlessAccessLog())
