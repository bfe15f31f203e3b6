"""Time budgets for grading one answer, counted in the grading process's CPU time.

A budget in wall-clock time makes verdicts depend on the machine's load: on a busy server
the same right answer that passes when the machine is idle runs out of time and is marked
wrong. So the budget counts the CPU time this process spends (``time.process_time`` for
the :class:`Deadline`, ``ITIMER_PROF``/SIGPROF for :func:`time_limit`), which another
process's work does not consume. A generous wall-clock backstop (:data:`WALL_BACKSTOP`,
``ITIMER_REAL``/SIGALRM) still ends a call that hangs without computing.
"""

from __future__ import annotations

import signal
import threading
import time
from contextlib import contextmanager

#: Budget for grading one answer, in CPU seconds of the grading process.
ANSWER_BUDGET = 0.5

#: Wall-clock seconds after which grading one answer stops however little CPU time it had:
#: only for a call that waits instead of computing, so far above what load can cause.
WALL_BACKSTOP = 60.0


class Deadline:
    """The end of an answer's budget: ``seconds`` of this process's CPU time, or
    :data:`WALL_BACKSTOP` of wall-clock time, whichever comes first."""

    def __init__(self, seconds: float = ANSWER_BUDGET, backstop: float = WALL_BACKSTOP):
        self.end = time.process_time() + seconds
        self.wall_end = time.monotonic() + backstop

    def remaining(self) -> float:
        """CPU seconds left (0 or less once the wall-clock backstop has passed)."""
        if time.monotonic() >= self.wall_end:
            return 0.0
        return self.end - time.process_time()

    def expired(self) -> bool:
        return self.remaining() <= 0


class OutOfTime(BaseException):
    """Raised inside a time-limited block (a BaseException so library code cannot swallow it)."""


def can_interrupt() -> bool:
    """Whether :func:`time_limit` can stop a computation (main thread, with interval timers)."""
    return hasattr(signal, "setitimer") and threading.current_thread() is threading.main_thread()


@contextmanager
def time_limit(seconds: float, backstop: float = WALL_BACKSTOP):
    """Interrupt the block with :class:`OutOfTime` after ``seconds`` of this process's CPU
    time, or after ``backstop`` seconds of wall-clock time (main thread only)."""
    if not can_interrupt():
        raise OutOfTime()

    def handler(signum, frame):
        raise OutOfTime()

    previous = {number: signal.signal(number, handler)
                for number in (signal.SIGPROF, signal.SIGALRM)}
    signal.setitimer(signal.ITIMER_PROF, max(seconds, 1e-3))
    signal.setitimer(signal.ITIMER_REAL, max(backstop, seconds, 1e-3))
    try:
        yield
    finally:
        signal.setitimer(signal.ITIMER_PROF, 0)
        signal.setitimer(signal.ITIMER_REAL, 0)
        for number, action in previous.items():
            signal.signal(number, action)
