"""End to end in a real browser: Debian's Chromium driven by Playwright against a real
`dynagrade serve` (uvicorn) process. Nothing is downloaded: Playwright launches
/usr/bin/chromium.

A student opens their link, types answers, sees the live preview, submits and sees the
verdict; reloads and sees the history; the staff page offers grades.csv for download.
"""

from __future__ import annotations

import csv
import io
from pathlib import Path

import pytest

from serve_support import exam_copy, exam_dir, serving_process  # noqa: F401

CHROMIUM = Path("/usr/bin/chromium")
ARGS = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
        "--disable-background-networking", "--disable-component-update", "--disable-sync"]

pytestmark = pytest.mark.skipif(not CHROMIUM.exists(),
                                reason="needs Chromium at /usr/bin/chromium (apt-get install "
                                       "chromium)")


@pytest.fixture
def running(exam_dir, tmp_path):
    """A served homework exam with its links: (manifest, links rows, staff url)."""
    manifest = exam_copy(exam_dir, tmp_path / "hw", mode="homework", feedback="immediate")
    with serving_process(manifest, tmp_path / "links.csv") as (_base, rows, staff):
        yield manifest, rows, staff


def test_a_student_answers_in_the_browser_and_the_staff_downloads_grades(running, tmp_path):
    from playwright.sync_api import expect, sync_playwright

    from dynagrade.exam.manifest import load

    manifest, rows, staff = running
    student = rows[0]
    records = load(manifest)
    variant = next(s for s in records.students
                   if s.student_id == student["student_id"]).variant("projectile-range")
    right = repr(variant.answers["x_max"])
    with sync_playwright() as playwright:
        browser = playwright.chromium.launch(executable_path=str(CHROMIUM), args=ARGS)
        try:
            page = browser.new_page()
            page.goto(student["url"])
            expect(page.locator("h1")).to_have_text("Serve test")
            box = page.locator("#projectile-range--x_max")
            preview = page.locator("#projectile-range output[data-preview-for=x_max]")
            box.fill("45 km")  # 45 km = 45000 m, shown back before submitting
            expect(preview).to_contain_text("reads as 45 km = 4.5e4 m")
            box.fill("3 kg")
            expect(preview).to_contain_text("expected a length")
            formula = page.locator("#projectile-range--x_max_formula")
            formula.fill("sqrt(2 g h)")  # h is not a name of this part
            shown = page.locator("#projectile-range output[data-preview-for=x_max_formula]")
            expect(shown).to_contain_text("unknown name 'h'")
            formula.fill("v0^2 sin(2 alpha)/g")  # typeset back: a fraction in MathML
            expect(shown.locator("math mfrac")).to_have_count(1)
            box.fill(right)
            expect(preview).to_contain_text("reads as")
            page.locator("#projectile-range button[type=submit]").click()
            history = page.locator("#projectile-range table.history")
            expect(history.first).to_contain_text("correct")
            page.reload()
            # one table per part answered: the attempt's two parts (the formula is the
            # reference's), each named by its label
            expect(history).to_have_count(2)
            expect(history.locator("td.correct")).to_have_count(2)
            expect(history.first).to_contain_text(right)

            page.goto(staff)
            expect(page.locator("table.gradebook")).to_contain_text(student["student_id"])
            with page.expect_download() as download:
                page.locator("a", has_text="grades.csv").click()
            saved = tmp_path / "grades.csv"
            download.value.save_as(saved)
        finally:
            browser.close()
    grades = {r["student_id"]: r for r in csv.DictReader(io.StringIO(saved.read_text()))}
    exercise = records.exercise("projectile-range")
    points = exercise.part("x_max").points + exercise.part("x_max_formula").points
    assert float(grades[student["student_id"]]["projectile-range"]) == pytest.approx(points)
    assert grades[rows[1]["student_id"]]["status"] == "absent"
