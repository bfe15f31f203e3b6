"""``GET /healthz``: whether this worker's database accepts a write (for monitoring).

A database that answers reads but cannot write (a full disk, a read-only file, a
PostgreSQL server in recovery) is not healthy: the check commits a heartbeat row.
"""

from __future__ import annotations

from fastapi import APIRouter
from fastapi.responses import PlainTextResponse
from starlette.concurrency import run_in_threadpool

from .. import db
from ..deps import ServerDep
from ..errors import RETRY_AFTER

router = APIRouter(tags=["health"])


@router.get("/healthz", response_class=PlainTextResponse, responses={
    200: {"description": "the database accepts a write: `ok: the database accepts writes`"},
    503: {"description": "it does not: `database: <error type>: <first line>`",
          "content": {"text/plain": {"schema": {"type": "string"}}}}})
async def healthz(server: ServerDep) -> PlainTextResponse:
    """200 when the database accepts a write, else 503 with ``Retry-After``."""
    try:
        await run_in_threadpool(db.accepts_writes, server.engine)
    except Exception as error:  # any failure of the database is "not healthy"
        reason = str(getattr(error, "orig", None) or error).strip().splitlines()
        return PlainTextResponse(
            f"database: {type(error).__name__}: {reason[0] if reason else ''}",
            status_code=503, headers={"Retry-After": RETRY_AFTER})
    return PlainTextResponse("ok: the database accepts writes")
