"""The grading processes the server talks to over a pipe (dynagrade.serve.grading_workers;
issue 28): a job's answer or exception comes back as a local call's would, and a process
that dies fails its job, is replaced, and the pool runs the job again."""

from __future__ import annotations

import asyncio
import os
import signal

import pytest

from serve_support import exam_dir  # noqa: F401

import grading_worker_jobs as jobs


def _worker(ended: list):
    from dynagrade.serve.grading_pool import _process_context
    from dynagrade.serve.grading_workers import Worker

    return Worker(_process_context(), jobs.nothing_to_set_up, (), on_end=ended.append)


def test_a_job_returns_its_answer_and_raises_its_exception_in_the_server():
    ended: list = []
    worker = _worker(ended)

    async def scenario():
        pid = await worker.run(jobs.pid_after, 0.0)
        assert not worker.busy
        with pytest.raises(ValueError, match="no such unit"):
            await worker.run(jobs.refuse, "no such unit")
        return pid

    try:
        worker.wait_ready()
        pid = asyncio.run(scenario())
    finally:
        worker.stop()
    assert pid == worker.process.pid != os.getpid()
    assert ended == []  # stopped, not ended on its own
    assert not worker.process.is_alive()


def test_a_process_killed_while_grading_fails_its_job_and_says_it_ended():
    from dynagrade.serve.grading_workers import WorkerDied

    ended: list = []
    worker = _worker(ended)

    async def scenario():
        job = worker.run(jobs.pid_after, 30.0)
        await asyncio.sleep(0.2)
        os.kill(worker.process.pid, signal.SIGKILL)
        with pytest.raises(WorkerDied):
            await asyncio.wait_for(job, 10)

    try:
        worker.wait_ready()
        asyncio.run(scenario())
    finally:
        worker.stop()
    assert ended == [worker] and not worker.busy


def test_the_pool_replaces_a_dead_process_and_grades_the_job_on_the_new_one(exam_dir):
    from dynagrade.exam.manifest import load
    from dynagrade.serve.grading_pool import GradingPool

    manifest = exam_dir / "manifest.json"
    student = load(manifest).students[0]
    right = {name: repr(value) for name, value in
             student.variant("projectile-range").answers.items() if isinstance(value, float)}
    pool = GradingPool(str(manifest), workers=1)
    try:
        pool.warm_up()
        (first,) = pool._workers
        os.kill(first.process.pid, signal.SIGKILL)
        first.process.join(10)
        graded = asyncio.run(pool.grade(student.student_id, "projectile-range", right, None))
        (second,) = pool._workers
    finally:
        pool.close()
    assert second is not first and second.process.pid != first.process.pid
    assert [part.readable for part in graded] == [True] * len(right)
    assert all(part.verdict.correct for part in graded)
