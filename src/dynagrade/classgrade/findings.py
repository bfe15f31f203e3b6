"""What a graded class shows beyond its grades: mistakes nobody declared
(:mod:`.discover`) and answers copied between variants (:mod:`.copies`).

Discovery runs first: an answer that a discovered mistake on the student's own numbers
explains is an honest mistake and no evidence of copying. Class grading and the
server's report both attach them to their outcome
(:func:`dynagrade.classgrade.grade.with_findings`); neither changes a grade.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Mapping

from ..exam.manifest import Manifest
from ..exercise.model import Exercise
from .answered import Answered
from .copies import Copies, detect
from .discover import Proposal, discover, explained_students


@dataclass(frozen=True)
class Findings:
    """The proposed misconceptions and the copied answers of one class."""

    copies: Copies = Copies()
    proposals: tuple[Proposal, ...] = field(default_factory=tuple)


def class_findings(manifest: Manifest, exercises: Mapping[str, Exercise],
                   records: list[Answered]) -> Findings:
    """Discovery, then copy detection with the answers discovery explains set aside."""
    proposals = tuple(discover(manifest, exercises, records))
    return Findings(detect(manifest, records, explained_students(proposals)), proposals)
