"""A server that is stopped leaves nothing running (issue 26, item 3): after a clean
SIGTERM to ``dynagrade serve``, with one server process or several, no process it
started (server workers, grading processes) is still alive."""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from serve_support import exam_copy, exam_dir, free_port  # noqa: F401


def _children() -> dict[int, int]:
    """Every process's parent, by process id (from /proc)."""
    parents = {}
    for entry in Path("/proc").iterdir():
        if not entry.name.isdigit():
            continue
        try:
            fields = (entry / "stat").read_text().rsplit(")", 1)[1].split()
        except OSError:
            continue
        parents[int(entry.name)] = int(fields[1])
    return parents


def _descendants(pid: int) -> set[int]:
    parents, found, frontier = _children(), set(), {pid}
    while frontier:
        frontier = {child for child, parent in parents.items() if parent in frontier} - found
        found |= frontier
    return found


def _command(pid: int) -> str:
    try:
        return Path(f"/proc/{pid}/cmdline").read_bytes().replace(b"\0", b" ").decode()[:120]
    except OSError:
        return ""


def _helpers(pids: set[int]) -> set[int]:
    """The processes of ``pids`` that are multiprocessing's helpers, a resource tracker or
    a fork server, not the grading processes forked from a fork server (which carry its
    command line)."""
    parents = _children()
    helper = ("multiprocessing.resource_tracker", "multiprocessing.forkserver")
    return {p for p in pids if any(h in _command(p) for h in helper)
            and not any(h in _command(parents.get(p, 0)) for h in helper)}


def _alive(pid: int) -> bool:
    try:
        state = Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()[0]
    except OSError:
        return False
    return state != "Z"


@pytest.mark.skipif(not Path("/proc/self/stat").exists(), reason="needs /proc (Linux)")
@pytest.mark.parametrize("workers", [1, 2])
def test_a_clean_sigterm_leaves_no_process_of_the_server_running(exam_dir, tmp_path, workers):
    import httpx

    manifest = exam_copy(exam_dir, tmp_path / "exam")
    port = free_port()
    server = subprocess.Popen([sys.executable, "-m", "dynagrade.cli", "serve", str(manifest),
                               "--port", str(port), "--workers", str(workers),
                               "--grading-workers", "2"], start_new_session=True,
                              stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    try:
        for _ in range(300):
            try:
                if httpx.get(f"http://127.0.0.1:{port}/healthz", timeout=1).status_code == 200:
                    break
            except httpx.HTTPError:
                time.sleep(0.1)
        else:
            pytest.fail("the server did not start")
        time.sleep(3)  # every worker up, with its grading processes warmed up
        started = _descendants(server.pid)
        # each server process has its grading processes (and multiprocessing's helper)
        assert len(started) >= workers * 2, started
        server.send_signal(signal.SIGTERM)
        server.wait(timeout=60)
        # when the command has ended, so has every process it started; only
        # multiprocessing's helpers, its resource tracker and the grading processes' fork
        # server, end after it (each waits for its parent's pipe to close), and within
        # a moment
        helpers = _helpers(started)
        assert [(p, _command(p)) for p in started - helpers
                if _alive(p) and _command(p)] == []  # (no command line: its memory is gone)
        deadline = time.monotonic() + 5
        while time.monotonic() < deadline and any(_alive(p) for p in started):
            time.sleep(0.1)
        assert [(p, _command(p)) for p in started if _alive(p)] == []
    finally:
        if server.poll() is None:
            os.killpg(server.pid, signal.SIGKILL)
        for pid in _descendants(server.pid):
            try:
                os.kill(pid, signal.SIGKILL)
            except OSError:
                pass
