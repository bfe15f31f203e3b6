"""The self-check of an exam's fill-in file: can every answer be read? No verdicts.

An exam's fill-in file carries a variant token, not a seed, so the public package cannot
know the student's numbers or key: ``grade FILE`` can only check what needs no key —
every answer readable, of the right kind (number, formula, vector, choice), a unit of the
right dimension, only the allowed names in a formula (:mod:`dynagrade.grading.readability`)
— and says that verdicts come when the staff grade.
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass

from .model import Exercise
from .params import ParamValues
from .parts import Part
from .sheet import Sheet

VERDICTS_LATER = ("this is an exam: only whether each answer can be read is checked "
                  "here; whether it is right you learn when the staff grade")


@dataclass(frozen=True)
class PartReading:
    """Whether one part's answer can be read, and how (or why not)."""

    name: str
    label: str
    readable: bool
    message: str

    def to_json(self) -> dict:
        return {"name": self.name, "readable": self.readable, "message": self.message}


def key_free_spec(part: Part):
    """The part's grading spec without what depends on the variant (its known wrong
    answers): enough to read an answer, nothing to judge it with."""
    bare = dataclasses.replace(part, misconceptions=()) if part.misconceptions else part
    return bare.spec(ParamValues({}))


def self_check(exercise: Exercise, sheet: Sheet) -> list[PartReading]:
    """How each of ``exercise``'s parts reads in ``sheet`` (never whether it is right)."""
    from ..grading.readability import readability

    readings = []
    for part in exercise.parts:
        text = sheet.answers.get(part.name)
        if part.name in sheet.problems:
            readable, message = False, sheet.problems[part.name]
        elif text is None or not text.strip():
            readable, message = False, "not answered yet"
        else:
            found = readability(key_free_spec(part), text)
            readable, message = found.readable, found.message
        readings.append(PartReading(part.name, part.label or part.name, readable, message))
    return readings


def self_check_json(exercise: Exercise, sheet: Sheet) -> dict:
    """``grade --json`` of an exam file: per part ``readable`` and ``message`` only."""
    return {"exercise": exercise.id, "mode": "exam", "message": VERDICTS_LATER,
            "parts": [r.to_json() for r in self_check(exercise, sheet)]}
