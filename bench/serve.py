"""Benchmark: a class submitting to `dynagrade serve` at once, and a crash in the middle.

Usage::

    PYTHONPATH=src python bench/serve.py                     # 20 students (CI)
    PYTHONPATH=src python bench/serve.py --students 500      # the target run
    PYTHONPATH=src python bench/serve.py --db postgresql://user@host/db

Builds the manifest of ``examples/exam.toml`` for N synthetic students (variants only, no
sheets), starts ``dynagrade serve`` on 127.0.0.1 with two workers and makes the links.
Wave 1: every student submits every exercise three times (right, off by 10 %, right
again), all students at once (``--concurrency`` requests in flight). Wave 2: the same
again; when a third of it is acknowledged the server is killed with SIGKILL (all its
processes), restarted, and every request that was not acknowledged is sent again with
its idempotency key. Then the database is checked against what was acknowledged.

Prints requests per second and the p50/p95/p99 latency of a submit (wave 1), and
``lost L doubled D``: L acknowledged submissions missing after the restart, D
submissions stored more than once. Exits non-zero when L or D is not 0.
"""

from __future__ import annotations

import argparse
import asyncio
import csv
import os
import signal
import subprocess
import sys
import tempfile
import time
import uuid
from dataclasses import replace
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent


def build_exam(folder: Path, students: int) -> Path:
    """The manifest of the example exam for ``students`` synthetic students."""
    from dynagrade.generation.generate import build_manifest, exercise_parts, load_exam
    from dynagrade.exam.manifest import StudentEntry, VariantEntry, dump
    from dynagrade.generation.variants import exam_variant
    from dynagrade.exercise.seeds import new_secret

    roster = folder / "roster.csv"
    roster.write_text("student_id,name\n" + "".join(
        f"b{n:04d},Student {n}\n" for n in range(1, students + 1)), encoding="utf-8")
    spec, people, exercises = load_exam(ROOT / "examples" / "exam.toml", roster)
    spec = replace(spec, secret=new_secret())
    parts = {item.id: exercise_parts(exercises[item.id], item.points) for item in spec.exercises}
    entries = []
    for person in people:
        variants = []
        for item in spec.exercises:
            variant, redraws = exam_variant(exercises[item.id], spec.secret, spec.id,
                                            person.student_id, item.set)
            variants.append(VariantEntry(item.id, variant.seed, variant.params,
                                         dict(variant.answers), redraws))
        entries.append(StudentEntry(person.student_id, person.name, person.email,
                                    tuple(variants)))
    path = folder / "manifest.json"
    dump(build_manifest(spec, exercises, parts, entries), path)
    return path


def class_with_links(folder: Path, students: int, db_url: str | None
                     ) -> tuple[Path, dict[str, str]]:
    """The example exam for ``students`` students (:func:`build_exam`) and each student's
    token (``dynagrade links``)."""
    manifest = build_exam(folder, students)
    subprocess.run([sys.executable, "-m", "dynagrade.cli", "links", str(manifest), "-o",
                    str(folder / "links.csv")] + (["--db", db_url] if db_url else []),
                   check=True, stdout=subprocess.DEVNULL)
    with open(folder / "links.csv", encoding="utf-8") as handle:
        return manifest, {r["student_id"]: r["url"].rsplit("/", 1)[1]
                          for r in csv.DictReader(handle)}


def server_arguments(parser: argparse.ArgumentParser, students: int) -> None:
    """The options of the class and its server, shared by the serve benchmarks."""
    parser.add_argument("--students", type=int, default=students)
    parser.add_argument("--workers", type=int, default=2)
    parser.add_argument("--grading-workers", type=int, default=1,
                        help="grading processes per server worker")
    parser.add_argument("--db", help="database URL (default: SQLite beside the manifest)")


def _answer_text(value, factor: float) -> str:
    if isinstance(value, tuple):
        return "(" + ", ".join(repr(v * factor) for v in value) + ")"
    if isinstance(value, float):
        return repr(value * factor)
    return str(value)


def plan(manifest_path: Path, tokens: dict[str, str], wave: str) -> list[dict]:
    """Three submits per student and exercise: right, 10 % off, right."""
    from dynagrade.exam.manifest import load

    manifest = load(manifest_path)
    requests = []
    for round_ in range(3):
        factor = 1.1 if round_ == 1 else 1.0
        for student in manifest.students:
            for variant in student.variants:
                requests.append({
                    "token": tokens[student.student_id], "key": f"{wave}-{uuid.uuid4().hex}",
                    "body": {"exercise": variant.exercise,
                             "answers": {k: _answer_text(v, factor)
                                         for k, v in variant.answers.items()}}})
    return requests


class Server:
    """``dynagrade serve`` in its own process group, so SIGKILL reaches every process."""

    def __init__(self, manifest: Path, port: int, db_url: str | None, workers: int,
                 grading_workers: int):
        self.command = [sys.executable, "-m", "dynagrade.cli", "serve", str(manifest),
                        "--port", str(port), "--workers", str(workers),
                        "--grading-workers", str(grading_workers)]
        if db_url:
            self.command += ["--db", db_url]
        self.url = f"http://127.0.0.1:{port}"
        self.process = None

    def start(self, log) -> None:
        self.process = subprocess.Popen(self.command, stdout=log, stderr=log,
                                        start_new_session=True)
        import httpx

        for _ in range(600):
            if self.process.poll() is not None:
                raise SystemExit(f"the server stopped at start; see {log.name}")
            try:
                if httpx.get(f"{self.url}/healthz", timeout=1).status_code == 200:
                    return
            except httpx.HTTPError:
                pass
            time.sleep(0.1)
        raise SystemExit("the server did not answer /healthz within 60 s")

    def kill(self) -> None:
        os.killpg(self.process.pid, signal.SIGKILL)
        self.process.wait()

    def stop(self) -> None:
        if self.process and self.process.poll() is None:
            os.killpg(self.process.pid, signal.SIGTERM)
            try:
                self.process.wait(timeout=20)
            except subprocess.TimeoutExpired:
                self.kill()


async def send_all(url: str, requests: list[dict], concurrency: int, acked: dict,
                   latencies: list, stop_after: int | None = None,
                   on_stop=None) -> None:
    """Send ``requests``; record acknowledged keys (200) and latencies. With
    ``stop_after``, call ``on_stop`` once that many are acknowledged."""
    import httpx

    queue = list(reversed(requests))
    stopped = asyncio.Event()

    async def worker(client):
        while queue and not stopped.is_set():
            request = queue.pop()
            started = time.perf_counter()
            try:
                response = await client.post(
                    f"{url}/api/v1/answers", json=request["body"], headers={
                        "Authorization": f"Bearer {request['token']}",
                        "Idempotency-Key": request["key"]})
            except httpx.HTTPError:
                continue
            if response.status_code == 200:
                latencies.append(time.perf_counter() - started)
                acked[request["key"]] = response.json()["attempt"]
                if stop_after is not None and len(acked) >= stop_after and not stopped.is_set():
                    stopped.set()
                    on_stop()

    limits = httpx.Limits(max_connections=concurrency)
    async with httpx.AsyncClient(timeout=60, limits=limits) as client:
        await asyncio.gather(*(worker(client) for _ in range(concurrency)))


def percentile(values: list[float], q: float) -> float:
    ordered = sorted(values)
    return ordered[min(len(ordered) - 1, int(round(q / 100 * (len(ordered) - 1))))]


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    server_arguments(parser, students=20)
    parser.add_argument("--concurrency", type=int, default=8,
                        help="requests in flight at once (the server is saturated at about 8 on 2 cores)")
    parser.add_argument("--port", type=int, default=0)
    args = parser.parse_args(argv)

    from dynagrade.serve import db
    from dynagrade.serve.exam_data import ExamData

    folder = Path(tempfile.mkdtemp(prefix="dynagrade-bench-serve-"))
    started = time.perf_counter()
    manifest, tokens = class_with_links(folder, args.students, args.db)
    print(f"exam for {args.students} students built in {time.perf_counter() - started:.1f} s")
    port = args.port or _free_port()
    server = Server(manifest, port, args.db, args.workers, args.grading_workers)
    log = open(folder / "server.log", "w")
    try:
        server.start(log)
        first = plan(manifest, tokens, "w1")
        acked1, latencies = {}, []
        began = time.perf_counter()
        asyncio.run(send_all(server.url, first, args.concurrency, acked1, latencies))
        elapsed = time.perf_counter() - began
        second = plan(manifest, tokens, "w2")
        acked2: dict = {}
        asyncio.run(send_all(server.url, second, args.concurrency, acked2, [],
                             stop_after=len(second) // 3, on_stop=server.kill))
        if server.process.poll() is None:
            server.kill()
        killed_after = len(acked2)
        server.start(log)
        retry = [r for r in second if r["key"] not in acked2]
        resent: dict = {}
        asyncio.run(send_all(server.url, retry, args.concurrency, resent, []))
    finally:
        server.stop()
        log.close()

    engine = db.connect(args.db or db.sqlite_url_beside(manifest))
    exam_id = ExamData(manifest).exam_id
    stored = db.idempotency_keys(engine, exam_id)
    stored_set = set(stored)
    acknowledged = {**acked1, **acked2}
    lost = sum(1 for key in acknowledged if key not in stored_set)
    doubled = len(stored) - len(stored_set)
    # every request was finally acknowledged once, so each (student, exercise) holds
    # exactly as many submissions as were sent for it
    missing_after_retry = len(first) + len(second) - len(stored)
    doubled += max(0, -missing_after_retry)
    print(f"wave 1: {len(first)} submits ({len(acked1)} acknowledged) in {elapsed:.1f} s: "
          f"{len(acked1) / elapsed:.1f} requests/s")
    print(f"submit latency: p50 {1000 * percentile(latencies, 50):.0f} ms, "
          f"p95 {1000 * percentile(latencies, 95):.0f} ms, "
          f"p99 {1000 * percentile(latencies, 99):.0f} ms")
    print(f"wave 2: killed (SIGKILL) after {killed_after} of {len(second)} acknowledged; "
          f"after the restart {len(resent)} of {len(retry)} resent were acknowledged; "
          f"{len(stored)} submissions stored for {len(first) + len(second)} sent")
    print(f"lost {lost} doubled {doubled}")
    print(f"(load average {os.getloadavg()[0]:.2f} on {os.cpu_count()} cores; {folder})")
    return 0 if lost == 0 and doubled == 0 and missing_after_retry == 0 else 1


def _free_port() -> int:
    import socket

    with socket.socket() as probe:
        probe.bind(("127.0.0.1", 0))
        return probe.getsockname()[1]


if __name__ == "__main__":
    sys.exit(main())
