"""Access tokens for a platform's services: OAuth 2.0 client credentials with a signed
JWT as the client's proof (1EdTech Security Framework 4.1, RFC 7523).

The client assertion is a JWT the tool signs with its key (:mod:`.keys`): issuer and
subject the tool's client id, audience the platform's token URL, a lifetime of five
minutes and a fresh ``jti``. The platform answers with a bearer token for the scopes
asked; it is kept in this process until a minute before it expires.
"""

from __future__ import annotations

import secrets
import threading
import time

import sqlalchemy as sa

from ...errors import DynagradeError
from . import http, keys
from .store import Platform

ASSERTION_TYPE = "urn:ietf:params:oauth:client-assertion-type:jwt-bearer"
ASSERTION_SECONDS = 300


class NoAccess(DynagradeError):
    """The platform gave no token; ``answer`` is what it said."""

    def __init__(self, answer: http.Answer):
        super().__init__(f"no access token: {answer.status} {answer.text[:200]}")
        self.answer = answer


#: the tokens held, by (token URL, client id, scopes): (token, until when, monotonic)
_tokens: dict[tuple[str, str, tuple[str, ...]], tuple[str, float]] = {}
_lock = threading.Lock()


def client_assertion(engine: sa.Engine, platform: Platform) -> str:
    now = int(time.time())
    return keys.sign(engine, {"iss": platform.client_id, "sub": platform.client_id,
                              "aud": platform.token_url, "iat": now,
                              "exp": now + ASSERTION_SECONDS, "jti": secrets.token_urlsafe(16)})


def access_token(engine: sa.Engine, platform: Platform, scopes: tuple[str, ...]) -> str:
    """A bearer token for ``scopes`` on ``platform`` (:class:`NoAccess` when refused)."""
    key = (platform.token_url, platform.client_id, tuple(sorted(scopes)))
    with _lock:
        held = _tokens.get(key)
        if held is not None and held[1] > time.monotonic():
            return held[0]
    answer = http.post_form(platform.token_url, {
        "grant_type": "client_credentials", "client_assertion_type": ASSERTION_TYPE,
        "client_assertion": client_assertion(engine, platform), "scope": " ".join(key[2])})
    try:
        found = answer.json() if answer.ok else {}
    except ValueError:
        found = {}
    token = found.get("access_token") if isinstance(found, dict) else None
    if not isinstance(token, str) or not token:
        raise NoAccess(answer)
    lifetime = found.get("expires_in", 3600)
    lifetime = lifetime if isinstance(lifetime, int) and lifetime > 0 else 3600
    with _lock:
        _tokens[key] = (token, time.monotonic() + max(lifetime - 60, 1))
    return token


def forget(platform: Platform) -> None:
    """Drop the platform's tokens (one was refused: ask for a new one next time)."""
    with _lock:
        for key in [k for k in _tokens if k[:2] == (platform.token_url, platform.client_id)]:
            del _tokens[key]
