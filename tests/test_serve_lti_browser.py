"""An LTI 1.3 launch in Debian's Chromium (Playwright) against a real `dynagrade serve`
and the test platform (tests/lti_platform.py): the platform sends the browser through
login initiation, its authorization endpoint and the id_token's form post to the
student's page, where she answers and submits, and her score reaches the platform's
gradebook (AGS), which the staff page lists; a user not on the roster reads why; a
teacher places a practice exercise from the activity chooser (deep linking).
axe-core finds nothing on either page; on SQLite and PostgreSQL."""

from __future__ import annotations

import subprocess
import sys
import time
from contextlib import contextmanager
from pathlib import Path

import pytest

from lti_platform import CLIENT_ID, DEPLOYMENT_ID, Platform, start, stop, with_users
from serve_support import (database, exam_copy, exam_dir, postgres_url,  # noqa: F401
                           serving_process)
from test_serve_browser import CHROMIUM
from test_serve_student_browser import AXE, assert_accessible, chromium, right

pytestmark = pytest.mark.skipif(not (CHROMIUM.exists() and AXE.exists()),
                                reason="needs Chromium (apt-get install chromium) and axe-core "
                                       "(npm install --prefix .cache/axe axe-core)")


def part_points(manifest: Path, exercise: str, part: str) -> float:
    """The points of one part, as the manifest gives them."""
    from dynagrade.exam.manifest import load

    entry = next(e for e in load(manifest).exercises if e.id == exercise)
    found = entry.part(part)
    assert found is not None
    return float(found.points)


@contextmanager
def launched(manifest: Path, tmp_path: Path, db_url: str | None):
    """`dynagrade serve` of ``manifest`` and the test platform, registered with each
    other by `dynagrade lti register`; yields the platform and a staff link."""
    with serving_process(manifest, tmp_path / "links.csv", db_url) as (base, _rows, staff):
        running = start(with_users(Platform(tool=base)))
        platform = running.platform
        try:
            where = ["--db", db_url] if db_url else []
            subprocess.run([sys.executable, "-m", "dynagrade.cli", "lti", "register",
                            str(manifest), *where, "--issuer", platform.issuer,
                            "--client-id", CLIENT_ID, "--deployment-id", DEPLOYMENT_ID,
                            "--auth-url", f"{platform.url}/auth",
                            "--token-url", f"{platform.url}/token",
                            "--jwks-url", f"{platform.url}/jwks"],
                           check=True, capture_output=True, text=True)
            yield platform, staff
        finally:
            stop(running)


def test_a_launched_student_answers_and_submits(exam_dir, tmp_path, database):
    from playwright.sync_api import expect

    manifest = exam_copy(exam_dir, tmp_path / "hw", mode="homework", feedback="immediate")
    with launched(manifest, tmp_path, database) as (platform, staff), chromium() as browser:
        page = browser.new_page()
        page.goto(f"{platform.url}/launch?user=u-ada")
        page.wait_for_url(f"{platform.tool}/s/lti-*")
        expect(page.locator("h1")).to_contain_text("Serve test")
        assert "Ada One" in page.content()
        assert_accessible(page, "launched student page")
        page.locator("#projectile-range--x_max").fill(
            right(manifest, "s1", "projectile-range", "x_max"))
        page.locator("#projectile-range button[type=submit]").click()
        expect(page.locator("#status")).to_contain_text("were saved")
        assert_accessible(page, "launched student page after a submit")
        # the score reaches the platform's gradebook (the server sends every 5 s)
        for _ in range(100):
            if platform.scores:
                break
            time.sleep(0.2)
        ((_line_item, score),) = platform.scores
        assert score["userId"] == "u-ada"
        assert (score["scoreGiven"], score["scoreMaximum"]) == \
            (part_points(manifest, "projectile-range", "x_max"), 10.0)
        # the staff's page of the course platform lists it, sent, with the answer
        page.goto(f"{staff}/lti")
        expect(page.locator("#lti-scores tbody tr")).to_have_count(1)
        expect(page.locator("#lti-scores tbody")).to_contain_text("Ada One (s1)")
        expect(page.locator("#lti-scores tbody")).to_contain_text("204")
        assert_accessible(page, "the staff's page of the course platform")
        page.get_by_role("button", name="Import the members").click()
        expect(page.get_by_role("status")).to_contain_text("2 learners linked to the roster")
        assert_accessible(page, "the course platform page after an import")


def test_a_user_not_on_the_roster_reads_why(exam_dir, tmp_path):
    from playwright.sync_api import expect

    manifest = exam_copy(exam_dir, tmp_path / "hw", mode="homework", feedback="immediate")
    with launched(manifest, tmp_path, None) as (platform, _staff), chromium() as browser:
        page = browser.new_page()
        page.goto(f"{platform.url}/launch?user=u-zed")
        page.wait_for_url(f"{platform.tool}/lti/launch")
        expect(page.locator("h1")).to_have_text("Not on the roster")
        expect(page.locator("main")).to_contain_text("zed@example.org")
        assert_accessible(page, "not on the roster")


def test_a_teacher_places_a_practice_exercise_from_the_activity_chooser(exam_dir, tmp_path):
    from playwright.sync_api import expect

    manifest = exam_copy(exam_dir, tmp_path / "pr", mode="practice", feedback="immediate")
    with launched(manifest, tmp_path, None) as (platform, _staff), chromium() as browser:
        page = browser.new_page()
        page.goto(f"{platform.url}/launch?user=u-prof&deep=1")
        page.wait_for_url(f"{platform.tool}/i/lti-*/lti/place")
        assert_accessible(page, "what to place")
        page.locator("input[value='exercise:sliding-up-a-slope']").check()
        page.get_by_role("button", name="Place it").click()
        # the signed answer goes back by itself (the page's script posts it)
        page.wait_for_url(f"{platform.url}/deep-link-return")
        expect(page.locator("h1")).to_contain_text("Placed:")
        (found,) = platform.placed
        (item,) = found["https://purl.imsglobal.org/spec/lti-dl/claim/content_items"]
        assert item["custom"] == {"exercise": "sliding-up-a-slope"}
        assert item["url"] == f"{platform.tool}/lti/launch"


def test_a_launch_inside_the_platform_s_iframe_shows_the_student_s_page(exam_dir, tmp_path):
    """The LMS embeds the activity: the launched page is framed by the registered
    platform's origin (frame-ancestors), and the cookies are sent within the frame."""
    from playwright.sync_api import expect

    manifest = exam_copy(exam_dir, tmp_path / "hw", mode="homework", feedback="immediate")
    with launched(manifest, tmp_path, None) as (platform, _staff), chromium() as browser:
        page = browser.new_page()
        page.goto(f"{platform.url}/course?user=u-bo")
        frame = page.frame_locator("iframe")
        expect(frame.locator("h1")).to_contain_text("Serve test", timeout=15000)
        expect(frame.locator("body")).to_contain_text("Bo Two")
