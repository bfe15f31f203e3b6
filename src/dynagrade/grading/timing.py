"""Wall-clock budgets: a deadline per answer, and a hard time limit for CAS calls."""

from __future__ import annotations

import signal
import threading
import time
from contextlib import contextmanager

#: Wall-clock budget for grading one answer, in seconds.
ANSWER_BUDGET = 0.5


class Deadline:
    def __init__(self, seconds: float = ANSWER_BUDGET):
        self.end = time.perf_counter() + seconds

    def remaining(self) -> float:
        return self.end - time.perf_counter()

    def expired(self) -> bool:
        return self.remaining() <= 0


class OutOfTime(BaseException):
    """Raised inside a time-limited block (a BaseException so library code cannot swallow it)."""


def can_interrupt() -> bool:
    """Whether :func:`time_limit` can stop a computation (main thread, with SIGALRM)."""
    return hasattr(signal, "setitimer") and threading.current_thread() is threading.main_thread()


@contextmanager
def time_limit(seconds: float):
    """Interrupt the block with :class:`OutOfTime` after ``seconds`` (main thread only)."""
    if not can_interrupt():
        raise OutOfTime()

    def handler(signum, frame):
        raise OutOfTime()

    previous = signal.signal(signal.SIGALRM, handler)
    signal.setitimer(signal.ITIMER_REAL, max(seconds, 1e-3))
    try:
        yield
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, previous)
