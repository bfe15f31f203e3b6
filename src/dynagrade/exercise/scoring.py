"""Grading every part of one variant: points, partial credit, follow-through.

Each part gets a verdict, whatever the student wrote; an answer the sheet reader could
not read is wrong with the reader's message. A numeric part with ``follow_through`` that
is wrong against the reference is graded again against the reference recomputed from the
student's own earlier answers, and earns its credit when it is consistent with them.
"""

from __future__ import annotations

from typing import Mapping

from ..grading import Verdict, grade, read_number
from ..grading.errors import AnswerError
from ..i18n import _
from .model import Exercise, Variant
from .parts import Part
from .results import ExerciseResult, GradedPart, Status
from .units import to_si


def grade_variant(exercise: Exercise, variant: Variant,
                  answers: Mapping[str, str | None],
                  problems: Mapping[str, str] | None = None) -> ExerciseResult:
    """The verdict on each of ``exercise``'s parts for the student's ``answers`` (text)."""
    problems = problems or {}
    params_si = exercise.si(variant.params)
    results = []
    for part in exercise.parts:
        text = answers.get(part.name)
        if part.name in problems:
            results.append(_result(part, text, Status.WRONG, 0.0,
                                   _("could not read the answer: {problem}").format(
                                       problem=problems[part.name])))
        elif text is None or not text.strip():
            results.append(_result(part, None, Status.NOT_ANSWERED, 0.0, _("not answered")))
        else:
            results.append(_graded_part(exercise, part, variant, answers, params_si, text))
    return ExerciseResult(exercise.id, variant.seed, tuple(results))


def _graded_part(exercise: Exercise, part: Part, variant: Variant,
                 answers: Mapping[str, str | None], params_si, text: str) -> GradedPart:
    """The verdict on one answered part; a failure of grading itself is that part's
    ``error`` (0 points, the message kept), never the end of the other parts' grading."""
    try:
        verdict = grade(part.spec(params_si), variant.answers[part.name], text)
        followed = None
        if not verdict.correct and part.follows_through:
            followed = _follow_through(exercise, part, variant, answers, text)
    except Exception as error:  # noqa: BLE001 - isolation is the point
        return graded_error(part, text, error)
    verdict = followed or verdict
    status = (Status.CORRECT if verdict.correct else Status.FOLLOW_THROUGH if followed
              else Status.PARTIAL if verdict.score > 0 else Status.WRONG)
    return _result(part, text, status, verdict.score, verdict.feedback, verdict.misconception)


def graded_error(part: Part, text: str | None, error: BaseException) -> GradedPart:
    """The result of a part whose grading failed: status ``error`` with the message."""
    message = str(error) or type(error).__name__
    return _result(part, text, Status.ERROR, 0.0,
                   _("could not be graded ({error}: {message}); the course staff will look "
                     "at it").format(error=type(error).__name__, message=message))


def _follow_through(exercise: Exercise, part: Part, variant: Variant,
                    answers: Mapping[str, str | None], text: str) -> Verdict | None:
    """The verdict against the reference recomputed from the student's earlier answers,
    when it is correct; ``None`` when the earlier answers cannot be read or it is wrong."""
    own: dict[str, float] = {}
    for name in part.follow_through_uses():
        earlier = exercise.part(name)
        earlier_text = answers.get(name)
        if earlier_text is None:
            return None
        try:
            own[name] = to_si(read_number(earlier_text, earlier.unit), earlier.unit)
        except AnswerError:
            return None
    params_si = exercise.si(variant.params)
    recomputed = part.followed_reference(params_si, own)
    verdict = grade(part.spec(params_si), recomputed, text)
    if not verdict.correct:
        return None
    return type(verdict)(correct=False, score=verdict.score, misconception=None,
                         error=None, feedback=_("consistent with your earlier answer to {parts}, "
                                                "which was not right: follow-through credit")
                         .format(parts=", ".join(part.follow_through_uses())))


def _result(part: Part, answer: str | None, status: Status, fraction: float, feedback: str,
            misconception: str | None = None) -> GradedPart:
    return GradedPart(part.name, part.label, status, round(fraction * part.points, 6),
                      part.points, answer, feedback, misconception)
