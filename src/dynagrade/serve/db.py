"""Every statement the server sends to its database, and nothing else.

Tables (created by the Alembic migrations in ``migrations/``; see docs/serve.md):

``settings``     key/value, e.g. the secret that signs CSRF fields (shared by all workers)
``tokens``       sha256 of each secret link's token, its role and its student
``submissions``  one row per accepted submit: exam, student, exercise, attempt number,
                 idempotency key, time, whether it counts (practice draws do not)
``answers``      one row per part of a submission: the raw text, how it read, the verdict
                 (status, points, feedback, the mistake the grader named)
``drafts``       what a student typed and has not submitted: one row per part, replaced
                 as they type (never counted)
``audit_log``    every change the staff make (a policy change, an exception, points by
                 hand, a regrade, a revoked link): who, when, what, and the JSON before
                 and after
``allowances``   a student's exceptions to the policy: their own opening and close, extra
                 minutes on a timed exam, extra attempts (JSON: scope -> number)
``starts``       when each student started a timed exam (their clock runs from then)
``overrides``    points a member of the staff set by hand on one part, with a comment
                 (the automatic verdict stays in ``answers``; removing the row restores it)
``regrades``     a regrade: previewed (the plan of changed verdicts, JSON), then applied
                 or discarded
``verdict_history`` the verdict an applied regrade replaced, one row per changed answer

Submissions and the audit log are only ever inserted, never updated or deleted. An
answer's text never changes; its verdict changes only by an applied regrade, which
first copies the old verdict to ``verdict_history``. A submit is one transaction; the
caller acknowledges it only after :func:`record_submission` returned, i.e. after the
commit.

Works on SQLite (WAL, one file) and PostgreSQL with the same statements.
"""

from __future__ import annotations

import contextlib
import datetime as dt
import fcntl
import hashlib
import secrets
import threading
from dataclasses import dataclass
from typing import overload
from importlib import resources
from pathlib import Path

import sqlalchemy as sa
from sqlalchemy.exc import IntegrityError

from ..errors import DynagradeError
from ..runs.files import create_private

metadata = sa.MetaData()

settings = sa.Table(
    "settings", metadata,
    sa.Column("key", sa.String(64), primary_key=True),
    sa.Column("value", sa.Text, nullable=False),
)

tokens = sa.Table(
    "tokens", metadata,
    sa.Column("token_hash", sa.String(64), primary_key=True),
    sa.Column("exam_id", sa.String(200), nullable=False),
    sa.Column("role", sa.String(16), nullable=False),  # "student" | "staff"
    sa.Column("student_id", sa.String(200), nullable=True),
    sa.Column("created_at", sa.DateTime(timezone=True), nullable=False),
    sa.Column("revoked", sa.Boolean, nullable=False, server_default=sa.false()),
    #: a staff link's name ("Anna (TA)"), as lists and the audit log show it
    sa.Column("label", sa.String(200), nullable=True),
    sa.Column("revoked_at", sa.DateTime(timezone=True), nullable=True),
    sa.Index("ix_tokens_exam_student", "exam_id", "student_id"),
)

submissions = sa.Table(
    "submissions", metadata,
    sa.Column("id", sa.Integer, primary_key=True, autoincrement=True),
    sa.Column("exam_id", sa.String(200), nullable=False),
    sa.Column("student_id", sa.String(200), nullable=False),
    sa.Column("exercise_id", sa.String(200), nullable=False),
    sa.Column("attempt", sa.Integer, nullable=False),
    sa.Column("seed", sa.BigInteger, nullable=False),
    sa.Column("counted", sa.Boolean, nullable=False),
    sa.Column("idempotency_key", sa.String(100), nullable=False),
    sa.Column("created_at", sa.DateTime(timezone=True), nullable=False),
    sa.UniqueConstraint("exam_id", "idempotency_key", name="uq_submissions_idempotency"),
    sa.UniqueConstraint("exam_id", "student_id", "exercise_id", "counted", "attempt",
                        name="uq_submissions_attempt"),
)

answers = sa.Table(
    "answers", metadata,
    sa.Column("id", sa.Integer, primary_key=True, autoincrement=True),
    sa.Column("submission_id", sa.Integer, sa.ForeignKey("submissions.id"), nullable=False,
              index=True),
    sa.Column("part", sa.String(200), nullable=False),
    sa.Column("raw", sa.Text, nullable=False),
    sa.Column("readable", sa.Boolean, nullable=False),
    sa.Column("message", sa.Text, nullable=False),
    sa.Column("status", sa.String(32), nullable=False),
    sa.Column("correct", sa.Boolean, nullable=False),
    sa.Column("score", sa.Float, nullable=False),
    sa.Column("max_score", sa.Float, nullable=False),
    sa.Column("feedback", sa.Text, nullable=False),
    sa.Column("misconception", sa.Text, nullable=True),
    sa.UniqueConstraint("submission_id", "part", name="uq_answers_part"),
)

drafts = sa.Table(
    "drafts", metadata,
    sa.Column("exam_id", sa.String(200), primary_key=True),
    sa.Column("student_id", sa.String(200), primary_key=True),
    sa.Column("exercise_id", sa.String(200), primary_key=True),
    sa.Column("part", sa.String(200), primary_key=True),
    sa.Column("text", sa.Text, nullable=False),
    sa.Column("saved_at", sa.DateTime(timezone=True), nullable=False),
)

audit_log = sa.Table(
    "audit_log", metadata,
    sa.Column("id", sa.Integer, primary_key=True, autoincrement=True),
    sa.Column("exam_id", sa.String(200), nullable=False),
    sa.Column("at", sa.DateTime(timezone=True), nullable=False),
    sa.Column("actor", sa.String(200), nullable=False),
    sa.Column("action", sa.String(64), nullable=False),
    sa.Column("subject", sa.String(200), nullable=False),
    sa.Column("before", sa.Text, nullable=True),  # JSON
    sa.Column("after", sa.Text, nullable=True),  # JSON
    sa.Index("ix_audit_log_exam_action", "exam_id", "action"),
)

allowances = sa.Table(
    "allowances", metadata,
    sa.Column("exam_id", sa.String(200), primary_key=True),
    sa.Column("student_id", sa.String(200), primary_key=True),
    sa.Column("opens", sa.DateTime(timezone=True), nullable=True),
    sa.Column("closes", sa.DateTime(timezone=True), nullable=True),
    sa.Column("extra_minutes", sa.Integer, nullable=False, server_default="0"),
    sa.Column("extra_attempts", sa.Text, nullable=False, server_default="{}"),  # JSON
    sa.Column("updated_at", sa.DateTime(timezone=True), nullable=False),
    sa.Column("updated_by", sa.String(200), nullable=False),
)

starts = sa.Table(
    "starts", metadata,
    sa.Column("exam_id", sa.String(200), primary_key=True),
    sa.Column("student_id", sa.String(200), primary_key=True),
    sa.Column("started_at", sa.DateTime(timezone=True), nullable=False),
)

overrides = sa.Table(
    "overrides", metadata,
    sa.Column("exam_id", sa.String(200), primary_key=True),
    sa.Column("student_id", sa.String(200), primary_key=True),
    sa.Column("exercise_id", sa.String(200), primary_key=True),
    sa.Column("part", sa.String(200), primary_key=True),
    sa.Column("points", sa.Float, nullable=False),
    sa.Column("comment", sa.Text, nullable=False, server_default=""),
    sa.Column("author", sa.String(200), nullable=False),
    sa.Column("at", sa.DateTime(timezone=True), nullable=False),
)

regrades = sa.Table(
    "regrades", metadata,
    sa.Column("id", sa.Integer, primary_key=True, autoincrement=True),
    sa.Column("exam_id", sa.String(200), nullable=False, index=True),
    sa.Column("created_at", sa.DateTime(timezone=True), nullable=False),
    sa.Column("actor", sa.String(200), nullable=False),
    sa.Column("state", sa.String(16), nullable=False),  # "previewed" | "applied" | "discarded"
    #: what the verdicts were recomputed against (the manifest's and exercises' digests)
    sa.Column("source", sa.Text, nullable=False),
    sa.Column("plan", sa.Text, nullable=False),  # JSON: the changed verdicts, old and new
    sa.Column("applied_at", sa.DateTime(timezone=True), nullable=True),
)

verdict_history = sa.Table(
    "verdict_history", metadata,
    sa.Column("id", sa.Integer, primary_key=True, autoincrement=True),
    sa.Column("answer_id", sa.Integer, sa.ForeignKey("answers.id"), nullable=False,
              index=True),
    sa.Column("regrade_id", sa.Integer, sa.ForeignKey("regrades.id"), nullable=False),
    sa.Column("status", sa.String(32), nullable=False),
    sa.Column("correct", sa.Boolean, nullable=False),
    sa.Column("score", sa.Float, nullable=False),
    sa.Column("feedback", sa.Text, nullable=False),
    sa.Column("misconception", sa.Text, nullable=True),
)


def hash_token(token: str) -> str:
    """What the database stores of a secret link's token."""
    return hashlib.sha256(token.encode("utf-8")).hexdigest()


def new_token() -> str:
    """A fresh secret: 32 random bytes, URL-safe."""
    return secrets.token_urlsafe(32)


def now() -> dt.datetime:
    return dt.datetime.now(dt.timezone.utc)


@overload
def utc(moment: dt.datetime) -> dt.datetime: ...
@overload
def utc(moment: None) -> None: ...


def utc(moment: dt.datetime | None) -> dt.datetime | None:
    """A time read back from the database, with its zone (None stays None): SQLite
    gives times back without one, and they were stored in UTC."""
    if moment is None:
        return None
    return moment if moment.tzinfo else moment.replace(tzinfo=dt.timezone.utc)


@overload
def iso(moment: dt.datetime) -> str: ...
@overload
def iso(moment: None) -> None: ...


def iso(moment: dt.datetime | None) -> str | None:
    """A time read back from the database as ISO 8601 text, to the second."""
    return None if moment is None else utc(moment).isoformat(timespec="seconds")


# -- connecting ---------------------------------------------------------------------------


def _bound(*columns: sa.Column):
    """The condition ``column == :name`` for each column, with a bind parameter named as
    the column: the statements a submit runs are built once with these, because building
    a statement costs ten times what executing a built one does (0.33 against 0.03 ms of
    CPU, measured on SQLite)."""
    return sa.and_(*(column == sa.bindparam(column.name) for column in columns))


def sqlite_url_beside(manifest: Path) -> str:
    """The default database: a SQLite file beside the manifest's folder, never inside it
    (:func:`dynagrade.serve.location.default_database`)."""
    from .location import default_database

    return f"sqlite:///{default_database(manifest)}"


def connect(url: str) -> sa.Engine:
    """An engine for ``url`` with the schema migrated to the newest version."""
    if url.startswith("postgresql://"):
        url = "postgresql+psycopg://" + url[len("postgresql://"):]
    if url.startswith("sqlite"):
        engine = sa.create_engine(url, connect_args={"timeout": 30})
        sa.event.listen(engine, "connect", _sqlite_pragmas)
        database = engine.url.database or ":memory:"
        if database != ":memory:":
            # made 0600 before SQLite opens it; its -wal and -shm files take its mode
            create_private(database)
        _WRITER_LOCKS.setdefault(database, _WriterLock(database))
    else:
        engine = sa.create_engine(url, pool_pre_ping=True, pool_size=5, max_overflow=5)
    migrate(engine)
    return engine


class _WriterLock:
    """SQLite has one writer at a time, and a writer that finds the database busy polls
    with growing sleeps (up to 100 ms each): under load that, not the work, makes the
    slow submits. Writers therefore queue on a lock instead: a thread lock within a
    process and ``flock`` on a file beside the database across the workers (a blocking
    wait, no polling). PostgreSQL needs none of this."""

    def __init__(self, database: str | None):
        self._threads = threading.Lock()
        self._path = f"{database}.writer-lock" if database and database != ":memory:" else None

    @contextlib.contextmanager
    def held(self):
        with self._threads:
            if self._path is None:
                yield
                return
            with open(self._path, "a") as handle:
                fcntl.flock(handle, fcntl.LOCK_EX)
                try:
                    yield
                finally:
                    fcntl.flock(handle, fcntl.LOCK_UN)


#: one writer lock per SQLite file in this process
_WRITER_LOCKS: dict[str, _WriterLock] = {}


def _writing(engine: sa.Engine):
    lock = _WRITER_LOCKS.get(engine.url.database or ":memory:") \
        if engine.dialect.name == "sqlite" else None
    return lock.held() if lock is not None else contextlib.nullcontext()


def writing(engine: sa.Engine):
    """The writer lock of ``engine`` (its SQLite file's; none on PostgreSQL), held
    around a transaction that writes, by the modules that keep tables of their own
    (:mod:`dynagrade.serve.lti`)."""
    return _writing(engine)


def _sqlite_pragmas(connection, _record) -> None:
    cursor = connection.cursor()
    cursor.execute("PRAGMA journal_mode=WAL")      # readers never block the writer
    cursor.execute("PRAGMA synchronous=FULL")      # a commit survives a power cut too
    cursor.execute("PRAGMA foreign_keys=ON")
    cursor.execute("PRAGMA busy_timeout=30000")    # several workers share the file
    cursor.close()


def migrate(engine: sa.Engine) -> None:
    """Bring the schema to the newest migration (``alembic upgrade head``)."""
    from alembic import command
    from alembic.config import Config

    config = Config()
    config.set_main_option("script_location",
                           str(resources.files("dynagrade.serve") / "migrations"))
    with engine.begin() as connection:
        if engine.dialect.name == "postgresql":  # several workers may start at once
            connection.execute(sa.text("SELECT pg_advisory_xact_lock(7413)"))
        config.attributes["connection"] = connection
        command.upgrade(config, "head")


def ping(engine: sa.Engine) -> None:
    """Raise when the database does not answer."""
    with engine.connect() as connection:
        connection.execute(sa.text("SELECT 1"))


def server_secret(engine: sa.Engine) -> str:
    """The secret every worker signs CSRF fields with, created once."""
    with engine.begin() as connection:
        value = connection.execute(sa.select(settings.c.value)
                                   .where(settings.c.key == "csrf_secret")).scalar()
        if value is not None:
            return value
        with contextlib.suppress(IntegrityError):  # another worker created it first
            with connection.begin_nested():
                connection.execute(settings.insert().values(key="csrf_secret",
                                                            value=secrets.token_hex(32)))
        return connection.execute(sa.select(settings.c.value)
                                  .where(settings.c.key == "csrf_secret")).scalar_one()


# -- tokens -------------------------------------------------------------------------------


@dataclass(frozen=True)
class Identity:
    """Who a token belongs to."""

    role: str
    student_id: str | None
    #: a staff link's name (None: unnamed, or a student's link)
    label: str | None = None


def identify(engine: sa.Engine, exam_id: str, token: str) -> Identity | None:
    """The holder of ``token`` in exam ``exam_id``, or ``None`` for an unknown token."""
    with engine.connect() as connection:
        row = connection.execute(
            sa.select(tokens.c.role, tokens.c.student_id, tokens.c.label).where(
                tokens.c.token_hash == hash_token(token), tokens.c.exam_id == exam_id,
                tokens.c.revoked == sa.false())).first()
    return Identity(row.role, row.student_id, row.label) if row else None


def issue_tokens(engine: sa.Engine, exam_id: str, student_ids: list[str],
                 rotate: bool = False) -> dict[str, str | None]:
    """A fresh token for each student without one (every student with ``rotate``).

    Returns ``{student_id: token}``; the token is ``None`` for a student who keeps an
    existing token (only its hash is stored, so it cannot be shown again).
    """
    issued: dict[str, str | None] = {}
    with engine.begin() as connection:
        have = set(connection.execute(
            sa.select(tokens.c.student_id).where(
                tokens.c.exam_id == exam_id, tokens.c.role == "student",
                tokens.c.revoked == sa.false())).scalars())
        if rotate:
            connection.execute(tokens.update().where(
                tokens.c.exam_id == exam_id, tokens.c.role == "student",
                tokens.c.revoked == sa.false()).values(revoked=True, revoked_at=now()))
            have = set()
        for student_id in student_ids:
            if student_id in have:
                issued[student_id] = None
                continue
            token = new_token()
            connection.execute(tokens.insert().values(
                token_hash=hash_token(token), exam_id=exam_id, role="student",
                student_id=student_id, created_at=now()))
            issued[student_id] = token
    return issued


def issue_staff_token(engine: sa.Engine, exam_id: str, label: str | None = None) -> str:
    """A new staff token named ``label`` (earlier staff links keep working until revoked:
    :func:`revoke_staff_links`)."""
    token = new_token()
    with _writing(engine), engine.begin() as connection:
        connection.execute(tokens.insert().values(
            token_hash=hash_token(token), exam_id=exam_id, role="staff", student_id=None,
            created_at=now(), label=label))
    return token


# -- drafts -------------------------------------------------------------------------------


@dataclass(frozen=True)
class Draft:
    """What a student typed into one part and has not submitted (never counted)."""

    exercise_id: str
    part: str
    text: str
    saved_at: dt.datetime


_DELETE_DRAFTS = drafts.delete().where(
    _bound(drafts.c.exam_id, drafts.c.student_id, drafts.c.exercise_id),
    drafts.c.part.in_(sa.bindparam("parts", expanding=True)))
_INSERT_DRAFTS = drafts.insert()


def save_drafts(engine: sa.Engine, exam_id: str, student_id: str, exercise_id: str,
                texts: dict[str, str]) -> None:
    """Keep ``texts`` (part -> text) as the student's drafts of an exercise, replacing
    the earlier ones of those parts, in one transaction."""
    if not texts:
        return
    key = {"exam_id": exam_id, "student_id": student_id, "exercise_id": exercise_id}
    with _writing(engine), engine.begin() as connection:
        connection.execute(_DELETE_DRAFTS, {**key, "parts": list(texts)})
        connection.execute(_INSERT_DRAFTS, [
            {**key, "part": part, "text": text, "saved_at": now()}
            for part, text in texts.items()])


_DRAFTS_OF = sa.select(drafts.c.exercise_id, drafts.c.part, drafts.c.text,
                       drafts.c.saved_at).where(_bound(drafts.c.exam_id, drafts.c.student_id))


def student_drafts(engine: sa.Engine, exam_id: str, student_id: str) -> list[Draft]:
    """Every draft of a student."""
    with engine.connect() as connection:
        rows = connection.execute(_DRAFTS_OF, {"exam_id": exam_id,
                                               "student_id": student_id}).all()
    return [Draft(*row) for row in rows]


_LAST_TEXTS = sa.select(answers.c.part, answers.c.raw).select_from(
    answers.join(submissions)).where(
    _bound(submissions.c.exam_id, submissions.c.student_id, submissions.c.exercise_id),
    submissions.c.counted == sa.true()).order_by(submissions.c.id)


def _last_texts(connection, exam_id: str, student_id: str, exercise_id: str
                ) -> dict[str, str]:
    """The text of each part's latest counted answer (what the form's submit compares
    with, to send only the parts that changed)."""
    rows = connection.execute(_LAST_TEXTS, {
        "exam_id": exam_id, "student_id": student_id, "exercise_id": exercise_id}).all()
    return {part: raw for part, raw in rows}


# -- submissions --------------------------------------------------------------------------


@dataclass(frozen=True)
class StoredAnswer:
    """One part of one submission, as stored."""

    submission_id: int
    student_id: str
    exercise_id: str
    attempt: int
    counted: bool
    seed: int
    created_at: dt.datetime
    part: str
    raw: str
    readable: bool
    message: str
    status: str
    correct: bool
    score: float
    max_score: float
    feedback: str
    misconception: str | None = None


class DuplicateAttempt(DynagradeError):
    """Another worker stored the same attempt number first; retry with the next one."""


class DuplicateSubmission(DynagradeError):
    """A submission with this idempotency key is stored already (the same submit arrived
    twice at once); the caller replays the stored one."""


def find_submission(engine: sa.Engine, exam_id: str, key: str) -> list[StoredAnswer] | None:
    """The answers of the submission with idempotency ``key``, or ``None``."""
    with engine.connect() as connection:
        return _find_submission(connection, exam_id, key)


#: the submission stored under an idempotency key (prepared once: see :func:`_bound`)
_SUBMISSION_BY_KEY = sa.select(submissions.c.id).where(
    submissions.c.exam_id == sa.bindparam("exam_id"),
    submissions.c.idempotency_key == sa.bindparam("key"))


def _find_submission(connection, exam_id: str, key: str) -> list[StoredAnswer] | None:
    found = connection.execute(_SUBMISSION_BY_KEY, {"exam_id": exam_id, "key": key}).scalar()
    return None if found is None else [StoredAnswer(*row) for row in connection.execute(
        _ANSWERS_OF_SUBMISSION, {"submission_id": found})]


def part_attempts(engine: sa.Engine, exam_id: str, student_id: str, exercise_id: str,
                  counted: bool = True) -> tuple[int, dict[str, int]]:
    """The number of (counted, or else practice) submissions of an exercise, and of
    answers per part."""
    with engine.connect() as connection:
        return _part_attempts(connection, exam_id, student_id, exercise_id, counted)


#: one row per part of an exercise's (counted, or else practice) submissions: the part,
#: its answers, the highest attempt among them
_PART_ATTEMPTS = sa.select(
    answers.c.part, sa.func.count(), sa.func.max(submissions.c.attempt)
).select_from(answers.join(submissions)).where(_bound(
    submissions.c.exam_id, submissions.c.student_id, submissions.c.exercise_id,
    submissions.c.counted)).group_by(answers.c.part)


def _part_attempts(connection, exam_id: str, student_id: str, exercise_id: str,
                   counted: bool) -> tuple[int, dict[str, int]]:
    # one query: every submission stores at least one answer, so the highest attempt
    # among the answers' submissions is the exercise's last attempt
    rows = connection.execute(_PART_ATTEMPTS, {
        "exam_id": exam_id, "student_id": student_id, "exercise_id": exercise_id,
        "counted": counted}).all()
    last = max((int(highest) for _part, _count, highest in rows), default=0)
    return last, {part: int(count) for part, count, _highest in rows}


@dataclass(frozen=True)
class SubmitReads:
    """What a submit reads before grading, read on one connection: the student's
    exceptions and timed start (:func:`student_terms`), the submission already stored
    under the idempotency key (or ``None``), the exercise's last attempt and answers per
    part (:func:`part_attempts`), and, when asked for, each part's last counted text
    (:func:`_last_texts`)."""

    terms: AllowanceRow | None
    started: dt.datetime | None
    stored: list[StoredAnswer] | None
    last_attempt: int
    per_part: dict[str, int]
    last_texts: dict[str, str] | None


def submit_reads(engine: sa.Engine, exam_id: str, student_id: str, exercise_id: str,
                 key: str | None, counted: bool, with_texts: bool) -> SubmitReads:
    """Everything a submit reads before grading (:class:`SubmitReads`), on one connection."""
    with engine.connect() as connection:
        terms, started = _student_terms(connection, exam_id, student_id)
        stored = _find_submission(connection, exam_id, key) if key is not None else None
        last, per_part = _part_attempts(connection, exam_id, student_id, exercise_id, counted)
        texts = _last_texts(connection, exam_id, student_id, exercise_id) \
            if with_texts else None
    return SubmitReads(terms, started, stored, last, per_part, texts)


_INSERT_SUBMISSION = submissions.insert().returning(submissions.c.id)
_INSERT_ANSWERS = answers.insert()


def record_submission(engine: sa.Engine, exam_id: str, student_id: str, exercise_id: str,
                      attempt: int, seed: int, counted: bool, key: str,
                      parts: list[dict]) -> None:
    """Store a submission and its answers in one transaction (committed on return).

    Raises :class:`DuplicateAttempt` when ``attempt`` was taken meanwhile, and
    :class:`DuplicateSubmission` when a submission with this idempotency key exists already.
    """
    try:
        with _writing(engine), engine.begin() as connection:
            submission_id = connection.execute(_INSERT_SUBMISSION, {
                "exam_id": exam_id, "student_id": student_id, "exercise_id": exercise_id,
                "attempt": attempt, "seed": seed, "counted": counted, "idempotency_key": key,
                "created_at": now()}).scalar_one()
            connection.execute(_INSERT_ANSWERS, [
                {**part, "submission_id": submission_id} for part in parts])
    except IntegrityError as error:
        if "idempotency" in str(error.orig):  # the constraint or column name
            raise DuplicateSubmission(key) from None
        raise DuplicateAttempt() from None


def student_answers(engine: sa.Engine, exam_id: str, student_id: str) -> list[StoredAnswer]:
    """Every answer a student submitted, oldest first."""
    with engine.connect() as connection:
        return [StoredAnswer(*row) for row in connection.execute(
            _ANSWERS_OF_STUDENT, {"exam_id": exam_id, "student_id": student_id})]


def all_answers(engine: sa.Engine, exam_id: str) -> list[StoredAnswer]:
    """Every answer of the exam, oldest first."""
    with engine.connect() as connection:
        return _answers(connection, submissions.c.exam_id == exam_id)


def counts(engine: sa.Engine, exam_id: str) -> dict[str, int]:
    """How many submissions and answers the exam holds (for monitoring and checks)."""
    with engine.connect() as connection:
        subs = connection.execute(sa.select(sa.func.count()).select_from(submissions)
                                  .where(submissions.c.exam_id == exam_id)).scalar_one()
        parts = connection.execute(sa.select(sa.func.count()).select_from(
            answers.join(submissions)).where(submissions.c.exam_id == exam_id)).scalar_one()
    return {"submissions": int(subs), "answers": int(parts)}


def idempotency_keys(engine: sa.Engine, exam_id: str) -> list[str]:
    """The idempotency key of every stored submission (a key appears at most once)."""
    with engine.connect() as connection:
        return list(connection.execute(sa.select(submissions.c.idempotency_key).where(
            submissions.c.exam_id == exam_id)).scalars())


def _answer_columns() -> tuple:
    """The columns of a :class:`StoredAnswer`, in its fields' order."""
    s, a = submissions.c, answers.c
    return (s.id, s.student_id, s.exercise_id, s.attempt, s.counted, s.seed, s.created_at,
            a.part, a.raw, a.readable, a.message, a.status, a.correct, a.score, a.max_score,
            a.feedback, a.misconception)


_ANSWERS_OF_SUBMISSION = sa.select(*_answer_columns()).select_from(
    answers.join(submissions)).where(
    submissions.c.id == sa.bindparam("submission_id")).order_by(answers.c.id)
_ANSWERS_OF_STUDENT = sa.select(*_answer_columns()).select_from(
    answers.join(submissions)).where(
    _bound(submissions.c.exam_id, submissions.c.student_id)
).order_by(submissions.c.id, answers.c.id)


def _answers(connection, condition) -> list[StoredAnswer]:
    rows = connection.execute(
        sa.select(*_answer_columns())
        .select_from(answers.join(submissions)).where(condition)
        .order_by(submissions.c.id, answers.c.id)).all()
    return [StoredAnswer(*row) for row in rows]


# -- the staff's changes: policy and the audit log -----------------------------------------


@dataclass(frozen=True)
class AuditEntry:
    """One recorded change: who made it, when, and the JSON before and after."""

    id: int
    at: dt.datetime
    actor: str
    action: str
    subject: str
    before: dict | None
    after: dict | None


#: the audit log's action of a policy change (``after``: the whole policy in force)
POLICY_CHANGE = "policy"


def record_change(engine: sa.Engine, exam_id: str, actor: str, action: str, subject: str,
                  before: dict | None, after: dict | None) -> int:
    """Append a change to the audit log (committed on return); its id."""
    with _writing(engine), engine.begin() as connection:
        return _append_change(connection, exam_id, actor, action, subject, before, after)


def _append_change(connection, exam_id: str, actor: str, action: str, subject: str,
                   before: dict | None, after: dict | None) -> int:
    """The audit log's insert, within the caller's transaction (a change and its record
    commit together); the entry's id."""
    import json

    return int(connection.execute(audit_log.insert().values(
        exam_id=exam_id, at=now(), actor=actor, action=action, subject=subject,
        before=None if before is None else json.dumps(before, sort_keys=True),
        after=None if after is None else json.dumps(after, sort_keys=True))
        .returning(audit_log.c.id)).scalar_one())


def latest_change(engine: sa.Engine, exam_id: str, action: str) -> AuditEntry | None:
    """The newest change of ``action`` to the exam, or ``None``."""
    entries = changes(engine, exam_id, action, limit=1)
    return entries[0] if entries else None


def changes(engine: sa.Engine, exam_id: str, action: str | None = None,
            limit: int | None = None) -> list[AuditEntry]:
    """The exam's recorded changes (of ``action``, if given), newest first."""
    import json

    query = sa.select(audit_log).where(audit_log.c.exam_id == exam_id)
    if action is not None:
        query = query.where(audit_log.c.action == action)
    query = query.order_by(audit_log.c.id.desc()).limit(limit)
    with engine.connect() as connection:
        rows = connection.execute(query).all()
    return [AuditEntry(r.id, r.at, r.actor, r.action, r.subject,
                       None if r.before is None else json.loads(r.before),
                       None if r.after is None else json.loads(r.after)) for r in rows]


def accepts_writes(engine: sa.Engine) -> None:
    """Raise unless the database accepts a write: a heartbeat row (the time of the
    check) committed in ``settings``, so that a full disk or a read-only file raises."""
    stamp = now().isoformat()
    with _writing(engine), engine.begin() as connection:
        updated = connection.execute(settings.update().where(
            settings.c.key == "heartbeat").values(value=stamp)).rowcount
        if not updated:
            with contextlib.suppress(IntegrityError):  # another worker inserted it first
                with connection.begin_nested():
                    connection.execute(settings.insert().values(key="heartbeat",
                                                                value=stamp))


# -- exceptions to the policy per student, and the starts of a timed exam ------------------
# (the statements of dynagrade.serve.allowances)

#: the audit log's action of an exception granted, changed or removed (subject: the student)
EXCEPTION_CHANGE = "exception"


@dataclass(frozen=True)
class AllowanceRow:
    """A student's exceptions as stored (``extra_attempts``: the JSON text)."""

    student_id: str
    opens: dt.datetime | None
    closes: dt.datetime | None
    extra_minutes: int
    extra_attempts: str
    updated_at: dt.datetime
    updated_by: str


@dataclass(frozen=True)
class AllowanceWrite:
    """One student's exceptions to store (``values``: the row's columns but the keys;
    None: remove them), with the audit log's before and after."""

    student_id: str
    values: dict | None
    before: dict | None
    after: dict | None


def allowance_rows(engine: sa.Engine, exam_id: str,
                   student_ids: list[str] | None = None) -> list[AllowanceRow]:
    """The exceptions of the exam (of ``student_ids``, if given), by student id."""
    query = sa.select(allowances.c.student_id, allowances.c.opens, allowances.c.closes,
                      allowances.c.extra_minutes, allowances.c.extra_attempts,
                      allowances.c.updated_at, allowances.c.updated_by).where(
        allowances.c.exam_id == exam_id).order_by(allowances.c.student_id)
    if student_ids is not None:
        query = query.where(allowances.c.student_id.in_(student_ids))
    with engine.connect() as connection:
        return [AllowanceRow(*row) for row in connection.execute(query).all()]


def student_terms(engine: sa.Engine, exam_id: str, student_id: str
                  ) -> tuple[AllowanceRow | None, dt.datetime | None]:
    """What decides for one student beside the policy: their exceptions (or None) and
    when they started a timed exam (or None), read together."""
    with engine.connect() as connection:
        return _student_terms(connection, exam_id, student_id)


_ALLOWANCE_OF = sa.select(
    allowances.c.student_id, allowances.c.opens, allowances.c.closes,
    allowances.c.extra_minutes, allowances.c.extra_attempts, allowances.c.updated_at,
    allowances.c.updated_by).where(_bound(allowances.c.exam_id, allowances.c.student_id))
_STARTED_AT = sa.select(starts.c.started_at).where(
    _bound(starts.c.exam_id, starts.c.student_id))


def _student_terms(connection, exam_id: str, student_id: str
                   ) -> tuple[AllowanceRow | None, dt.datetime | None]:
    student = {"exam_id": exam_id, "student_id": student_id}
    row = connection.execute(_ALLOWANCE_OF, student).first()
    started = connection.execute(_STARTED_AT, student).scalar()
    return (AllowanceRow(*row) if row else None), started


def write_allowances(engine: sa.Engine, exam_id: str, actor: str,
                     writes: list[AllowanceWrite]) -> None:
    """Store (or remove) the exceptions of several students and record each change in
    the audit log, all in one transaction."""
    if not writes:
        return
    with _writing(engine), engine.begin() as connection:
        for write in writes:
            connection.execute(allowances.delete().where(
                allowances.c.exam_id == exam_id, allowances.c.student_id == write.student_id))
            if write.values is not None:
                connection.execute(allowances.insert().values(
                    exam_id=exam_id, student_id=write.student_id, updated_at=now(),
                    updated_by=actor, **write.values))
            _append_change(connection, exam_id, actor, EXCEPTION_CHANGE, write.student_id,
                           write.before, write.after)


def record_start(engine: sa.Engine, exam_id: str, student_id: str,
                 at: dt.datetime) -> dt.datetime:
    """Store that a student started a timed exam at ``at``, unless they started before:
    the first start counts. The start that counts."""
    condition = (starts.c.exam_id == exam_id, starts.c.student_id == student_id)
    with _writing(engine), engine.begin() as connection:
        first = connection.execute(sa.select(starts.c.started_at).where(*condition)).scalar()
        if first is not None:
            return first
        with contextlib.suppress(IntegrityError):  # another worker stored it first
            with connection.begin_nested():
                connection.execute(starts.insert().values(
                    exam_id=exam_id, student_id=student_id, started_at=at))
        return connection.execute(sa.select(starts.c.started_at).where(*condition)
                                  ).scalar_one()


def started_times(engine: sa.Engine, exam_id: str) -> dict[str, dt.datetime]:
    """When each student who started a timed exam started it."""
    with engine.connect() as connection:
        rows = connection.execute(sa.select(starts.c.student_id, starts.c.started_at).where(
            starts.c.exam_id == exam_id)).all()
    return {student_id: at for student_id, at in rows}


# -- points by hand -----------------------------------------------------------------------
# (the statements of dynagrade.serve.overrides)

#: the audit log's action of points set, changed or removed by hand (subject
#: ``student/exercise/part``; before and after: ``{"points", "comment"}`` or null)
OVERRIDE_CHANGE = "override"


@dataclass(frozen=True)
class StoredOverride:
    """Points a member of the staff set by hand on one part of one student."""

    student_id: str
    exercise_id: str
    part: str
    points: float
    comment: str
    #: who set them (the staff link's name)
    author: str
    at: dt.datetime


def stored_overrides(engine: sa.Engine, exam_id: str,
                     student_id: str | None = None) -> list[StoredOverride]:
    """The exam's points set by hand (of one student, if given)."""
    o = overrides.c
    query = sa.select(o.student_id, o.exercise_id, o.part, o.points, o.comment, o.author,
                      o.at).where(o.exam_id == exam_id)
    if student_id is not None:
        query = query.where(o.student_id == student_id)
    with engine.connect() as connection:
        rows = connection.execute(query.order_by(o.student_id, o.exercise_id, o.part)).all()
    return [StoredOverride(*row) for row in rows]


def put_override(engine: sa.Engine, exam_id: str, actor: str, student_id: str,
                 exercise_id: str, part: str, points: float | None,
                 comment: str = "") -> tuple[dict | None, dict | None] | None:
    """Set (``points`` a number) or remove (``None``) the points of a part by hand, and
    record the change in the audit log, in one transaction: (before, after) as recorded,
    or ``None`` when nothing changed (the same points and comment again, or removing
    what is not there), which records nothing."""
    try:
        return _put_override(engine, exam_id, actor, student_id, exercise_id, part, points,
                             comment)
    except IntegrityError:  # another change of the part was committed meanwhile
        return _put_override(engine, exam_id, actor, student_id, exercise_id, part, points,
                             comment)


def _put_override(engine: sa.Engine, exam_id: str, actor: str, student_id: str,
                  exercise_id: str, part: str, points: float | None,
                  comment: str) -> tuple[dict | None, dict | None] | None:
    o = overrides.c
    key = (o.exam_id == exam_id, o.student_id == student_id, o.exercise_id == exercise_id,
           o.part == part)
    with _writing(engine), engine.begin() as connection:
        # the row locked on PostgreSQL (one change of a part at a time); SQLite has one
        # writer anyway, and SQLAlchemy leaves FOR UPDATE out there
        row = connection.execute(sa.select(o.points, o.comment).where(*key)
                                 .with_for_update()).first()
        before = None if row is None else {"points": row.points, "comment": row.comment}
        after = None if points is None else {"points": float(points), "comment": comment}
        if before == after:
            return None
        connection.execute(overrides.delete().where(*key))
        if after is not None:
            connection.execute(overrides.insert().values(
                exam_id=exam_id, student_id=student_id, exercise_id=exercise_id, part=part,
                points=after["points"], comment=comment, author=actor, at=now()))
        _append_change(connection, exam_id, actor, OVERRIDE_CHANGE,
                       f"{student_id}/{exercise_id}/{part}", before, after)
    return before, after


# -- regrades -----------------------------------------------------------------------------
# (the statements of dynagrade.serve.regrade)

#: the audit log's action of an applied or discarded regrade (subject: the plan's id)
REGRADE = "regrade"


@dataclass(frozen=True)
class Regrade:
    """A regrade: who previewed it and when, its state, what the verdicts were
    recomputed against (``source``) and the plan (the verdicts that change, old and new)."""

    id: int
    created_at: dt.datetime
    actor: str
    state: str  # "previewed" | "applied" | "discarded"
    source: dict
    plan: dict
    applied_at: dt.datetime | None


class RegradeConflict(DynagradeError):
    """A regrade cannot be applied or discarded: ``why`` is its state ("applied",
    "discarded") or "answers changed" (an answer no longer holds the plan's old verdict)."""

    def __init__(self, why: str):
        super().__init__(why)
        self.why = why


def counted_answers_by_id(engine: sa.Engine, exam_id: str) -> list[tuple[int, StoredAnswer]]:
    """Every counted answer of the exam with its row id, oldest first (what a regrade
    recomputes)."""
    with engine.connect() as connection:
        rows = connection.execute(
            sa.select(answers.c.id, *_answer_columns())
            .select_from(answers.join(submissions))
            .where(submissions.c.exam_id == exam_id, submissions.c.counted == sa.true())
            .order_by(submissions.c.id, answers.c.id)).all()
    return [(int(row[0]), StoredAnswer(*row[1:])) for row in rows]


def store_regrade(engine: sa.Engine, exam_id: str, actor: str, source: dict,
                  plan: dict) -> int:
    """Keep a previewed regrade; its id."""
    import json

    with _writing(engine), engine.begin() as connection:
        return int(connection.execute(regrades.insert().values(
            exam_id=exam_id, created_at=now(), actor=actor, state="previewed",
            source=json.dumps(source, sort_keys=True), plan=json.dumps(plan),
            applied_at=None).returning(regrades.c.id)).scalar_one())


def _regrade(row) -> Regrade:
    import json

    return Regrade(int(row.id), row.created_at, row.actor, row.state, json.loads(row.source),
                   json.loads(row.plan), row.applied_at)


def find_regrade(engine: sa.Engine, exam_id: str, regrade_id: int) -> Regrade | None:
    """The exam's regrade ``regrade_id``, or ``None``."""
    with engine.connect() as connection:
        row = connection.execute(sa.select(regrades).where(
            regrades.c.exam_id == exam_id, regrades.c.id == regrade_id)).first()
    return None if row is None else _regrade(row)


def list_regrades(engine: sa.Engine, exam_id: str, limit: int = 50) -> list[Regrade]:
    """The exam's regrades, newest first."""
    with engine.connect() as connection:
        rows = connection.execute(sa.select(regrades).where(regrades.c.exam_id == exam_id)
                                  .order_by(regrades.c.id.desc()).limit(limit)).all()
    return [_regrade(row) for row in rows]


def applied_regrades(engine: sa.Engine, exam_id: str) -> int:
    """How many regrades of the exam were applied (it only grows: a worker that sees it
    grow loads the exam again)."""
    with engine.connect() as connection:
        return int(connection.execute(sa.select(sa.func.count()).select_from(regrades).where(
            regrades.c.exam_id == exam_id, regrades.c.state == "applied")).scalar_one())


def counted_answers_after(engine: sa.Engine, exam_id: str, answer_id: int,
                          until: dt.datetime | None = None) -> int:
    """How many counted answers were stored after the answer ``answer_id`` (and, given
    ``until``, before that time)."""
    condition = [submissions.c.exam_id == exam_id, submissions.c.counted == sa.true(),
                 answers.c.id > answer_id]
    if until is not None:
        condition.append(submissions.c.created_at <= until)
    with engine.connect() as connection:
        return int(connection.execute(
            sa.select(sa.func.count()).select_from(answers.join(submissions))
            .where(*condition)).scalar_one())


#: the verdict columns a regrade replaces (and ``verdict_history`` keeps)
VERDICT = ("status", "correct", "score", "feedback", "misconception")


def _same_verdict(row, verdict: dict) -> bool:
    return (row.status == verdict["status"] and bool(row.correct) == verdict["correct"]
            and abs(float(row.score) - float(verdict["score"])) <= 1e-9
            and row.misconception == verdict["misconception"])


def _already(connection, exam_id: str, regrade_id: int, target: str) -> bool:
    """Whether the regrade is in the ``target`` state already (its row locked until the
    transaction ends); :class:`RegradeConflict` unless it is that or still previewed."""
    state = connection.execute(sa.select(regrades.c.state).where(
        regrades.c.exam_id == exam_id, regrades.c.id == regrade_id)
        .with_for_update()).scalar()
    if state == target:
        return True
    if state != "previewed":
        raise RegradeConflict(str(state))
    return False


def apply_regrade(engine: sa.Engine, exam_id: str, regrade_id: int, actor: str,
                  changes: list[dict], before: dict, after: dict) -> bool:
    """Apply the previewed regrade in one transaction: each answer of ``changes``
    (``{"answer_id", "old": verdict, "new": verdict}``) must still hold its old verdict;
    the old verdict goes to ``verdict_history``, the new one replaces it, the regrade is
    marked applied and the audit log gets ``before`` and ``after``. False when it was
    applied already (nothing done); :class:`RegradeConflict` when it cannot be applied."""
    with _writing(engine), engine.begin() as connection:
        if _already(connection, exam_id, regrade_id, "applied"):
            return False
        ids = [change["answer_id"] for change in changes]
        current = {}
        for chunk in range(0, len(ids), 500):
            rows = connection.execute(sa.select(answers.c.id, *(answers.c[c] for c in VERDICT))
                                      .where(answers.c.id.in_(ids[chunk:chunk + 500]))
                                      .with_for_update()).all()
            current.update({row.id: row for row in rows})
        moved = [i for i, change in zip(ids, changes)
                 if i not in current or not _same_verdict(current[i], change["old"])]
        if moved:
            raise RegradeConflict("answers changed")
        if changes:
            connection.execute(verdict_history.insert(), [
                {"answer_id": change["answer_id"], "regrade_id": regrade_id,
                 **{c: change["old"][c] for c in VERDICT}} for change in changes])
            for change in changes:
                connection.execute(answers.update().where(
                    answers.c.id == change["answer_id"]).values(
                    **{c: change["new"][c] for c in VERDICT}))
        connection.execute(regrades.update().where(regrades.c.id == regrade_id)
                           .values(state="applied", applied_at=now()))
        _append_change(connection, exam_id, actor, REGRADE, str(regrade_id), before, after)
    return True


def discard_regrade(engine: sa.Engine, exam_id: str, regrade_id: int, actor: str) -> bool:
    """Discard a previewed regrade (recorded in the audit log); False when it was
    discarded already; :class:`RegradeConflict` when it was applied."""
    with _writing(engine), engine.begin() as connection:
        if _already(connection, exam_id, regrade_id, "discarded"):
            return False
        connection.execute(regrades.update().where(regrades.c.id == regrade_id)
                           .values(state="discarded"))
        _append_change(connection, exam_id, actor, REGRADE, str(regrade_id),
                       {"state": "previewed"}, {"state": "discarded"})
    return True


@dataclass(frozen=True)
class ReplacedVerdict:
    """A verdict an applied regrade replaced: when, which answer, and the points before
    and after (``after``: the next regrade's old points, or the answer's points now)."""

    applied_at: dt.datetime
    exercise_id: str
    part: str
    attempt: int
    before: float
    after: float


def replaced_verdicts(engine: sa.Engine, exam_id: str, student_id: str
                      ) -> list[ReplacedVerdict]:
    """Every verdict of the student's answers that an applied regrade replaced, oldest
    first."""
    h = verdict_history.c
    with engine.connect() as connection:
        rows = connection.execute(
            sa.select(h.answer_id, h.score, regrades.c.applied_at, submissions.c.exercise_id,
                      answers.c.part, submissions.c.attempt, answers.c.score.label("now"))
            .select_from(verdict_history.join(regrades).join(answers)
                         .join(submissions, answers.c.submission_id == submissions.c.id))
            .where(submissions.c.exam_id == exam_id, submissions.c.student_id == student_id,
                   regrades.c.state == "applied")
            .order_by(h.id)).all()
    out = []
    for index, row in enumerate(rows):
        later = next((r.score for r in rows[index + 1:] if r.answer_id == row.answer_id),
                     row.now)
        out.append(ReplacedVerdict(row.applied_at, row.exercise_id, row.part, int(row.attempt),
                                   float(row.score), float(later)))
    return out


# -- staff links: named, listed, revoked ---------------------------------------------------
# (the statements of dynagrade.serve.links)

#: how many leading characters of a token's hash name a staff link in lists and commands
LINK_ID_CHARS = 8


@dataclass(frozen=True)
class StaffLinkRecord:
    """A staff link as lists show it: never the token, which only its holder has."""

    #: the first :data:`LINK_ID_CHARS` characters of the token's hash
    id: str
    label: str | None
    created_at: dt.datetime
    revoked_at: dt.datetime | None

    @property
    def revoked(self) -> bool:
        return self.revoked_at is not None


def link_id(token: str) -> str:
    """The name of a link in lists: the start of its token's hash."""
    return hash_token(token)[:LINK_ID_CHARS]


def staff_links(engine: sa.Engine, exam_id: str) -> list[StaffLinkRecord]:
    """Every staff link of the exam, oldest first, revoked ones included."""
    t = tokens.c
    with engine.connect() as connection:
        rows = connection.execute(
            sa.select(t.token_hash, t.label, t.created_at, t.revoked, t.revoked_at)
            .where(t.exam_id == exam_id, t.role == "staff")
            .order_by(t.created_at, t.token_hash)).all()
    return [StaffLinkRecord(row.token_hash[:LINK_ID_CHARS], row.label, row.created_at,
                            (row.revoked_at or row.created_at) if row.revoked else None)
            for row in rows]


def revoke_staff_links(engine: sa.Engine, exam_id: str, ids: list[str] | None
                       ) -> list[StaffLinkRecord]:
    """Revoke the staff links whose :func:`link_id` is in ``ids`` (``None``: every staff
    link); the links this revoked (a link revoked before is left as it was)."""
    t = tokens.c
    condition = sa.and_(t.exam_id == exam_id, t.role == "staff", t.revoked == sa.false())
    with _writing(engine), engine.begin() as connection:
        hashes = [h for h in connection.execute(sa.select(t.token_hash).where(condition))
                  .scalars() if ids is None or h[:LINK_ID_CHARS] in ids]
        if hashes:
            connection.execute(tokens.update().where(t.token_hash.in_(hashes))
                               .values(revoked=True, revoked_at=now()))
    revoked = set(h[:LINK_ID_CHARS] for h in hashes)
    return [link for link in staff_links(engine, exam_id) if link.id in revoked]
