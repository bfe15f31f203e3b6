"""The JSON API and the pages of `dynagrade serve`, on SQLite and on a real PostgreSQL.

Each backend runs the same tests. Expected points are the manifest's part points (the
exam's scale, worked out by `dynagrade exam`), reference answers the manifest's.
"""

from __future__ import annotations

import csv
import datetime as dt
import io
import re

import pytest

from serve_support import (Clock, database, exam_copy, exam_dir, postgres_url,  # noqa: F401
                           reference_answers, serve)

UTC = dt.timezone.utc
OPENS = dt.datetime(2025, 4, 14, 8, 0, tzinfo=UTC)
CLOSES = dt.datetime(2025, 4, 14, 12, 0, tzinfo=UTC)

def _points(served, exercise) -> dict[str, float]:
    return {p.name: p.points for p in served.server.data.parts(exercise)}


def _off(text: str, factor: float) -> str:
    return repr(float(text) * factor)


# -- exam mode: answers saved, only readability shown -------------------------------------


def test_exam_mode_saves_and_shows_only_readability(exam_dir, tmp_path, database):
    manifest = exam_copy(exam_dir, tmp_path / "exam", mode="exam", opens=OPENS, closes=CLOSES)
    clock = Clock()
    with serve(manifest, database, clock) as served:
        assert served.client.get("/healthz").status_code == 200
        described = served.client.get("/api/openapi.json").json()["paths"]
        assert {"/api/v1/answers", "/api/v1/preview", "/api/v1/grades.csv"} <= set(described)
        first = served.submit("s1", "projectile-range", {"x_max": "45 km/h", "h_max": "3 kg"})
        # a velocity for a length is the wrong dimension, a mass too: neither can be read,
        # so nothing is graded or stored and no attempt is spent; the reason per part
        assert first.status_code == 422
        assert "velocity" in first.json()["detail"] and "mass" in first.json()["detail"]
        saved = served.submit("s1", "projectile-range", {"x_max": "28.9 m", "h_max": "3 kg"})
        body = saved.json()
        assert saved.status_code == 200
        assert body["exercise"] == "projectile-range" and body["attempt"] == 1
        parts = {p["name"]: p for p in body["parts"]}
        assert parts["x_max"] == {"name": "x_max", "readable": True,
                                  "message": "reads as 28.9 m"}
        assert parts["h_max"]["readable"] is False and "mass" in parts["h_max"]["message"]
        # no right/wrong, points or feedback may leak before the close
        for part in body["parts"]:
            assert set(part) == {"name", "readable", "message"}
        assert "score" not in body and "max_score" not in body
        second = served.submit("s1", "projectile-range", {"x_max": "29.1 m"}).json()
        assert second["attempt"] == 2
        # after the close: refused, and the verdicts of the stored answers appear
        clock.now = CLOSES
        late = served.submit("s1", "projectile-range", {"x_max": "1 m"})
        assert late.status_code == 403 and "closed" in late.json()["detail"]
        page = served.client.get(f"/s/{served.tokens['s1']}").text
        assert "28.9 m" in page and "29.1 m" in page  # the history: both attempts kept
        assert "3 kg" not in page  # never stored
        preview = served.client.post("/api/v1/preview", json={
            "exercise": "projectile-range", "part": "x_max_formula",
            "answer": "v0^2 sin(2 alpha)/g"},
            headers={"Authorization": f"Bearer {served.tokens['s1']}"}).json()
        assert preview["readable"] and "<mfrac>" in preview["formula"]
        assert "<mi>α</mi>" in preview["formula"] and "correct" not in preview
        clock.now = OPENS - dt.timedelta(minutes=1)
        early = served.submit("s1", "projectile-range", {"x_max": "1 m"})
        assert early.status_code == 403 and "opens" in early.json()["detail"]


def test_exam_page_shows_no_reference_answer(exam_dir, tmp_path, database):
    manifest = exam_copy(exam_dir, tmp_path / "exam", mode="exam")
    with serve(manifest, database) as served:
        page = served.client.get(f"/s/{served.tokens['s2']}")
        assert page.status_code == 200
        assert "Bo Two" in page.text and "<math" in page.text and "<svg" in page.text
        assert page.headers["referrer-policy"] == "no-referrer"  # the token is in the URL
        assert page.headers["cache-control"] == "no-store"
        for exercise in ("projectile-range", "sliding-up-a-slope"):
            for name, value in served.variant("s2", exercise).answers.items():
                if isinstance(value, float):
                    assert repr(value) not in page.text
                    assert f"{value:.4g}" not in page.text, (exercise, name)


# -- homework: verdicts, attempts, penalty ------------------------------------------------


def test_homework_verdicts_attempts_and_penalty(exam_dir, tmp_path, database):
    manifest = exam_copy(exam_dir, tmp_path / "hw", mode="homework", feedback="immediate",
                         counts="best", attempts=2, penalty=0.25)
    with serve(manifest, database) as served:
        points = _points(served, "projectile-range")
        right = reference_answers(served, "s1", "projectile-range")
        wrong = served.submit("s1", "projectile-range", {"x_max": _off(right["x_max"], 1.1)})
        body = wrong.json()
        assert wrong.status_code == 200 and body["score"] == 0.0
        assert body["max_score"] == pytest.approx(points["x_max"])
        assert body["parts"][0]["correct"] is False and body["parts"][0]["feedback"]
        again = served.submit("s1", "projectile-range", {"x_max": right["x_max"]}).json()
        assert again["parts"][0]["correct"] is True
        # second attempt of the part: 25 % of its points lost
        assert again["score"] == pytest.approx(0.75 * points["x_max"])
        third = served.submit("s1", "projectile-range", {"x_max": right["x_max"]})
        assert third.status_code == 403 and "x_max" in third.json()["detail"]
        # another part still has both attempts
        fine = served.submit("s1", "projectile-range", {"h_max": right["h_max"]}).json()
        assert fine["score"] == pytest.approx(points["h_max"])
        grades = list(csv.DictReader(io.StringIO(served.staff_get("/api/v1/grades.csv").text)))
        row = next(r for r in grades if r["student_id"] == "s1")
        assert float(row["projectile-range"]) == pytest.approx(
            0.75 * points["x_max"] + points["h_max"])
        assert row["status"] == "incomplete"


def test_counts_last_takes_the_latest_answer(exam_dir, tmp_path, database):
    manifest = exam_copy(exam_dir, tmp_path / "hw", mode="homework", feedback="immediate",
                         counts="last")
    with serve(manifest, database) as served:
        points = _points(served, "projectile-range")
        right = reference_answers(served, "s2", "projectile-range")
        served.submit("s2", "projectile-range", {"x_max": right["x_max"]})
        served.submit("s2", "projectile-range", {"x_max": _off(right["x_max"], 2.0)})
        grades = list(csv.DictReader(io.StringIO(served.staff_get("/api/v1/grades.csv").text)))
        assert float(next(r for r in grades if r["student_id"] == "s2")["projectile-range"]) \
            == 0.0
        assert points["x_max"] > 0


# -- access -------------------------------------------------------------------------------


def test_tokens_decide_who_you_are(exam_dir, tmp_path, database):
    manifest = exam_copy(exam_dir, tmp_path / "exam", mode="homework", feedback="immediate")
    with serve(manifest, database) as served:
        client = served.client
        body = {"exercise": "projectile-range", "answers": {"x_max": "1"}}
        assert client.post("/api/v1/answers", json=body).status_code == 401
        assert client.post("/api/v1/answers", json=body,
                           headers={"Authorization": "Bearer nope"}).status_code == 401
        assert client.post("/api/v1/answers", json=body, headers={
            "Authorization": f"Bearer {served.staff}"}).status_code == 403
        assert client.get("/api/v1/grades.csv", headers={
            "Authorization": f"Bearer {served.tokens['s1']}"}).status_code == 403
        assert client.get("/s/not-a-token").status_code == 401
        assert client.get(f"/i/{served.tokens['s1']}").status_code == 403
        assert client.get(f"/s/{served.staff}").status_code == 403
        served.submit("s1", "projectile-range", {"x_max": "123.456 m"})
        # s2 sees nothing of s1's answers; s1's own page shows them
        assert "123.456" not in client.get(f"/s/{served.tokens['s2']}").text
        assert "123.456" in client.get(f"/s/{served.tokens['s1']}").text
        # the same reference answers graded for s2 are s2's own variant, not s1's
        s1_right = reference_answers(served, "s1", "projectile-range")["x_max"]
        s2_right = reference_answers(served, "s2", "projectile-range")["x_max"]
        if abs(float(s1_right) / float(s2_right) - 1) > 0.02:
            verdict = served.submit("s2", "projectile-range", {"x_max": s1_right}).json()
            assert verdict["parts"][0]["correct"] is False
        # tokens are stored as sha256 hashes only
        from dynagrade.serve import db
        import sqlalchemy as sa

        with served.server.engine.connect() as connection:
            stored = set(connection.execute(sa.select(db.tokens.c.token_hash)).scalars())
        assert served.tokens["s1"] not in stored and db.hash_token(served.tokens["s1"]) in stored


def test_malformed_bodies_get_422(exam_dir, tmp_path, database):
    manifest = exam_copy(exam_dir, tmp_path / "exam")
    with serve(manifest, database) as served:
        headers = {"Authorization": f"Bearer {served.tokens['s1']}"}
        post = served.client.post
        assert post("/api/v1/answers", content=b"{not json", headers={
            **headers, "Content-Type": "application/json"}).status_code == 422
        assert post("/api/v1/answers", json={"exercise": "projectile-range"},
                    headers=headers).status_code == 422
        assert post("/api/v1/answers", json={"exercise": "projectile-range",
                                             "answers": {"x_max": 5}},
                    headers=headers).status_code == 422
        unknown = post("/api/v1/answers", json={"exercise": "nope", "answers": {"a": "1"}},
                       headers=headers)
        assert unknown.status_code == 422 and "nope" in unknown.json()["detail"]
        part = served.submit("s1", "projectile-range", {"zzz": "1"})
        assert part.status_code == 422 and "zzz" in part.json()["detail"]
        assert served.submit("s1", "projectile-range", {"x_max": "  "}).status_code == 422
        assert served.submit("s1", "projectile-range",
                             {"x_max": "1" * 2001}).status_code == 422
        big = post("/api/v1/answers", content=b"x" * 70_000, headers={
            **headers, "Content-Type": "application/json"})
        assert big.status_code == 413
        assert served.server.data and _count(served) == 0


def _count(served) -> int:
    from dynagrade.serve import db

    return db.counts(served.server.engine, served.server.data.exam_id)["submissions"]


# -- faults: idempotency, pathological answers --------------------------------------------


def test_idempotency_key_stores_a_submit_once(exam_dir, tmp_path, database):
    manifest = exam_copy(exam_dir, tmp_path / "exam")
    with serve(manifest, database) as served:
        first = served.submit("s3", "projectile-range", {"x_max": "3 m"}, key="retry-0001")
        again = served.submit("s3", "projectile-range", {"x_max": "3 m"}, key="retry-0001")
        assert first.status_code == again.status_code == 200
        assert again.json()["attempt"] == first.json()["attempt"] == 1
        assert again.json()["replayed"] is True
        assert _count(served) == 1
        stolen = served.submit("s1", "projectile-range", {"x_max": "3 m"}, key="retry-0001")
        assert stolen.status_code == 422 and _count(served) == 1


def test_pathological_answers_get_verdicts_not_errors(exam_dir, tmp_path, database):
    manifest = exam_copy(exam_dir, tmp_path / "hw", mode="homework", feedback="immediate")
    with serve(manifest, database) as served:
        for text in ("9^9^9^9", "(" * 300 + "1" + ")" * 300, "deg^deg", "1 km^-200",
                     "__import__('os')", "sqrt(-1)"):
            response = served.submit("s1", "projectile-range", {"x_max": text})
            # an answer the grader cannot read is refused with the reason, one it reads
            # is graded wrong; never a crash
            assert response.status_code in (200, 422), text
            if response.status_code == 422:
                assert "could be read" in response.json()["detail"], text
                continue
            part = response.json()["parts"][0]
            assert part["correct"] is False and part["score"] == 0.0, text
        right = reference_answers(served, "s2", "projectile-range")["x_max"]
        assert served.submit("s2", "projectile-range",
                             {"x_max": right}).json()["parts"][0]["correct"] is True


# -- the staff page and the offline regrade -----------------------------------------------


def test_downloaded_submissions_regrade_to_the_same_gradebook(exam_dir, tmp_path, database):
    from dynagrade.classgrade.grade import gradebook_csv, grade_class

    manifest = exam_copy(exam_dir, tmp_path / "hw", mode="homework", feedback="immediate",
                         counts="best")
    with serve(manifest, database) as served:
        s1 = reference_answers(served, "s1", "projectile-range")
        served.submit("s1", "projectile-range", s1)
        served.submit("s1", "projectile-range", {"x_max": _off(s1["x_max"], 3.0)})
        s1b = reference_answers(served, "s1", "sliding-up-a-slope")
        served.submit("s1", "sliding-up-a-slope", {k: _off(v, 1.5) if re.fullmatch(
            r"[-0-9.e]+", v) else v for k, v in s1b.items()})
        s2 = reference_answers(served, "s2", "projectile-range")
        served.submit("s2", "projectile-range", {"x_max": s2["x_max"], "h_max": "1 m"})
        grades = served.staff_get("/api/v1/grades.csv")
        responses = served.staff_get("/api/v1/submissions.csv")
        staff_page = served.client.get(f"/i/{served.staff}")
        page_grades = served.client.get(f"/i/{served.staff}/grades.csv")
        report = served.client.get(f"/i/{served.staff}/report.html")
        assert report.status_code == 200 and "Serve test" in report.text
        assert "<svg" in report.text  # the score histogram of class grading
    assert grades.status_code == responses.status_code == staff_page.status_code == 200
    assert page_grades.text == grades.text
    assert "Ada One" in staff_page.text and "gradebook" in staff_page.text
    path = tmp_path / "responses.csv"
    path.write_text(responses.text, encoding="utf-8")
    offline = grade_class(manifest, [path], jobs=1)
    assert gradebook_csv(offline) == grades.text
    rows = {r["student_id"]: r for r in csv.DictReader(io.StringIO(grades.text))}
    assert rows["s3"]["status"] == "absent" and rows["s1"]["status"] == "graded"
    assert float(rows["s1"]["projectile-range"]) == pytest.approx(6.0)  # best: all right


# -- the student page's form --------------------------------------------------------------


def test_form_needs_its_csrf_field(exam_dir, tmp_path, database):
    manifest = exam_copy(exam_dir, tmp_path / "exam")
    with serve(manifest, database) as served:
        token = served.tokens["s1"]
        page = served.client.get(f"/s/{token}").text
        csrf = re.search(r'name="csrf" value="([0-9a-f]+)"', page).group(1)
        key = re.search(r'name="key" value="([0-9a-f]+)"', page).group(1)
        form = {"exercise": "projectile-range", "answer.x_max": "12 m", "key": key}
        refused = served.client.post(f"/s/{token}/submit", data=form)
        assert refused.status_code == 403 and _count(served) == 0
        forged = served.client.post(f"/s/{token}/submit", data={**form, "csrf": "0" * 64})
        assert forged.status_code == 403 and _count(served) == 0
        other = served.client.get(f"/s/{served.tokens['s2']}").text
        other_csrf = re.search(r'name="csrf" value="([0-9a-f]+)"', other).group(1)
        assert served.client.post(f"/s/{token}/submit", data={
            **form, "csrf": other_csrf}).status_code == 403
        accepted = served.client.post(f"/s/{token}/submit", data={**form, "csrf": csrf},
                                      follow_redirects=False)
        assert accepted.status_code == 303 and _count(served) == 1
        # the browser's reload of the same form (same key) stores nothing new
        served.client.post(f"/s/{token}/submit", data={**form, "csrf": csrf})
        assert _count(served) == 1


def test_practice_draws_are_graded_but_not_counted(exam_dir, tmp_path, database):
    manifest = exam_copy(exam_dir, tmp_path / "pr", mode="practice", feedback="immediate",
                         counts="best")
    with serve(manifest, database) as served:
        token = served.tokens["s1"]
        page = served.client.get(f"/s/{token}").text
        csrf = re.search(r'name="csrf" value="([0-9a-f]+)"', page).group(1)
        drawn = served.client.post(f"/s/{token}/practice", data={
            "csrf": csrf, "exercise": "projectile-range"}, follow_redirects=False)
        assert drawn.status_code == 303
        value = re.search(r"practice=projectile-range:([0-9]+\.[0-9a-f]+)",
                          drawn.headers["location"]).group(1)
        seed = int(value.split(".")[0])
        data = served.server.data
        fresh = data.entry("s1", "projectile-range", seed).answers["x_max"]
        submitted = served.client.post(f"/s/{token}/submit", data={
            "csrf": csrf, "exercise": "projectile-range", "practice": value,
            "answer.x_max": repr(fresh), "key": "practice-0001"}, follow_redirects=False)
        assert submitted.status_code == 303
        from dynagrade.serve import db

        stored = db.student_answers(served.server.engine, data.exam_id, "s1")
        assert [(a.counted, a.correct, a.seed) for a in stored] == [(False, True, seed)]
        grades = served.staff_get("/api/v1/grades.csv").text
        # a practice draw counts for nothing: s1 is absent, with empty cells (no grade)
        assert "s1,Ada One,ada@example.org,,,,10,,absent" in grades
        tampered = served.client.post(f"/s/{token}/submit", data={
            "csrf": csrf, "exercise": "projectile-range", "practice": f"{seed + 1}.00",
            "answer.x_max": "1"})
        assert tampered.status_code == 422
