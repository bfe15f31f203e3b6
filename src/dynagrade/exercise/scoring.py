"""Grading every part of one variant: points, partial credit, follow-through.

Each part gets a verdict, whatever the student wrote; an answer the sheet reader could
not read is wrong with the reader's message. A numeric part with ``follow_through`` that
is wrong against the reference is graded again against the reference recomputed from the
student's own earlier answers, and earns its credit when it is consistent with them.
"""

from __future__ import annotations

from dataclasses import asdict, dataclass
from typing import Mapping

from ..grading import grade, read_number
from ..grading.errors import AnswerError
from .model import Exercise, Variant
from .parts import Numeric, Part
from .units import from_si, to_si


@dataclass(frozen=True)
class PartResult:
    """The verdict on one part, with the points it earned."""

    name: str
    label: str
    status: str  # "correct", "follow-through", "partial", "wrong", "not answered", "error"
    correct: bool
    score: float
    max_score: float
    feedback: str
    answer: str | None
    misconception: str | None = None


@dataclass(frozen=True)
class Result:
    """The verdicts on every part of a variant and the total."""

    exercise_id: str
    seed: int
    parts: tuple[PartResult, ...]

    @property
    def score(self) -> float:
        return sum(p.score for p in self.parts)

    @property
    def max_score(self) -> float:
        return sum(p.max_score for p in self.parts)

    def to_json(self) -> dict:
        return {"exercise": self.exercise_id, "seed": self.seed,
                "score": round(self.score, 6), "max_score": self.max_score,
                "parts": [{k: v for k, v in asdict(p).items() if k != "label"}
                          for p in self.parts]}


def grade_variant(exercise: Exercise, variant: Variant,
                  answers: Mapping[str, str | None],
                  problems: Mapping[str, str] | None = None) -> Result:
    """The verdict on each of ``exercise``'s parts for the student's ``answers`` (text)."""
    problems = problems or {}
    params_si = exercise.si(variant.params)
    results = []
    for part in exercise.parts:
        text = answers.get(part.name)
        if part.name in problems:
            results.append(_result(part, text, "wrong", 0.0,
                                   f"could not read the answer: {problems[part.name]}"))
        elif text is None or not text.strip():
            results.append(_result(part, None, "not answered", 0.0, "not answered"))
        else:
            results.append(_graded_part(exercise, part, variant, answers, params_si, text))
    return Result(exercise.id, variant.seed, tuple(results))


def _graded_part(exercise: Exercise, part: Part, variant: Variant,
                 answers: Mapping[str, str | None], params_si, text: str) -> PartResult:
    """The verdict on one answered part; a failure of grading itself is that part's
    ``error`` (0 points, the message kept), never the end of the other parts' grading."""
    try:
        verdict = grade(part.spec(params_si), variant.answers[part.name], text)
        followed = None
        if not verdict.correct and part.follows_through:
            followed = _follow_through(exercise, part, variant, answers)
    except Exception as error:  # noqa: BLE001 - isolation is the point
        return graded_error(part, text, error)
    verdict = followed or verdict
    status = ("correct" if verdict.correct else "follow-through" if followed
              else "partial" if verdict.score > 0 else "wrong")
    return _result(part, text, status, verdict.score, verdict.feedback, verdict.misconception)


def graded_error(part: Part, text: str | None, error: BaseException) -> PartResult:
    """The result of a part whose grading failed: status ``error`` with the message."""
    message = str(error) or type(error).__name__
    return _result(part, text, "error", 0.0,
                   f"could not be graded ({type(error).__name__}: {message}); the course "
                   "staff will look at it")


def _follow_through(exercise: Exercise, part: Numeric, variant: Variant,
                    answers: Mapping[str, str | None]):
    """The verdict against the reference recomputed from the student's earlier answers,
    when it is correct; ``None`` when the earlier answers cannot be read or it is wrong."""
    own = {}
    for name in part.uses:
        earlier = exercise.part(name)
        text = answers.get(name)
        if text is None:
            return None
        try:
            own[name] = to_si(read_number(text, earlier.unit), earlier.unit)
        except AnswerError:
            return None
    params_si = exercise.si(variant.params)
    recomputed = from_si(part.follow_through(params_si, own), part.unit)
    verdict = grade(part.spec(params_si), recomputed, answers[part.name])
    if not verdict.correct:
        return None
    return type(verdict)(correct=False, score=verdict.score, misconception=None,
                         error=None, feedback="consistent with your earlier answer to "
                         + ", ".join(part.uses) + ", which was not right: follow-through "
                         "credit")


def _result(part: Part, answer, status, fraction, feedback, misconception=None) -> PartResult:
    return PartResult(part.name, part.label, status, status == "correct",
                      round(fraction * part.points, 6), part.points, feedback, answer,
                      misconception)
