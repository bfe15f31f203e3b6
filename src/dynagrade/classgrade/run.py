"""The state of one class grading, handed to worker processes explicitly
(:mod:`dynagrade.runs.workers`), where the exercises are loaded again from their files."""

from __future__ import annotations

from dataclasses import dataclass

from ..exam.manifest import PartEntry
from ..exercise.model import Exercise
from ..runs.caches import load_exercises


@dataclass
class GradingRun:
    """One ``dynagrade grade --manifest``: the exercises that grade the exam and each
    exercise's parts as the manifest stored them."""

    exercises: dict[str, Exercise]
    parts: dict[str, tuple[PartEntry, ...]]

    def __getstate__(self):
        return ({i: e.path for i, e in self.exercises.items()}, self.parts)

    def __setstate__(self, state):
        paths, parts = state
        GradingRun.__init__(self, load_exercises(paths), parts)
