"""Two of issue 24's promises in Debian's Chromium, with axe-core on each page state: a
German exam's student and staff pages are German (no English interface word left) and
accessible at phone and desktop widths; and when the database stops accepting writes, a
submit gives a 503 page that keeps what the student typed, ready to send again."""

from __future__ import annotations

import re
from types import SimpleNamespace

import pytest

from serve_support import (exam_copy, exam_dir, fresh_database, postgres_url,  # noqa: F401
                           serving_process)
from test_i18n_serve import _english_left, _statements, german_exam  # noqa: F401
from test_serve_browser import ARGS, CHROMIUM
from test_serve_staff_browser import AXE, _violations

pytestmark = pytest.mark.skipif(not (CHROMIUM.exists() and AXE.exists()),
                                reason="needs Chromium and axe-core (npm install --prefix "
                                       ".cache/axe axe-core)")


def test_a_german_exam_is_german_and_accessible_in_the_browser(german_exam, tmp_path):
    from playwright.sync_api import sync_playwright

    from dynagrade.serve.exam_data import ExamData

    manifest = exam_copy(german_exam, tmp_path / "exam", mode="homework",
                         feedback="immediate", attempts=3)
    shown = SimpleNamespace(server=SimpleNamespace(data=ExamData(manifest)))
    with serving_process(manifest, tmp_path / "links.csv") as (base, rows, staff), \
            sync_playwright() as playwright:
        browser = playwright.chromium.launch(executable_path=str(CHROMIUM), args=ARGS)
        try:
            student = next(r for r in rows if r["student_id"] == "s1")
            for width in (320, 1280):
                page = browser.new_page(viewport={"width": width, "height": 900})
                for name, url in (("student", student["url"]), ("staff", staff)):
                    page.goto(url)
                    assert page.locator("html").get_attribute("lang") == "de", name
                    assert _violations(page) == [], (name, width)
                    statements = _statements(shown, "s1") if name == "student" else []
                    # the figures' English descriptions, marked lang="en", are no
                    # interface string (see the student page template)
                    html = re.sub(r'<figure lang="en">.*?</figure>', " ", page.content(),
                                  flags=re.S)
                    assert _english_left(shown, html, statements) == [], name
                    wide = page.evaluate("document.documentElement.scrollWidth")
                    assert wide <= width, (name, width, wide)
                page.close()
        finally:
            browser.close()


def test_a_database_that_stops_writing_keeps_the_typed_answer_in_the_browser(
        exam_dir, tmp_path, postgres_url):
    import sqlalchemy as sa
    from playwright.sync_api import sync_playwright

    manifest = exam_copy(exam_dir, tmp_path / "exam", mode="homework", feedback="immediate")
    url = fresh_database(postgres_url, "browser_refusing_writes")
    with serving_process(manifest, tmp_path / "links.csv", url) as (base, rows, staff), \
            sync_playwright() as playwright:
        admin = sa.create_engine(postgres_url.replace("postgresql://", "postgresql+psycopg://"),
                                 isolation_level="AUTOCOMMIT")
        browser = playwright.chromium.launch(executable_path=str(CHROMIUM), args=ARGS)
        try:
            page = browser.new_page(viewport={"width": 390, "height": 900})
            page.goto(rows[0]["url"])
            typed = "12.5 m"
            box = page.locator('input[name="answer.x_max"]')
            box.fill(typed)
            with admin.connect() as connection:  # from now on, no write succeeds
                connection.execute(sa.text("ALTER DATABASE browser_refusing_writes SET "
                                           "default_transaction_read_only = on"))
                connection.execute(sa.text("SELECT pg_terminate_backend(pid) FROM "
                                           "pg_stat_activity WHERE datname = "
                                           "'browser_refusing_writes'"))
            with page.expect_navigation():
                box.locator("xpath=ancestor::form").locator("button[type=submit]").click()
            assert "Please try again shortly" in page.content()
            assert page.locator(f'input[value="{typed}"]').count() >= 1
            assert _violations(page) == []
        finally:
            browser.close()
            admin.dispose()
