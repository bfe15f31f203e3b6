"""Loading the exam again in a server process once a regrade was applied anywhere.

Each server process (``--workers N``, on any host) holds its own
:class:`~dynagrade.serve.exam_data.ExamData` and grading pool, loaded at its start from
the manifest and the exercise files. An applied regrade (:mod:`.regrade`) means those
files changed on disk and the stored verdicts now follow them, so new submits must be
graded by them too. :class:`ExamReloader` asks the database every :data:`FRESH_SECONDS`
how many regrades were applied; when the number grew, it loads the exam from disk, starts
a new grading pool and warms it up, then swaps both in and retires the old pool once its
running jobs are done (:meth:`GradingPool.retire
<dynagrade.serve.grading_pool.GradingPool.retire>`): no request in flight is dropped.
The process that applies a regrade reloads at once; the others within
:data:`FRESH_SECONDS` plus the time a load takes (a few seconds).
"""

from __future__ import annotations

import asyncio
import logging

import sqlalchemy as sa
from starlette.concurrency import run_in_threadpool

from . import db
from .exam_data import ExamData
from .grading_pool import GradingPool
from .state import Server

_log = logging.getLogger(__name__)

#: how often a server process asks whether a regrade was applied (seconds)
FRESH_SECONDS = 2.0


class ExamReloader:
    """Reloads one server process's exam and grading pool after an applied regrade."""

    def __init__(self, server: Server, fresh: float = FRESH_SECONDS):
        self.server, self.fresh = server, fresh
        self.seen = db.applied_regrades(server.engine, server.data.exam_id)
        self._lock = asyncio.Lock()

    async def catch_up(self) -> bool:
        """Reload when a regrade was applied since the last look; whether it did."""
        async with self._lock:
            applied = await run_in_threadpool(db.applied_regrades, self.server.engine,
                                              self.server.data.exam_id)
            if applied == self.seen:
                return False
            await self._reload()
            self.seen = applied
            return True

    async def _reload(self) -> None:
        server = self.server
        settings = server.settings
        data = await run_in_threadpool(_load, server)
        pool = GradingPool(str(settings.manifest), settings.folders, settings.grading_workers)
        await run_in_threadpool(pool.warm_up)
        old = server.pool
        server.data, server.pool = data, pool
        if old is not None:
            await run_in_threadpool(old.retire, pool)

    async def watch(self) -> None:
        """Look every :attr:`fresh` seconds, for as long as the app runs."""
        while True:
            await asyncio.sleep(self.fresh)
            try:
                await self.catch_up()
            except sa.exc.SQLAlchemyError:  # the database is down: the next look tries again
                continue
            except Exception:  # the files cannot be loaded: keep serving, say so, try again
                _log.exception("cannot load the exam again after a regrade")


def _load(server: Server) -> ExamData:
    """The exam as it is on disk now, with the policy of the running one."""
    from ..exercise.loader import open_bank

    data = ExamData(server.settings.manifest, open_bank(server.settings.folders))
    data.policy_source = server.data.policy_source
    return data
