"""Exceptions and timed exams in Debian's Chromium against a real `dynagrade serve`
(issue 25's "Done when"): a TA extends one student's close on the exceptions page, the
class's close passes, and that student (and only that student) can still submit while
the other's page says closed; a timed exam shows the Start button, then the exercises and
the time left. axe-core finds nothing on each page state, and nothing scrolls sideways at
320 px."""

from __future__ import annotations

import datetime as dt
import time

import pytest

from serve_support import exam_copy, exam_dir, serving_process  # noqa: F401
from test_serve_browser import ARGS, CHROMIUM
from test_serve_staff_browser import AXE, _violations

pytestmark = pytest.mark.skipif(not (CHROMIUM.exists() and AXE.exists()),
                                reason="needs Chromium and axe-core (npm install --prefix "
                                       ".cache/axe axe-core)")
UTC = dt.timezone.utc


def _accessible_and_narrow(page, state: str) -> None:
    """axe-core finds nothing, and at 320 px nothing scrolls sideways."""
    for width in (1280, 320):
        page.set_viewport_size({"width": width, "height": 900})
        assert _violations(page) == [], (state, width)
        wide = page.evaluate("document.documentElement.scrollWidth")
        assert wide <= width, (state, width, wide)


def test_a_ta_extends_one_students_close_and_only_they_submit_after_it(exam_dir, tmp_path):
    import httpx
    from playwright.sync_api import expect, sync_playwright

    manifest = exam_copy(exam_dir, tmp_path / "hw", mode="homework", feedback="immediate")
    with serving_process(manifest, tmp_path / "links.csv") as (base, rows, staff), \
            sync_playwright() as playwright:
        urls = {r["student_id"]: r["url"] for r in rows}
        browser = playwright.chromium.launch(executable_path=str(CHROMIUM), args=ARGS)
        try:
            ta = browser.new_page()
            ta.goto(f"{staff}/exceptions")
            expect(ta.locator("main")).to_contain_text("None yet")
            _accessible_and_narrow(ta, "exceptions, none granted")
            later = (dt.datetime.now(UTC) + dt.timedelta(hours=1)).replace(microsecond=0)
            ta.get_by_label("Students").fill("s1 nobody")
            ta.get_by_label("Their close").fill(later.isoformat())
            ta.get_by_role("button", name="Grant").click()
            expect(ta.get_by_role("alert")).to_have_text("not on the roster: nobody")
            expect(ta.get_by_label("Students")).to_have_value("s1 nobody")
            _accessible_and_narrow(ta, "exceptions, a refusal")
            ta.get_by_label("Students").fill("s1")
            ta.get_by_role("button", name="Grant").click()
            rows_shown = ta.locator("table.exceptions tbody tr")
            expect(rows_shown).to_have_count(1)
            expect(rows_shown).to_contain_text("Ada One")
            _accessible_and_narrow(ta, "exceptions, one granted")

            # the class's close, a few seconds ahead, set on the staff page's policy form
            ta.goto(staff)
            closes = (dt.datetime.now(UTC) + dt.timedelta(seconds=4)).replace(microsecond=0)
            ta.locator("#policy-closes").fill(closes.isoformat())
            ta.get_by_role("button", name="Change the policy").click()
            expect(ta.locator("main")).to_contain_text(f"closes {closes.isoformat()}")
            time.sleep(max(0.0, (closes - dt.datetime.now(UTC)).total_seconds()) + 1)

            other = browser.new_page()
            other.goto(urls["s2"])
            expect(other.locator("main")).to_contain_text(
                "The exam is closed; answers are no longer accepted.")
            expect(other.locator("#projectile-range button[type=submit]")).to_have_count(0)
            expect(other.locator("main")).not_to_contain_text("Your close")
            refused = httpx.post(f"{base}/api/v1/answers", headers={
                "Authorization": f"Bearer {urls['s2'].rsplit('/', 1)[1]}"},
                json={"exercise": "projectile-range", "answers": {"x_max": "1 m"}})
            assert refused.status_code == 403 and "closed" in refused.json()["detail"]

            student = browser.new_page()
            student.goto(urls["s1"])
            expect(student.locator("main")).to_contain_text("Your close:")
            expect(student.locator("main")).to_contain_text("(extended)")
            student.locator("#projectile-range--x_max").fill("12.5 m")
            student.locator("#projectile-range button[type=submit]").click()
            expect(student.locator("#status")).to_contain_text(
                "were saved.")
            expect(student.locator("#projectile-range table.history")).to_contain_text("12.5 m")
        finally:
            browser.close()


def test_a_timed_exam_starts_on_the_students_button_and_shows_the_time_left(exam_dir,
                                                                           tmp_path):
    from playwright.sync_api import expect, sync_playwright

    manifest = exam_copy(exam_dir, tmp_path / "timed", mode="exam", time_limit=30)
    with serving_process(manifest, tmp_path / "links.csv") as (base, rows, staff), \
            sync_playwright() as playwright:
        browser = playwright.chromium.launch(executable_path=str(CHROMIUM), args=ARGS)
        try:
            page = browser.new_page()
            page.goto(next(r["url"] for r in rows if r["student_id"] == "s1"))
            expect(page.locator("main")).to_contain_text("Time limit: 30 minutes")
            expect(page.locator("#projectile-range")).to_have_count(0)
            _accessible_and_narrow(page, "timed, before the start")
            page.get_by_role("button", name="Start").click()
            expect(page.locator("#projectile-range")).to_have_count(1)
            expect(page.locator("main")).to_contain_text("You may answer until")
            # whole minutes, changed about once a minute; no live region
            expect(page.locator("#countdown")).to_have_text("Time left: 29 min")
            assert page.locator("#countdown").get_attribute("aria-live") is None
            _accessible_and_narrow(page, "timed, running")
        finally:
            browser.close()
