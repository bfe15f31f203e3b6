"""The staff's page of one student (issue 25, item 1) and its API twin: every attempt of
every part, the one that counts marked by the policy's ``counts``, drafts, points set by
hand through the page's forms (refusals shown beside the part with what was typed), and
404 for an id not on the roster, in the exam's language.
"""

from __future__ import annotations

import dataclasses
import datetime as dt
import re

import pytest

from serve_support import exam_copy, exam_dir, reference_answers, serve  # noqa: F401
from test_i18n_serve import german_exam  # noqa: F401

ZONE = dt.timezone(dt.timedelta(hours=2))


def _three_attempts(served) -> tuple[str, str]:
    """s1 answers x_max three times: wrong, right, wrong (the part's attempts 1, 2, 3)."""
    right = reference_answers(served, "s1", "projectile-range")["x_max"]
    wrong = repr(2 * float(right))
    for text in (wrong, right, wrong):
        assert served.submit("s1", "projectile-range", {"x_max": text}).status_code == 200
    return right, wrong


def _record(served, student: str = "s1"):
    return served.staff_get(f"/api/v1/students/{student}")


def _part(record: dict, exercise: str, part: str) -> dict:
    found = next(e for e in record["exercises"] if e["exercise"] == exercise)
    return next(p for p in found["parts"] if p["part"] == part)


def _counted_rows(html: str) -> list[str]:
    """The attempt number of each row marked as the one that counts."""
    return re.findall(r'<tr class="counts"><td>(\d+)', html)


@pytest.mark.parametrize("counts, expected", [("best", 2), ("last", 3)])
def test_every_attempt_is_listed_and_the_counted_one_marked(exam_dir, tmp_path, counts,
                                                            expected):
    manifest = exam_copy(exam_dir, tmp_path / "exam", mode="homework", feedback="immediate",
                         counts=counts)
    with serve(manifest) as served:
        right, wrong = _three_attempts(served)
        record = _record(served)
        page = served.client.get(f"/i/{served.staff}/students/s1")
    assert record.status_code == page.status_code == 200
    part = _part(record.json(), "projectile-range", "x_max")
    assert [(a["attempt"], a["answer"], a["status"]) for a in part["attempts"]] == [
        (1, wrong, "wrong"), (2, right, "correct"), (3, wrong, "wrong")]
    assert [a["attempt"] for a in part["attempts"] if a["counts"]] == [expected]
    assert part["counted_attempt"] == expected
    points = 2.4  # x_max's share of projectile-range's 6 points (2:1:1:1)
    assert part["score"] == (points if counts == "best" else 0.0)
    assert record.json()["counts"] == counts
    # the page: the three attempts, as typed and as read, the counted row marked
    html = page.text
    assert html.count(f"<code>{wrong}</code>") == 2 and html.count(f"<code>{right}</code>") == 1
    assert _counted_rows(html) == [str(expected)]
    why = {"best": "The best score counts", "last": "The last saved answer counts"}[counts]
    assert why in html
    assert "Ada One" in html and "ada@example.org" in html
    assert "/i/{}/exceptions?students=s1".format(served.staff) in html


def test_times_are_in_the_courses_zone_to_the_second(exam_dir, tmp_path):
    closes = dt.datetime(2099, 4, 14, 12, 0, tzinfo=ZONE)
    manifest = exam_copy(exam_dir, tmp_path / "exam", mode="homework", feedback="immediate",
                         closes=closes)
    with serve(manifest) as served:
        _three_attempts(served)
        from dynagrade.serve import db

        stored = db.student_answers(served.server.engine, "serve-test", "s1")
        page = served.client.get(f"/i/{served.staff}/students/s1").text
        tables = served.client.get(f"/i/{served.staff}/tables").json()
    first = stored[0].created_at.replace(tzinfo=dt.timezone.utc).astimezone(ZONE)
    assert f"{first:%Y-%m-%d %H:%M:%S} UTC+02:00" in page
    last = stored[-1].created_at.replace(tzinfo=dt.timezone.utc).astimezone(ZONE)
    assert tables["progress"]["columns"][-1] == "last submit (UTC+02:00)"
    assert tables["progress"]["rows"][0][-1] == f"{last:%Y-%m-%d %H:%M:%S} UTC+02:00"


def test_drafts_are_shown_and_never_counted(exam_dir, tmp_path):
    manifest = exam_copy(exam_dir, tmp_path / "exam", mode="homework", feedback="immediate")
    with serve(manifest) as served:
        saved = served.client.put("/api/v1/drafts", json={
            "exercise": "sliding-up-a-slope", "answers": {"a_up": "9.81 m/s^2 half typed"}},
            headers={"Authorization": f"Bearer {served.tokens['s1']}"})
        assert saved.status_code == 200
        record = _record(served).json()
        page = served.client.get(f"/i/{served.staff}/students/s1").text
    part = _part(record, "sliding-up-a-slope", "a_up")
    assert part["draft"]["text"] == "9.81 m/s^2 half typed"
    assert part["attempts"] == [] and part["counted_attempt"] is None
    assert record["total"] is None
    assert "<code>9.81 m/s^2 half typed</code>" in page


def _form(served, **fields):
    from dynagrade.serve import limits

    return {"csrf": limits.csrf_field(served.server.secret, served.staff), **fields}


def test_the_pages_forms_set_and_remove_points_and_refuse_with_the_reason(exam_dir,
                                                                         tmp_path):
    manifest = exam_copy(exam_dir, tmp_path / "exam", mode="homework", feedback="immediate",
                         counts="last")
    with serve(manifest) as served:
        _three_attempts(served)
        url = f"/i/{served.staff}/students/s1/overrides"
        done = served.client.post(url, data=_form(
            served, exercise="projectile-range", part="x_max", points="1,5",
            comment="method right"), follow_redirects=False)
        assert done.status_code == 303
        assert done.headers["location"].endswith("/students/s1#projectile-range--x_max")
        page = served.client.get(f"/i/{served.staff}/students/s1").text
        assert "Points set by hand: 1.5 of 2.4 (graded 0)" in page
        assert _part(_record(served).json(), "projectile-range", "x_max")["score"] == 1.5

        refused = served.client.post(url, data=_form(
            served, exercise="projectile-range", part="h_max", points="7",
            comment="too much"))
        assert refused.status_code == 422
        assert "points 7 is outside 0 to 1.2, the points of part &#39;h_max&#39;" in \
            refused.text
        assert 'aria-invalid="true" aria-describedby="projectile-range--h_max--reason"' in \
            refused.text and 'value="7"' in refused.text and ">too much</textarea>" in \
            refused.text

        stale = served.client.post(url, data={"csrf": "x", "exercise": "projectile-range",
                                              "part": "x_max", "points": "0"})
        assert stale.status_code == 403

        removed = served.client.post(f"{url}/remove", data=_form(
            served, exercise="projectile-range", part="x_max"), follow_redirects=False)
        assert removed.status_code == 303
        assert _part(_record(served).json(), "projectile-range", "x_max")["score"] == 0.0
        from dynagrade.serve import db

        entries = db.changes(served.server.engine, "serve-test", "override")
    assert [(e.before, e.after) for e in reversed(entries)] == [
        (None, {"points": 1.5, "comment": "method right"}),
        ({"points": 1.5, "comment": "method right"}, None)]


def test_a_student_not_on_the_roster_is_404_in_the_exams_language(exam_dir, tmp_path):
    from dynagrade.exam import manifest as records

    path = exam_copy(exam_dir, tmp_path / "exam", mode="homework")
    manifest = records.load(path)
    records.dump(dataclasses.replace(
        manifest, exam=dataclasses.replace(manifest.exam, language="de")), path)
    with serve(path) as served:
        page = served.client.get(f"/i/{served.staff}/students/s9",
                                 headers={"Accept": "text/html"})
        api = _record(served, "s9")
        known = served.client.get(f"/i/{served.staff}/students/s1")
        student = served.client.get(f"/i/{served.tokens['s1']}/students/s1")
    assert page.status_code == api.status_code == 404
    assert '<html lang="de">' in page.text and "Seite nicht gefunden" in page.text
    assert "s9" in api.json()["detail"]
    assert known.status_code == 200 and '<html lang="de">' in known.text
    assert student.status_code == 403  # a student's link is not a staff link


def test_the_german_student_staff_page_has_no_english_fixed_string(german_exam,
                                                                   tmp_path):
    """Every state of the page in a German exam: attempts, a draft, points set by hand, a
    refused form (its reason from the overrides' checks)."""
    from test_i18n_serve import _english_left

    from dynagrade.serve import db

    manifest = exam_copy(german_exam, tmp_path / "exam", mode="homework",
                         feedback="immediate")
    with serve(manifest) as served:
        right = reference_answers(served, "s1", "projectile-range")
        served.submit("s1", "projectile-range", {"x_max": right["x_max"]})
        served.submit("s1", "projectile-range", {"x_max": "1"})
        served.client.put("/api/v1/drafts", json={
            "exercise": "projectile-range", "answers": {"h_max": "2"}},
            headers={"Authorization": f"Bearer {served.tokens['s1']}"})
        url = f"/i/{served.staff}/students/s1"
        assert served.client.post(f"{url}/overrides", data=_form(
            served, exercise="projectile-range", part="x_max", points="1",
            comment="Methode richtig"), follow_redirects=False).status_code == 303
        page = served.client.get(url)
        refused = served.client.post(f"{url}/overrides", data=_form(
            served, exercise="projectile-range", part="h_max", points="99"))
        assert page.status_code == 200 and refused.status_code == 422
        assert "Punkte von Hand: 1 von" in page.text and "Versuche bei" in page.text
        assert "Entwurf" in page.text and "liegen nicht zwischen 0 und" in refused.text
        # who set the points is stored data (the staff link's name), not the interface's
        author = db.stored_overrides(served.server.engine, "german-test")[0].author
        assert _english_left(served, page.text.replace(author, ""), []) == []
        assert _english_left(served, refused.text.replace(author, ""), []) == []


def test_a_practice_draws_answers_are_listed_and_never_count(exam_dir, tmp_path):
    """Practice mode: s1 answers their own variant wrong, then a practice draw (any
    readable answer); under counts=best neither a right nor a wrong practice answer may
    count, so the own wrong answer (attempt 1) is the counted one."""
    from dynagrade.serve import limits
    from dynagrade.serve.practice import practice_value

    manifest = exam_copy(exam_dir, tmp_path / "exam", mode="practice", feedback="immediate",
                         counts="best")
    with serve(manifest) as served:
        right = reference_answers(served, "s1", "projectile-range")["x_max"]
        assert served.submit("s1", "projectile-range",
                             {"x_max": repr(2 * float(right))}).status_code == 200
        draw = practice_value(served.server.secret, "s1", "projectile-range", 12345)
        posted = served.client.post(f"/s/{served.tokens['s1']}/submit", data={
            "csrf": limits.csrf_field(served.server.secret, served.tokens["s1"]),
            "exercise": "projectile-range", "practice": draw, "key": "practice-1",
            "answer.x_max": "30 m"}, follow_redirects=False)
        assert posted.status_code == 303, posted.text
        part = _part(_record(served).json(), "projectile-range", "x_max")
        page = served.client.get(f"/i/{served.staff}/students/s1").text
    assert [(a["attempt"], a["practice"], a["counts"]) for a in part["attempts"]] == [
        (1, False, True), (1, True, False)]
    assert part["counted_attempt"] == 1 and part["score"] == 0.0
    assert "1 (practice)" in page and "never (practice)" in page
    assert _counted_rows(page) == ["1"]


def test_the_record_shows_the_exceptions_granted_and_the_timed_start(exam_dir, tmp_path):
    from serve_support import Clock

    opens = dt.datetime(2030, 4, 14, 8, 0, tzinfo=ZONE)
    manifest = exam_copy(exam_dir, tmp_path / "timed", mode="homework", feedback="immediate",
                         opens=opens, closes=opens + dt.timedelta(hours=4), time_limit=30,
                         attempts=2)
    clock = Clock(opens + dt.timedelta(hours=1))  # 09:00
    with serve(manifest, clock=clock) as served:
        granted = served.client.put("/api/v1/exceptions", json={
            "students": ["s1"], "closes": "2030-04-14T14:00:00+02:00", "extra_minutes": 15,
            "extra_attempts": {"projectile-range": 1}},
            headers={"Authorization": f"Bearer {served.staff}"})
        assert granted.status_code == 200, granted.text
        started = served.client.post("/api/v1/start",
                                     headers={"Authorization": f"Bearer {served.tokens['s1']}"})
        assert started.status_code == 200, started.text
        s1, s2 = _record(served, "s1").json()["terms"], _record(served, "s2").json()["terms"]
        page = served.client.get(f"/i/{served.staff}/students/s1").text
    # 09:00 start, 30 + 15 minutes: 09:45, before their close at 14:00
    assert (s1["closes"], s1["extended"]) == ("2030-04-14 14:00:00 UTC+02:00", True)
    assert (s1["started_at"], s1["time_ends"], s1["minutes"]) == \
        ("2030-04-14 09:00:00 UTC+02:00", "2030-04-14 09:45:00 UTC+02:00", 45)
    assert s1["exceptions"] == ["closes 2030-04-14 14:00 UTC+02:00", "15 extra minutes",
                                "1 extra attempt on projectile-range"]
    assert s1["granted_by"] == f"staff link {_link_id(served.staff)}"
    assert (s2["exceptions"], s2["extended"], s2["started_at"]) == ([], False, None)
    assert s2["closes"] == "2030-04-14 12:00:00 UTC+02:00"
    assert "15 extra minutes" in page and "their time ends at 2030-04-14 09:45:00" in page


def _link_id(token: str) -> str:
    from dynagrade.serve import db

    return db.link_id(token)
