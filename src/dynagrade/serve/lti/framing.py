"""Which origins may frame a page: the registered platforms', for launched pages only.

An LTI tool runs in the platform's iframe, so the pages a launch leads to (the launch
answer itself and the pages of a session's handle, ``/s/lti-…`` and ``/i/lti-…``) may be
framed by the origins of the registered platforms (their issuer's, login URL's and token
URL's) and by nothing else. The token URL counts because Canvas's issuer and login URL
are Instructure's shared hosts, while its token URL is the school's own Canvas, the page
that frames the tool. Every other page keeps ``frame-ancestors 'none'``
(:mod:`dynagrade.serve.headers`). The origins are read from the database at most every
:data:`REREAD_SECONDS`, so a platform registered by ``dynagrade lti register`` is framed
soon without a restart.
"""

from __future__ import annotations

import threading
import time
from urllib.parse import urlsplit

import sqlalchemy as sa

from . import sessions, store

REREAD_SECONDS = 30.0


def framed_path(path: str) -> bool:
    """Whether the page at ``path`` (the root path taken off) is a launched page."""
    parts = path.split("/")
    return path == "/lti/launch" or (len(parts) > 2 and parts[1] in ("s", "i")
                                     and sessions.is_handle(parts[2]))


def origin(url: str) -> str | None:
    parts = urlsplit(url)
    return f"{parts.scheme}://{parts.netloc}" if parts.scheme in ("http", "https") \
        and parts.netloc else None


class PlatformOrigins:
    """The registered platforms' origins, read again every :data:`REREAD_SECONDS`."""

    def __init__(self, engine: sa.Engine):
        self.engine = engine
        self._origins: tuple[str, ...] = ()
        self._read_at = float("-inf")
        self._lock = threading.Lock()

    def __call__(self) -> tuple[str, ...]:
        with self._lock:
            if time.monotonic() - self._read_at > REREAD_SECONDS:
                found = {origin(url) for p in store.all_platforms(self.engine)
                         for url in (p.issuer, p.auth_login_url, p.token_url)}
                self._origins = tuple(sorted(o for o in found if o))
                self._read_at = time.monotonic()
            return self._origins
