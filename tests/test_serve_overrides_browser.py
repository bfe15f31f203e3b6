"""Points by hand and the student's staff page in Debian's Chromium (issue 25, "Done
when"): a TA sets points with a comment on the student's staff page, the student sees
them with the comment in their feedback and grades.csv holds them; removed, both go back.
axe-core on every state of the pages (before and after an override, a refused form, the
overview with a sorted and filtered gradebook), no sideways scrolling at 320 px.
"""

from __future__ import annotations

import csv
import io

import pytest

from serve_support import exam_copy, exam_dir, serving_process  # noqa: F401
from test_serve_browser import ARGS, CHROMIUM
from test_serve_staff_browser import AXE, _violations
from test_serve_student_browser import chromium

pytestmark = pytest.mark.skipif(not (CHROMIUM.exists() and AXE.exists()),
                                reason="needs Chromium and axe-core (npm install --prefix "
                                       ".cache/axe axe-core)")

NOTE = "Points set by the staff: 1.5 (graded 0): sign slip only, method right"


@pytest.fixture(scope="module")
def served(exam_dir, tmp_path_factory):
    """A homework exam (verdicts shown) where Ada (s1) answered x_max wrong and Bo (s2)
    right: (base url, links rows by student, staff url). One server for the module: each
    test leaves the points set by hand as it found them."""
    tmp_path = tmp_path_factory.mktemp("overrides")
    import httpx

    from dynagrade.exam.manifest import load

    manifest = exam_copy(exam_dir, tmp_path / "hw", mode="homework", feedback="immediate")
    records = {s.student_id: s for s in load(manifest).students}
    with serving_process(manifest, tmp_path / "links.csv") as (base, rows, staff):
        links = {row["student_id"]: row["url"] for row in rows}
        for student, factor in (("s1", 2), ("s2", 1)):
            right = records[student].variant("projectile-range").answers["x_max"]
            reply = httpx.post(f"{base}/api/v1/answers", json={
                "exercise": "projectile-range", "answers": {"x_max": repr(factor * right)}},
                headers={"Authorization": f"Bearer {links[student].rsplit('/', 1)[1]}"})
            assert reply.status_code == 200, reply.text
        yield base, links, staff


def _grades(base: str, staff: str) -> dict[str, dict[str, str]]:
    import httpx

    token = staff.rsplit("/", 1)[1]
    text = httpx.get(f"{base}/api/v1/grades.csv",
                     headers={"Authorization": f"Bearer {token}"}).text
    return {row["student_id"]: row for row in csv.DictReader(io.StringIO(text))}


def _fits(page, width: int) -> None:
    assert page.evaluate("document.documentElement.scrollWidth") <= width


def test_a_ta_sets_points_the_student_sees_them_and_removing_restores_them(served):
    from playwright.sync_api import expect

    base, links, staff = served
    assert _grades(base, staff)["s1"]["projectile-range"] == "0"
    with chromium() as browser:
        page = browser.new_page(viewport={"width": 320, "height": 800})
        page.goto(staff)
        page.get_by_role("link", name="s1", exact=True).first.click()
        expect(page.locator("h1")).to_contain_text("Ada One")
        assert _violations(page) == []
        _fits(page, 320)
        part = page.locator("form", has=page.locator("#projectile-range--x_max--points"))
        part.get_by_label("Points by hand").fill("1.5")
        part.get_by_label("Comment").fill("sign slip only, method right")
        part.get_by_role("button", name="Set the points").click()
        expect(page.locator("p.notice")).to_contain_text(
            "Points set by hand: 1.5 of 2.4 (graded 0)")
        assert _violations(page) == []
        _fits(page, 320)
        assert _grades(base, staff)["s1"]["projectile-range"] == "1.5"

        student = browser.new_page(viewport={"width": 320, "height": 800})
        student.goto(links["s1"])
        note = student.locator("#projectile-range--x_max--staff")
        expect(note).to_have_text(NOTE)
        expect(student.locator("#projectile-range--x_max--hint")).to_contain_text(
            "counted: 1.5 of 2.4 points")

        with page.expect_navigation():  # the form posts, the page comes back (303)
            page.get_by_role("button", name="Remove the points set by hand").click()
        expect(page.locator("p.notice")).to_have_count(0)
        assert _grades(base, staff)["s1"]["projectile-range"] == "0"
        student.reload()
        expect(student.locator("#projectile-range--x_max--staff")).to_have_count(0)
        expect(student.locator("body")).not_to_contain_text("Points set by the staff")


def test_a_refused_form_shows_the_reason_and_passes_axe(served):
    from playwright.sync_api import expect

    base, links, staff = served
    with chromium() as browser:
        for width in (320, 1280):
            page = browser.new_page(viewport={"width": width, "height": 800})
            page.goto(f"{staff}/students/s1")
            field = page.locator("#projectile-range--h_max--points")
            field.fill("0.3333")
            page.locator("form", has=field).get_by_role(
                "button", name="Set the points").click()
            reason = page.locator("#projectile-range--h_max--reason")
            expect(reason).to_contain_text("is not one of the exam's multiples of 0.01")
            expect(field).to_have_value("0.3333")
            expect(field).to_have_attribute("aria-invalid", "true")
            assert _violations(page) == [], width
            _fits(page, width)
            page.close()


def test_the_gradebook_sorts_filters_and_keeps_both_across_a_refresh(served):
    from playwright.sync_api import expect

    base, links, staff = served
    with chromium() as browser:
        page = browser.new_page(viewport={"width": 320, "height": 800})
        page.clock.install()
        page.goto(staff)
        book = page.locator("table.gradebook")
        ids = lambda: book.locator("tbody tr:not([hidden]) td:first-child").all_inner_texts()  # noqa: E731
        assert ids() == ["s1", "s2", "s3"]  # roster order
        total = book.get_by_role("button", name="total", exact=True)
        total.click()  # s1 0, s2 2.4, s3 absent (—, last)
        header = book.locator("th", has=page.get_by_role("button", name="total",
                                                         exact=True))
        expect(header).to_have_attribute("aria-sort", "ascending")
        assert ids() == ["s1", "s2", "s3"]
        total.click()
        expect(header).to_have_attribute("aria-sort", "descending")
        assert ids() == ["s3", "s2", "s1"]  # blanks last ascending, first descending
        name = book.get_by_role("button", name="name", exact=True)
        name.click()
        expect(header).not_to_have_attribute("aria-sort", "descending")
        assert ids() == ["s1", "s2", "s3"]  # Ada, Bo, Cy
        page.get_by_label("Find a student").fill("bo@")
        expect(page.locator("#find-count")).to_have_text("Showing 1 of 3 students")
        assert ids() == ["s2"]
        assert _violations(page) == []
        _fits(page, 320)
        name.click()  # descending, filter still on
        with page.expect_response(lambda r: r.url.endswith("/tables")):
            page.clock.run_for(31_000)
        page.wait_for_timeout(200)
        assert ids() == ["s2"]
        page.get_by_label("Find a student").fill("")
        assert ids() == ["s3", "s2", "s1"]  # Cy, Bo, Ada: the sort survived
        expect(page.locator("#find-count")).to_have_text("Showing 3 of 3 students")
        assert _violations(page) == []


def test_without_javascript_the_gradebook_is_a_plain_table_with_links(served):
    base, links, staff = served
    with chromium() as browser:
        page = browser.new_page(java_script_enabled=False)
        page.goto(staff)
        assert page.locator("#find").is_hidden()
        assert page.locator("table.gradebook th button").count() == 0
        page.locator("table.gradebook a", has_text="s2").click()
        assert page.locator("h1").inner_text().startswith("Bo Two")
