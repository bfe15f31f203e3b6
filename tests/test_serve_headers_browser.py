"""The pages under their Content-Security-Policy in Debian's Chromium, served by a real
`dynagrade serve` (uvicorn): the browser refuses nothing, the stylesheets apply and the
scripts run; HEAD and an oversized streamed body are answered by the real server as by
the app (issue 26, item 5)."""

from __future__ import annotations

import pytest

from test_serve_browser import ARGS, CHROMIUM, running  # noqa: F401
from serve_support import exam_dir  # noqa: F401

pytestmark = pytest.mark.skipif(not CHROMIUM.exists(), reason="needs Chromium")


def test_every_page_kind_runs_its_scripts_and_styles_and_the_browser_refuses_nothing(running):
    from playwright.sync_api import expect, sync_playwright

    manifest, rows, staff = running
    base = staff.split("/i/")[0]
    pages = [rows[0]["url"], staff, *(f"{staff}/{tail}" for tail in (
        "exceptions", "regrade", "links", "audit", f"students/{rows[0]['student_id']}")),
        f"{base}/s/not-a-token", staff + "/report.html"]
    with sync_playwright() as playwright:
        browser = playwright.chromium.launch(executable_path=str(CHROMIUM), args=ARGS)
        try:
            page = browser.new_page()
            refused: list[str] = []
            page.on("console", lambda message: refused.append(message.text)
                    if "Content Security Policy" in message.text else None)
            for address in pages:
                page.goto(address)
                page.wait_for_load_state("networkidle")
                if not address.endswith("/report.html"):  # base.css: 60rem at 16 px
                    width = page.evaluate("getComputedStyle(document.body).maxWidth")
                    assert width == "960px", address
            assert refused == []
            page.goto(staff)  # staff.js ran: the search box and the pause button shown
            expect(page.locator("#find")).to_be_visible()
            expect(page.get_by_role("button", name="Pause updates")).to_be_visible()
            page.goto(rows[0]["url"])  # student.js ran: a preview fetched from the API
            page.locator("#projectile-range--x_max").fill("45 km")
            expect(page.locator("#projectile-range output[data-preview-for=x_max]")) \
                .to_contain_text("reads as 45 km")
            assert refused == []
        finally:
            browser.close()


def test_the_real_server_answers_head_and_refuses_a_long_streamed_body(running):
    import httpx

    from dynagrade.serve.limits import MAX_BODY_BYTES

    manifest, rows, staff = running
    page = httpx.get(staff)
    head = httpx.head(staff)
    assert head.status_code == page.status_code == 200 and head.content == b""
    assert head.headers["content-security-policy"] == page.headers["content-security-policy"]
    base = staff.split("/i/")[0]

    def chunks():
        for _ in range(MAX_BODY_BYTES // 4096 + 2):
            yield b"answer.x_max=" + b"1" * 4083

    refused = httpx.post(rows[0]["url"], content=chunks(),
                         headers={"Content-Type": "application/x-www-form-urlencoded"})
    assert refused.status_code == 413
    assert httpx.get(f"{base}/healthz").status_code == 200
