"""The server's wall-clock wait for a grading job, against the grader's CPU-time budget
(issue 26, item 6): when the wait runs out (a loaded machine), the answer is "not graded
in time", stored with status error for the staff to grade, never marked wrong."""

from __future__ import annotations

from serve_support import (database, exam_copy, exam_dir, postgres_url,  # noqa: F401
                           reference_answers, serve)


def test_a_job_over_the_servers_wait_is_not_graded_never_wrong(exam_dir, tmp_path, database,
                                                                monkeypatch):
    from dynagrade.serve import grading_pool

    manifest = exam_copy(exam_dir, tmp_path / "exam", mode="practice")
    with serve(manifest, database) as served:
        right = reference_answers(served, "s1", "projectile-range")
        monkeypatch.setattr(grading_pool, "budget", lambda parts: 0.0)  # the wait runs out
        body = served.submit("s1", "projectile-range", right).json()
        assert {p["message"] for p in body["parts"]} == {
            "could not be graded in time; the staff will grade it"}
        monkeypatch.undo()
        served.submit("s1", "projectile-range", right)  # the same answers, in time
        stored = _stored(served)
    # the first attempt: status error (for the staff), not a wrong verdict; the second,
    # the same right answers graded in time: correct
    assert {(s, c) for a, s, c in stored if a == 1} == {("error", False)}
    assert {(s, c) for a, s, c in stored if a == 2} == {("correct", True)}
    assert len(stored) == 2 * len(right)


def _stored(served) -> list[tuple[int, str, bool]]:
    import sqlalchemy as sa

    from dynagrade.serve import db

    query = sa.select(db.submissions.c.attempt, db.answers.c.status, db.answers.c.correct
                      ).join(db.submissions, db.answers.c.submission_id == db.submissions.c.id)
    with served.server.engine.connect() as connection:
        return [tuple(row) for row in connection.execute(query)]
