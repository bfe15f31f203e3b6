"""Grading off the event loop, in a bounded pool of processes.

Each pool process loads the exam once and grades in its main thread, so the grader's own
time limits (interval timers around the exact symbolic check) work as they do on the
command line, and in the exam's language (``language`` of exam.toml), so the feedback
stored with each answer reads as the page around it. The grader's budget is CPU time, so
its verdicts do not depend on the load; the server's own wait, :func:`budget`, is
wall-clock seconds: a job that takes longer gets "not graded in time" (status error, for
the staff to grade), never a wrong verdict, and the other students' jobs go on in the
other processes. At most ``queue`` jobs wait per server process; beyond that a request gets
503 with ``Retry-After`` instead of piling up.
"""

from __future__ import annotations

import asyncio
import multiprocessing
import time
from concurrent.futures import ProcessPoolExecutor
from concurrent.futures.process import BrokenProcessPool

from typing import TYPE_CHECKING

from ..errors import DynagradeError
from ..grading.timing import ANSWER_BUDGET
from ..i18n import language

if TYPE_CHECKING:
    from .exam_data import ExamData

_EXAM: dict[str, ExamData] = {}


class Busy(DynagradeError):
    """Too many grading jobs are waiting; the client should retry shortly."""


def budget(parts: int) -> float:
    """Seconds the server waits for the grading of ``parts`` answers."""
    return 2.0 + 4 * ANSWER_BUDGET * max(1, parts)


def _load(manifest_path: str, folders: tuple[str, ...]) -> None:
    """Worker start: the exam, and what any answer may need (pint, the exact checks), so
    that no student's verdict spends its time budget on imports."""
    from ..exercise.loader import open_bank
    from ..grading import prepare
    from .exam_data import ExamData

    _EXAM["data"] = ExamData(manifest_path, open_bank(folders))
    prepare()


def _grade(student_id, exercise_id, answers, seed):
    data = _EXAM["data"]
    with language(data.manifest.exam.language):
        return data.grade(student_id, exercise_id, answers, seed)


def _read(student_id, exercise_id, part, text, seed):
    data = _EXAM["data"]
    with language(data.manifest.exam.language):
        return data.preview(student_id, exercise_id, part, text, seed)


def _process_context():
    """How grading processes start: forked from a fork server that has imported
    :mod:`.grading_preload` (the grader's libraries, built once), where the platform has
    one; otherwise each process starts afresh. Never forked from the server itself, whose
    threads a fork would copy mid-flight."""
    if "forkserver" not in multiprocessing.get_all_start_methods():
        return multiprocessing.get_context("spawn")
    context = multiprocessing.get_context("forkserver")
    context.set_forkserver_preload(["dynagrade.serve.grading_preload"])
    return context


class GradingPool:
    """``workers`` processes grading answers for one exam."""

    def __init__(self, manifest_path: str, folders: tuple[str, ...] = (), workers: int = 2,
                 queue: int = 256):
        self._args = (str(manifest_path), tuple(folders))
        self._workers = workers
        self._waiting = 0
        self._queue = queue
        self._executor = self._start()
        #: the pool that took over after a reload (:meth:`retire`)
        self._successor: GradingPool | None = None

    def _start(self) -> ProcessPoolExecutor:
        return ProcessPoolExecutor(self._workers, mp_context=_process_context(),
                                   initializer=_load, initargs=self._args)

    def warm_up(self) -> None:
        """Start every process and load the exam now, not on the first request."""
        futures = [self._executor.submit(_read, None, None, None, None, None)
                   for _ in range(self._workers)]
        for future in futures:
            future.exception()

    async def grade(self, student_id, exercise_id, answers: dict, seed) -> list[dict] | None:
        """The graded parts, or ``None`` when grading took longer than its budget."""
        return await self._run(budget(len(answers)), _grade, student_id, exercise_id,
                               answers, seed)

    async def read(self, student_id, exercise_id, part, text, seed) -> dict | None:
        """How an answer reads (``ExamData.preview``), or ``None`` when reading took too
        long."""
        return await self._run(budget(1), _read, student_id, exercise_id, part, text, seed)

    async def _run(self, seconds, function, *args):
        if self._successor is not None:  # a request that held this pool across a reload
            return await self._successor._run(seconds, function, *args)
        if self._waiting >= self._queue:
            raise Busy()
        self._waiting += 1
        try:
            loop = asyncio.get_running_loop()
            for tries in (1, 2):
                try:
                    future = loop.run_in_executor(self._executor, function, *args)
                    return await asyncio.wait_for(future, seconds)
                except asyncio.TimeoutError:
                    return None
                except BrokenProcessPool:  # a process died (e.g. out of memory): restart
                    if tries == 2:
                        raise
                    self._executor = self._start()
        finally:
            self._waiting -= 1

    def retire(self, successor: GradingPool) -> None:
        """Hand new jobs to ``successor`` and stop once the jobs already running here are
        done (a reload of the exam drops no request in flight)."""
        self._successor = successor
        self._executor.shutdown(wait=True)

    def close(self, seconds: float = 5.0) -> None:
        """Stop the grading processes before the server process ends, so that none is
        left running after it: waiting jobs are cancelled, a running one may finish
        within ``seconds``, and a process still alive then is killed."""
        processes = list((getattr(self._executor, "_processes", None) or {}).values())
        self._executor.shutdown(wait=False, cancel_futures=True)
        deadline = time.monotonic() + seconds
        for process in processes:
            process.join(max(0.0, deadline - time.monotonic()))
            if process.is_alive():
                process.kill()
                process.join(1.0)
