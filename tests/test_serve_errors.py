"""Errors answer as pages for browsers and JSON for the API; a failing database gives
503 with Retry-After and gives back what was typed; /healthz checks a write; the staff
change the policy from their page, validated and recorded (issue 24, items 1 and 7)."""

from __future__ import annotations

import datetime as dt

import pytest

from serve_support import Clock, exam_copy, exam_dir, fresh_database, postgres_url, serve  # noqa: F401

BROWSER = {"Accept": "text/html,application/xhtml+xml,application/xml;q=0.9,*/*;q=0.8"}


def test_an_unknown_link_is_a_page_with_help_for_a_browser_and_json_for_the_api(
        exam_dir, tmp_path):
    with serve(exam_copy(exam_dir, tmp_path / "x")) as served:
        page = served.client.get("/s/not-a-token", headers=BROWSER)
        assert page.status_code == 401 and page.headers["content-type"].startswith("text/html")
        assert '<html lang="en">' in page.text and "<title>This link is not known (401)" in page.text
        assert "Links are personal" in page.text and "ask the course staff" in page.text
        api = served.client.get("/api/v1/gradebook", headers={
            **BROWSER, "Authorization": "Bearer nope"})
        assert api.status_code == 401 and api.json() == {"detail": "unknown link"}
        assert served.client.get("/s/not-a-token").json() == {"detail": "unknown link"}
        missing = served.client.get("/no/such/page", headers=BROWSER)
        assert missing.status_code == 404 and "Page not found" in missing.text


def test_a_database_that_refuses_writes_gives_503_and_the_typed_text_back(
        exam_dir, tmp_path, postgres_url):
    import sqlalchemy as sa

    from dynagrade.serve import limits

    url = fresh_database(postgres_url, "refusing_writes")
    with serve(exam_copy(exam_dir, tmp_path / "x", mode="homework", feedback="immediate"),
               url) as served:
        token = served.tokens["s1"]
        assert served.client.get("/healthz").text == "ok: the database accepts writes"
        admin = sa.create_engine(postgres_url.replace("postgresql://", "postgresql+psycopg://"),
                                 isolation_level="AUTOCOMMIT")
        with admin.connect() as connection:  # the database stops accepting writes
            connection.execute(sa.text("ALTER DATABASE refusing_writes SET "
                                       "default_transaction_read_only = on"))
            connection.execute(sa.text("SELECT pg_terminate_backend(pid) FROM "
                                       "pg_stat_activity WHERE datname = 'refusing_writes'"))
        admin.dispose()
        served.server.engine.dispose()
        typed = "12.5 m"  # readable: only a readable answer reaches the database
        posted = served.client.post(f"/s/{token}/submit", headers=BROWSER, data={
            "csrf": limits.csrf_field(served.server.secret, token),
            "exercise": "projectile-range", "answer.x_max": typed, "key": "k" * 20})
        assert posted.status_code == 503 and posted.headers["retry-after"]
        assert "Please try again shortly" in posted.text
        assert f'value="{typed}"' in posted.text and f'action="/s/{token}/submit"' in posted.text
        api = served.submit("s1", "projectile-range", {"x_max": "12 m"})
        assert api.status_code == 503 and api.headers["retry-after"]
        assert "database" in api.json()["detail"]
        health = served.client.get("/healthz")
        assert health.status_code == 503 and "read-only" in health.text


def _staff_form(served, **values):
    from dynagrade.serve import limits

    return served.client.post(f"/i/{served.staff}/policy", headers=BROWSER,
                              follow_redirects=False,
                              data={"csrf": limits.csrf_field(served.server.secret,
                                                              served.staff), **values})


def test_the_staff_change_the_policy_from_their_page_validated_and_recorded(exam_dir,
                                                                            tmp_path):
    from dynagrade.serve import db

    clock = Clock(dt.datetime(2025, 4, 14, 10, 0, tzinfo=dt.timezone.utc))
    with serve(exam_copy(exam_dir, tmp_path / "x"), clock=clock) as served:
        refused = _staff_form(served, feedback="immediate", closes="2025-04-20T12:00")
        assert refused.status_code == 422
        assert "an exam shows verdicts only after it closes" in refused.text
        assert 'value="2025-04-20T12:00"' in refused.text  # what was typed comes back
        no_offset = _staff_form(served, closes="2025-04-20T12:00")
        assert no_offset.status_code == 422 and "add the offset" in no_offset.text
        backwards = _staff_form(served, opens="2025-04-20T12:00:00Z",
                                closes="2025-04-19T12:00:00Z")
        assert backwards.status_code == 422 and "is not after opens" in backwards.text
        assert _staff_form(served, attempts="two").status_code == 422
        assert db.changes(served.server.engine, "serve-test") == []
        done = _staff_form(served, closes="2025-04-14T10:00:00Z", attempts="2")
        assert done.status_code == 303
        (entry,) = db.changes(served.server.engine, "serve-test")
        assert entry.actor.startswith("staff link ") and entry.before["closes"] is None
        assert entry.after["closes"] == "2025-04-14T10:00:00+00:00" and entry.after["attempts"] == 2
        late = served.submit("s1", "projectile-range", {"x_max": "12 m"})
        assert late.status_code == 403  # in force at once in this worker
        page = served.client.get(f"/i/{served.staff}").text
        assert "closes — → 2025-04-14T10:00:00+00:00" in page


def test_every_worker_sees_a_change_within_its_freshness(exam_dir, tmp_path):
    from dynagrade.serve import db
    from dynagrade.serve.policy_changes import PolicySource, change_policy

    manifest = exam_copy(exam_dir, tmp_path / "x")
    with serve(manifest) as served:
        engine, data = served.server.engine, served.server.data
        now = [100.0]
        other_worker = PolicySource(db.connect(str(engine.url)), data.exam_id,
                                    data.manifest_policy, fresh=2.0, clock=lambda: now[0])
        assert other_worker().attempts == 0
        change_policy(engine, data.exam_id, data.manifest_policy, "ta", {"attempts": 3})
        now[0] += 1.9
        assert other_worker().attempts == 0  # trusted for up to 2 s
        now[0] += 0.2
        assert other_worker().attempts == 3
