"""Grading off the event loop, in a bounded pool of processes.

Each pool process loads the exam once and grades in its main thread, so the grader's own
time limits (interval timers around the exact symbolic check) work as they do on the
command line, and in the exam's language (``language`` of exam.toml), so the feedback
stored with each answer reads as the page around it. The grader's budget is CPU time, so
its verdicts do not depend on the load; the server's own wait, :func:`budget`, is
wall-clock seconds: a job that takes longer gets "not graded in time" (status error, for
the staff to grade), never a wrong verdict, and the other students' jobs go on in the
other processes.

Jobs wait in two lanes (:class:`Lanes`), one for submits and one for previews, and a
process that comes free takes the oldest submit before any preview, so that a class
typing (a preview at every pause) never delays a submit by more than the job each process
is on. Each lane has its own bound per server process: at most ``queue`` submits wait,
and at most ``preview_queue`` previews, each for at most ``preview_wait`` seconds (a
preview that waited longer is stale: the student typed on). Beyond that a request gets
503 with ``Retry-After`` (:class:`Busy`) instead of piling up; previews are therefore
refused first, and previews filling their lane never refuse a submit.

The event loop talks to each process over its own pipe (:mod:`.grading_workers`), with no
thread between them. A process that dies (killed, out of memory) is replaced, and the job
it was running is run once more, by another process.
"""

from __future__ import annotations

import asyncio
import multiprocessing
import time
from collections import deque
from typing import TYPE_CHECKING

from ..errors import DynagradeError
from ..grading.timing import ANSWER_BUDGET
from ..i18n import language
from .grading_workers import Worker, WorkerDied

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


#: the lanes, in the order a free process takes from them
SUBMIT, PREVIEW = "submit", "preview"


class Lanes:
    """``slots`` jobs running at once (one per grading process, so that no job waits
    inside the executor, where it could not be overtaken); the others wait in their lane,
    submits served before previews. Runs on one event loop."""

    def __init__(self, slots: int, bounds: dict[str, int]):
        self.free = slots
        self.bounds = bounds
        self.waiting: dict[str, deque[asyncio.Future]] = {lane: deque() for lane in bounds}

    async def enter(self, lane: str, seconds: float | None = None) -> None:
        """Take a slot, after the jobs ahead (every waiting submit is ahead of a preview);
        :class:`Busy` when ``lane`` is full or the slot did not come within ``seconds``."""
        if self.free > 0 and not any(self.waiting.values()):
            self.free -= 1
            return
        queue = self.waiting[lane]
        if len(queue) >= self.bounds[lane]:
            raise Busy()
        turn = asyncio.get_running_loop().create_future()
        queue.append(turn)
        try:
            await asyncio.wait_for(asyncio.shield(turn), seconds)
        except (asyncio.TimeoutError, asyncio.CancelledError) as error:
            if turn.done() and not turn.cancelled():  # the slot came as it gave up: pass it on
                self.leave()
            else:
                turn.cancel()
                queue.remove(turn)
            if isinstance(error, asyncio.TimeoutError):
                raise Busy() from None
            raise

    def leave(self) -> None:
        """Give the slot to the oldest waiting submit, else the oldest preview."""
        for queue in self.waiting.values():
            while queue:
                turn = queue.popleft()
                if not turn.done():
                    turn.set_result(None)
                    return
        self.free += 1


class GradingPool:
    """``workers`` processes grading answers for one exam (:mod:`.grading_workers`)."""

    def __init__(self, manifest_path: str, folders: tuple[str, ...] = (), workers: int = 2,
                 queue: int = 256, preview_queue: int = 64, preview_wait: float = 2.0):
        self._args = (str(manifest_path), tuple(folders))
        self._context = _process_context()
        self._lanes = Lanes(workers, {SUBMIT: queue, PREVIEW: preview_queue})
        self._preview_wait = preview_wait
        self._workers = [self._start() for _ in range(workers)]
        self._closing = False
        #: the pool that took over after a reload (:meth:`retire`)
        self._successor: GradingPool | None = None

    def _start(self) -> Worker:
        return Worker(self._context, _load, self._args, on_end=self._replace)

    def _replace(self, ended: Worker) -> None:
        """A process died (e.g. out of memory): a new one takes its place."""
        if not self._closing:
            self._workers[self._workers.index(ended)] = self._start()

    def warm_up(self) -> None:
        """Start every process and load the exam now, not on the first request (before
        the pool's first job). A process that dies loading is replaced at its first job,
        whose request then fails if the new one dies too."""
        for worker in self._workers:
            try:
                worker.wait_ready()
            except (EOFError, OSError):
                pass

    async def grade(self, student_id, exercise_id, answers: dict, seed) -> list[dict] | None:
        """The graded parts, or ``None`` when grading took longer than its budget."""
        return await self._run(SUBMIT, budget(len(answers)), _grade, student_id,
                               exercise_id, answers, seed)

    async def read(self, student_id, exercise_id, part, text, seed) -> dict | None:
        """How an answer reads (``ExamData.preview``), or ``None`` when reading took too
        long; :class:`Busy` when the previews' lane is full or the preview waited too
        long for a process."""
        return await self._run(PREVIEW, budget(1), _read, student_id, exercise_id, part,
                               text, seed)

    async def _run(self, lane, seconds, function, *args):
        if self._successor is not None:  # a request that held this pool across a reload
            return await self._successor._run(lane, seconds, function, *args)
        await self._lanes.enter(lane, self._preview_wait if lane == PREVIEW else None)
        if self._successor is not None:  # retired while this job waited
            self._lanes.leave()
            return await self._successor._run(lane, seconds, function, *args)
        for tries in (1, 2):
            worker = next(w for w in self._workers if not w.busy)
            try:
                job = worker.run(function, *args)
            except BaseException:
                self._lanes.leave()
                raise
            # the slot is free when the process is, not when the wait below gives up
            job.add_done_callback(self._free)
            try:
                return await asyncio.wait_for(asyncio.shield(job), seconds)
            except asyncio.TimeoutError:
                return None
            except WorkerDied:
                if tries == 2:
                    raise
            # the process died (and was replaced): the job queues again
            await self._lanes.enter(lane)

    def _free(self, job: asyncio.Future) -> None:
        """A job is done: its process takes the next one (its outcome, should nobody wait
        for it any more, is taken here, so that none goes unread)."""
        self._lanes.leave()
        if not job.cancelled():
            job.exception()

    def retire(self, successor: GradingPool) -> None:
        """Hand new jobs to ``successor`` and stop once the jobs already running here are
        done (a reload of the exam drops no request in flight). Blocks: call it in a
        thread, not on the event loop."""
        self._successor = successor
        while any(worker.busy for worker in self._workers):
            time.sleep(0.05)
        self.close()

    def close(self, seconds: float = 5.0) -> None:
        """Stop the grading processes before the server process ends, so that none is
        left running after it: a running job may finish within ``seconds``, and a
        process still alive then is killed."""
        self._closing = True
        deadline = time.monotonic() + seconds
        for worker in self._workers:
            worker.stop(max(0.0, deadline - time.monotonic()))
