"""Choosing a student's variant of an exercise: seeded by (exam, student, exercise), and
redrawn, deterministically, while the variant cannot tell right from wrong.

A variant is handed out only when :func:`dynagrade.exercise.verify.variant_problems`
finds nothing wrong with it. Otherwise the next seed is the stable hash of (exam,
student, exercise, "redraw", attempt); the seeds tried and the reasons are kept for the
manifest, so the choice can be checked and explained.
"""

from __future__ import annotations

from typing import Mapping

from ..exercise.model import ConstraintError, Exercise, Variant
from ..exercise.seeds import exam_seed, stable_seed
from ..exercise.verify import variant_problems
from .manifest import Redraw

MAX_ATTEMPTS = 25


class NoUsableVariant(RuntimeError):
    """Every seed tried gave a variant that cannot discriminate."""


def attempt_seed(exam_id: str, student_id: str, exercise_id: str, attempt: int) -> int:
    """The seed of the ``attempt``-th draw (0: the student's own exam seed)."""
    if attempt == 0:
        return exam_seed(exam_id, student_id, exercise_id)
    return stable_seed("exam", exam_id, student_id, exercise_id, "redraw", str(attempt))


_PROBLEMS: dict[tuple, tuple[str, ...]] = {}


def cached_problems(exercise: Exercise, variant: Variant) -> tuple[str, ...]:
    """:func:`variant_problems`, remembered for identical parameters of one exercise."""
    key = (exercise.id, tuple(sorted(variant.params.items())))
    if key not in _PROBLEMS:
        if len(_PROBLEMS) > 50_000:
            _PROBLEMS.clear()
        _PROBLEMS[key] = tuple(variant_problems(exercise, variant))
    return _PROBLEMS[key]


def exam_variant(exercise: Exercise, exam_id: str, student_id: str,
                 overrides: Mapping[str, float] | None = None) -> tuple[Variant, tuple[Redraw, ...]]:
    """The variant handed to ``student_id``, and the draws rejected before it."""
    redraws = []
    for attempt in range(MAX_ATTEMPTS):
        seed = attempt_seed(exam_id, student_id, exercise.id, attempt)
        try:
            variant = exercise.variant(seed, overrides or None)
        except ConstraintError as error:
            redraws.append(Redraw(seed, (str(error),)))
            continue
        problems = cached_problems(exercise, variant)
        if not problems:
            return variant, tuple(redraws)
        redraws.append(Redraw(seed, problems))
    reasons = sorted({p for r in redraws for p in r.problems})
    raise NoUsableVariant(f"exercise {exercise.id!r}, student {student_id!r}: none of "
                          f"{MAX_ATTEMPTS} draws can be handed out: " + "; ".join(reasons[:3]))
