"""Running an exercise's checks on one variant: the findings ``dynagrade verify`` reports
and the recomputed values a worked solution may print (``{{ checks.name }}``)."""

from __future__ import annotations

from typing import Any, Mapping

from ..params import ParamValues
from .base import CheckCase, Outcome


def check_case(exercise, params: ParamValues) -> CheckCase:
    """The variant with SI ``params`` as the checks see it."""

    def resolve(changed: Mapping[str, float]) -> Mapping[str, Any]:
        return exercise.solve(ParamValues({**params, **changed}))

    return CheckCase(params, exercise.solve(params), resolve)


def outcomes(exercise, params: ParamValues) -> list[Outcome]:
    """Every check's comparison for the variant with SI ``params``; a check that raises
    is the author's error and propagates (``verify`` reports it)."""
    case = check_case(exercise, params)
    return [check.outcome(case) for check in exercise.checks]


def check_problems(exercise, params: ParamValues) -> list[str]:
    """One line per check that fails for the variant with SI ``params``: the check's name,
    the key, both numbers and the tolerance; a check that raises is named with its error."""
    case = check_case(exercise, params)
    problems = []
    for check in exercise.checks:
        try:
            outcome = check.outcome(case)
        except Exception as error:  # the author's route: reported, never a traceback
            problems.append(f"check '{check.name}' fails: {type(error).__name__}: {error}")
            continue
        if not outcome.ok:
            problems.append(outcome.problem())
    return problems


def recomputed_values(exercise, params: ParamValues) -> dict[str, Any]:
    """Each check's recomputed value by the check's name (SI), for a worked solution's
    closing sanity line."""
    return {outcome.check: outcome.recomputed for outcome in outcomes(exercise, params)}
