"""The ASGI application: the routers of :mod:`dynagrade.serve.routes` on one server.

``create_app(manifest, db_url)`` builds it; every worker process builds its own, and
they share nothing but the database. A token in the path (pages) or in
``Authorization: Bearer`` (API) decides who is asking (:mod:`dynagrade.serve.deps`);
nothing else does. docs/serve.md lists the routes; ``/api/openapi.json`` describes them
(no browsable page: it would load scripts from elsewhere on a server of tokens).
"""

from __future__ import annotations

import asyncio
import datetime as dt
import os
from contextlib import asynccontextmanager
from pathlib import Path
from typing import Callable

from fastapi import FastAPI
from starlette.concurrency import run_in_threadpool

from . import db, errors, headers, limits
from .exam_data import ExamData
from .lti import grade_sync
from .lti.framing import PlatformOrigins
from .policy_changes import PolicySource
from .reload import ExamReloader
from .routes import ROUTERS
from .state import ENVIRONMENT, Server, Settings

__all__ = ["create_app", "build_app", "app_from_environment"]


def create_app(manifest: str | os.PathLike, db_url: str | None = None,
               folders: tuple[str, ...] = (), base_url: str = "",
               grading_workers: int = 2,
               clock: Callable[[], dt.datetime] | None = None) -> FastAPI:
    """The server of the exam in ``manifest`` (database: ``db_url`` or SQLite beside it)."""
    settings = Settings(Path(manifest), db_url, tuple(folders), base_url, grading_workers)
    return build_app(settings, clock)


def build_app(settings: Settings, clock: Callable[[], dt.datetime] | None = None) -> FastAPI:
    """The app of ``settings``: the exam and the database opened, the routers included."""
    from ..exercise.loader import open_bank
    from ..grading import prepare

    data = ExamData(settings.manifest, open_bank(settings.folders))
    engine = db.connect(settings.db_url or db.sqlite_url_beside(settings.manifest))
    data.policy_source = PolicySource(engine, data.exam_id, data.manifest_policy)
    server = Server(settings, data, engine, db.server_secret(engine), clock or db.now)
    server.platform_origins = PlatformOrigins(engine)

    @asynccontextmanager
    async def lifespan(app: FastAPI):
        pool = server.start_pool()
        # pages read the answers they show (ExamData.reading): load the readers here too,
        # while the pool loads the exam, not in the first student's page
        await asyncio.gather(run_in_threadpool(pool.warm_up), run_in_threadpool(prepare))
        reloader = await run_in_threadpool(ExamReloader, server)
        server.catch_up = reloader.catch_up
        watching = asyncio.create_task(reloader.watch())
        sending = asyncio.create_task(grade_sync.run(server))  # LTI scores, if any
        try:
            yield
        finally:
            watching.cancel()
            sending.cancel()
            if server.pool is not None:
                server.pool.close()
            engine.dispose()

    app = FastAPI(title=f"dynagrade serve: {data.title}", lifespan=lifespan,
                  root_path=settings.root_path, docs_url=None, redoc_url=None,
                  openapi_url="/api/openapi.json")
    app.add_middleware(limits.BodySizeLimit)
    app.add_middleware(headers.SecurityHeaders)
    app.add_middleware(headers.HeadAsGet)
    app.add_middleware(limits.ExamLanguage, code=data.manifest.exam.language)
    app.state.server = server
    errors.install(app)  # pages for browsers, JSON for the API, 503 when the store fails
    limits.hide_tokens_in_access_log()
    for router in ROUTERS:
        app.include_router(router)
    return app


def app_from_environment() -> FastAPI:
    """The app ``dynagrade serve`` describes in ``$DYNAGRADE_SERVE`` (one per worker)."""
    return build_app(Settings.from_json(os.environ[ENVIRONMENT]))
