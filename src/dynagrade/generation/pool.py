"""A pool of variants for Moodle's random questions, independent of any roster.

``dynagrade moodle ID... --variants N -o pool.xml`` writes N distinct variants of every
exercise, each exercise in its own question category, so that a quiz slot "random
question from this category" hands every student one of them.

The variants are drawn exactly as an exam's are (:func:`.variants.exam_variant`): slot
``k`` of an exercise is seeded by the keyed hash of (:data:`POOL_ID`, ``variant-k``,
exercise id) with a secret, and redrawn while the variant cannot tell right from wrong.
The same secret (``--secret-file``) gives the same pool; without it every run draws a
new one. A slot whose variant repeats an earlier one (same parameters) is skipped, so an
exercise with few possible variants yields fewer than N, with a notice. The parts carry
the exercise's own points (:func:`.generate.exercise_parts`, the exam's rule).
"""

from __future__ import annotations

from pathlib import Path

from ..exercise.model import Exercise
from ..render.moodle import Category, variant_idnumber
from .generate import exercise_parts
from ..exam.manifest import ExerciseEntry, VariantEntry
from ..runs.caches import file_sha256
from .variants import exam_variant

#: the exam id a pool's variants are keyed with
POOL_ID = "moodle-pool"
#: how many slots are tried per variant asked for, before an exercise is taken to have
#: no more distinct variants
ATTEMPTS_PER_VARIANT = 3


def pool_categories(exercises: list[Exercise], count: int,
                    secret: str) -> tuple[list[Category], list[str]]:
    """``count`` distinct variants of each exercise, a category each, and notices for
    exercises that have fewer."""
    categories, notices = [], []
    for exercise in exercises:
        variants = _distinct_variants(exercise, count, secret)
        if len(variants) < count:
            notices.append(f"exercise {exercise.id!r} has only {len(variants)} distinct "
                           f"variants of the {count} asked for; all of them are in the pool")
        categories.append(Category(exercise, _described(exercise), tuple(variants)))
    return categories, notices


def _distinct_variants(exercise: Exercise, count: int, secret: str) -> list[VariantEntry]:
    variants: list[VariantEntry] = []
    seen = set()
    for slot in range(ATTEMPTS_PER_VARIANT * count + 10):
        if len(variants) == count:
            break
        variant, redraws = exam_variant(exercise, secret, POOL_ID, f"variant-{slot}")
        entry = VariantEntry(exercise.id, variant.seed, variant.params,
                             dict(variant.answers), redraws)
        key = variant_idnumber(entry)
        if key not in seen:
            seen.add(key)
            variants.append(entry)
    return variants


def _described(exercise: Exercise) -> ExerciseEntry:
    """The exercise as an exam that gives it its own points would describe it."""
    points = sum(part.points for part in exercise.parts)
    path = Path(exercise.path) if exercise.path else None
    return ExerciseEntry(exercise.id, exercise.title, exercise.source, points, {},
                         "/".join(path.parts[-2:]) if path else "",
                         file_sha256(path) if path else "",
                         exercise_parts(exercise, points))
