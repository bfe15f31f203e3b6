"""The record of graded work, one shape for every path that grades.

A :class:`GradedPart` is the verdict on one part: its :class:`Status`, the points the
grader gave (``auto_score``), an optional :class:`StaffOverride` (points set by hand,
with the comment, who set them and when) and the score derived from the two: the
override wins, and the automatic score is kept beside it. An :class:`ExerciseResult`
holds the parts of one exercise and is rounded one way, :meth:`ExerciseResult.rounded`:
each part's score to the exam's step, the exercise's score the exact sum of the rounded
parts. ``grade exercise.py``, class grading, the staff's overrides, the statistics, the
report, the server's submits and gradebook, and the platform gradebooks all read and
write these records, so every path gives the same marks.

The shape follows the usual split of a gradebook entry into an automatic and a manual
score with a derived total::

    >>> part = GradedPart("v", "speed", Status.WRONG, 0.0, 2.0, "3 m/s", "not right")
    >>> part.with_override(StaffOverride(1.5, "method right")).score
    1.5
"""

from __future__ import annotations

from ..i18n import N_, _
from dataclasses import dataclass, field, replace
from enum import StrEnum
from typing import Any, Protocol, Sequence


class Status(StrEnum):
    """What the grader made of one part's answer."""

    # stored and exported as these English words; marked for the catalogs and shown through
    # :attr:`shown` in the page's language
    CORRECT = N_("correct")
    #: wrong against the reference, right against the student's own earlier answers
    FOLLOW_THROUGH = N_("follow-through")
    #: some credit, not all (e.g. some components of a vector)
    PARTIAL = N_("partial")
    WRONG = N_("wrong")
    NOT_ANSWERED = N_("not answered")
    #: grading itself failed; the staff look at it
    ERROR = N_("error")

    @property
    def shown(self) -> str:
        """The status as a person reads it, in the active language."""
        return _(self.value)

    @property
    def answered_wrong(self) -> bool:
        """Whether the status means "answered, and not right"."""
        return self in (Status.WRONG, Status.PARTIAL, Status.FOLLOW_THROUGH)


class RoundingRule(Protocol):
    """How an exam rounds points (:class:`dynagrade.exam.points.Rounding`)."""

    def round(self, value: float) -> float:
        """``value`` rounded to the nearest multiple of the step."""

    def total(self, values: Sequence[float]) -> float:
        """The exact sum of values that are multiples of the step."""

    def text(self, value: float) -> str:
        """``value`` written with the step's decimals."""


@dataclass(frozen=True)
class StaffOverride:
    """Points a member of the staff set by hand for one part, and why."""

    points: float
    comment: str = ""
    #: who set them (a name, or the file they came from)
    author: str = ""
    #: when, as ISO 8601 text ("" when not recorded)
    at: str = ""


@dataclass(frozen=True)
class GradedPart:
    """The verdict on one part: what the grader gave and what the staff set."""

    name: str
    label: str
    status: Status
    #: the points the grader gave
    auto_score: float
    #: the points the part is worth
    points: float
    #: the answer as the student wrote it (None: not answered)
    answer: str | None
    feedback: str
    #: the mistake that explains a wrong answer, as the grader named it
    misconception: str | None = None
    override: StaffOverride | None = None
    #: the reference answer, where the record is shown to the staff or after the key
    expected: Any = None
    #: the unit of the reference answer (None: it has none)
    unit: str | None = None

    @property
    def score(self) -> float:
        """The points that count: the staff's override where there is one."""
        return self.override.points if self.override is not None else self.auto_score

    @property
    def fraction(self) -> float:
        """The share of the part's points earned (0 for a part worth no points)."""
        return self.score / self.points if self.points else 0.0

    @property
    def correct(self) -> bool:
        return self.status is Status.CORRECT

    def scaled(self, points: float) -> GradedPart:
        """The same verdict in a part worth ``points`` (an exam's share of the part)."""
        fraction = self.auto_score / self.points if self.points else 0.0
        return replace(self, auto_score=fraction * points, points=points)

    def rounded(self, rule: RoundingRule) -> GradedPart:
        """The automatic score rounded to ``rule``'s step (an override is already)."""
        return replace(self, auto_score=rule.round(self.auto_score))

    def with_override(self, override: StaffOverride) -> GradedPart:
        """The part with the staff's points; the automatic score is kept."""
        return replace(self, override=override)

    def shown_feedback(self, rule: RoundingRule | None = None) -> str:
        """The grader's feedback, followed by the staff's note where they set the points
        (both scores written with ``rule``'s decimals)."""
        if self.override is None:
            return self.feedback
        return f"{self.feedback} {self.override_note(rule)}".strip()

    def override_note(self, rule: RoundingRule | None = None) -> str:
        """What the staff did to this part, in a sentence ("" when nothing)."""
        if self.override is None:
            return ""
        text = rule.text if rule is not None else (lambda value: f"{value:g}")
        note = _("Points set by the staff: {points} (graded {graded})").format(
            points=text(self.override.points), graded=text(self.auto_score))
        return note + (f": {self.override.comment}" if self.override.comment else "")

    def to_json(self) -> dict:
        """The part as ``grade --json`` prints it."""
        return {"name": self.name, "status": str(self.status), "correct": self.correct,
                "score": round(self.score, 6), "max_score": self.points,
                "feedback": self.shown_feedback(), "answer": self.answer,
                "misconception": self.misconception}


@dataclass(frozen=True)
class ExerciseResult:
    """The verdicts on every part of one exercise.

    Before :meth:`rounded` the score is the plain sum of the parts' scores; after it,
    each part's score is a multiple of the rule's step and the exercise's score their
    exact sum in steps.
    """

    exercise_id: str
    seed: int | None
    parts: tuple[GradedPart, ...]
    #: where the answers came from (a file, a row, "server")
    source: str = ""
    rule: RoundingRule | None = field(default=None, compare=False, repr=False)

    @property
    def score(self) -> float:
        scores = [p.score for p in self.parts]
        return self.rule.total(scores) if self.rule is not None else round(sum(scores), 6)

    @property
    def max_score(self) -> float:
        return sum(p.points for p in self.parts)

    def part(self, name: str) -> GradedPart:
        return next(p for p in self.parts if p.name == name)

    def rounded(self, rule: RoundingRule) -> ExerciseResult:
        """Every part's score rounded to ``rule``'s step; the score their exact sum."""
        return replace(self, parts=tuple(p.rounded(rule) for p in self.parts), rule=rule)

    def with_part(self, part: GradedPart) -> ExerciseResult:
        """The result with ``part`` in place of the part of the same name."""
        return replace(self, parts=tuple(part if p.name == part.name else p
                                         for p in self.parts))

    def to_json(self) -> dict:
        """The result as ``grade --json`` prints it."""
        return {"exercise": self.exercise_id, "seed": self.seed,
                "score": round(self.score, 6), "max_score": self.max_score,
                "parts": [p.to_json() for p in self.parts]}
