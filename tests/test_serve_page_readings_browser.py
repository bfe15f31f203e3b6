"""The student page in Chromium against a real `dynagrade serve` (issue 28, item 1): a page
with filled boxes sends no preview request on load (before, every load previewed every
filled box: half of a class's requests) and shows how each answer reads; typing asks."""

from __future__ import annotations

import pytest

from serve_support import exam_copy, exam_dir, serving_process  # noqa: F401
from test_serve_browser import CHROMIUM
from test_serve_student_browser import AXE, assert_accessible, chromium

pytestmark = pytest.mark.skipif(not (CHROMIUM.exists() and AXE.exists()),
                                reason="needs Chromium (apt-get install chromium) and axe-core "
                                       "(npm install --prefix .cache/axe axe-core)")


def test_a_page_load_sends_no_preview_and_shows_the_reading(exam_dir, tmp_path):
    import httpx
    from playwright.sync_api import expect

    manifest = exam_copy(exam_dir, tmp_path / "exam", mode="homework")
    with serving_process(manifest, tmp_path / "links.csv", instructor=False) as (
            base, rows, _staff):
        url = rows[0]["url"]
        bearer = {"Authorization": f"Bearer {url.rsplit('/', 1)[1]}"}
        # a counted answer and a draft: both shown in their boxes on load
        assert httpx.post(f"{base}/api/v1/answers", headers=bearer, json={
            "exercise": "projectile-range", "answers": {"x_max": "45 km"}}).status_code == 200
        assert httpx.put(f"{base}/api/v1/drafts", headers=bearer, json={
            "exercise": "sliding-up-a-slope", "answers": {"delta_x": "3 kg"}}
            ).status_code == 200
        with chromium() as browser:
            page = browser.new_page()
            previews: list[str] = []
            page.on("request", lambda request: previews.append(request.url)
                    if request.url.endswith("/api/v1/preview") else None)
            page.goto(url)
            page.wait_for_load_state("networkidle")
            counted = page.locator("#projectile-range--x_max--preview")
            expect(counted).to_have_text("reads as 45 km = 4.5e4 m")
            draft = page.locator("#sliding-up-a-slope--delta_x--preview")
            expect(draft).to_contain_text("expected a length")
            expect(page.locator("#sliding-up-a-slope--delta_x")).to_have_attribute(
                "aria-invalid", "true")
            assert previews == []  # the load asked for nothing
            assert_accessible(page, "readings on load, one answer unreadable")
            page.reload()
            page.wait_for_load_state("networkidle")
            assert previews == []
            # typing still asks, and the answer replaces the page's reading
            page.locator("#projectile-range--x_max").fill("2 km")
            expect(counted).to_contain_text("reads as 2 km =")
            assert len(previews) == 1
