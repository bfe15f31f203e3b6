"""What a student's submits cost and what their page shows (issue 24, items 2-6 and 9):
attempts spent only on parts that changed, nothing spent on unreadable answers, drafts,
the page before the exam opens, and where the student stands. SQLite and PostgreSQL."""

from __future__ import annotations

import datetime as dt
import re

import pytest

from serve_support import (Clock, exam_copy, exam_dir, fresh_database, postgres_url,  # noqa: F401
                           reference_answers, serve)
from test_serve_api import CLOSES, OPENS, database  # noqa: F401

EXERCISE = "projectile-range"


def _form(served, student: str, answers: dict[str, str], exercise: str = EXERCISE):
    """A post of the student page's form (every box of the exercise, as the page sends)."""
    from dynagrade.serve import limits

    token = served.tokens[student]
    fields = {"exercise": exercise, "csrf": limits.csrf_field(served.server.secret, token),
              **{f"answer.{name}": text for name, text in answers.items()}}
    return served.client.post(f"/s/{token}/submit", data=fields, follow_redirects=False)


def _attempts(served, student: str) -> dict[str, int]:
    from dynagrade.serve import db

    _, per_part = db.part_attempts(served.server.engine, served.server.data.exam_id, student,
                                   EXERCISE)
    return per_part


def _page(served, student: str) -> str:
    return served.client.get(f"/s/{served.tokens[student]}").text


# -- invalid answers cost nothing -----------------------------------------------------------


def test_in_an_exam_an_unreadable_answer_never_replaces_the_counted_one(exam_dir, tmp_path,
                                                                         database):
    manifest = exam_copy(exam_dir, tmp_path / "exam", mode="exam", opens=OPENS, closes=CLOSES)
    clock = Clock()
    with serve(manifest, database, clock) as served:
        right = reference_answers(served, "s1", EXERCISE)["x_max"]
        assert served.submit("s1", EXERCISE, {"x_max": right}).status_code == 200
        slip = served.submit("s1", EXERCISE, {"x_max": "1.8423 kg"})  # a mass for a length
        assert slip.status_code == 422 and "mass" in slip.json()["detail"]
        assert _attempts(served, "s1") == {"x_max": 1}
        clock.now = CLOSES
        row = next(r for r in served.staff_get("/api/v1/gradebook").json()["rows"]
                   if r["student_id"] == "s1")
        points = {p.name: p.points for p in served.server.data.parts(EXERCISE)}
        assert row["exercises"][EXERCISE] == pytest.approx(points["x_max"])


def test_in_homework_unreadable_answers_spend_no_attempt(exam_dir, tmp_path, database):
    manifest = exam_copy(exam_dir, tmp_path / "hw", mode="homework", feedback="immediate",
                         attempts=2, penalty=0.5)
    with serve(manifest, database) as served:
        for text in ("5 kg", "abc"):
            refused = served.submit("s1", EXERCISE, {"x_max": text})
            assert refused.status_code == 422, text
        assert _attempts(served, "s1") == {}
        right = reference_answers(served, "s1", EXERCISE)
        body = served.submit("s1", EXERCISE, {"x_max": right["x_max"], "h_max": "abc"}).json()
        # the first attempt: full points, no penalty; the unreadable part named, not stored
        points = {p.name: p.points for p in served.server.data.parts(EXERCISE)}
        assert body["attempt"] == 1 and body["score"] == pytest.approx(points["x_max"])
        assert {p["name"]: p["readable"] for p in body["parts"]} == {"x_max": True,
                                                                       "h_max": False}
        assert _attempts(served, "s1") == {"x_max": 1}


# -- attempts spent only on what changed ----------------------------------------------------


def test_the_page_submits_only_changed_parts_and_an_exhausted_part_blocks_nothing(
        exam_dir, tmp_path, database):
    manifest = exam_copy(exam_dir, tmp_path / "hw", mode="homework", feedback="immediate",
                         attempts=1, penalty=0.25)
    with serve(manifest, database) as served:
        right = reference_answers(served, "s1", EXERCISE)
        first = _form(served, "s1", {"x_max": right["x_max"], "h_max": "", "t_flight": ""})
        assert first.status_code == 303 and first.headers["location"].endswith("#status")
        # the form sends the prefilled x_max again: unchanged, it is not submitted, and its
        # spent attempts do not refuse the new h_max
        second = _form(served, "s1", {"x_max": right["x_max"], "h_max": right["h_max"],
                                      "t_flight": ""})
        assert second.status_code == 303
        assert _attempts(served, "s1") == {"x_max": 1, "h_max": 1}
        page = _page(served, "s1")
        assert "no attempts left" in page
        assert re.search(r'id="projectile-range--x_max"[^>]*readonly', page)
        # a changed text for an exhausted part: refused beside the part, the typed text kept
        refused = _form(served, "s1", {"x_max": "12 m", "h_max": right["h_max"],
                                       "t_flight": "3.25 s"})
        assert refused.status_code == 403
        assert 'value="3.25 s"' in refused.text and 'value="12 m"' in refused.text
        assert re.search(r'id="projectile-range--x_max--reason">no attempts left',
                         refused.text)
        assert 'aria-invalid="true"' in refused.text


def test_an_unreadable_answer_on_the_page_is_shown_again_beside_its_reason(exam_dir,
                                                                            tmp_path):
    manifest = exam_copy(exam_dir, tmp_path / "hw", mode="homework", feedback="immediate")
    with serve(manifest) as served:
        right = reference_answers(served, "s2", EXERCISE)
        answered = _form(served, "s2", {"x_max": right["x_max"], "h_max": "5 kg"})
        assert answered.status_code == 200  # x_max saved; the page again for h_max
        assert 'value="5 kg"' in answered.text and "expected a length" in answered.text
        assert _attempts(served, "s2") == {"x_max": 1}
        assert 'role="alert"' in answered.text


# -- drafts ---------------------------------------------------------------------------------


def test_drafts_are_shown_until_a_newer_answer_is_submitted(exam_dir, tmp_path, database):
    manifest = exam_copy(exam_dir, tmp_path / "hw", mode="homework", feedback="immediate")
    with serve(manifest, database) as served:
        token = served.tokens["s3"]
        auth = {"Authorization": f"Bearer {token}"}
        saved = served.client.put("/api/v1/drafts", headers=auth, json={
            "exercise": "sliding-up-a-slope", "answers": {"a_up": "3 m/s^2"}})
        assert saved.status_code == 200 and saved.json()["saved"] == ["a_up"]
        assert 'value="3 m/s^2"' in _page(served, "s3")
        assert served.submit("s3", "sliding-up-a-slope", {"a_up": "4 m/s^2"}).status_code == 200
        page = _page(served, "s3")
        assert 'value="4 m/s^2"' in page and 'value="3 m/s^2"' not in page
        unknown = served.client.put("/api/v1/drafts", headers=auth, json={
            "exercise": "sliding-up-a-slope", "answers": {"nope": "1"}})
        assert unknown.status_code == 422
        from dynagrade.serve import db
        assert db.counts(served.server.engine, served.server.data.exam_id)["submissions"] == 1


# -- before the exam opens ------------------------------------------------------------------


def test_before_it_opens_the_page_shows_only_title_policy_and_opening_time(exam_dir,
                                                                           tmp_path):
    manifest = exam_copy(exam_dir, tmp_path / "exam", mode="exam", opens=OPENS, closes=CLOSES)
    with serve(manifest, None, Clock(OPENS - dt.timedelta(hours=1))) as served:
        page = _page(served, "s1")
        assert "Serve test" in page and f'datetime="{OPENS.isoformat()}"' in page
        assert "<math" not in page and "<svg" not in page and "<form" not in page
        assert "24.5" not in page  # no number of the statement
        preview = served.client.post("/api/v1/preview", json={
            "exercise": EXERCISE, "part": "x_max", "answer": "1 m"},
            headers={"Authorization": f"Bearer {served.tokens['s1']}"})
        assert preview.status_code == 403


# -- where the student stands ---------------------------------------------------------------


def test_the_page_says_where_the_student_stands(exam_dir, tmp_path, database):
    manifest = exam_copy(exam_dir, tmp_path / "hw", mode="homework", feedback="immediate",
                         counts="best", attempts=3, closes=CLOSES)
    with serve(manifest, database, Clock()) as served:
        right = reference_answers(served, "s1", EXERCISE)
        served.submit("s1", EXERCISE, {"x_max": "1 m"})
        served.submit("s1", EXERCISE, {"x_max": right["x_max"]})
        page = _page(served, "s1")
        points = {p.name: p.points for p in served.server.data.parts(EXERCISE)}
        assert "What counts: the best attempt of each part" in page
        assert "1 attempt left" in page and "3 attempts left" in page
        assert f"Counted so far: {points['x_max']} of 6.0 points" in page
        assert f"Total: {points['x_max']} of 10.0 points" in page
        history = page[page.index('<caption id="projectile-range--x_max--caption">'):]
        assert history.startswith('<caption id="projectile-range--x_max--caption">landing '
                                  'distance</caption>')
        assert history.index("<code>1 m</code>") < history.index(f"<code>{right['x_max']}")
        assert not re.search(r"\d\d:\d\d:\d\d\.\d{6}", page)  # no raw microseconds
        assert "2025-04-14 12:00 UTC" in page  # the close in the exam's zone, named
