"""No answer is lost when the staff move an exam's times (issue 24, item 1).

The reproduction: generate an exam, serve it, submit, re-run `dynagrade exam` to move
`closes`, restart. Before, the re-run swapped the folder holding the database: the
running server wrote to the moved file, a restart found an empty database (every link
401), a second re-run deleted the answers. Now the database lives beside the exam folder,
`dynagrade exam` refuses to replace a folder that is served or has a database, and
`dynagrade policy` moves `closes` without a new run, recorded in the audit log.
"""

from __future__ import annotations

import csv
import datetime as dt
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest
from click.testing import CliRunner

from serve_support import EXAM_TOML, ROSTER, free_port

CLI = [sys.executable, "-m", "dynagrade.cli"]


def _exam(folder: Path, closes: str) -> list[str]:
    (folder / "exam.toml").write_text(f'mode = "homework"\ncloses = {closes}\n' + EXAM_TOML,
                                      encoding="utf-8")
    (folder / "roster.csv").write_text(ROSTER, encoding="utf-8")
    return ["exam", str(folder / "exam.toml"), "--roster", str(folder / "roster.csv"), "-o",
            str(folder / "out"), "--no-pdf", "--jobs", "1"]


def _start(manifest: Path, port: int) -> subprocess.Popen:
    import httpx

    server = subprocess.Popen([*CLI, "serve", str(manifest), "--port", str(port),
                               "--grading-workers", "1"], start_new_session=True,
                              stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    for _ in range(300):
        try:
            if httpx.get(f"http://127.0.0.1:{port}/healthz", timeout=1).status_code == 200:
                return server
        except httpx.HTTPError:
            pass
        time.sleep(0.1)
    _stop(server)
    pytest.fail("the server did not start")


def _stop(server: subprocess.Popen) -> None:
    os.killpg(server.pid, signal.SIGTERM)
    server.wait(timeout=30)


def test_moving_closes_while_served_loses_nothing(tmp_path):
    import httpx

    from dynagrade.cli import main

    runner = CliRunner()
    made = runner.invoke(main, _exam(tmp_path, "2099-01-01T00:00:00Z"))
    assert made.exit_code == 0, made.output
    out = tmp_path / "out"
    manifest = out / "manifest.json"
    linked = runner.invoke(main, ["links", str(manifest), "-o", str(tmp_path / "links.csv"),
                                  "--instructor"])
    assert linked.exit_code == 0, linked.output
    staff = linked.output.strip().splitlines()[-1].split("/i/")[1]
    tokens = [row["url"].rsplit("/s/", 1)[1]
              for row in csv.DictReader((tmp_path / "links.csv").open())]
    assert not list(out.glob("*.sqlite3*"))  # the database is not in the exam folder
    assert (tmp_path / "out.serve.sqlite3").exists()
    port = free_port()
    base = f"http://127.0.0.1:{port}"
    server = _start(manifest, port)
    try:
        for token in tokens:
            sent = httpx.post(f"{base}/api/v1/answers", timeout=60,
                              headers={"Authorization": f"Bearer {token}"},
                              json={"exercise": "projectile-range",
                                    "answers": {"x_max": "12 m"}})
            assert sent.status_code == 200, sent.text
        before = manifest.read_bytes()
        # the old way to move closes: edit exam.toml and generate again -- refused
        rerun = runner.invoke(main, _exam(tmp_path, "2025-01-01T00:00:00Z"))
        assert rerun.exit_code != 0
        assert "dynagrade serve" in rerun.output and "dynagrade policy" in rerun.output
        assert manifest.read_bytes() == before and not (tmp_path / "out.previous").exists()
        # the new way: no new run, in force on the running server within seconds
        moved = runner.invoke(main, ["policy", str(manifest), "--closes",
                                     "2025-01-01T00:00:00+00:00", "--by", "ta@example.org"])
        assert moved.exit_code == 0, moved.output
        assert "closes: 2099-01-01T00:00:00+00:00 → 2025-01-01T00:00:00+00:00" in moved.output
        time.sleep(2.5)
        late = httpx.post(f"{base}/api/v1/answers", timeout=60,
                          headers={"Authorization": f"Bearer {tokens[0]}"},
                          json={"exercise": "projectile-range", "answers": {"x_max": "1 m"}})
        assert late.status_code == 403, late.text
    finally:
        _stop(server)
    # with the server stopped, the exam's database beside the folder still protects it
    again = runner.invoke(main, _exam(tmp_path, "2025-01-01T00:00:00Z"))
    assert again.exit_code != 0 and "out.serve.sqlite3" in again.output
    server = _start(manifest, port)
    try:
        for token in tokens:  # every link still works after the restart
            assert httpx.get(f"{base}/s/{token}", timeout=60).status_code == 200
        book = httpx.get(f"{base}/api/v1/gradebook", timeout=60,
                         headers={"Authorization": f"Bearer {staff}"}).json()
        assert [row["status"] for row in book["rows"]] == ["incomplete"] * 3
    finally:
        _stop(server)
    shown = runner.invoke(main, ["policy", str(manifest)])
    assert "closes = 2025-01-01T00:00:00+00:00" in shown.output
    assert "by ta@example.org" in shown.output


def test_exam_refuses_a_folder_holding_a_database(tmp_path):
    from dynagrade.cli import main

    runner = CliRunner()
    assert runner.invoke(main, _exam(tmp_path, "2099-01-01T00:00:00Z")).exit_code == 0
    (tmp_path / "out" / "serve.sqlite3").write_bytes(b"answers of an earlier version")
    rerun = runner.invoke(main, _exam(tmp_path, "2099-01-02T00:00:00Z"))
    assert rerun.exit_code != 0 and "holds a database (serve.sqlite3)" in rerun.output
    assert (tmp_path / "out" / "serve.sqlite3").read_bytes() == b"answers of an earlier version"


def test_a_mark_left_by_a_killed_server_does_not_block(tmp_path):
    from dynagrade.runs.outputs import SERVING_MARK, refuse_if_in_use, serving_pid
    from dynagrade.serve.location import serving

    folder = tmp_path / "out"
    folder.mkdir()
    with serving(folder):
        assert serving_pid(folder) == os.getpid()
        with pytest.raises(Exception, match="is serving this exam"):
            refuse_if_in_use(folder)
    assert (folder / SERVING_MARK).exists() and serving_pid(folder) is None
    refuse_if_in_use(folder)  # no server holds it: a new run may replace the folder


def test_a_database_at_the_old_place_is_used_where_it_is_with_a_warning(tmp_path, exam_dir):
    from serve_support import exam_copy

    from dynagrade.cli import main
    from dynagrade.serve import db
    from dynagrade.serve.location import database_notices, default_database

    manifest = exam_copy(exam_dir, tmp_path / "old")
    old = tmp_path / "old" / "serve.sqlite3"
    engine = db.connect(f"sqlite:///{old}")
    db.issue_staff_token(engine, "serve-test")
    engine.dispose()
    assert default_database(manifest) == old
    assert "used where it is" in database_notices(manifest)[0]
    linked = CliRunner().invoke(main, ["links", str(manifest), "-o",
                                       str(tmp_path / "links.csv")])
    assert linked.exit_code == 0 and "warning: the database" in linked.output
    assert not (tmp_path / "old.serve.sqlite3").exists()


from serve_support import exam_dir  # noqa: E402,F401  (the session's generated exam)
