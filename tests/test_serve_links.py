"""`dynagrade links`, and the kill -9 guarantee of a running `dynagrade serve`."""

from __future__ import annotations

import csv
import io
import os
import signal
import subprocess
import sys
import time

import pytest
from click.testing import CliRunner

from dynagrade.cli import main
from serve_support import exam_copy, exam_dir, free_port  # noqa: F401


def _links(manifest, out, *extra):
    result = CliRunner().invoke(main, ["links", str(manifest), "-o", str(out), *extra])
    assert result.exit_code == 0, result.output
    return result, {r["student_id"]: r for r in csv.DictReader(io.StringIO(out.read_text()))}


def test_links_are_kept_on_rerun_and_replaced_with_rotate(exam_dir, tmp_path):
    manifest = exam_copy(exam_dir, tmp_path / "exam")
    out = tmp_path / "links.csv"
    _, first = _links(manifest, out, "--base-url", "https://exams.example.org/dyn")
    assert list(first) == ["s1", "s2", "s3"]
    assert first["s2"]["name"] == "Bo Two" and first["s2"]["email"] == "bo@example.org"
    assert all(r["url"].startswith("https://exams.example.org/dyn/s/") for r in first.values())
    assert len({r["url"] for r in first.values()}) == 3
    assert oct(out.stat().st_mode & 0o777) == "0o600"
    _, again = _links(manifest, out, "--base-url", "https://exams.example.org/dyn")
    assert again == first
    _, rotated = _links(manifest, out, "--rotate")
    assert not {r["url"].rsplit("/", 1)[1] for r in rotated.values()} & \
        {r["url"].rsplit("/", 1)[1] for r in first.values()}
    # the old links no longer open anything
    from dynagrade.serve import db

    engine = db.connect(db.sqlite_url_beside(manifest))
    old = first["s1"]["url"].rsplit("/", 1)[1]
    assert db.identify(engine, "serve-test", old) is None
    assert db.identify(engine, "serve-test", rotated["s1"]["url"].rsplit("/", 1)[1]) \
        == db.Identity("student", "s1")


def test_links_without_the_earlier_file_say_why_a_url_is_empty(exam_dir, tmp_path):
    manifest = exam_copy(exam_dir, tmp_path / "exam")
    _links(manifest, tmp_path / "a.csv")
    result, rows = _links(manifest, tmp_path / "b.csv", "--instructor")
    assert all(r["url"] == "" for r in rows.values())
    assert "--rotate" in result.output and "3 students" in result.output
    assert "staff link: http://127.0.0.1:8000/i/" in result.output


def test_a_bad_database_url_is_a_message_not_a_traceback(exam_dir, tmp_path):
    manifest = exam_copy(exam_dir, tmp_path / "exam")
    result = CliRunner().invoke(main, ["links", str(manifest), "--db",
                                       "postgresql://nobody@127.0.0.1:1/none"])
    assert result.exit_code != 0 and "cannot open the database" in result.output
    assert "Traceback" not in result.output


def test_acknowledged_submissions_survive_kill_9_and_none_is_doubled(exam_dir, tmp_path):
    import httpx

    manifest = exam_copy(exam_dir, tmp_path / "exam")
    _, links = _links(manifest, tmp_path / "links.csv")
    tokens = {s: r["url"].rsplit("/", 1)[1] for s, r in links.items()}
    port = free_port()
    command = [sys.executable, "-m", "dynagrade.cli", "serve", str(manifest), "--port",
               str(port), "--grading-workers", "1"]
    url = f"http://127.0.0.1:{port}"

    def start():
        server = subprocess.Popen(command, start_new_session=True,
                                  stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        for _ in range(300):
            try:
                if httpx.get(f"{url}/healthz", timeout=1).status_code == 200:
                    return server
            except httpx.HTTPError:
                time.sleep(0.1)
        server.kill()
        pytest.fail("the server did not start")

    sent = [(s, f"key-{s}-{n:03d}") for n in range(12) for s in tokens]
    acknowledged = {}
    server = start()
    try:
        with httpx.Client(timeout=30) as client:
            for number, (student, key) in enumerate(sent):
                if number == len(sent) // 2:
                    os.killpg(server.pid, signal.SIGKILL)  # no chance to flush anything
                    server.wait()
                    server = start()
                try:
                    response = client.post(f"{url}/api/v1/answers", json={
                        "exercise": "projectile-range", "answers": {"x_max": f"{number} m"}},
                        headers={"Authorization": f"Bearer {tokens[student]}",
                                 "Idempotency-Key": key})
                except httpx.HTTPError:
                    continue
                if response.status_code == 200:
                    acknowledged[key] = response.json()["attempt"]
            # a client that lost its responses sends everything again
            for student, key in sent:
                client.post(f"{url}/api/v1/answers", json={
                    "exercise": "projectile-range", "answers": {"x_max": "0 m"}},
                    headers={"Authorization": f"Bearer {tokens[student]}",
                             "Idempotency-Key": key})
    finally:
        os.killpg(server.pid, signal.SIGKILL)
        server.wait()
    from dynagrade.serve import db

    engine = db.connect(db.sqlite_url_beside(manifest))
    stored = db.all_answers(engine, "serve-test")
    keys = db.idempotency_keys(engine, "serve-test")
    assert len(keys) == len(set(keys)) == len(sent)
    assert set(acknowledged) <= set(keys)
    # each student's attempts are numbered 1..12 without gaps or repeats
    for student in tokens:
        assert sorted(a.attempt for a in stored if a.student_id == student) == \
            list(range(1, 13))
    # an acknowledged submit kept the answer it was acknowledged with, not the resend's
    first_answers = {a.attempt: a.raw for a in stored if a.student_id == "s1"}
    assert sum(raw != "0 m" for raw in first_answers.values()) >= 6
