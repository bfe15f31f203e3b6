"""The policy's API twin of the staff page's form (issue 25: every staff action is an
API call): ``GET`` and ``PUT /api/v1/policy``, on SQLite and on the session's
PostgreSQL."""

from __future__ import annotations

import datetime as dt

from serve_support import (Clock, database, exam_copy, exam_dir, postgres_url,  # noqa: F401
                           reference_answers, serve)

UTC = dt.timezone.utc
OPENS = dt.datetime(2025, 4, 14, 8, 0, tzinfo=UTC)


def _as(token: str) -> dict:
    return {"Authorization": f"Bearer {token}"}


def test_the_staff_change_the_policy_by_api_checked_recorded_and_in_force(
        exam_dir, tmp_path, database):
    from dynagrade.serve import db

    manifest = exam_copy(exam_dir, tmp_path / "hw", mode="homework", feedback="immediate",
                         opens=OPENS, closes=OPENS + dt.timedelta(hours=4), attempts=1)
    with serve(manifest, database, Clock(OPENS + dt.timedelta(hours=1))) as served:
        client, staff = served.client, served.staff
        assert client.get("/api/v1/policy", headers=_as(staff)).json()["policy"]["attempts"] == 1
        right = reference_answers(served, "s1", "projectile-range")["x_max"]
        assert served.submit("s1", "projectile-range", {"x_max": "1 m"}).status_code == 200
        assert served.submit("s1", "projectile-range",
                             {"x_max": right}).status_code == 403  # its one attempt spent

        changed = client.put("/api/v1/policy", json={"attempts": 2, "penalty": 0.5},
                             headers=_as(staff))
        assert changed.status_code == 200, changed.text
        assert changed.json()["changed"] is True
        assert (changed.json()["policy"]["attempts"], changed.json()["policy"]["penalty"]) \
            == (2, 0.5)
        # in force at once: the second attempt is accepted and earns half the points
        second = served.submit("s1", "projectile-range", {"x_max": right})
        assert second.status_code == 200
        x_max = next(p for p in served.server.data.parts("projectile-range")
                     if p.name == "x_max")
        assert second.json()["parts"][0]["score"] == x_max.points * 0.5

        again = client.put("/api/v1/policy", json={"attempts": 2}, headers=_as(staff))
        assert again.json()["changed"] is False
        refused = client.put("/api/v1/policy", json={"feedback": "sometimes"},
                             headers=_as(staff))
        assert refused.status_code == 422 and "feedback" in refused.json()["detail"]
        no_offset = client.put("/api/v1/policy", json={"closes": "2025-04-14T18:00"},
                               headers=_as(staff))
        assert no_offset.status_code == 422 and "closes" in no_offset.json()["detail"]
        mode = client.put("/api/v1/policy", json={"mode": "exam"}, headers=_as(staff))
        assert mode.status_code == 422  # the mode is the exam's nature
        student = client.put("/api/v1/policy", json={"attempts": 9},
                             headers=_as(served.tokens["s1"]))
        assert student.status_code == 403
        entries = db.changes(served.server.engine, served.server.data.exam_id, "policy")
    assert len(entries) == 1  # one real change; the repeat and the refusals record nothing
    assert entries[0].actor == f"staff link {db.link_id(staff)}"
    assert (entries[0].before["attempts"], entries[0].after["attempts"]) == (1, 2)
