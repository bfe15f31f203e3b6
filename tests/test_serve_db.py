"""The server's schema: the migrations build exactly the tables db.py queries."""

from __future__ import annotations

from alembic.autogenerate import compare_metadata
from alembic.migration import MigrationContext

from dynagrade.serve import db


def test_the_migrations_build_the_schema_that_db_py_declares(tmp_path):
    engine = db.connect(f"sqlite:///{tmp_path / 'serve.sqlite3'}")  # runs upgrade head
    with engine.connect() as connection:
        differences = compare_metadata(MigrationContext.configure(connection), db.metadata)
    assert differences == []


def test_migrating_twice_changes_nothing_and_keeps_the_data(tmp_path):
    url = f"sqlite:///{tmp_path / 'serve.sqlite3'}"
    issued = db.issue_tokens(db.connect(url), "exam-a", ["s1"])
    again = db.connect(url)
    assert db.identify(again, "exam-a", issued["s1"]) == db.Identity("student", "s1")
    assert db.identify(again, "exam-b", issued["s1"]) is None  # tokens belong to one exam
