"""The student page in Debian's Chromium (Playwright) against a real `dynagrade serve`:
drafts survive a submit of another exercise and a reload, an unreadable answer spends
nothing, an exhausted part blocks nothing, the countdown, choice parts as radio buttons,
and axe-core finds nothing in every state, on a phone (320 px) and a desktop."""

from __future__ import annotations

import datetime as dt
from contextlib import contextmanager
from pathlib import Path

import pytest

from serve_support import exam_copy, exam_dir, serving_process  # noqa: F401
from test_serve_browser import ARGS, CHROMIUM

AXE = Path(__file__).resolve().parent.parent / ".cache" / "axe" / "node_modules" / \
    "axe-core" / "axe.min.js"
UTC = dt.timezone.utc
CHOICE_TOML = """\
id = "choice-test"
title = "Choice test"
date = 2025-04-14
mode = "homework"

[[exercise]]
id = "degrees-of-freedom"
points = 4
"""

pytestmark = pytest.mark.skipif(not (CHROMIUM.exists() and AXE.exists()),
                                reason="needs Chromium (apt-get install chromium) and axe-core "
                                       "(npm install --prefix .cache/axe axe-core)")


@contextmanager
def served(manifest: Path, tmp_path: Path):
    """A running `dynagrade serve` of ``manifest``: each student's page URL by id."""
    links = tmp_path / f"links-{next(_RUNS)}.csv"
    with serving_process(manifest, links, instructor=False) as (_base, rows, _staff):
        yield {r["student_id"]: r["url"] for r in rows}


_RUNS = iter(range(10_000))


@contextmanager
def chromium():
    from playwright.sync_api import sync_playwright

    with sync_playwright() as playwright:
        browser = playwright.chromium.launch(executable_path=str(CHROMIUM), args=ARGS)
        try:
            yield browser
        finally:
            browser.close()


def axe_violations(page) -> list:
    """axe-core's violations on the page as it is now (WCAG 2.x A and AA and best
    practice). Evaluated, not added as a script, which the page's policy would refuse."""
    page.evaluate(AXE.read_text(encoding="utf-8"))
    found = page.evaluate("async () => (await axe.run(document)).violations.map("
                          "v => [v.id, v.impact, v.nodes.map(n => n.target.join(' '))])")
    return found


def assert_accessible(page, state: str) -> None:
    for width, height in ((320, 640), (1280, 900)):
        page.set_viewport_size({"width": width, "height": height})
        assert axe_violations(page) == [], (state, width)
        wide = page.evaluate("document.documentElement.scrollWidth")
        assert wide <= width, (state, width, wide)


def right(manifest: Path, student: str, exercise: str, part: str) -> str:
    from dynagrade.exam.manifest import load

    entry = next(s for s in load(manifest).students
                 if s.student_id == student).variant(exercise)
    return repr(entry.answers[part])


def test_drafts_survive_a_submit_elsewhere_and_a_reload(exam_dir, tmp_path):
    from playwright.sync_api import expect

    manifest = exam_copy(exam_dir, tmp_path / "hw", mode="homework", feedback="immediate",
                         attempts=1)
    with served(manifest, tmp_path) as urls, chromium() as browser:
        page = browser.new_page()
        page.goto(urls["s1"])
        assert_accessible(page, "homework, open")
        other = page.locator("#sliding-up-a-slope--a_up")
        other.fill("3 m/s^2")
        page.wait_for_timeout(1500)  # the draft is saved (debounced)
        page.locator("#projectile-range--x_max").fill(right(manifest, "s1", "projectile-range",
                                                            "x_max"))
        page.locator("#projectile-range button[type=submit]").click()
        status = page.locator("#status")
        expect(status).to_be_focused()
        expect(status).to_contain_text("were saved")
        expect(other).to_have_value("3 m/s^2")  # typed in the other exercise, kept
        assert_accessible(page, "homework, after a submit, one part exhausted")
        # the exhausted part is read-only; another part of the exercise is still accepted
        expect(page.locator("#projectile-range--x_max")).to_have_attribute("readonly", "")
        page.locator("#projectile-range--h_max").fill("5 kg")  # unreadable: costs nothing
        page.locator("#projectile-range button[type=submit]").click()
        expect(page.locator("#projectile-range--h_max--reason")).to_contain_text(
            "expected a length")
        expect(page.locator("#projectile-range--h_max")).to_have_attribute("aria-invalid",
                                                                           "true")
        expect(page.locator("#projectile-range--h_max--hint")).to_contain_text(
            "1 attempt left")
        assert_accessible(page, "homework, an unreadable answer refused")
        page.locator("#projectile-range--h_max").fill("12 m")
        page.locator("#projectile-range button[type=submit]").click()
        expect(page.locator("#status")).to_contain_text("were saved")
        expect(page.locator("#projectile-range--h_max--hint")).to_contain_text(
            "no attempts left")
        page.reload()
        expect(other).to_have_value("3 m/s^2")
        history = page.locator("#projectile-range .scroll table.history")
        expect(history).to_have_count(2)  # one table per part answered
        expect(history.first.locator("caption")).to_have_text("landing distance")


def test_a_warning_before_leaving_with_a_draft_not_saved(exam_dir, tmp_path):
    manifest = exam_copy(exam_dir, tmp_path / "hw", mode="homework", feedback="immediate")
    leaving = ("() => { const e = new Event('beforeunload', {cancelable: true}); "
               "window.dispatchEvent(e); return e.defaultPrevented; }")
    with served(manifest, tmp_path) as urls, chromium() as browser:
        page = browser.new_page()
        page.goto(urls["s2"])
        assert page.evaluate(leaving) is False  # nothing typed
        page.locator("#projectile-range--x_max").fill("1 m")
        assert page.evaluate(leaving) is True  # typed, the draft not saved yet: asks
        page.wait_for_timeout(2000)  # the draft is saved
        assert page.evaluate(leaving) is False
        page.reload()
        assert page.locator("#projectile-range--x_max").input_value() == "1 m"


def test_the_countdown_warns_and_the_close_locks_the_page(exam_dir, tmp_path):
    from playwright.sync_api import expect

    now = dt.datetime.now(UTC)
    closes = (now + dt.timedelta(minutes=9)).replace(microsecond=0)
    manifest = exam_copy(exam_dir, tmp_path / "exam", mode="exam", closes=closes)
    with served(manifest, tmp_path) as urls, chromium() as browser:
        page = browser.new_page()
        page.goto(urls["s1"])
        expect(page.locator("#countdown")).to_contain_text("Time left: 8 min")
        expect(page.locator("#warning")).to_have_text(
            "10 minutes left: submit your answers now.")
        assert_accessible(page, "exam, open, the countdown running")
    soon = exam_copy(exam_dir, tmp_path / "soon", mode="exam",
                     closes=(dt.datetime.now(UTC) + dt.timedelta(seconds=12)
                             ).replace(microsecond=0))
    with served(soon, tmp_path) as urls, chromium() as browser:
        page = browser.new_page()
        page.goto(urls["s1"])
        expect(page.locator("#countdown")).to_contain_text("The exam is closed",
                                                           timeout=20_000)
        expect(page.locator("#projectile-range button[type=submit]")).to_be_disabled()


def test_closed_states_and_before_opening_are_accessible(exam_dir, tmp_path):
    from playwright.sync_api import expect

    past = dt.datetime(2025, 4, 14, 12, tzinfo=UTC)
    states = {
        "exam, closed, verdicts shown": exam_copy(exam_dir, tmp_path / "closed", mode="exam",
                                                  closes=past),
        "homework, closed, worked solutions": exam_copy(
            exam_dir, tmp_path / "solved", mode="homework", feedback="immediate",
            solutions="after-close", closes=past),
        "practice, open": exam_copy(exam_dir, tmp_path / "practice", mode="practice",
                                    feedback="immediate"),
        "exam, before opening": exam_copy(exam_dir, tmp_path / "early", mode="exam",
                                          opens=dt.datetime(2099, 1, 1, tzinfo=UTC)),
    }
    for state, manifest in states.items():
        with served(manifest, tmp_path) as urls, chromium() as browser:
            page = browser.new_page()
            page.goto(urls["s3"])
            if "before" in state:
                expect(page.locator("form")).to_have_count(0)
                expect(page.locator("math")).to_have_count(0)
            if "solutions" in state:
                expect(page.locator(".solution")).to_have_count(2)
            assert_accessible(page, state)


def test_choice_parts_are_radio_buttons_and_checkboxes(tmp_path):
    from playwright.sync_api import expect

    from dynagrade.generation.generate import generate_exam
    from serve_support import ROSTER

    (tmp_path / "exam.toml").write_text(CHOICE_TOML, encoding="utf-8")
    (tmp_path / "roster.csv").write_text(ROSTER, encoding="utf-8")
    generate_exam(tmp_path / "exam.toml", tmp_path / "roster.csv", tmp_path / "out",
                  pdf=False, jobs=1, secret="5e" * 32)
    manifest = tmp_path / "out" / "manifest.json"
    with served(manifest, tmp_path) as urls, chromium() as browser:
        page = browser.new_page()
        page.goto(urls["s1"])
        free = page.locator("#degrees-of-freedom--free")
        expect(free.locator("input[type=radio]")).to_have_count(4)
        expect(page.locator("#degrees-of-freedom--reaction input[type=checkbox]")
               ).to_have_count(4)
        free.get_by_label("3").check()
        boxes = page.locator("#degrees-of-freedom--reaction input[type=checkbox]")
        boxes.nth(1).check()
        boxes.nth(2).check()
        assert_accessible(page, "choice parts, open")
        page.locator("#degrees-of-freedom button[type=submit]").click()
        expect(page.locator("#status")).to_contain_text("were saved")
        expect(free.get_by_label("3")).to_be_checked()
        expect(boxes.nth(1)).to_be_checked()
        expect(boxes.nth(2)).to_be_checked()
        expect(boxes.nth(0)).not_to_be_checked()
        free_table = page.locator("table.history", has_text="free particle")
        expect(free_table).to_contain_text("correct")
