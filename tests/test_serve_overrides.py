"""Points by hand on the server (issue 25, item 4), through the API, on SQLite and on a
real PostgreSQL: set, repeat (nothing recorded), change, remove (the grader's points count
again), and every refusal with its reason, as the offline overrides file words it.

The exam is serve_support's: projectile-range (6 points: x_max 2.4, h_max 1.2, t_flight
1.2, x_max_formula 1.2) and sliding-up-a-slope (4 points), copied with ``round = 0.1``.
"""

from __future__ import annotations

import csv
import dataclasses
import io

import pytest

from serve_support import (database, exam_copy, exam_dir, postgres_url,  # noqa: F401
                           reference_answers, serve)


def rounded_copy(exam_dir, target, step: float = 0.1, **policy):
    """A copy of the exam that rounds to ``step`` (``round =`` of exam.toml)."""
    from dynagrade.exam import manifest as records

    path = exam_copy(exam_dir, target, **policy)
    manifest = records.load(path)
    records.dump(dataclasses.replace(
        manifest, exam=dataclasses.replace(manifest.exam, rounding=step)), path)
    return path


def _grades(served) -> dict[str, dict[str, str]]:
    rows = csv.DictReader(io.StringIO(served.staff_get("/api/v1/grades.csv").text))
    return {row["student_id"]: row for row in rows}


def _put(served, **body):
    return served.client.put("/api/v1/overrides", json=body,
                             headers={"Authorization": f"Bearer {served.staff}"})


def _delete(served, path: str):
    return served.client.delete(f"/api/v1/overrides/{path}",
                                headers={"Authorization": f"Bearer {served.staff}"})


def _audit(served):
    from dynagrade.serve import db

    return db.changes(served.server.engine, served.server.data.exam_id, "override")


def test_points_set_by_hand_win_are_recorded_once_and_removal_restores_the_grader(
        exam_dir, tmp_path, database):
    manifest = rounded_copy(exam_dir, tmp_path / "exam", mode="homework",
                            feedback="immediate")
    with serve(manifest, database) as served:
        right = reference_answers(served, "s1", "projectile-range")
        wrong = repr(2 * float(right["x_max"]))
        # x_max wrong (0 of 2.4), h_max right (1.2 of 1.2): the exercise earns 1.2
        reply = served.submit("s1", "projectile-range", {"x_max": wrong,
                                                         "h_max": right["h_max"]})
        assert reply.status_code == 200, reply.text
        assert _grades(served)["s1"]["projectile-range"] == "1.2"

        first = _put(served, student="s1", exercise="projectile-range", part="x_max",
                     points=1.5, comment="sign slip only, method right")
        assert first.status_code == 200 and first.json() == {"changed": True}, first.text
        grades = _grades(served)["s1"]
        # 1.5 by hand + 1.2 graded = 2.7 of the exam's 10 points
        assert (grades["projectile-range"], grades["total"], grades["percent"]) == \
            ("2.7", "2.7", "27.00")
        again = _put(served, student="s1", exercise="projectile-range", part="x_max",
                     points=1.5, comment="sign slip only, method right")
        assert again.json() == {"changed": False}
        entries = _audit(served)
        assert len(entries) == 1  # the repeat recorded nothing
        assert entries[0].subject == "s1/projectile-range/x_max"
        assert entries[0].before is None
        assert entries[0].after == {"points": 1.5, "comment": "sign slip only, method right"}
        assert entries[0].actor.startswith("staff link ")

        listed = served.staff_get("/api/v1/overrides").json()["overrides"]
        assert [(o["student"], o["part"], o["points"], o["comment"]) for o in listed] == \
            [("s1", "x_max", 1.5, "sign slip only, method right")]
        assert listed[0]["author"] == entries[0].actor and "T" in listed[0]["at"]
        gradebook = served.staff_get("/api/v1/gradebook").json()["rows"][0]
        assert gradebook["exercises"]["projectile-range"] == 2.7

        changed = _put(served, student="s1", exercise="projectile-range", part="x_max",
                       points=2, comment="")
        assert changed.json() == {"changed": True}
        assert _grades(served)["s1"]["projectile-range"] == "3.2"
        assert _audit(served)[0].before == {"points": 1.5,
                                            "comment": "sign slip only, method right"}

        removed = _delete(served, "s1/projectile-range/x_max")
        assert removed.json() == {"changed": True}
        assert _grades(served)["s1"]["projectile-range"] == "1.2"  # the grader's again
        assert _delete(served, "s1/projectile-range/x_max").json() == {"changed": False}
        entries = _audit(served)
        assert len(entries) == 3 and entries[0].after is None
        assert entries[0].before == {"points": 2.0, "comment": ""}
        assert served.staff_get("/api/v1/overrides").json() == {"overrides": []}


@pytest.mark.parametrize("body, reason", [
    ({"points": 2.5}, "points 2.5 is outside 0 to 2.4, the points of part 'x_max'"),
    ({"points": -1}, "points -1 is outside 0 to 2.4"),
    ({"points": 1.25}, "points 1.25 is not one of the exam's multiples of 0.1"),
    ({"student": "s9"}, "student 's9' is not on the exam's roster"),
    ({"exercise": "projectile"}, "exercise 'projectile' is not in the exam"),
    ({"part": "x_maximum"}, "exercise 'projectile-range' has no part 'x_maximum'"),
    ({"exercise": "sliding-up-a-slope", "part": "a_up", "points": 0.5},
     "s1 handed in nothing gradable for 'sliding-up-a-slope'"),
    ({"student": "s2"}, "s2 handed in nothing gradable for 'projectile-range'"),
])
def test_refusals_name_what_is_wrong_and_change_nothing(exam_dir, tmp_path, body, reason):
    manifest = rounded_copy(exam_dir, tmp_path / "exam", mode="homework",
                            feedback="immediate")
    with serve(manifest) as served:
        right = reference_answers(served, "s1", "projectile-range")
        assert served.submit("s1", "projectile-range",
                             {"h_max": right["h_max"]}).status_code == 200
        before = _grades(served)
        reply = _put(served, **{"student": "s1", "exercise": "projectile-range",
                                "part": "x_max", "points": 1, "comment": "", **body})
        assert reply.status_code == 422
        assert reason in reply.json()["detail"]
        assert _grades(served) == before and _audit(served) == []


def test_the_refusals_hold_on_both_databases(exam_dir, tmp_path, database):
    """One refusal of each kind of check (the rules, the stored answers) per backend,
    and the removal of a part that was never overridden."""
    manifest = rounded_copy(exam_dir, tmp_path / "exam", mode="homework",
                            feedback="immediate")
    with serve(manifest, database) as served:
        above = _put(served, student="s1", exercise="projectile-range", part="x_max",
                     points=3)
        assert above.status_code == 422 and "outside 0 to 2.4" in above.json()["detail"]
        absent = _put(served, student="s1", exercise="projectile-range", part="x_max",
                      points=1)
        assert "handed in nothing gradable" in absent.json()["detail"]
        assert _delete(served, "s9/projectile-range/x_max").status_code == 422
        assert _delete(served, "s1/projectile-range/x_max").json() == {"changed": False}
        assert _audit(served) == []


def test_only_staff_may_set_points(exam_dir, tmp_path):
    manifest = rounded_copy(exam_dir, tmp_path / "exam", mode="homework")
    with serve(manifest) as served:
        body = {"student": "s1", "exercise": "projectile-range", "part": "x_max",
                "points": 1}
        student = served.client.put("/api/v1/overrides", json=body, headers={
            "Authorization": f"Bearer {served.tokens['s1']}"})
        nobody = served.client.put("/api/v1/overrides", json=body)
        assert (student.status_code, nobody.status_code) == (403, 401)


def test_the_students_own_page_shows_the_points_and_the_comment(exam_dir, tmp_path):
    manifest = rounded_copy(exam_dir, tmp_path / "exam", mode="homework",
                            feedback="immediate")
    with serve(manifest) as served:
        right = reference_answers(served, "s1", "projectile-range")
        served.submit("s1", "projectile-range", {"x_max": repr(2 * float(right["x_max"]))})
        _put(served, student="s1", exercise="projectile-range", part="x_max", points=1.5,
             comment="method right")
        page = served.client.get(f"/s/{served.tokens['s1']}").text
        other = served.client.get(f"/s/{served.tokens['s2']}").text
    assert "Points set by the staff: 1.5 (graded 0): method right" in page
    assert "counted: 1.5 of 2.4 points" in page
    assert "Points set by the staff" not in other


def test_the_overrides_download_is_the_offline_file(exam_dir, tmp_path):
    """Roster and exam order; the points written with the exam's decimals."""
    from dynagrade.classgrade.overrides import parse_overrides

    manifest = rounded_copy(exam_dir, tmp_path / "exam", mode="homework")
    with serve(manifest) as served:
        for student in ("s2", "s1"):
            right = reference_answers(served, student, "projectile-range")
            served.submit(student, "projectile-range", {"h_max": right["h_max"]})
        _put(served, student="s2", exercise="projectile-range", part="h_max", points=0.5,
             comment='said "roughly", no unit')
        _put(served, student="s1", exercise="projectile-range", part="x_max", points=1)
        _put(served, student="s1", exercise="projectile-range", part="h_max", points=0)
        text = served.staff_get("/api/v1/overrides.csv").text
        page = served.client.get(f"/i/{served.staff}/overrides.csv").text
        data = served.server.data
    assert text == page == (
        "student_id,exercise,part,points,comment\n"
        "s1,projectile-range,x_max,1,\n"
        "s1,projectile-range,h_max,0,\n"
        's2,projectile-range,h_max,0.5,"said ""roughly"", no unit"\n')
    read = parse_overrides(text.encode(), "overrides.csv", data.manifest, data.rounding)
    assert [(o.student_id, o.part, o.points) for o in read] == [
        ("s1", "x_max", 1.0), ("s1", "h_max", 0.0), ("s2", "h_max", 0.5)]
