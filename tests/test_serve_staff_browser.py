"""The staff page and the error pages in Debian's Chromium with axe-core: no violations
at phone and desktop widths, no sideways scrolling at 320 px, tables in focusable
labelled regions, and updates that never reload the page and can be paused (issue 24,
items 7 and 8; WCAG 1.4.10 and 2.2.1)."""

from __future__ import annotations

from pathlib import Path

import pytest

from test_serve_browser import ARGS, CHROMIUM, running  # noqa: F401
from serve_support import exam_dir  # noqa: F401

AXE = Path(__file__).resolve().parent.parent / ".cache" / "axe" / "node_modules" / \
    "axe-core" / "axe.min.js"

pytestmark = pytest.mark.skipif(not (CHROMIUM.exists() and AXE.exists()),
                                reason="needs Chromium and axe-core (npm install --prefix "
                                       ".cache/axe axe-core)")


def _violations(page) -> list[str]:
    """axe-core's violations on the page as it is. axe is evaluated by the browser's
    debugging protocol, not added as a script: the page's Content-Security-Policy runs
    only the server's own scripts, and would refuse an inline one."""
    page.evaluate(AXE.read_text(encoding="utf-8"))
    found = page.evaluate("async () => (await axe.run(document)).violations"
                          ".map(v => v.id + ': ' + v.nodes.map(n => n.target).join(' '))")
    return found


def test_staff_and_error_pages_pass_axe_and_fit_a_phone(running):
    from playwright.sync_api import sync_playwright

    manifest, rows, staff = running
    base = staff.split("/i/")[0]
    pages = {"staff": staff, "unknown link": f"{base}/s/not-a-token",
             "not found": f"{base}/nothing-here"}
    with sync_playwright() as playwright:
        browser = playwright.chromium.launch(executable_path=str(CHROMIUM), args=ARGS)
        try:
            for width in (320, 390, 1280):
                page = browser.new_page(viewport={"width": width, "height": 800})
                for name, url in pages.items():
                    page.goto(url)
                    assert page.locator("html").get_attribute("lang") == "en", name
                    assert page.title(), name
                    assert _violations(page) == [], (name, width)
                    wide = page.evaluate("document.documentElement.scrollWidth")
                    assert wide <= width, (name, width, wide)
                page.close()
        finally:
            browser.close()


def test_the_staff_page_updates_without_reloading_and_can_be_paused(running):
    from playwright.sync_api import sync_playwright

    manifest, rows, staff = running
    with sync_playwright() as playwright:
        browser = playwright.chromium.launch(executable_path=str(CHROMIUM), args=ARGS)
        try:
            page = browser.new_page(viewport={"width": 320, "height": 800})
            page.clock.install()
            page.goto(staff)
            assert page.locator("meta[http-equiv=refresh]").count() == 0
            for region in page.locator("[role=region]").all():
                assert region.get_attribute("tabindex") == "0"
                assert region.get_attribute("aria-labelledby")
            page.evaluate("window.stayed = true")  # gone if the page reloads
            with page.expect_response(lambda r: r.url.endswith("/tables")):
                page.clock.run_for(31_000)
            assert page.evaluate("window.stayed === true")
            button = page.get_by_role("button", name="Pause updates")
            button.click()
            assert page.get_by_role("status").inner_text() == "Updates paused."
            asked = []
            page.on("request", lambda r: asked.append(r.url) if r.url.endswith("/tables")
                    else None)
            page.clock.run_for(120_000)
            assert asked == []
            page.get_by_role("button", name="Resume updates").click()
            page.wait_for_timeout(500)
            assert asked  # resumed: asks at once
        finally:
            browser.close()
