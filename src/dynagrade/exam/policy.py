"""An exam's delivery policy: when students may answer, how often, and what they see.

Top-level keys of ``exam.toml`` (all optional)::

    mode = "homework"                       # "exam" (default) | "homework" | "practice"
    opens = 2025-04-14T08:00:00+02:00       # a TOML date-time with its offset (or "Z")
    closes = 2025-04-21T23:59:00+02:00
    attempts = 3                            # submissions per part; 0 = no limit (default)
    penalty = 0.1                           # fraction of a part's points lost per extra attempt
    feedback = "immediate"                  # "immediate" | "after-close"
    counts = "best"                         # which attempt the gradebook takes: "best" | "last"
    solutions = "after-close"               # when worked solutions are shown (solution_policy.py)
    time_limit = 90                         # minutes from the student's "Start"; 0 = untimed

Defaults follow the mode: an exam shows feedback after the close, counts the last saved
answer and shows no worked solution; homework and practice show verdicts at once, count
the best attempt and show worked solutions with the feedback.
An exam cannot show verdicts before its close (``feedback = "immediate"`` is refused).
The server enforces ``opens`` and ``closes`` with its own clock. With a ``time_limit``
each student's clock starts when they press "Start" on their page, and they may answer
until ``time_limit`` minutes later or the close, whichever comes first
(:mod:`dynagrade.serve.allowances`, which also holds the exceptions granted per student).
"""

from __future__ import annotations

import datetime as dt
import math
from dataclasses import dataclass
from typing import Any, Callable, Mapping, TypeGuard

from ..errors import DynagradeError
from .solution_policy import SOLUTIONS, default_solutions

MODES = ("exam", "homework", "practice")
FEEDBACK = ("immediate", "after-close")
COUNTS = ("best", "last")
POLICY_KEYS = {"mode", "opens", "closes", "attempts", "penalty", "feedback", "counts",
               "solutions", "time_limit"}
#: the longest time limit and the most attempts a policy (or an exception) may give
MAX_MINUTES = 10080  # a week
MAX_ATTEMPTS = 1000


class PolicyError(DynagradeError, ValueError):
    """A policy key with a bad value; the message names the file, line and key."""


@dataclass(frozen=True)
class Policy:
    """How an exam is delivered. Times are timezone-aware (``None``: no limit)."""

    mode: str = "exam"
    opens: dt.datetime | None = None
    closes: dt.datetime | None = None
    attempts: int = 0
    penalty: float = 0.0
    feedback: str = "after-close"
    counts: str = "last"
    solutions: str = ""  # "": the mode's default (solution_policy.py)
    #: minutes a student has from their "Start" (0: untimed, no Start)
    time_limit: int = 0

    def __post_init__(self):
        if not self.solutions:
            object.__setattr__(self, "solutions", default_solutions(self.mode))

    def is_open(self, now: dt.datetime) -> bool:
        """Whether answers are accepted at ``now``."""
        return (self.opens is None or now >= self.opens) and \
            (self.closes is None or now < self.closes)

    def shows_verdicts(self, now: dt.datetime) -> bool:
        """Whether students see right/wrong and points at ``now``."""
        if self.feedback == "immediate":
            return True
        return self.closes is not None and now >= self.closes

    @property
    def zone(self) -> dt.tzinfo:
        """The zone the exam's times were written in (that of ``closes`` or ``opens``),
        else UTC: the course's zone, in which pages and downloads show times."""
        for moment in (self.closes, self.opens):
            if moment is not None and moment.tzinfo is not None:
                return moment.tzinfo
        return dt.timezone.utc

    def attempt_factor(self, attempt: int) -> float:
        """The fraction of the points an answer earns at its ``attempt``-th try (1-based)."""
        return max(0.0, 1.0 - self.penalty * (attempt - 1))

    def to_json(self) -> dict:
        return {"mode": self.mode, "opens": _iso(self.opens), "closes": _iso(self.closes),
                "attempts": self.attempts, "penalty": self.penalty,
                "feedback": self.feedback, "counts": self.counts,
                "solutions": self.solutions, "time_limit": self.time_limit}

    @classmethod
    def from_json(cls, data: Mapping[str, Any] | None) -> "Policy":
        """The policy a manifest stored (a manifest without one: the exam defaults)."""
        if not data:
            return cls()
        return cls(data["mode"], _parse_iso(data.get("opens")), _parse_iso(data.get("closes")),
                   int(data["attempts"]), float(data["penalty"]), data["feedback"],
                   data["counts"], data.get("solutions") or "",
                   int(data.get("time_limit") or 0))


def read_policy(data: dict, where: str, line_of: Callable[[str], str]) -> Policy:
    """The policy in the top-level table ``data`` of an exam spec.

    ``where`` names the file and ``line_of(key)`` the line of a key, for the errors (a
    change made elsewhere, e.g. on the server, has no lines: ``line_of`` gives ``""``).
    """
    def fail(key: str, message: str):
        line = line_of(key)
        at = f"{where}, line {line}" if line else where
        raise PolicyError(f"{at}, field {key!r}: {message}")

    mode = data.get("mode", "exam")
    if mode not in MODES:
        fail("mode", f"{mode!r}; choose one of {', '.join(MODES)}")
    feedback = data.get("feedback", "after-close" if mode == "exam" else "immediate")
    if feedback not in FEEDBACK:
        fail("feedback", f"{feedback!r}; choose one of {', '.join(FEEDBACK)}")
    if mode == "exam" and feedback == "immediate":
        fail("feedback", "an exam shows verdicts only after it closes; use mode = "
                         "\"homework\" for immediate feedback")
    counts = data.get("counts", "last" if mode == "exam" else "best")
    if counts not in COUNTS:
        fail("counts", f"{counts!r}; choose one of {', '.join(COUNTS)}")
    opens, closes = (read_moment(data.get(k), lambda m, k=k: fail(k, m))
                     for k in ("opens", "closes"))
    if opens and closes and closes <= opens:
        fail("closes", f"{_iso(closes)} is not after opens = {_iso(opens)}")
    attempts = data.get("attempts", 0)
    if not whole_number(attempts, 0, MAX_ATTEMPTS):
        fail("attempts", f"{attempts!r}; give a whole number of attempts per part "
                         f"(0 for no limit, at most {MAX_ATTEMPTS})")
    penalty = data.get("penalty", 0.0)
    if isinstance(penalty, bool) or not isinstance(penalty, (int, float)) \
            or not math.isfinite(penalty) or not 0 <= penalty <= 1:
        fail("penalty", f"{penalty!r}; give the fraction of the points lost per extra "
                        "attempt, between 0 and 1")
    solutions = data.get("solutions", default_solutions(mode))
    if solutions not in SOLUTIONS:
        fail("solutions", f"{solutions!r}; choose one of {', '.join(SOLUTIONS)}")
    time_limit = data.get("time_limit", 0)
    if not whole_number(time_limit, 0, MAX_MINUTES):
        fail("time_limit", f"{time_limit!r}; give the minutes a student has from their "
                           f"start as a whole number (0 for untimed, at most {MAX_MINUTES})")
    return Policy(mode, opens, closes, attempts, float(penalty), feedback, counts, solutions,
                  time_limit)


def whole_number(value, low: int, high: int) -> TypeGuard[int]:
    """Whether ``value`` is a whole number (not a bool) from ``low`` to ``high``."""
    return not isinstance(value, bool) and isinstance(value, int) and low <= value <= high


def read_moment(value, fail) -> dt.datetime | None:
    """``value`` (a TOML date-time or ISO text) as an aware date-time; ``fail(message)``
    when it is not one or has no offset (the server would not know when it is)."""
    if value is None:
        return None
    if isinstance(value, str):
        try:
            value = dt.datetime.fromisoformat(value.strip())
        except ValueError:
            fail(f"{value!r} is not a date-time; write e.g. 2025-04-21T23:59:00+02:00")
    if not isinstance(value, dt.datetime):
        fail(f"{value!r}; give a date and time with its offset, e.g. "
             "2025-04-21T23:59:00+02:00")
    if value.tzinfo is None:
        fail(f"{value.isoformat()} has no time zone; add the offset (e.g. +02:00 or Z) so "
             "that the server closes at the time you mean")
    return value


def _iso(moment: dt.datetime | None) -> str | None:
    return moment.isoformat() if moment else None


def _parse_iso(text: str | None) -> dt.datetime | None:
    return dt.datetime.fromisoformat(text) if text else None
