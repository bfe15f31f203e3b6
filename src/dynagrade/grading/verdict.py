"""The result of grading one answer part."""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class Verdict:
    """Outcome of grading one answer.

    ``score`` is the credit in [0, 1] (partial credit is allowed even when
    ``correct`` is False); ``feedback`` is written for the student; ``error`` is set
    when the answer could not be read (then ``correct`` is False and ``score`` 0);
    ``misconception`` names the known mistake that explained the answer, if any.
    """

    correct: bool
    score: float
    feedback: str
    error: str | None = None
    misconception: str | None = None

    def __post_init__(self) -> None:
        if not 0.0 <= self.score <= 1.0:
            raise ValueError(f"score must lie in [0, 1], got {self.score}")


def unreadable(message: str) -> Verdict:
    """The verdict for an answer that could not be read."""
    return Verdict(correct=False, score=0.0, feedback=message, error=message)
