"""The state of one exam generation, held by the run itself and handed to worker
processes explicitly (:mod:`dynagrade.runs.workers`), where it is rebuilt from what
pickles (the exercises' files; caches and compiler start empty)."""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

from ..exam.manifest import PartEntry
from ..exam.spec import ExamSpec
from ..exercise.model import Exercise, Variant
from ..render.pdf import PdfCompiler
from ..runs.caches import Identities, PartProblemsCache, VariantCache, load_exercises


def _figure(exercise: Exercise, variant: Variant) -> str | None:
    from ..render.figures import figure_svg

    return figure_svg(exercise, variant)


@dataclass
class GenerationRun:
    """One ``dynagrade exam``: the spec, the exercises by id, every exercise's parts with
    points scaled to the exam, where files go, and this run's caches and compiler."""

    spec: ExamSpec
    exercises: dict[str, Exercise]
    parts: dict[str, tuple[PartEntry, ...]]
    out_dir: Path
    pdf: bool = True
    solutions: bool = False  # write each student's worked solutions (``--solutions``)
    compiler: PdfCompiler = field(default_factory=PdfCompiler)
    part_problems: PartProblemsCache = field(init=False)
    problems: VariantCache[tuple[str, ...]] = field(init=False)
    figures: VariantCache[str | None] = field(init=False)

    def __post_init__(self):
        identities = Identities()
        self.part_problems = PartProblemsCache(10_000, identities)
        self.problems = VariantCache(self._variant_problems, 50_000, identities)
        self.figures = VariantCache(_figure, 2_000, identities)

    def _variant_problems(self, exercise: Exercise, variant: Variant) -> tuple[str, ...]:
        from .variants import check_variant

        return check_variant(exercise, variant, self.part_problems)

    def __getstate__(self):
        paths = {i: e.path for i, e in self.exercises.items()}
        return (self.spec, paths, self.parts, self.out_dir, self.pdf, self.solutions)

    def __setstate__(self, state):
        spec, paths, parts, out_dir, pdf, solutions = state
        GenerationRun.__init__(self, spec, load_exercises(paths), parts, out_dir, pdf,
                               solutions)
