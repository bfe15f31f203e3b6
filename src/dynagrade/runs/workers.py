"""Running a run's jobs in worker processes, or in this process when one job at a time
is asked for.

A job is a function ``job(run, item)`` at module level. The pool hands the run to each
worker process once, when the process starts (it is pickled where processes are
spawned, inherited where they are forked); the worker keeps it as the run it serves and
calls each job with it. Results come back in the order of the items.

Usage::

    with Pool(run, jobs=2) as pool:
        results = list(pool.map(student_job, roster))
        later = pool.submit(compile_key, source)        # a Future (done at once without workers)
"""

from __future__ import annotations

import multiprocessing
import os
from concurrent.futures import Future, ProcessPoolExecutor
from functools import partial
from typing import Callable, Iterable, Iterator

#: the run this worker process serves (set once by the pool's initializer; a process
#: serves one run in its life)
_SERVED = None


def _serve(run) -> None:
    global _SERVED
    _SERVED = run


def _call(job: Callable, item):
    return job(_SERVED, item)


def default_jobs(jobs: int | None) -> int:
    """Worker processes to use: ``jobs``, or up to 2 when not given; at least 1."""
    return max(1, jobs if jobs is not None else min(2, os.cpu_count() or 1))


class Pool:
    """Worker processes serving ``run`` (none when ``jobs`` is 1: jobs run here)."""

    def __init__(self, run, jobs: int):
        self.run = run
        self._executor = None
        if jobs > 1:
            methods = multiprocessing.get_all_start_methods()
            context = multiprocessing.get_context("fork" if "fork" in methods else "spawn")
            self._executor = ProcessPoolExecutor(max_workers=jobs, mp_context=context,
                                                 initializer=_serve, initargs=(run,))

    def map(self, job: Callable, items: Iterable, chunksize: int = 1) -> Iterator:
        """``job(run, item)`` for every item, results in order."""
        if self._executor is None:
            return map(partial(job, self.run), items)
        return self._executor.map(partial(_call, job), items, chunksize=chunksize)

    def submit(self, job: Callable, item) -> Future:
        """``job(run, item)`` in a worker (here, at once, without workers)."""
        if self._executor is not None:
            return self._executor.submit(_call, job, item)
        future: Future = Future()
        future.set_result(job(self.run, item))
        return future

    def close(self) -> None:
        if self._executor is not None:
            self._executor.shutdown()

    def __enter__(self) -> Pool:
        return self

    def __exit__(self, *exc) -> None:
        self.close()
