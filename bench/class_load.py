"""Benchmark: a class working on `dynagrade serve` the way students do, for a while.

Usage::

    PYTHONPATH=src python bench/class_load.py                        # 50 students, 20 s (CI)
    PYTHONPATH=src python bench/class_load.py --students 1000 --seconds 180 --scale 1

Builds the example exam (``examples/exam.toml``, variants only) for N students, starts
``dynagrade serve`` with two workers on SQLite (or ``--db``) and lets every student work:
open their page, then exercise after exercise think 10-30 s, type each answer (a preview
at each pause: half the answer, then all of it), have the draft saved, submit (right or
10 % off), and reload the page after every third submit. ``--scale`` divides every
think and typing time, so that a short run sees as many submits per student as a long
one (the default, 5, makes 2-6 s of thinking). A monitor asks ``/healthz`` each second.

The client is plain asyncio (HTTP/1.1 with keep-alive, a connection per student, as a
browser keeps one), so that its own CPU, printed, stays small beside the server's.

Prints per request kind (page, preview, draft, submit, healthz) the count, p50/p95/p99
latency and the 5xx; the server's CPU over the run (all its processes, from /proc) per
request; then, in a short calibration with one kind of request at a time, the server's
CPU per request of each kind (``--rounds R``: the kinds in turn R times, the median and
the range printed, since a shared machine's other work shows in any one round). Exits non-zero when any request got a 5xx (but for previews
shed with 503 while the graders are busy, as the server is meant to) or no answer.
"""

from __future__ import annotations

import argparse
import asyncio
import html
import json
import os
import random
import re
import statistics
import sys
import tempfile
import time
import uuid
from collections import defaultdict
from dataclasses import dataclass, field
from pathlib import Path
from urllib.parse import urlsplit

sys.path.insert(0, str(Path(__file__).resolve().parent))
from serve import (Server, _answer_text, _free_port, class_with_links,  # noqa: E402
                   percentile, server_arguments)

KINDS = ("page", "preview", "draft", "submit", "healthz")
#: uvicorn closes a connection idle for 5 s; the client opens a new one before that
IDLE_SECONDS = 4.0


class Connection:
    """One keep-alive HTTP/1.1 connection, as a browser tab holds it (opened again after
    :data:`IDLE_SECONDS` without a request)."""

    def __init__(self, host: str, port: int):
        self.host, self.port = host, port
        self.reader: asyncio.StreamReader | None = None
        self.writer: asyncio.StreamWriter | None = None
        self.used = 0.0

    async def request(self, method: str, path: str, headers: dict[str, str],
                      body: bytes = b"") -> tuple[int, bytes]:
        if self.writer is None or time.monotonic() - self.used > IDLE_SECONDS:
            self.close()
            self.reader, self.writer = await asyncio.open_connection(self.host, self.port)
        lines = [f"{method} {path} HTTP/1.1", f"Host: {self.host}:{self.port}",
                 f"Content-Length: {len(body)}", *(f"{k}: {v}" for k, v in headers.items())]
        assert self.writer is not None and self.reader is not None
        self.writer.write(("\r\n".join(lines) + "\r\n\r\n").encode() + body)
        try:
            head = await self.reader.readuntil(b"\r\n\r\n")
            status = int(head.split(b" ", 2)[1])
            fields = dict(line.split(b":", 1) for line in head.split(b"\r\n")[1:] if b":" in line)
            fields = {k.strip().lower(): v.strip() for k, v in fields.items()}
            if fields.get(b"transfer-encoding") == b"chunked":
                content = await self._chunks()
            else:
                content = await self.reader.readexactly(int(fields.get(b"content-length", 0)))
        except Exception:
            self.close()
            raise
        if fields.get(b"connection") == b"close":
            self.close()
        self.used = time.monotonic()
        return status, content

    async def _chunks(self) -> bytes:
        assert self.reader is not None
        content = b""
        while True:
            size = int((await self.reader.readuntil(b"\r\n")).strip(), 16)
            content += (await self.reader.readexactly(size + 2))[:size]
            if size == 0:
                return content

    def close(self) -> None:
        if self.writer is not None:
            self.writer.close()
        self.reader = self.writer = None


@dataclass
class Record:
    """What the client saw: latencies and status codes per kind of request."""

    latencies: dict[str, list[float]] = field(default_factory=lambda: defaultdict(list))
    statuses: dict[str, dict[int, int]] = field(
        default_factory=lambda: defaultdict(lambda: defaultdict(int)))
    failed: dict[str, int] = field(default_factory=lambda: defaultdict(int))

    async def send(self, kind: str, connection: Connection, method: str, path: str,
                   headers: dict[str, str], payload=None) -> str:
        """Send a request and record it; the body's text ("" when it failed)."""
        body = json.dumps(payload).encode() if payload is not None else b""
        if payload is not None:
            headers = {**headers, "Content-Type": "application/json"}
        started = time.perf_counter()
        try:
            status, _content = await connection.request(method, path, headers, body)
        except (OSError, asyncio.IncompleteReadError, ValueError):
            self.failed[kind] += 1
            return ""
        self.latencies[kind].append(time.perf_counter() - started)
        self.statuses[kind][status] += 1
        return _content.decode("utf-8", "replace")

    def count(self) -> int:
        return sum(len(v) for v in self.latencies.values())


@dataclass(frozen=True)
class Work:
    """One exercise as a student answers it: the texts to submit and which parts are
    typed (and so previewed) rather than ticked."""

    exercise: str
    answers: dict[str, str]
    typed: tuple[str, ...]


def class_work(manifest: Path) -> dict[str, list[Work]]:
    """Each student's exercises with their right answers (a tenth of the submits are
    10 % off, :func:`answer`)."""
    from dynagrade.serve.exam_data import ExamData

    data = ExamData(manifest)
    typed = {e: tuple(p.name for p in data.parts(e) if not p.options) for e in data.exercise_ids}
    return {s.student_id: [Work(v.exercise, {k: _answer_text(a, 1.0)
                                             for k, a in v.answers.items()}, typed[v.exercise])
                           for v in s.variants]
            for s in data.manifest.students}


class Student:
    """One simulated student: page, then think, type (previews), draft, submit, and a
    reload every third submit."""

    def __init__(self, url: str, token: str, work: list[Work], record: Record,
                 scale: float, rng: random.Random):
        parts = urlsplit(url)
        self.connection = Connection(parts.hostname or "127.0.0.1", parts.port or 80)
        self.token, self.work, self.record, self.scale, self.rng = token, work, record, scale, rng
        self.auth = {"Authorization": f"Bearer {token}"}
        self.until = float("inf")

    async def pause(self, low: float, high: float) -> None:
        await asyncio.sleep(self.rng.uniform(low, high) / self.scale)

    async def page(self) -> None:
        """Load the page, and preview what its script would preview on load: each filled
        box whose reading the page does not carry (dynagrade before issue 28 read every
        one of them again)."""
        page = await self.record.send("page", self.connection, "GET", f"/s/{self.token}", {})
        for exercise, part, text in unread_boxes(page):
            await self.record.send("preview", self.connection, "POST", "/api/v1/preview",
                                   self.auth, {"exercise": exercise, "part": part,
                                               "answer": text})

    async def answer(self, work: Work) -> None:
        for part in work.typed:
            text = work.answers[part]
            for typed in (text[:max(1, len(text) // 2)], text):
                await self.pause(1, 3)
                if time.monotonic() > self.until:
                    return
                await self.record.send("preview", self.connection, "POST", "/api/v1/preview",
                                       self.auth, {"exercise": work.exercise, "part": part,
                                                   "answer": typed})
        await self.record.send("draft", self.connection, "PUT", "/api/v1/drafts", self.auth,
                               {"exercise": work.exercise, "answers": {
                                   p: work.answers[p] for p in work.typed}})

    def submitted(self, work: Work) -> dict[str, str]:
        off = self.rng.random() < 0.1
        return {p: (_off(t) if off else t) for p, t in work.answers.items()}

    async def run(self, until: float, start_within: float) -> None:
        self.until = until
        await asyncio.sleep(self.rng.uniform(0, start_within))
        await self.page()
        submits = 0
        while True:
            for work in self.work:
                await self.pause(10, 30)
                if time.monotonic() > until:
                    return self.connection.close()
                await self.answer(work)
                if time.monotonic() > until:
                    return self.connection.close()
                await self.record.send("submit", self.connection, "POST", "/api/v1/answers",
                                       {**self.auth, "Idempotency-Key": uuid.uuid4().hex},
                                       {"exercise": work.exercise,
                                        "answers": self.submitted(work)})
                submits += 1
                if submits % 3 == 0:
                    await self.page()


_BOX = re.compile(r'<input id="([^"]+)--([^"]+)" name="answer\.[^"]+" data-part="[^"]*"'
                  r'[^>]*?value="([^"]+)"([^>]*)>')


def unread_boxes(page: str) -> list[tuple[str, str, str]]:
    """(exercise, part, text) of each filled, writable box of ``page`` whose preview is
    empty: what the page's script previews on load."""
    found = []
    for match in _BOX.finditer(page):
        exercise, part, text, rest = match.groups()
        empty = f'id="{exercise}--{part}--preview" data-preview-for="{part}" ' \
                'aria-live="polite"></output>'
        if "readonly" not in rest and empty in page:
            found.append((exercise, part, html.unescape(text)))
    return found


def _off(text: str) -> str:
    try:
        return repr(float(text) * 1.1)
    except ValueError:
        return text


async def monitor(url: str, record: Record, until: float) -> None:
    parts = urlsplit(url)
    connection = Connection(parts.hostname or "127.0.0.1", parts.port or 80)
    while time.monotonic() < until:
        await record.send("healthz", connection, "GET", "/healthz", {})
        await asyncio.sleep(1.0)
    connection.close()


def server_cpu(group: int) -> float:
    """CPU seconds (user + system) of every live process in the server's process group."""
    total = 0
    for entry in os.listdir("/proc"):
        if not entry.isdigit():
            continue
        try:
            with open(f"/proc/{entry}/stat", "rb") as handle:
                fields = handle.read().rsplit(b")", 1)[1].split()
        except OSError:
            continue
        if int(fields[2]) == group:  # field 5 of stat, the process group
            total += int(fields[11]) + int(fields[12])  # utime, stime
    return total / os.sysconf("SC_CLK_TCK")


async def calibrate(url: str, students: list[Student], kind: str, count: int,
                    group: int) -> float:
    """Server CPU milliseconds per request of ``kind``, sent ``count`` times four at a
    time, with the server's idle CPU over the same time taken away."""
    idle_before = server_cpu(group)
    await asyncio.sleep(1.0)
    idle_rate = server_cpu(group) - idle_before
    record = Record()
    queue = list(range(count))

    async def one(student: Student, number: int) -> None:
        work = student.work[number % len(student.work)]
        if kind == "page":
            await student.page()
        elif kind == "preview":
            part = work.typed[0]
            await record.send(kind, student.connection, "POST", "/api/v1/preview",
                              student.auth, {"exercise": work.exercise, "part": part,
                                             "answer": work.answers[part]})
        elif kind == "draft":
            await record.send(kind, student.connection, "PUT", "/api/v1/drafts", student.auth,
                              {"exercise": work.exercise,
                               "answers": {p: work.answers[p] for p in work.typed}})
        else:
            await record.send(kind, student.connection, "POST", "/api/v1/answers",
                              {**student.auth, "Idempotency-Key": uuid.uuid4().hex},
                              {"exercise": work.exercise, "answers": student.submitted(work)})

    async def lane(lane_students: list[Student]) -> None:
        while queue:
            number = queue.pop()
            await one(lane_students[number % len(lane_students)], number)

    before, began = server_cpu(group), time.monotonic()
    await asyncio.gather(*(lane(students[i::4]) for i in range(4)))
    spent = server_cpu(group) - before - idle_rate * (time.monotonic() - began)
    return 1000 * max(0.0, spent) / count


async def run(url: str, tokens: dict[str, str], work: dict[str, list[Work]],
              args: argparse.Namespace, group: int) -> int:
    rng = random.Random(args.seed)
    record = Record()
    students = [Student(url, tokens[s], work[s], record, args.scale, rng)
                for s in sorted(tokens)]
    began = time.monotonic()
    until = began + args.seconds
    cpu_before, client_before = server_cpu(group), time.process_time()
    await asyncio.gather(monitor(url, record, until),
                         *(s.run(until, min(args.seconds / 3, 30 / args.scale))
                           for s in students))
    elapsed = time.monotonic() - began
    cpu = server_cpu(group) - cpu_before
    client = time.process_time() - client_before
    total = record.count()
    print(f"{len(students)} students, {elapsed:.0f} s, think time 10-30 s / {args.scale:g}: "
          f"{total} requests ({total / elapsed:.1f}/s)")
    print(f"{'kind':8} {'count':>7} {'p50 ms':>7} {'p95 ms':>7} {'p99 ms':>7} {'5xx':>5} "
          f"{'no answer':>9}  statuses")
    errors = 0
    for kind in KINDS:
        values = record.latencies.get(kind, [])
        fives = sum(n for status, n in record.statuses[kind].items() if status >= 500)
        # a preview refused while the graders are busy (503) is shed by design, no error
        errors += fives - (record.statuses[kind].get(503, 0) if kind == "preview" else 0)
        errors += record.failed[kind]
        shown = " ".join(f"{status}:{n}" for status, n in sorted(record.statuses[kind].items()))
        if values:
            print(f"{kind:8} {len(values):7d} {1000 * percentile(values, 50):7.0f} "
                  f"{1000 * percentile(values, 95):7.0f} {1000 * percentile(values, 99):7.0f} "
                  f"{fives:5d} {record.failed[kind]:9d}  {shown}")
    print(f"server CPU {cpu:.1f} s ({1000 * cpu / max(1, total):.1f} ms a request, "
          f"{100 * cpu / elapsed:.0f} % of one core); client CPU {client:.1f} s "
          f"({1000 * client / max(1, total):.2f} ms a request)")
    if args.calibrate:
        kinds = ("page", "preview", "draft", "submit")
        rounds: dict[str, list[float]] = {kind: [] for kind in kinds}
        for _round in range(args.rounds):  # the kinds in turn, so that noise hits all alike
            for kind in kinds:
                rounds[kind].append(await calibrate(url, students, kind, args.calibrate, group))
        print(f"server CPU per request, one kind at a time ({args.calibrate} each, median of "
              f"{args.rounds} rounds [lowest-highest]): " + ", ".join(
                  f"{kind} {statistics.median(ms):.1f} ms [{min(ms):.1f}-{max(ms):.1f}]"
                  for kind, ms in rounds.items()))
    for student in students:
        student.connection.close()
    return errors


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    server_arguments(parser, students=50)
    parser.add_argument("--seconds", type=float, default=20)
    parser.add_argument("--scale", type=float, default=5,
                        help="divide think and typing times by this (1: real 10-30 s)")
    parser.add_argument("--calibrate", type=int, default=40,
                        help="requests of each kind for the CPU per kind (0: skip)")
    parser.add_argument("--rounds", type=int, default=1,
                        help="calibration rounds; the median is printed (a shared machine "
                             "is noisy)")
    parser.add_argument("--seed", type=int, default=1)
    args = parser.parse_args(argv)

    folder = Path(tempfile.mkdtemp(prefix="dynagrade-bench-class-"))
    manifest, tokens = class_with_links(folder, args.students, args.db)
    server = Server(manifest, _free_port(), args.db, args.workers, args.grading_workers)
    with open(folder / "server.log", "w") as log:
        try:
            server.start(log)
            assert server.process is not None
            errors = asyncio.run(run(server.url, tokens, class_work(manifest), args,
                                     server.process.pid))
        finally:
            server.stop()
    print(f"(load average {os.getloadavg()[0]:.2f} on {os.cpu_count()} cores; {folder})")
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main())
