"""When students see their worked solutions, as ``exam.toml`` says::

    solutions = "with-feedback"       # with class grading's feedback and the server's
                                      # verdicts (the default for homework and practice)
    solutions = "after-close"         # once the exam closes
    solutions = "after-last-attempt"  # once the student has no attempt left, or it closes
    solutions = "never"               # the default for exams

The exam's mode comes from its delivery policy, which the manifest stores.
"""

from __future__ import annotations

from typing import Any, Callable, Mapping

#: the values of ``solutions`` in ``exam.toml``
SOLUTIONS = ("with-feedback", "after-close", "after-last-attempt", "never")


def read_solutions_setting(data: Mapping[str, Any], fail: Callable[[str], None]) -> str | None:
    """The ``solutions`` key of an exam spec's top-level table ``data`` (``None`` when
    absent: the mode's default); ``fail(message)`` reports a bad value."""
    setting = data.get("solutions")
    if setting is not None and setting not in SOLUTIONS:
        fail(f"{setting!r}; choose one of {', '.join(SOLUTIONS)}")
    return setting


def exam_mode(policy: Mapping[str, Any] | None) -> str:
    """The exam's mode ("exam", "homework" or "practice") from the delivery policy the
    manifest stores; an exam unless the policy says otherwise."""
    return (policy or {}).get("mode") or "exam"


def solutions_setting(policy: Mapping[str, Any] | None) -> str:
    """When students see their worked solutions: the policy's ``solutions``, or by
    default never in an exam and with the feedback in homework and practice."""
    setting = (policy or {}).get("solutions")
    if setting:
        return setting
    return "never" if exam_mode(policy) == "exam" else "with-feedback"


def with_feedback(policy: Mapping[str, Any] | None) -> bool:
    """Whether class grading's feedback ends with the worked solutions: graded after the
    exam, so under every setting but "never"."""
    return solutions_setting(policy) != "never"


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
