"""The server's graded answers: one part of a submit, and the record
(:class:`~dynagrade.exercise.results.GradedPart`) it is stored as and read back from.

A submit grades each given part as class grading does; what the student sees, what the
``answers`` table holds and what the gradebook and report are built from are the same
record, so the server's marks are class grading's marks (docs/serve.md, "What counts").
"""

from __future__ import annotations

from dataclasses import dataclass, replace

from ..exam.manifest import PartEntry
from ..exercise.results import GradedPart, Status
from ..i18n import _
from .db import StoredAnswer


@dataclass(frozen=True)
class SubmittedPart:
    """One part of a submit: the text, how it read, and the verdict on it."""

    raw: str
    readable: bool
    #: how the answer read ("reads as ...") or why it could not be read
    message: str
    verdict: GradedPart

    @property
    def name(self) -> str:
        return self.verdict.name

    @property
    def invalid(self) -> bool:
        """Whether the grader could not read the answer: then it was not graded, and it
        is neither stored nor counted, nor does it spend an attempt (docs/serve.md,
        "Attempts")."""
        return not self.readable and self.verdict.status is Status.NOT_ANSWERED

    @classmethod
    def unread(cls, part: PartEntry, text: str, message: str) -> SubmittedPart:
        """A part whose answer cannot be read (``message`` says why): not graded."""
        return cls(text, False, message, GradedPart(
            part.name, part.label, Status.NOT_ANSWERED, 0.0, float(part.points), text,
            message, unit=part.unit))

    def penalised(self, factor: float, attempt: int) -> SubmittedPart:
        """The part at its ``attempt``-th try, worth ``factor`` of its points (the
        policy's penalty); the feedback says so."""
        if factor >= 1.0:
            return self
        note = " " + _("(attempt {attempt}: {percent} % of the points)").format(
            attempt=attempt, percent=round(100 * factor))
        verdict = replace(self.verdict, auto_score=self.verdict.auto_score * factor,
                          feedback=self.verdict.feedback + note)
        return replace(self, verdict=verdict)

    def row(self) -> dict:
        """The columns of the ``answers`` table (:mod:`.db`)."""
        verdict = self.verdict
        return {"part": verdict.name, "raw": self.raw, "readable": self.readable,
                "message": self.message, "status": str(verdict.status),
                "correct": verdict.correct, "score": verdict.auto_score,
                "max_score": verdict.points, "feedback": verdict.feedback,
                "misconception": verdict.misconception}

    @classmethod
    def stored(cls, answer: StoredAnswer, label: str = "") -> SubmittedPart:
        """A part as the database holds it."""
        verdict = GradedPart(answer.part, label, Status(answer.status), answer.score,
                             answer.max_score, answer.raw, answer.feedback,
                             answer.misconception)
        return cls(answer.raw, answer.readable, answer.message, verdict)


def not_answered(part: PartEntry) -> GradedPart:
    """A part of a handed-in exercise that has no counted answer, as class grading
    records a part left empty."""
    return GradedPart(part.name, part.label, Status.NOT_ANSWERED, 0.0, float(part.points),
                      None, _("not answered"), expected=None, unit=part.unit)
