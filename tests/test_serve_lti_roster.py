"""Names and Role Provisioning: the course's learners imported from the test platform
(two a page) and merged with the roster by the registered claim, from the staff page's
button and from `dynagrade lti roster`: those on the roster are linked (their score then
reaches the platform without a launch of their own), the others listed and written as
rows to add, the roster's students the platform lacks listed."""

from __future__ import annotations

import csv
import datetime as dt
import io
import re

from click.testing import CliRunner

from dynagrade.serve import limits
from lti_platform import User
from lti_support import launch_as, platform, tool  # noqa: F401
from serve_support import Clock, exam_copy, exam_dir  # noqa: F401
from test_serve_lti_grades import fresh_platform, launched_submit, sync  # noqa: F401

UTC = dt.timezone.utc


def staff_session(client, platform) -> str:
    """An instructor's launch (which also tells the tool where the members are): the
    staff page's token."""
    answer = launch_as(client, platform, "u-prof")
    assert answer.status_code == 303
    return answer.headers["location"].split("/")[2]


def test_the_staff_button_links_the_roster_s_learners_and_lists_the_rest(exam_dir, tmp_path,
                                                                         platform):
    manifest = exam_copy(exam_dir, tmp_path / "hw", mode="homework", feedback="immediate")
    with tool(manifest, None, platform) as client:
        server = client.app.state.server
        handle = staff_session(client, platform)
        page = client.post(f"/i/{handle}/lti/roster",
                           data={"csrf": limits.csrf_field(server.secret, handle)})
        assert page.status_code == 200, page.text
        text = re.sub(r"\s+", " ", page.text)
        # s1 (ada@) and s2 (BO@ for bo@) by email; zed is on no roster; s3 not listed;
        # the instructor is no learner
        assert "2 learners linked to the roster (2 of them new); 1 not on the roster; " \
               "1 roster students the platform does not list." in text
        assert "Zed Stranger (zed@example.org)" in text and "Cy Three (s3)" in text
        assert "Pat Professor" not in text
        again = client.post(f"/i/{handle}/lti/roster",
                            data={"csrf": limits.csrf_field(server.secret, handle)})
        assert "(0 of them new)" in again.text


def test_an_imported_learner_s_score_reaches_the_platform_without_their_launch(
        exam_dir, tmp_path, platform):
    from dynagrade.serve import db
    from dynagrade.serve.lti import roster_import

    manifest = exam_copy(exam_dir, tmp_path / "hw", mode="homework", feedback="immediate")
    with tool(manifest, None, platform, clock=Clock()) as client:
        server = client.app.state.server
        launched_submit(client, platform, "u-ada", "s1", "projectile-range")  # makes the item
        staff_session(client, platform)
        roster_import.import_roster(server.engine, server.data.exam_id, server.data.students,
                                    server.clock())
        # Bo answers by a secret link, never launched
        token = db.issue_tokens(server.engine, server.data.exam_id, ["s2"])["s2"]
        stored = client.post("/api/v1/answers", headers={"Authorization": f"Bearer {token}"},
                             json={"exercise": "sliding-up-a-slope",
                                   "answers": _right(server, "s2", "sliding-up-a-slope")})
        assert stored.status_code == 200
        sync(client)
        users = sorted(score["userId"] for _, score in platform.scores)
        assert users == ["u-ada", "u-bo"]
        assert next(s for _, s in platform.scores if s["userId"] == "u-bo")["scoreGiven"] == 4.0


def test_dynagrade_lti_roster_writes_the_rows_the_roster_lacks(exam_dir, tmp_path, platform):
    from dynagrade.cli import main

    manifest = exam_copy(exam_dir, tmp_path / "hw", mode="homework", feedback="immediate")
    platform.users["u-new"] = User("u-new", "Nia New", "nia@example.org", "s77",
                                   ["Learner"])
    try:
        with tool(manifest, None, platform) as client:
            staff_session(client, platform)
            out = tmp_path / "additions.csv"
            result = CliRunner().invoke(main, ["lti", "roster", str(manifest), "-o", str(out)])
            assert result.exit_code == 0, result.output
            assert "2 learners linked to the roster (2 new); 2 not on the roster" in \
                result.output
            rows = list(csv.DictReader(io.StringIO(out.read_text(encoding="utf-8"))))
            assert rows == [{"student_id": "s9", "name": "Zed Stranger",
                             "email": "zed@example.org"},
                            {"student_id": "s77", "name": "Nia New",
                             "email": "nia@example.org"}]
    finally:
        del platform.users["u-new"]


def test_an_import_before_any_launch_says_what_to_do(exam_dir, tmp_path, platform):
    from dynagrade.serve import db

    manifest = exam_copy(exam_dir, tmp_path / "hw", mode="homework", feedback="immediate")
    with tool(manifest, None, platform) as client:
        server = client.app.state.server
        token = db.issue_staff_token(server.engine, server.data.exam_id)
        page = client.post(f"/i/{token}/lti/roster",
                           data={"csrf": limits.csrf_field(server.secret, token)})
        assert page.status_code == 200
        assert "open the activity from the course once, as a teacher" in page.text


def _right(server, student: str, exercise: str) -> dict[str, str]:
    from types import SimpleNamespace

    from serve_support import reference_answers

    return reference_answers(SimpleNamespace(variant=server.data.entry), student, exercise)
