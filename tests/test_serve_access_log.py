"""`dynagrade serve`'s access log (issue 28, item 2): off unless asked for with
``--access-log`` (at a class's rate it costs CPU that submits need), and when on, a
request's line shows a link's token as the start of its hash, never the token."""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import time

import pytest

from serve_support import exam_copy, exam_dir, free_port  # noqa: F401


def _served_log(manifest, tmp_path, *flags: str) -> tuple[str, str]:
    """The server's standard error after one page request, and the page's token."""
    import httpx

    from dynagrade.serve import db
    from dynagrade.serve.exam_data import ExamData

    data = ExamData(manifest)
    engine = db.connect(db.sqlite_url_beside(manifest))
    token = db.issue_tokens(engine, data.exam_id, ["s1"], rotate=True)["s1"]
    engine.dispose()
    port = free_port()
    log = tmp_path / f"server{len(flags)}.log"
    with open(log, "w") as handle:
        server = subprocess.Popen([sys.executable, "-m", "dynagrade.cli", "serve", str(manifest),
                                   "--port", str(port), "--grading-workers", "1", *flags],
                                  start_new_session=True, stdout=handle, stderr=handle)
        try:
            for _ in range(300):
                try:
                    if httpx.get(f"http://127.0.0.1:{port}/healthz").status_code == 200:
                        break
                except httpx.HTTPError:
                    time.sleep(0.1)
            else:
                pytest.fail("the server did not start")
            assert httpx.get(f"http://127.0.0.1:{port}/s/{token}").status_code == 200
        finally:
            os.killpg(server.pid, signal.SIGTERM)
            server.wait(timeout=30)
    return log.read_text(encoding="utf-8"), token


def test_the_access_log_is_off_unless_asked_for_and_then_tokenless(exam_dir, tmp_path):
    from dynagrade.serve import db

    manifest = exam_copy(exam_dir, tmp_path / "exam")
    quiet, token = _served_log(manifest, tmp_path)
    assert "GET /s/" not in quiet and "/healthz" not in quiet
    assert token not in quiet
    logged, token = _served_log(manifest, tmp_path, "--access-log")
    assert f'"GET /s/{db.link_id(token)}… HTTP/1.1" 200' in logged
    assert token not in logged
