"""Shared pieces of the server tests: a small generated exam, a PostgreSQL server of our
own, a running app with tokens.

The exam is generated once per session (two exercises, three students, no PDFs); a test
that needs another policy copies it and rewrites the manifest's ``policy``, which is what
``dynagrade exam`` writes from exam.toml (tests/test_serve_policy.py checks that step).
"""

from __future__ import annotations

import datetime as dt
import os
import shutil
import socket
import subprocess
import time
from contextlib import contextmanager
from dataclasses import dataclass
from pathlib import Path

import pytest

def _pg_bin() -> Path:
    """Debian's PostgreSQL binaries (the newest version installed; 15 on bookworm)."""
    found = sorted(Path("/usr/lib/postgresql").glob("*/bin/initdb"),
                   key=lambda p: int(p.parent.parent.name) if p.parent.parent.name.isdigit()
                   else 0)
    return found[-1].parent if found else Path("/usr/lib/postgresql/15/bin")


PG_BIN = _pg_bin()

EXAM_TOML = """\
id = "serve-test"
title = "Serve test"
date = 2025-04-14

[[exercise]]
id = "projectile-range"
points = 6

[[exercise]]
id = "sliding-up-a-slope"
points = 4
"""

ROSTER = """\
student_id,name,email
s1,Ada One,ada@example.org
s2,Bo Two,bo@example.org
s3,Cy Three,cy@example.org
"""


@pytest.fixture(scope="session")
def exam_dir(tmp_path_factory) -> Path:
    """A generated exam (manifest, sheets, figures)."""
    from dynagrade.generation.generate import generate_exam

    root = tmp_path_factory.mktemp("exam")
    (root / "exam.toml").write_text(EXAM_TOML, encoding="utf-8")
    (root / "roster.csv").write_text(ROSTER, encoding="utf-8")
    generate_exam(root / "exam.toml", root / "roster.csv", root / "out", pdf=False, jobs=1,
                  secret="5e" * 32)  # a fixed secret: the same variants on every run
    return root / "out"


def exam_copy(exam_dir: Path, target: Path, **policy) -> Path:
    """A copy of the exam whose manifest carries ``policy`` (over the exam defaults)."""
    import dataclasses

    from dynagrade.exam import manifest as records
    from dynagrade.exam.policy import Policy

    shutil.copytree(exam_dir, target, ignore=shutil.ignore_patterns("serve.sqlite3*"))
    path = target / "manifest.json"
    manifest = records.load(path)
    merged = {**Policy().to_json(), **{k: _iso(v) for k, v in policy.items()}}
    records.dump(dataclasses.replace(
        manifest, exam=dataclasses.replace(manifest.exam, policy=merged)), path)
    return path


def _iso(value):
    return value.isoformat() if isinstance(value, dt.datetime) else value


def free_port() -> int:
    with socket.socket() as probe:
        probe.bind(("127.0.0.1", 0))
        return probe.getsockname()[1]


# -- PostgreSQL ---------------------------------------------------------------------------


def _as_postgres(command: list[str]) -> list[str]:
    return ["runuser", "-u", "postgres", "--", *command] if os.geteuid() == 0 else command


@pytest.fixture(scope="session")
def postgres_url():
    """A PostgreSQL server of the session's own (initdb into a temporary folder, loopback
    port, unix socket in that folder); skipped with the reason when none can be started.

    The folder is made with :mod:`tempfile` (not pytest's, which the ``postgres`` user
    could not enter when the tests run as root) and removed at the end."""
    if not (PG_BIN / "initdb").exists():
        pytest.skip(f"PostgreSQL is not installed ({PG_BIN}/initdb missing; apt-get install "
                    "postgresql)")
    import tempfile

    root = Path(tempfile.mkdtemp(prefix="dynagrade-pg-"))
    try:
        yield from _postgres(root)
    finally:
        shutil.rmtree(root, ignore_errors=True)


def _postgres(root: Path):
    data, sockets = root / "data", root / "sockets"
    sockets.mkdir()
    if os.geteuid() == 0:
        shutil.chown(root, "postgres")
        shutil.chown(sockets, "postgres")
    port = free_port()
    try:
        subprocess.run(_as_postgres([str(PG_BIN / "initdb"), "-D", str(data), "-U",
                                     "dynagrade", "--auth=trust", "-E", "UTF8",
                                     "--no-sync"]),
                       check=True, capture_output=True, timeout=120)
        server = subprocess.Popen(_as_postgres([
            str(PG_BIN / "postgres"), "-D", str(data), "-p", str(port), "-k", str(sockets),
            "-c", "listen_addresses=127.0.0.1", "-c", "fsync=off", "-c", "max_connections=100"]),
            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    except subprocess.CalledProcessError as error:
        pytest.skip(f"cannot start a PostgreSQL server: initdb failed: "
                    f"{error.stderr.decode(errors='replace').strip()[-300:]}")
    except (OSError, subprocess.SubprocessError) as error:
        pytest.skip(f"cannot start a PostgreSQL server: {error}")
    url = f"postgresql://dynagrade@127.0.0.1:{port}/postgres"
    import sqlalchemy as sa

    engine = sa.create_engine(url.replace("postgresql://", "postgresql+psycopg://"))
    for _ in range(100):
        try:
            with engine.connect():
                break
        except sa.exc.OperationalError:
            if server.poll() is not None:
                pytest.skip("the PostgreSQL server stopped at start")
            time.sleep(0.1)
    else:
        server.kill()
        pytest.skip("the PostgreSQL server did not answer within 10 s")
    engine.dispose()
    yield url
    # a throwaway cluster: stop at once instead of waiting for pooled connections to end
    subprocess.run(_as_postgres([str(PG_BIN / "pg_ctl"), "-D", str(data), "stop", "-m",
                                 "immediate"]), capture_output=True, timeout=60)
    server.wait(timeout=30)


_DATABASES = iter(range(100_000))


@pytest.fixture(params=["sqlite", "postgresql"])
def database(request, tmp_path):
    """A fresh database URL of each backend (None: SQLite beside the manifest)."""
    if request.param == "sqlite":
        return None
    url = request.getfixturevalue("postgres_url")
    return fresh_database(url, f"t{next(_DATABASES)}_{tmp_path.name[-8:].lower()}"
                          .replace("-", "_"))


def fresh_database(postgres_url: str, name: str) -> str:
    """A new empty database on the session's server."""
    import sqlalchemy as sa

    engine = sa.create_engine(postgres_url.replace("postgresql://", "postgresql+psycopg://"),
                              isolation_level="AUTOCOMMIT")
    with engine.connect() as connection:
        connection.execute(sa.text(f'CREATE DATABASE "{name}"'))
    engine.dispose()
    return postgres_url.rsplit("/", 1)[0] + "/" + name


_DATABASES = iter(range(100_000))


@pytest.fixture(params=["sqlite", "postgresql"])
def database(request, tmp_path):
    """A fresh database URL of each backend, so that a test runs on both (None: SQLite
    beside the manifest; else a new database on the session's PostgreSQL)."""
    if request.param == "sqlite":
        return None
    url = request.getfixturevalue("postgres_url")
    return fresh_database(url, f"t{next(_DATABASES)}_{tmp_path.name[-8:].lower()}"
                          .replace("-", "_"))


# -- a running app ------------------------------------------------------------------------


@dataclass
class Served:
    """A test client of a running app with one token per student and a staff token."""

    client: object
    app: object
    tokens: dict[str, str]
    staff: str

    def submit(self, student: str, exercise: str, answers: dict, key: str | None = None):
        headers = {"Authorization": f"Bearer {self.tokens[student]}"}
        if key:
            headers["Idempotency-Key"] = key
        return self.client.post("/api/v1/answers", json={"exercise": exercise,
                                                         "answers": answers}, headers=headers)

    def staff_get(self, path: str):
        return self.client.get(path, headers={"Authorization": f"Bearer {self.staff}"})

    @property
    def server(self):
        """The app's :class:`dynagrade.serve.state.Server` (its exam, its database)."""
        return self.app.state.server

    def variant(self, student: str, exercise: str):
        return self.server.data.entry(student, exercise)


class Clock:
    """The server's clock, set by the test."""

    def __init__(self, now: dt.datetime | None = None):
        self.now = now or dt.datetime(2025, 4, 14, 10, 0, tzinfo=dt.timezone.utc)

    def __call__(self) -> dt.datetime:
        return self.now


def serve(manifest: Path, db_url: str | None = None, clock=None, folders=()):
    """A context manager yielding :class:`Served` for ``manifest`` (exercises also
    looked for in ``folders``)."""
    from contextlib import contextmanager

    @contextmanager
    def running():
        from fastapi.testclient import TestClient

        from dynagrade.serve import db
        from dynagrade.serve.app import create_app

        app = create_app(manifest, db_url, folders=tuple(map(str, folders)),
                         grading_workers=1, clock=clock)
        data, engine = app.state.server.data, app.state.server.engine
        tokens = {s: t for s, t in db.issue_tokens(engine, data.exam_id,
                                                   list(data.students)).items()}
        staff = db.issue_staff_token(engine, data.exam_id)
        with TestClient(app) as client:
            yield Served(client, app, tokens, staff)

    return running()


def reference_answers(served: Served, student: str, exercise: str) -> dict[str, str]:
    """The manifest's reference answers as text (a correct submission)."""
    out = {}
    for name, value in served.variant(student, exercise).answers.items():
        out[name] = ", ".join(map(repr, value)) if isinstance(value, tuple) else str(value)
    return out


@contextmanager
def serving_process(manifest: Path, links: Path, db: str | None = None,
                    instructor: bool = True):
    """``dynagrade serve`` of ``manifest`` in a process of its own, on a free loopback port,
    with its links written to ``links``: yields (base url, the links' rows, the staff url
    or None). The server is stopped at the end."""
    import csv
    import io
    import signal
    import sys

    import httpx

    port = free_port()
    base = f"http://127.0.0.1:{port}"
    cli = [sys.executable, "-m", "dynagrade.cli"]
    where = ["--db", db] if db else []
    made = subprocess.run([*cli, "links", str(manifest), "-o", str(links), "--base-url", base,
                           *(["--instructor"] if instructor else []), *where],
                          check=True, capture_output=True, text=True)
    staff = made.stdout.strip().splitlines()[-1].split("staff link: ")[1] if instructor \
        else None
    rows = list(csv.DictReader(io.StringIO(links.read_text(encoding="utf-8"))))
    server = subprocess.Popen([*cli, "serve", str(manifest), "--port", str(port),
                               "--grading-workers", "1", *where], start_new_session=True,
                              stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    try:
        for _ in range(300):
            try:
                if httpx.get(f"{base}/healthz", timeout=1).status_code == 200:
                    break
            except httpx.HTTPError:
                time.sleep(0.1)
        else:
            pytest.fail("the server did not start")
        yield base, rows, staff
    finally:
        os.killpg(server.pid, signal.SIGTERM)
        server.wait(timeout=30)
