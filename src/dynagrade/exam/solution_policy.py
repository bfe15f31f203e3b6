"""When students see their worked solutions, as ``exam.toml``'s ``solutions`` says (a key
of the delivery policy, :mod:`.policy`)::

    solutions = "with-feedback"       # with class grading's feedback and, on the server,
                                      # with the verdicts once the student can no longer
                                      # answer (the default for homework and practice)
    solutions = "after-close"         # once the exam closes
    solutions = "after-last-attempt"  # once the student has no attempt left, or it closes
    solutions = "never"               # the default for exams

This module is a leaf: the policy imports it, not the other way round.
"""

from __future__ import annotations

#: the values of ``solutions`` in ``exam.toml``
SOLUTIONS = ("with-feedback", "after-close", "after-last-attempt", "never")


def default_solutions(mode: str) -> str:
    """The ``solutions`` setting of an exam that does not set it: never in an exam, with
    the feedback in homework and practice."""
    return "never" if mode == "exam" else "with-feedback"


def with_feedback(setting: str) -> bool:
    """Whether class grading's feedback ends with the worked solutions: it is written
    after the exam, so under every setting but "never"."""
    return setting != "never"


def solution_visible(setting: str, closed: bool, verdicts_shown: bool,
                     out_of_attempts: bool) -> bool:
    """Whether the server shows a student the worked solution of an exercise: after the
    close (``closed``) or once every part of it has used its attempts
    (``out_of_attempts``), as ``setting`` says. ``"with-feedback"`` waits for the same
    moment as ``"after-last-attempt"`` and for the verdicts to be shown, so a solution
    never arrives while the student can still change an answer."""
    finished = closed or out_of_attempts
    return {"never": False, "after-close": closed, "after-last-attempt": finished,
            "with-feedback": finished and verdicts_shown}[setting]
