"""What one server process holds: its settings and the resources built from them.

:class:`Settings` is what ``dynagrade serve`` hands every worker process (through the
environment, as JSON); :class:`Server` is what a worker builds from it once, at start:
the exam, the database engine, the server's secret, the guards that remember tokens,
and (from the app's start to its end) the grading pool. Routes reach these only through
the dependencies of :mod:`dynagrade.serve.deps`.
"""

from __future__ import annotations

import datetime as dt
import json
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Awaitable, Callable

from . import limits
from .exam_data import ExamData
from .grading_pool import GradingPool

if TYPE_CHECKING:
    from sqlalchemy import Engine

#: the environment variable that carries the settings to every worker process
ENVIRONMENT = "DYNAGRADE_SERVE"


@dataclass(frozen=True)
class Settings:
    """How ``dynagrade serve`` was asked to serve an exam."""

    manifest: Path
    db_url: str | None = None
    folders: tuple[str, ...] = ()
    base_url: str = ""
    grading_workers: int = 2

    @property
    def root_path(self) -> str:
        """The path the server is reached under behind a proxy (``""`` at the root)."""
        from urllib.parse import urlparse

        return urlparse(self.base_url).path.rstrip("/") if self.base_url else ""

    def to_json(self) -> str:
        """The settings as one JSON text, for the worker processes' environment."""
        return json.dumps({"manifest": str(Path(self.manifest).resolve()), "db": self.db_url,
                           "folders": [str(Path(f).resolve()) for f in self.folders],
                           "base_url": self.base_url,
                           "grading_workers": self.grading_workers})

    @classmethod
    def from_json(cls, text: str) -> "Settings":
        values = json.loads(text)
        return cls(Path(values["manifest"]), values["db"], tuple(values["folders"]),
                   values["base_url"], values["grading_workers"])


@dataclass
class Server:
    """A worker's exam, database and guards; ``pool`` is set while the app runs."""

    settings: Settings
    data: ExamData
    engine: Engine
    secret: str
    clock: Callable[[], dt.datetime]
    limiter: limits.RateLimiter = field(default_factory=limits.RateLimiter)
    identities: limits.RecentlySeen = field(default_factory=limits.RecentlySeen)
    pool: GradingPool | None = None
    #: loads the exam again when a regrade was applied since the last look, and says
    #: whether it did (:meth:`.reload.ExamReloader.catch_up`); set while the app runs
    catch_up: Callable[[], Awaitable[bool]] | None = None
    #: the registered LTI platforms' origins, which alone may frame launched pages
    #: (:class:`.lti.framing.PlatformOrigins`; none until the app sets it)
    platform_origins: Callable[[], tuple[str, ...]] = lambda: ()

    def start_pool(self) -> GradingPool:
        """Start the grading processes (at the app's start)."""
        self.pool = GradingPool(str(self.settings.manifest), self.settings.folders,
                                self.settings.grading_workers)
        return self.pool
