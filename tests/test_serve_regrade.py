"""Regrade online (issue 25, item 3), on SQLite and on the session's PostgreSQL: after
the exercise file is fixed and the manifest re-keyed, a preview lists exactly the stored
answers whose verdict changes, with the points worked out by hand; applying it changes
the gradebook to exactly those, keeps the old verdicts, does nothing a second time,
refuses a stale plan, and the server grades the next submit by the new key."""

from __future__ import annotations

import time

import pytest

from regrade_support import EXERCISE_ID, demo_exam, lengths, write_exercise
from serve_support import Clock, database, postgres_url, serve  # noqa: F401

def _fix(manifest, folder, **changes) -> None:
    """The author's fix: y = 2 x + 1 m and z's tolerance 5 %, and the manifest re-keyed."""
    from dynagrade.exercise.loader import open_bank
    from dynagrade.generation.rekey import rekey

    write_exercise(folder, y="2 * p.x + 1", rtol=0.05, **changes)
    rekey(manifest, [EXERCISE_ID], open_bank([folder]))


def _staff(served, method: str, path: str):
    return served.client.request(method, path,
                                 headers={"Authorization": f"Bearer {served.staff}"})


def _m(value: float) -> str:
    return f"{value!r} m"


def _submit_the_class(served, x):
    """The answers whose verdicts the fix changes (and one it does not)."""
    ok = [served.submit("s1", EXERCISE_ID, {"y": _m(2 * x["s1"])}),       # right, then wrong
          served.submit("s2", EXERCISE_ID, {"y": "0 m"}),                 # wrong both times
          served.submit("s2", EXERCISE_ID, {"y": _m(2 * x["s2"] + 1)}),   # 2nd try: wrong, then right
          served.submit("s3", EXERCISE_ID, {"z": _m(3 * x["s3"] * 1.03)}),  # 3 % off: 1 % → 5 %
          served.submit("s4", EXERCISE_ID, {"y": _m(2 * x["s4"]), "z": _m(3 * x["s4"])})]
    assert [r.status_code for r in ok] == [200] * 5, [r.text for r in ok]
    scores = [[p["score"] for p in r.json()["parts"]] for r in ok]
    assert scores == [[2.0], [0.0], [0.0], [0.0], [2.0, 2.0]]  # before the fix


#: the plan worked out by hand: (student, part, attempt) -> (old points, new points);
#: s2's second attempt earns half (penalty 0.5) of the 2 points of y
EXPECTED = {("s1", "y", 1): (2.0, 0.0), ("s2", "y", 2): (0.0, 1.0),
            ("s3", "z", 1): (0.0, 2.0), ("s4", "y", 1): (2.0, 0.0)}
#: the totals before and after
TOTALS = {"s1": [2.0, 0.0], "s2": [0.0, 1.0], "s3": [0.0, 2.0], "s4": [4.0, 2.0]}


def _history(served) -> list[tuple]:
    import sqlalchemy as sa

    from dynagrade.serve import db

    with served.server.engine.connect() as connection:
        return [tuple(r) for r in connection.execute(sa.select(
            db.verdict_history.c.answer_id, db.verdict_history.c.status,
            db.verdict_history.c.score).order_by(db.verdict_history.c.id)).all()]


def test_a_regrade_previews_applies_once_and_grades_new_submits_by_the_new_key(
        tmp_path, database):
    from dynagrade.serve import db

    manifest, folder = demo_exam(tmp_path)
    x = lengths(manifest)
    with serve(manifest, database, Clock(), folders=[folder]) as served:
        _submit_the_class(served, x)
        assert _staff(served, "POST", "/api/v1/regrades").json()["changes"] == []  # no fix yet
        _fix(manifest, folder)
        # the worker still holds the key it loaded; the preview reads the files on disk
        assert served.server.data.entry("s1", EXERCISE_ID).answers["y"] == 2 * x["s1"]
        preview = _staff(served, "POST", "/api/v1/regrades")
        assert preview.status_code == 200, preview.text
        plan = preview.json()
        assert plan["state"] == "previewed" and plan["answers"] == 6  # 1 + 2 + 1 + 2 parts
        got = {(c["student_id"], c["part"], c["attempt"]): (c["old"]["score"],
                                                            c["new"]["score"])
               for c in plan["changes"]}
        assert got == EXPECTED
        assert all(c["counts"] for c in plan["changes"])
        assert {s: t["total"] for s, t in plan["grades"].items()} == TOTALS
        assert plan["source"]["exercise_files"][EXERCISE_ID]["path"].endswith("regrade_demo.py")
        other = _staff(served, "POST", "/api/v1/regrades").json()  # a second, same plan
        # nothing changed yet
        book = {r["student_id"]: r["total"] for r in
                _staff(served, "GET", "/api/v1/gradebook").json()["rows"]}
        assert book == {"s1": 2.0, "s2": 0.0, "s3": 0.0, "s4": 4.0, "s5": None}

        applied = _staff(served, "POST", f"/api/v1/regrades/{plan['id']}/apply")
        assert applied.status_code == 200, applied.text
        assert applied.json()["state"] == "applied" and applied.json()["done"] is True
        assert applied.json()["answers_since"] == 0  # none came between preview and apply
        book = {r["student_id"]: r["total"] for r in
                _staff(served, "GET", "/api/v1/gradebook").json()["rows"]}
        assert book == {"s1": 0.0, "s2": 1.0, "s3": 2.0, "s4": 2.0, "s5": None}
        grades = _staff(served, "GET", "/api/v1/grades.csv").text.splitlines()
        assert [line.split(",")[-4] for line in grades[1:]] == ["0", "1", "2", "2", ""]
        old = {c["answer_id"]: (c["old"]["status"], c["old"]["score"])
               for c in plan["changes"]}
        history = _history(served)
        assert {row[0]: (row[1], row[2]) for row in history} == old
        assert sorted(score for _a, _s, score in history) == [0.0, 0.0, 2.0, 2.0]
        audit = db.changes(served.server.engine, served.server.data.exam_id, db.REGRADE)
        assert [(e.subject, e.before["totals"], e.after["totals"]) for e in audit] == [
            (str(plan["id"]), {s: t[0] for s, t in TOTALS.items()},
             {s: t[1] for s, t in TOTALS.items()})]

        again = _staff(served, "POST", f"/api/v1/regrades/{plan['id']}/apply")
        assert again.status_code == 200 and again.json()["done"] is False
        assert _history(served) == history
        assert len(db.changes(served.server.engine, served.server.data.exam_id,
                              db.REGRADE)) == 1

        stale = _staff(served, "POST", f"/api/v1/regrades/{other['id']}/apply")
        assert stale.status_code == 409
        assert stale.json() == {"detail": "answers changed since the preview; preview again"}

        # the next submit is graded by the new key and the new tolerance
        fresh = served.submit("s5", EXERCISE_ID, {"y": _m(2 * x["s5"] + 1),
                                                  "z": _m(3 * x["s5"] * 1.03)})
        assert [(p["correct"], p["score"]) for p in fresh.json()["parts"]] == \
            [(True, 2.0), (True, 2.0)]
        # s5's answers came within the bound every server reloads in: counted as answers
        # that may have been graded by the files of before
        assert _staff(served, "GET", f"/api/v1/regrades/{plan['id']}").json()[
            "answers_since"] == 2


def test_a_plan_is_refused_when_the_files_changed_and_can_be_discarded(tmp_path, database):
    manifest, folder = demo_exam(tmp_path)
    x = lengths(manifest)
    with serve(manifest, database, Clock(), folders=[folder]) as served:
        served.submit("s3", EXERCISE_ID, {"z": _m(3 * x["s3"] * 1.03)})
        _fix(manifest, folder)
        plan = _staff(served, "POST", "/api/v1/regrades").json()
        assert len(plan["changes"]) == 1
        write_exercise(folder, y="2 * p.x + 1", rtol=0.02)  # changed again after the preview
        moved = _staff(served, "POST", f"/api/v1/regrades/{plan['id']}/apply")
        assert moved.status_code == 409
        assert moved.json()["detail"] == ("the manifest or an exercise file changed since "
                                          "the preview; preview again")
        discarded = _staff(served, "POST", f"/api/v1/regrades/{plan['id']}/discard")
        assert discarded.json()["state"] == "discarded" and discarded.json()["done"] is True
        twice = _staff(served, "POST", f"/api/v1/regrades/{plan['id']}/discard")
        assert twice.status_code == 200 and twice.json()["done"] is False
        refused = _staff(served, "POST", f"/api/v1/regrades/{plan['id']}/apply")
        assert refused.status_code == 409
        assert refused.json()["detail"] == "this regrade was discarded; preview again"
        assert _history(served) == []
        fresh = _staff(served, "POST", "/api/v1/regrades").json()  # z: 3 % off, 2 % allowed
        assert fresh["changes"] == []
        assert _staff(served, "POST", f"/api/v1/regrades/{fresh['id']}/apply").json()[
            "done"] is True
        applied = _staff(served, "POST", f"/api/v1/regrades/{fresh['id']}/discard")
        assert applied.status_code == 409
        assert applied.json()["detail"] == "this regrade was applied; it cannot be discarded"
        assert _staff(served, "GET", "/api/v1/regrades/999").status_code == 404


def test_the_students_whose_verdicts_changed_are_told_where_verdicts_are_shown(tmp_path):
    from dynagrade.serve import db
    from dynagrade.serve.policy_changes import change_policy

    manifest, folder = demo_exam(tmp_path)
    x = lengths(manifest)
    with serve(manifest, None, Clock(), folders=[folder]) as served:
        served.submit("s1", EXERCISE_ID, {"y": _m(2 * x["s1"])})
        served.submit("s2", EXERCISE_ID, {"z": _m(3 * x["s2"])})
        _fix(manifest, folder)
        plan = _staff(served, "POST", "/api/v1/regrades").json()
        _staff(served, "POST", f"/api/v1/regrades/{plan['id']}/apply")
        found = db.find_regrade(served.server.engine, served.server.data.exam_id, plan["id"])
        day = f"{found.applied_at:%Y-%m-%d}"  # no close: the course's zone is UTC
        page = served.client.get(f"/s/{served.tokens['s1']}").text
        assert f"Regraded on {day}: Regrade demo y (attempt 1): 2 → 0 points" in page
        assert "Regraded" not in served.client.get(f"/s/{served.tokens['s2']}").text
        # the staff see it on the student's record, whatever the policy shows students
        record = _staff(served, "GET", "/api/v1/students/s1").json()
        assert [(r["exercise"], r["part"], r["attempt"], r["before"], r["after"])
                for r in record["regrades"]] == [(EXERCISE_ID, "y", 1, 2.0, 0.0)]
        assert _staff(served, "GET", "/api/v1/students/s2").json()["regrades"] == []
        staff_page = served.client.get(f"/i/{served.staff}/students/s1").text
        assert f"{EXERCISE_ID} y (attempt 1): 2 → 0 points" in staff_page
        data = served.server.data
        change_policy(served.server.engine, data.exam_id, data.manifest_policy, "test",
                      {"feedback": "after-close", "closes": "2099-01-01T00:00:00+00:00"})
        data.policy_source.forget()
        assert "Regraded" not in served.client.get(f"/s/{served.tokens['s1']}").text


def test_every_server_process_grades_by_the_new_key_within_seconds(tmp_path):
    """Two app instances on one database, as two workers: the one that did not apply the
    regrade loads the exam again within the reload bound."""
    from dynagrade.serve.reload import FRESH_SECONDS

    manifest, folder = demo_exam(tmp_path)
    x = lengths(manifest)
    with serve(manifest, None, Clock(), folders=[folder]) as first, \
            serve(manifest, None, Clock(), folders=[folder]) as second:
        loaded = second.server.data
        _fix(manifest, folder)
        plan = _staff(first, "POST", "/api/v1/regrades").json()
        applied_at = time.monotonic()
        _staff(first, "POST", f"/api/v1/regrades/{plan['id']}/apply")
        while second.server.data is loaded:
            assert time.monotonic() - applied_at < FRESH_SECONDS + 15, "no reload"
            time.sleep(0.2)
        second.tokens = first.tokens  # the links the first instance issued
        answer = second.submit("s1", EXERCISE_ID, {"y": _m(2 * x["s1"] + 1)})
        assert answer.json()["parts"][0]["correct"] is True


def test_the_pages_forms_preview_apply_and_show_a_refusal_with_its_reason(tmp_path):
    from dynagrade.serve import limits

    manifest, folder = demo_exam(tmp_path)
    x = lengths(manifest)
    with serve(manifest, None, Clock(), folders=[folder]) as served:
        served.submit("s1", EXERCISE_ID, {"y": _m(2 * x["s1"])})
        _fix(manifest, folder)
        page = f"/i/{served.staff}/regrade"
        form = {"csrf": limits.csrf_field(served.server.secret, served.staff)}
        assert served.client.post(f"{page}/preview", data={}).status_code == 403  # no CSRF
        made = served.client.post(f"{page}/preview", data=form, follow_redirects=False)
        assert made.status_code == 303 and made.headers["location"].endswith("/regrade#plan")
        shown = served.client.get(page).text
        assert "Apply plan 1" in shown and "Ada One" in shown and "2 → 0" in shown
        discarded = served.client.post(f"{page}/1/discard", data=form, follow_redirects=False)
        assert discarded.status_code == 303
        refused = served.client.post(f"{page}/1/apply", data=form,
                                     headers={"Accept": "text/html"})
        assert refused.status_code == 409
        assert "this regrade was discarded; preview again" in refused.text
        assert "No plan is open" in refused.text
        served.client.post(f"{page}/preview", data=form)
        applied = served.client.post(f"{page}/2/apply", data=form, follow_redirects=False)
        assert applied.headers["location"].endswith("/regrade?applied=2#result")
        result = served.client.get(f"{page}?applied=2").text
        assert "Regrade 2 applied: 1 verdict changed. The total of 1 student changed." in result
