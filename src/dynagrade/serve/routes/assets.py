"""``GET /static/{name}``: the pages' own stylesheets and scripts, files of this package.

The pages hold no inline script or style and load nothing from elsewhere, so that the
Content-Security-Policy (:mod:`dynagrade.serve.headers`) can allow these files and
nothing else. They are public (no token: they hold nothing of a student's) and are
revalidated on each use (``Cache-Control: no-cache`` with an ``ETag``), so a new version
of dynagrade is used by the next page load.
"""

from __future__ import annotations

import hashlib
from dataclasses import dataclass
from pathlib import Path
from typing import Annotated

from fastapi import APIRouter, Header, HTTPException
from fastapi import Path as PathParameter
from fastapi.responses import Response

router = APIRouter(tags=["assets"])

FOLDER = Path(__file__).resolve().parent.parent / "static"
MEDIA_TYPES = {".css": "text/css; charset=utf-8", ".js": "text/javascript; charset=utf-8"}


@dataclass(frozen=True)
class Asset:
    """One file of :data:`FOLDER`: its bytes, its media type and its entity tag."""

    body: bytes
    media_type: str
    etag: str


def _assets() -> dict[str, Asset]:
    """Every stylesheet and script of :data:`FOLDER`, by file name (read once)."""
    found = {}
    for path in sorted(FOLDER.iterdir()):
        if path.suffix in MEDIA_TYPES and path.is_file():
            body = path.read_bytes()
            found[path.name] = Asset(body, MEDIA_TYPES[path.suffix],
                                     f'"{hashlib.sha256(body).hexdigest()[:20]}"')
    return found


ASSETS = _assets()


@router.get("/static/{name}", response_class=Response, responses={
    200: {"description": "the file", "content": {
        media: {"schema": {"type": "string"}} for media in ("text/css", "text/javascript")}},
    304: {"description": "the copy the browser holds (its `If-None-Match`) is current"},
    404: {"description": "no such file"}})
def static_file(name: Annotated[str, PathParameter(description="a file name, e.g. base.css")],
                if_none_match: Annotated[str | None, Header()] = None) -> Response:
    """A stylesheet or script of the pages."""
    asset = ASSETS.get(name)
    if asset is None:
        raise HTTPException(404, "no such file")
    headers = {"ETag": asset.etag, "Cache-Control": "no-cache"}
    if if_none_match is not None and asset.etag in (t.strip() for t in if_none_match.split(",")):
        return Response(status_code=304, headers=headers)
    return Response(asset.body, media_type=asset.media_type, headers=headers)
