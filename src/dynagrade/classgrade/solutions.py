"""The worked solutions that end a student's feedback after class grading, when the exam's
``solutions`` policy shows them with the feedback (:mod:`dynagrade.exam.solution_policy`).

A variant's solution is rendered from the parameters the manifest stores, so the
solutions of a graded exam are the ones its students were given numbers for.
"""

from __future__ import annotations

from typing import Callable, Iterable

from ..exercise.model import Exercise, Variant
from ..exercise.solution import SolutionError, render_solution


def feedback_solutions(solved: Iterable[tuple[Exercise, Variant]],
                       warn: Callable[[str, str], None]) -> dict[str, str | None]:
    """The worked solution of each of a student's variants, by exercise id; one that
    cannot be rendered is left out and ``warn(exercise_id, message)`` told why."""
    solutions = {}
    for exercise, variant in solved:
        try:
            solutions[exercise.id] = render_solution(exercise, variant)
        except SolutionError as error:
            solutions[exercise.id] = None
            warn(exercise.id, str(error))
    return solutions
