"""Timed exams (policy ``time_limit``, serve/timed.py) on SQLite and on a real PostgreSQL:
the page shows the rules and a Start button until the student starts; the first start
counts; submits and drafts after the student's deadline (start + time limit + their extra
minutes, or the close when it comes first) are refused with the time it ran out."""

from __future__ import annotations

import datetime as dt

import pytest

from serve_support import (Clock, database, exam_copy, exam_dir, postgres_url,  # noqa: F401
                           reference_answers, serve)

UTC = dt.timezone.utc


def at(hour: int, minute: int = 0) -> dt.datetime:
    return dt.datetime(2025, 4, 14, hour, minute, tzinfo=UTC)


def _bearer(token: str) -> dict:
    return {"Authorization": f"Bearer {token}"}


def _start(served, student: str):
    return served.client.post("/api/v1/start", headers=_bearer(served.tokens[student]))


def test_a_timed_exam_runs_from_each_students_start(exam_dir, tmp_path, database):
    from dynagrade.serve import limits

    manifest = exam_copy(exam_dir, tmp_path / "exam", mode="exam", opens=at(9),
                         closes=at(12), time_limit=30)
    clock = Clock(at(9, 30))
    with serve(manifest, database, clock) as served:
        answers = {s: reference_answers(served, s, "projectile-range") for s in ("s1", "s2")}
        assert served.client.put("/api/v1/exceptions", headers=_bearer(served.staff), json={
            "students": ["s1"], "extra_minutes": 15}).status_code == 200
        # before the start: the rules and the Start button, no exercise, nothing accepted
        page = served.client.get(f"/s/{served.tokens['s1']}").text
        assert "Time limit: 45 minutes" in page and ">Start</button>" in page
        assert 'id="projectile-range"' not in page
        refused = served.submit("s1", "projectile-range", answers["s1"])
        assert refused.status_code == 403 and "Start" in refused.json()["detail"]
        preview = served.client.post("/api/v1/preview", headers=_bearer(served.tokens["s1"]),
                                     json={"exercise": "projectile-range", "part": "x_max",
                                           "answer": "1 m"})
        assert preview.status_code == 403
        # the page's form starts s1 at 10:00; the API starts s2 at 10:00
        clock.now = at(10)
        csrf = limits.csrf_field(served.server.secret, served.tokens["s1"])
        started = served.client.post(f"/s/{served.tokens['s1']}/start", data={"csrf": csrf},
                                     follow_redirects=False)
        assert started.status_code == 303
        body = _start(served, "s2").json()
        assert body["timed"] and body["minutes"] == 30
        assert dt.datetime.fromisoformat(body["deadline"]) == at(10, 30)
        clock.now = at(10, 10)  # pressing again changes nothing: the first start counts
        again = _start(served, "s1").json()
        assert dt.datetime.fromisoformat(again["started_at"]) == at(10)
        assert dt.datetime.fromisoformat(again["deadline"]) == at(10, 45)
        page = served.client.get(f"/s/{served.tokens['s1']}").text
        assert 'id="projectile-range"' in page and ">Start</button>" not in page
        # the sentence without JavaScript, and the countdown's end, are s1's own
        assert "You may answer until" in page and "2025-04-14 10:45 UTC" in page
        assert 'data-closes="2025-04-14T10:45:00+00:00"' in page
        clock.now = at(10, 40)
        assert served.submit("s1", "projectile-range", answers["s1"]).status_code == 200
        late = served.submit("s2", "projectile-range", answers["s2"])
        assert late.status_code == 403
        assert "your time ran out at 2025-04-14 10:30 UTC" in late.json()["detail"]
        drafts = served.client.put("/api/v1/drafts", headers=_bearer(served.tokens["s2"]),
                                   json={"exercise": "projectile-range",
                                         "answers": {"x_max": "1 m"}})
        assert drafts.status_code == 403
        over = served.client.get(f"/s/{served.tokens['s2']}").text
        assert "Your time ran out at" in over and "<button type=\"submit\">" not in over
        clock.now = at(10, 45)
        assert served.submit("s1", "projectile-range", answers["s1"]).status_code == 403
        # s3 never started: after the close there is nothing to start
        clock.now = at(12)
        assert _start(served, "s3").status_code == 403


def test_a_late_start_ends_at_the_close_and_untimed_exams_start_nothing(exam_dir, tmp_path):
    manifest = exam_copy(exam_dir, tmp_path / "exam", mode="exam", closes=at(12),
                         time_limit=60)
    clock = Clock(at(11, 30))
    with serve(manifest, None, clock) as served:
        body = _start(served, "s1").json()
        assert dt.datetime.fromisoformat(body["deadline"]) == at(12)
        page = served.client.get(f"/s/{served.tokens['s1']}").text
        assert 'data-closes="2025-04-14T12:00:00+00:00"' in page
    untimed = exam_copy(exam_dir, tmp_path / "untimed", mode="exam", closes=at(12))
    with serve(untimed, None, Clock(at(10))) as served:
        body = _start(served, "s1").json()
        assert body == {"timed": False, "started_at": None, "minutes": 0,
                        "deadline": "2025-04-14T12:00:00+00:00"}
        assert ">Start</button>" not in served.client.get(f"/s/{served.tokens['s1']}").text


def test_the_time_limit_is_changed_on_the_staff_page_and_the_command_line(exam_dir, tmp_path):
    from click.testing import CliRunner

    from dynagrade.cli import main
    from dynagrade.serve import limits

    manifest = exam_copy(exam_dir, tmp_path / "exam", mode="exam")
    with serve(manifest, None, Clock()) as served:
        csrf = limits.csrf_field(served.server.secret, served.staff)
        page = served.client.get(f"/i/{served.staff}").text
        assert 'name="time_limit"' in page
        changed = served.client.post(f"/i/{served.staff}/policy",
                                     data={"csrf": csrf, "time_limit": "40"},
                                     follow_redirects=False)
        assert changed.status_code == 303
        assert served.server.data.policy.time_limit == 40
        bad = served.client.post(f"/i/{served.staff}/policy",
                                 data={"csrf": csrf, "time_limit": "-3"})
        assert bad.status_code == 422 and "time_limit" in bad.text
    runner = CliRunner()
    refused = runner.invoke(main, ["policy", str(manifest), "--time-limit", "x"])
    assert refused.exit_code == 1 and "'time_limit'" in refused.output
    done = runner.invoke(main, ["policy", str(manifest), "--time-limit", "25"])
    assert done.exit_code == 0 and "time_limit: 40 → 25" in done.output
