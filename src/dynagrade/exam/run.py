"""The state of one exam generation and of one class grading, held by the run itself.

A run owns its exercises, its caches (each variant's problems and figure) and its PDF
compiler; it is handed to worker processes explicitly (:mod:`.workers`), where it is
rebuilt from what pickles (the exercises' files; caches and compilers start empty).
Nothing about an exercise is cached under its id alone: the key is the exercise's
identity, its file's content hash, so a corrected exercise with the same id is never
answered from an older one's cache, and two runs never share state.
"""

from __future__ import annotations

import hashlib
import os
from dataclasses import dataclass, field
from pathlib import Path
from typing import Callable, Generic, TypeVar

from ..exercise.model import Exercise, Variant
from ..render.pdf import PdfCompiler
from .manifest import PartEntry
from .spec import ExamSpec

T = TypeVar("T")


def file_sha256(path: str | os.PathLike) -> str:
    """The SHA-256 of a file's bytes, in hex."""
    return hashlib.sha256(Path(path).read_bytes()).hexdigest()


def exercise_identity(exercise: Exercise) -> str:
    """What anything cached about ``exercise`` is keyed by: its file's content hash (the
    loader's ``fingerprint`` where it records one), or, for an exercise built in memory
    without a file, the object itself."""
    fingerprint = getattr(exercise, "fingerprint", None)
    if fingerprint:
        return fingerprint
    if exercise.path:
        return file_sha256(exercise.path)
    return f"object-{id(exercise)}"


class VariantCache(Generic[T]):
    """``compute(exercise, variant)`` remembered per (exercise identity, parameters), up
    to ``limit`` entries (then forgotten all at once, which keeps memory bounded)."""

    def __init__(self, compute: Callable[[Exercise, Variant], T], limit: int):
        self.compute, self.limit = compute, limit
        self._values: dict[tuple, T] = {}
        self._identities: dict[int, tuple[Exercise, str]] = {}

    def _identity(self, exercise: Exercise) -> str:
        known = self._identities.get(id(exercise))
        if known is None or known[0] is not exercise:
            known = (exercise, exercise_identity(exercise))
            self._identities[id(exercise)] = known
        return known[1]

    def __call__(self, exercise: Exercise, variant: Variant) -> T:
        key = (self._identity(exercise), tuple(sorted(variant.params.items())))
        if key not in self._values:
            if len(self._values) >= self.limit:
                self._values.clear()
            self._values[key] = self.compute(exercise, variant)
        return self._values[key]


def _variant_problems(exercise: Exercise, variant: Variant) -> tuple[str, ...]:
    from .variants import check_variant

    return check_variant(exercise, variant)


def _figure(exercise: Exercise, variant: Variant) -> str | None:
    from ..render.figures import figure_svg

    return figure_svg(exercise, variant)


def _load(paths: dict[str, str]) -> dict[str, Exercise]:
    from ..exercise.loader import load_file

    return {exercise_id: load_file(path) for exercise_id, path in paths.items()}


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
    problems: VariantCache[tuple[str, ...]] = field(
        default_factory=lambda: VariantCache(_variant_problems, 50_000))
    figures: VariantCache[str | None] = field(
        default_factory=lambda: VariantCache(_figure, 2_000))
    compiler: PdfCompiler = field(default_factory=PdfCompiler)

    def __getstate__(self):
        paths = {i: e.path for i, e in self.exercises.items()}
        return (self.spec, paths, self.parts, self.out_dir, self.pdf, self.solutions)

    def __setstate__(self, state):
        spec, paths, parts, out_dir, pdf, solutions = state
        self.__init__(spec, _load(paths), parts, out_dir, pdf, solutions)


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
        self.__init__(_load(paths), parts)
