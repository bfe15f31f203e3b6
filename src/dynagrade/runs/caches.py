"""What a run caches, keyed so that nothing is answered from another exercise's state.

A run (:class:`dynagrade.generation.run.GenerationRun`,
:class:`dynagrade.classgrade.run.GradingRun`) owns its exercises, its caches (each variant's problems and figure, a part's own
checks where they depend on less than the variant) and its PDF compiler; it is handed to
worker processes explicitly (:mod:`.workers`), where it is rebuilt from what pickles
(the exercises' files; caches and compilers start empty).
Nothing about an exercise is cached under its id alone: the key is the exercise's
identity, its file's content hash, so a corrected exercise with the same id is never
answered from an older one's cache, and two runs never share state.
"""

from __future__ import annotations

import hashlib
import os
from pathlib import Path
from typing import Callable, Generic, TypeVar

from ..exercise.model import Exercise, Variant
from ..exercise.params import ParamValues
from ..exercise.parts import Part

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


class Identities:
    """Each exercise's :func:`exercise_identity`, worked out once per exercise object (the
    object is kept, so its ``id`` is never another's)."""

    def __init__(self):
        self._known: dict[int, tuple[Exercise, str]] = {}

    def __call__(self, exercise: Exercise) -> str:
        known = self._known.get(id(exercise))
        if known is None or known[0] is not exercise:
            known = (exercise, exercise_identity(exercise))
            self._known[id(exercise)] = known
        return known[1]


class VariantCache(Generic[T]):
    """``compute(exercise, variant)`` remembered per (exercise identity, parameters), up
    to ``limit`` entries (then forgotten all at once, which keeps memory bounded)."""

    def __init__(self, compute: Callable[[Exercise, Variant], T], limit: int,
                 identities: Identities | None = None):
        self.compute, self.limit = compute, limit
        self._values: dict[tuple, T] = {}
        self._identity = identities or Identities()

    def __call__(self, exercise: Exercise, variant: Variant) -> T:
        key = (self._identity(exercise), tuple(sorted(variant.params.items())))
        if key not in self._values:
            if len(self._values) >= self.limit:
                self._values.clear()
            self._values[key] = self.compute(exercise, variant)
        return self._values[key]


class PartProblemsCache:
    """:func:`~dynagrade.exercise.verify.part_own_problems` remembered per (exercise
    identity, part name, :meth:`~dynagrade.exercise.parts.Part.own_checks_key`), for the
    parts that give such a key (a formula's checks are the same in most variants); the
    others' are computed every time. Up to ``limit`` entries, then forgotten at once."""

    def __init__(self, limit: int, identities: Identities | None = None):
        self.limit = limit
        self._values: dict[tuple, tuple[str, ...]] = {}
        self._identity = identities or Identities()

    def __call__(self, exercise: Exercise, part: Part, params: ParamValues,
                 expected) -> tuple[str, ...]:
        from ..exercise.verify import part_own_problems

        depends_on = part.own_checks_key(params, expected)
        if depends_on is None:
            return part_own_problems(exercise, part, params, expected)
        key = (self._identity(exercise), part.name, depends_on)
        if key not in self._values:
            if len(self._values) >= self.limit:
                self._values.clear()
            self._values[key] = part_own_problems(exercise, part, params, expected)
        return self._values[key]


def load_exercises(paths: dict[str, str]) -> dict[str, Exercise]:
    """The exercises of a run by id, loaded again from their files (in a worker process)."""
    from ..exercise.loader import load_file

    return {exercise_id: load_file(path) for exercise_id, path in paths.items()}
