"""Staff links that are named, listed and revoked (issue 25, item 5), the audit log as a
page, CSV and JSON, and the downloads the staff take to their platform (item 7): on
SQLite and on the session's PostgreSQL."""

from __future__ import annotations

import csv
import datetime as dt
import io
import json
import re

import pytest
from click.testing import CliRunner

from dynagrade.cli import main
from serve_support import (database, exam_copy, exam_dir, postgres_url,  # noqa: F401
                           reference_answers, serve)

ZURICH = dt.timezone(dt.timedelta(hours=2))

def _bearer(token: str) -> dict:
    return {"Authorization": f"Bearer {token}"}


def _csrf(page: str) -> str:
    return re.search(r'name="csrf" value="([^"]+)"', page).group(1)


# -- staff links ---------------------------------------------------------------------------


def test_a_named_staff_link_works_until_revoked_and_each_step_is_audited(
        exam_dir, tmp_path, database):
    from dynagrade.serve import db

    manifest = exam_copy(exam_dir, tmp_path / "exam")
    with serve(manifest, database) as served:
        client, mine = served.client, served.staff
        listed = client.get("/api/v1/staff-links", headers=_bearer(mine)).json()["links"]
        assert [link["id"] for link in listed] == [db.link_id(mine)]
        made = client.post("/api/v1/staff-links", json={"name": "Anna (TA)"},
                           headers=_bearer(mine))
        assert made.status_code == 201
        anna = made.json()
        assert anna["name"] == "Anna (TA)" and anna["url"].endswith(f"/i/{anna['token']}")
        assert anna["id"] == db.link_id(anna["token"])
        assert client.get("/api/v1/gradebook", headers=_bearer(anna["token"])).status_code == 200
        listed = client.get("/api/v1/staff-links", headers=_bearer(mine)).json()["links"]
        assert [(link["name"], link["revoked_at"]) for link in listed] == \
            [(None, None), ("Anna (TA)", None)]
        assert "token" not in json.dumps(listed)

        # Anna's own changes are recorded under her name
        assert client.delete(f"/api/v1/staff-links/{db.link_id(mine)}",
                             headers=_bearer(anna["token"])).status_code == 200
        assert client.get("/api/v1/gradebook", headers=_bearer(mine)).status_code == 401
        fresh = client.post("/api/v1/staff-links", json={"name": "Ben"},
                            headers=_bearer(anna["token"])).json()["token"]
        gone = client.delete(f"/api/v1/staff-links/{anna['id']}", headers=_bearer(fresh))
        assert gone.status_code == 200 and gone.json()["revoked_at"] is not None
        # revoked in this process at once, though it had just been seen
        assert client.get("/api/v1/gradebook", headers=_bearer(anna["token"])).status_code == 401
        again = client.delete(f"/api/v1/staff-links/{anna['id']}", headers=_bearer(fresh))
        assert again.status_code == 200 and again.json() == gone.json()
        itself = client.delete(f"/api/v1/staff-links/{db.link_id(fresh)}",
                               headers=_bearer(fresh))
        assert itself.status_code == 409 and "you are using" in itself.json()["detail"]
        unknown = client.delete("/api/v1/staff-links/00000000", headers=_bearer(fresh))
        assert unknown.status_code == 404 and "00000000" in unknown.json()["detail"]
        long = client.post("/api/v1/staff-links", json={"name": "x" * 150},
                           headers=_bearer(fresh))
        assert long.status_code == 422 and "100" in long.json()["detail"]

        entries = client.get("/api/v1/audit?action=staff-link",
                             headers=_bearer(fresh)).json()["entries"]
    # newest first: Ben revoked Anna's link (once), Anna made Ben's, Anna revoked the
    # first, the first made Anna's
    assert [(e["actor"], e["subject"], e["before"], e["after"]) for e in entries] == [
        ("Ben", anna["id"], {"name": "Anna (TA)", "revoked": False},
         {"name": "Anna (TA)", "revoked": True}),
        ("Anna (TA)", db.link_id(fresh), None, {"name": "Ben", "revoked": False}),
        ("Anna (TA)", db.link_id(mine), {"name": None, "revoked": False},
         {"name": None, "revoked": True}),
        (f"staff link {db.link_id(mine)}", anna["id"], None,
         {"name": "Anna (TA)", "revoked": False})]


def test_the_links_page_shows_a_new_link_once_and_revokes_another(exam_dir, tmp_path):
    manifest = exam_copy(exam_dir, tmp_path / "exam")
    with serve(manifest) as served:
        client, mine = served.client, served.staff
        page = client.get(f"/i/{mine}/links")
        assert page.status_code == 200 and "the link you are using" in page.text
        made = client.post(f"/i/{mine}/links", data={"csrf": _csrf(page.text),
                                                     "name": "Cleo"})
        assert made.status_code == 200
        url = re.search(r'<code id="new-link">([^<]+)</code>', made.text).group(1)
        token = url.rsplit("/i/", 1)[1]
        assert client.get(f"/i/{token}").status_code == 200
        later = client.get(f"/i/{mine}/links")
        assert "Cleo" in later.text and token not in later.text
        from dynagrade.serve import db

        refused = client.post(f"/i/{mine}/links/revoke", data={"link": db.link_id(token)})
        assert refused.status_code == 403  # no CSRF field
        done = client.post(f"/i/{mine}/links/revoke",
                           data={"csrf": _csrf(later.text), "link": db.link_id(token)})
        assert done.status_code == 200 and "Revoked" in done.text and "Cleo" in done.text
        assert client.get(f"/i/{token}").status_code == 401
        own = client.post(f"/i/{mine}/links/revoke",
                          data={"csrf": _csrf(later.text), "link": db.link_id(mine)})
        assert own.status_code == 422 and "you are using" in own.text
        too_long = client.post(f"/i/{mine}/links", data={"csrf": _csrf(later.text),
                                                          "name": "y" * 101})
        assert too_long.status_code == 422 and "y" * 101 in too_long.text  # typed kept


def test_the_links_command_names_lists_and_revokes_staff_links(exam_dir, tmp_path):
    from dynagrade.serve import db

    manifest = exam_copy(exam_dir, tmp_path / "exam")
    out = tmp_path / "links.csv"
    run = CliRunner().invoke
    made = run(main, ["links", str(manifest), "-o", str(out), "--instructor", "--name",
                      "Dana (TA)", "--by", "prof"])
    assert made.exit_code == 0, made.output
    token = made.output.split("staff link: ")[1].split("/i/")[1].strip()
    listed = run(main, ["links", str(manifest), "--list-staff"])
    assert listed.exit_code == 0
    line = next(line for line in listed.output.splitlines() if "Dana (TA)" in line)
    assert line.startswith(db.link_id(token)) and line.endswith("active")
    unknown = run(main, ["links", str(manifest), "--revoke-staff", "zzzz"])
    assert unknown.exit_code != 0 and "no staff link zzzz" in unknown.output
    revoked = run(main, ["links", str(manifest), "--revoke-staff", db.link_id(token),
                         "--by", "prof"])
    assert revoked.exit_code == 0 and "revoked 1 staff link" in revoked.output
    engine = db.connect(db.sqlite_url_beside(manifest))
    assert db.identify(engine, "serve-test", token) is None
    again = run(main, ["links", str(manifest), "--list-staff"])
    assert "revoked" in next(line for line in again.output.splitlines() if "Dana" in line)
    entries = db.changes(engine, "serve-test", "staff-link")
    assert [(e.actor, e.after["revoked"]) for e in entries] == [("prof", True),
                                                                ("prof", False)]
    # --revoke-staff all leaves no staff link working
    other = db.issue_staff_token(engine, "serve-test", "Eve")
    assert run(main, ["links", str(manifest), "--revoke-staff", "all"]).exit_code == 0
    assert db.identify(engine, "serve-test", other) is None


# -- the audit log -------------------------------------------------------------------------


def test_the_audit_log_is_a_page_a_csv_and_json_in_the_courses_zone(exam_dir, tmp_path,
                                                                     database):
    manifest = exam_copy(exam_dir, tmp_path / "exam", closes=dt.datetime(
        2030, 4, 14, 12, 0, tzinfo=ZURICH))
    with serve(manifest, database) as served:
        client, mine = served.client, served.staff
        page = client.get(f"/i/{mine}").text
        assert client.post(f"/i/{mine}/policy", data={"csrf": _csrf(page), "attempts": "3"},
                           follow_redirects=False).status_code == 303
        client.post("/api/v1/staff-links", json={"name": "Finn"}, headers=_bearer(mine))
        table = client.get(f"/i/{mine}/audit")
        only_policy = client.get(f"/i/{mine}/audit?action=policy")
        audit_csv = client.get(f"/i/{mine}/audit.csv")
        api_csv = client.get("/api/v1/audit.csv", headers=_bearer(mine))
    assert table.status_code == 200 and "Finn" in table.text and "attempts: 0 → 3" in table.text
    assert "attempts: 0 → 3" in only_policy.text and "Finn" not in only_policy.text
    assert audit_csv.text == api_csv.text
    assert audit_csv.headers["content-disposition"] == 'attachment; filename="audit.csv"'
    rows = list(csv.DictReader(io.StringIO(audit_csv.text)))
    assert [r["action"] for r in rows] == ["policy", "staff-link"]  # oldest first
    assert all(r["at"].endswith("+02:00") for r in rows)
    assert json.loads(rows[0]["before"])["attempts"] == 0
    assert json.loads(rows[0]["after"])["attempts"] == 3
    assert json.loads(rows[1]["after"]) == {"name": "Finn", "revoked": False}


# -- downloads -----------------------------------------------------------------------------


@pytest.mark.parametrize("counts", ["best", "last"])
def test_submissions_csv_holds_every_attempt_and_flags_the_one_that_counts(
        exam_dir, tmp_path, counts):
    manifest = exam_copy(exam_dir, tmp_path / "hw", mode="homework", feedback="immediate",
                         counts=counts)
    with serve(manifest) as served:
        right = reference_answers(served, "s1", "projectile-range")["x_max"]
        wrong = repr(float(right) * 3)
        served.submit("s1", "projectile-range", {"x_max": right})
        served.submit("s1", "projectile-range", {"x_max": wrong})
        text = served.staff_get("/api/v1/submissions.csv").text
    rows = list(csv.DictReader(io.StringIO(text)))
    assert [(r["student_id"], r["part"], r["answer"], r["attempt"], r["counts"])
            for r in rows] == [
        ("s1", "x_max", right, "1", "yes" if counts == "best" else "no"),
        ("s1", "x_max", wrong, "2", "no" if counts == "best" else "yes")]
    assert all(dt.datetime.fromisoformat(r["submitted_at"]).utcoffset() is not None
               for r in rows)


@pytest.mark.parametrize("layout", ["moodle", "canvas"])
def test_platform_gradebooks_from_the_server_are_class_gradings(exam_dir, tmp_path, layout):
    from dynagrade.classgrade.grade import grade_class
    from dynagrade.classgrade.gradebook import platform_gradebook

    manifest = exam_copy(exam_dir, tmp_path / "hw", mode="homework", feedback="immediate")
    with serve(manifest) as served:
        for student in ("s1", "s2"):
            served.submit(student, "projectile-range",
                          reference_answers(served, student, "projectile-range"))
        served.submit("s2", "sliding-up-a-slope", {"a_up": "1 m/s^2"})
        page = served.client.get(f"/i/{served.staff}/grades-{layout}.csv")
        api = served.staff_get(f"/api/v1/grades-{layout}.csv")
        responses = served.staff_get("/api/v1/submissions.csv").text
        unknown = served.staff_get("/api/v1/grades-blackboard.csv")
    assert page.status_code == 200 and page.text == api.text
    assert page.headers["content-disposition"] == \
        f'attachment; filename="grades-{layout}.csv"'
    assert unknown.status_code == 422
    (tmp_path / "responses.csv").write_text(responses, encoding="utf-8")
    offline = grade_class(manifest, [tmp_path / "responses.csv"], jobs=1)
    assert page.text == platform_gradebook(offline, layout, "Serve test")
    rows = list(csv.reader(io.StringIO(page.text)))
    # s1 full marks on projectile-range (6 of 10), s3 absent (no grade)
    total_column = 3 if layout == "moodle" else 5
    by_id = {r[0 if layout == "moodle" else 2]: r[total_column] for r in rows[1:]}
    assert float(by_id["s1"]) == pytest.approx(6.0) and by_id["s3"] == ""
