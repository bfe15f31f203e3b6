"""Jobs for a grading process under test (tests/test_serve_grading_workers.py): module
functions, so that a process started from the fork server can import them."""

from __future__ import annotations

import os
import time


def nothing_to_set_up() -> None:
    """A process that needs nothing loaded."""


def pid_after(seconds: float) -> int:
    """The process's id, after ``seconds``."""
    time.sleep(seconds)
    return os.getpid()


def refuse(message: str) -> None:
    """Raise, as a grader's own failure would."""
    raise ValueError(message)
