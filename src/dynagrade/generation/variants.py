"""Choosing a student's variant of an exercise: seeded by a keyed hash of (exam, student,
exercise) with the exam's secret, and redrawn, deterministically, while the variant
cannot tell right from wrong.

A variant is handed out only when :func:`dynagrade.exercise.verify.variant_problems`
finds nothing wrong with it. Otherwise the next seed is the keyed hash of (exam, student,
exercise, "redraw", attempt); the seeds tried and the reasons are kept for the manifest,
so the choice can be checked and explained (by whoever holds the secret).
"""

from __future__ import annotations

from typing import Callable, Mapping

from ..errors import DynagradeError
from ..exercise.model import ConstraintError, Exercise, Variant
from ..exercise.seeds import exam_seed
from ..exercise.verify import OwnProblems, variant_problems
from ..exam.manifest import Redraw

MAX_ATTEMPTS = 25


class NoUsableVariant(DynagradeError, RuntimeError):
    """Every seed tried gave a variant that cannot discriminate."""


def check_variant(exercise: Exercise, variant: Variant,
                  own_problems: OwnProblems | None = None) -> tuple[str, ...]:
    """Why ``variant`` cannot be handed out (:func:`variant_problems`); empty when it can.
    ``own_problems``: a run's cache of each part's own checks
    (:attr:`dynagrade.generation.run.GenerationRun.part_problems`), or None to compute them."""
    return tuple(variant_problems(exercise, variant, own_problems))


def exam_variant(exercise: Exercise, secret: str, exam_id: str, student_id: str,
                 overrides: Mapping[str, float] | None = None,
                 problems: Callable[[Exercise, Variant], tuple[str, ...]] = check_variant,
                 ) -> tuple[Variant, tuple[Redraw, ...]]:
    """The variant handed to ``student_id``, and the draws rejected before it.
    ``problems`` is :func:`check_variant` or a run's cache of it
    (:attr:`dynagrade.generation.run.GenerationRun.problems`)."""
    redraws = []
    for attempt in range(MAX_ATTEMPTS):
        seed = exam_seed(secret, exam_id, student_id, exercise.id, attempt)
        try:
            variant = exercise.variant(seed, overrides or None)
        except ConstraintError as error:
            redraws.append(Redraw(seed, (str(error),)))
            continue
        found = problems(exercise, variant)
        if not found:
            return variant, tuple(redraws)
        redraws.append(Redraw(seed, found))
    reasons = sorted({p for r in redraws for p in r.problems})
    raise NoUsableVariant(f"exercise {exercise.id!r}, student {student_id!r}: none of "
                          f"{MAX_ATTEMPTS} draws can be handed out: " + "; ".join(reasons[:3]))
