"""Staff links and the audit log in Debian's Chromium with axe-core (issue 25, items 5
and 7): a TA revokes another's link from the page, a link revoked on the command line is
refused by the running server within 30 seconds, and the links and audit pages pass axe
in each state and fit a 320 px phone."""

from __future__ import annotations

import subprocess
import sys
import time

import pytest

from test_serve_browser import ARGS, CHROMIUM, running  # noqa: F401
from test_serve_staff_browser import AXE, _violations
from serve_support import exam_dir  # noqa: F401

pytestmark = pytest.mark.skipif(not (CHROMIUM.exists() and AXE.exists()),
                                reason="needs Chromium and axe-core (npm install --prefix "
                                       ".cache/axe axe-core)")


def _links(manifest, *arguments) -> str:
    done = subprocess.run([sys.executable, "-m", "dynagrade.cli", "links", str(manifest),
                           *arguments], check=True, capture_output=True, text=True)
    return done.stdout


def _checked(page, name: str, width: int) -> None:
    assert _violations(page) == [], (name, width)
    wide = page.evaluate("document.documentElement.scrollWidth")
    assert wide <= width, (name, width, wide)


def test_a_ta_makes_and_revokes_links_on_pages_that_pass_axe(running, tmp_path):
    from playwright.sync_api import expect, sync_playwright

    manifest, _rows, staff = running
    with sync_playwright() as playwright:
        browser = playwright.chromium.launch(executable_path=str(CHROMIUM), args=ARGS)
        try:
            page = browser.new_page(viewport={"width": 320, "height": 800})
            page.goto(staff)
            page.get_by_role("link", name="Staff links").click()
            expect(page.get_by_role("heading", level=1)).to_contain_text("Staff links")
            _checked(page, "links", 320)
            page.get_by_label("Name of its holder").fill("Gil (TA)")
            page.get_by_role("button", name="Make a staff link").click()
            made = page.locator("#new-link").inner_text()
            _checked(page, "links, a new link", 320)
            page.get_by_label("Name of its holder").fill("z" * 101)
            page.get_by_role("button", name="Make a staff link").click()
            expect(page.get_by_role("alert")).to_contain_text("at most 100")
            _checked(page, "links, refused", 320)

            gil = browser.new_page(viewport={"width": 1280, "height": 800})
            gil.goto(made)
            expect(gil.get_by_role("heading", level=1)).to_contain_text("staff")
            page.goto(staff + "/links")
            page.get_by_role("button", name="Revoke Gil (TA)").click()
            expect(page.get_by_role("status").first).to_contain_text("Revoked")
            assert gil.goto(made).status == 401

            page.get_by_role("link", name="Audit log").click()
            rows = page.locator("#audit tbody tr")
            expect(rows).to_have_count(3)  # the first link made, Gil's made, then revoked
            assert "Gil (TA)" in rows.first.inner_text()
            for width in (320, 1280):
                page.set_viewport_size({"width": width, "height": 800})
                _checked(page, "audit", width)
            page.get_by_label("Show").select_option("staff-link")
            page.get_by_role("button", name="Show").click()
            expect(rows).to_have_count(3)
            _checked(page, "audit, filtered", 1280)
        finally:
            browser.close()


def test_a_link_revoked_on_the_command_line_is_refused_within_30_seconds(running):
    import httpx

    from dynagrade.serve import db, links

    manifest, _rows, staff = running
    base = staff.split("/i/")[0]
    made = _links(manifest, "--instructor", "--name", "Hal", "--base-url", base,
                  "-o", str(manifest.parent / "again.csv"))
    hal = made.split("staff link: ")[1].strip()
    assert httpx.get(hal).status_code == 200  # seen: the server now remembers the token
    _links(manifest, "--revoke-staff", db.link_id(hal.rsplit("/i/", 1)[1]))
    revoked_at = time.monotonic()
    while httpx.get(hal).status_code != 401:
        assert time.monotonic() - revoked_at <= links.REVOKED_WITHIN + 1
        time.sleep(1)
    assert httpx.get(staff).status_code == 200  # the other staff link still works
