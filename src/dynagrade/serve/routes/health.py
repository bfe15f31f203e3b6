"""``GET /healthz``: whether this worker's database answers (for monitoring)."""

from __future__ import annotations

from fastapi import APIRouter
from fastapi.responses import PlainTextResponse

from .. import db
from ..deps import ServerDep

router = APIRouter(tags=["health"])


@router.get("/healthz", response_class=PlainTextResponse, responses={
    200: {"description": "the database answers: `ok`"},
    503: {"description": "the database does not answer: `database: <error type>`",
          "content": {"text/plain": {"schema": {"type": "string"}}}}})
def healthz(server: ServerDep) -> PlainTextResponse:
    """200 ``ok`` when the database answers, else 503."""
    try:
        db.ping(server.engine)
    except Exception as error:  # any failure of the database is "not healthy"
        return PlainTextResponse(f"database: {type(error).__name__}", status_code=503)
    return PlainTextResponse("ok")
