"""The regrade page in Debian's Chromium, against a real `dynagrade serve`: it shows the
plan's diff and applying it changes grades.csv (issue 25, "Done when"); axe-core finds
nothing on the page with nothing to regrade, with a plan and after applying it, and the
page never scrolls sideways at 320 px."""

from __future__ import annotations

import csv
import io

import pytest

from regrade_support import EXERCISE_ID, demo_exam, lengths, write_exercise
from serve_support import serving_process
from test_serve_browser import ARGS, CHROMIUM  # noqa: F401
from test_serve_staff_browser import AXE, _violations

pytestmark = pytest.mark.skipif(not (CHROMIUM.exists() and AXE.exists()),
                                reason="needs Chromium and axe-core (npm install --prefix "
                                       ".cache/axe axe-core)")


def _totals(httpx, staff: str) -> dict[str, str]:
    text = httpx.get(f"{staff}/grades.csv").text
    return {row["student_id"]: row["total"] for row in csv.DictReader(io.StringIO(text))}


def _checked(page, width: int, state: str) -> None:
    assert _violations(page) == [], state
    wide = page.evaluate("document.documentElement.scrollWidth")
    assert wide <= width, (state, wide)


def test_the_regrade_page_shows_the_diff_and_applying_it_changes_grades_csv(
        tmp_path, monkeypatch):
    import httpx
    from click.testing import CliRunner
    from playwright.sync_api import expect, sync_playwright

    from dynagrade.cli import main
    from dynagrade.exercise.loader import ENVIRONMENT_VARIABLE

    manifest, folder = demo_exam(tmp_path)
    x = lengths(manifest)
    monkeypatch.setenv(ENVIRONMENT_VARIABLE, str(folder))  # the server finds the exercise
    with serving_process(manifest, tmp_path / "links.csv") as (base, rows, staff):
        token = {row["student_id"]: row["url"].rsplit("/", 1)[1] for row in rows}
        for student, answers in (("s1", {"y": f"{2 * x['s1']!r} m"}),    # right, then wrong
                                 ("s2", {"y": f"{2 * x['s2'] + 1!r} m"})):  # wrong, then right
            sent = httpx.post(f"{base}/api/v1/answers", json={
                "exercise": EXERCISE_ID, "answers": answers},
                headers={"Authorization": f"Bearer {token[student]}"})
            assert sent.status_code == 200, sent.text
        assert _totals(httpx, staff) == {"s1": "2", "s2": "0", "s3": "", "s4": "", "s5": ""}
        with sync_playwright() as playwright:
            browser = playwright.chromium.launch(executable_path=str(CHROMIUM), args=ARGS)
            try:
                page = browser.new_page(viewport={"width": 320, "height": 800})
                page.goto(f"{staff}/regrade")
                expect(page.get_by_text("No plan is open")).to_be_visible()
                _checked(page, 320, "nothing to regrade")
                write_exercise(folder, y="2 * p.x + 1")  # the author's fix, and the re-key
                rekeyed = CliRunner().invoke(main, ["rekey", str(manifest), EXERCISE_ID])
                assert rekeyed.exit_code == 0, rekeyed.output
                page.get_by_role("button", name="Preview regrade").click()
                table = page.locator("#plan-table")
                expect(table).to_be_visible()
                cells = [[c.strip() for c in row.locator("td").all_inner_texts()]
                         for row in table.locator("tbody tr").all()]
                # student, exercise, part, attempt, answer, old, new, counted, total
                assert [(r[0], r[2], r[5], r[6], r[8]) for r in cells] == [
                    ("s1 Ada One", "y", "correct, 2", "wrong, 0", "2 → 0"),
                    ("s2 Bo Two", "y", "wrong, 0", "correct, 2", "0 → 2")]
                _checked(page, 320, "a plan shown")
                page.get_by_role("button", name="Apply plan").click()
                result = page.locator("#result")
                expect(result).to_contain_text("verdicts changed")
                expect(result).to_contain_text("The totals of 2 students changed.")
                _checked(page, 320, "applied")
                expect(page.locator("#history")).to_contain_text("applied")
                page.close()
            finally:
                browser.close()
        assert _totals(httpx, staff) == {"s1": "0", "s2": "2", "s3": "", "s4": "", "s5": ""}
