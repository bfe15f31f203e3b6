"""The dimension of every formula key: a Symbolic part's expected formula, in its
variables' units, must have the dimension of the numeric part it ``equals``.

The ``equals`` cross-check compares values at the variant's parameters; this one compares
units, so a formula that matches at one point by accident (a missing ``g`` where g is
near 10, a length where a speed belongs) is caught. It needs no author input, so
``dynagrade verify`` runs it on every exercise with a formula (radians count as 1).
"""

from __future__ import annotations

from functools import lru_cache
from typing import Iterator

from ...grading.dims import DimensionIssue, dimension, show
from ...grading.errors import AnswerError
from ...grading.parser import parse_expression
from ...grading.quantity import unit_info
from ...grading.units import same


def formula_dimension_problems(exercise) -> Iterator[str]:
    """One line for each Symbolic part whose formula's dimension differs from the unit of
    the part it ``equals`` (or cannot be worked out)."""
    for part in exercise.parts:
        equals = getattr(part, "equals", None)
        if not equals:
            continue
        units = tuple((name, variable.unit) for name, variable in part.variables.items())
        problem = _dimension_problem(part.expected, units, exercise.part(equals).unit)
        if problem:
            yield f"check 'dimensions' on {part.name}: {problem}"


@lru_cache(maxsize=512)
def _dimension_problem(expected: str, units: tuple[tuple[str, str | None], ...],
                       target_unit: str | None) -> str | None:
    """Why ``expected`` (variables with ``units``) does not have the dimension of
    ``target_unit``; ``None`` when it does. A variable without a unit is a pure number,
    as a parameter without one is."""
    variables = {name: unit_info(unit)[1] for name, unit in units}
    try:
        got = dimension(parse_expression(expected, frozenset(variables)), variables)
    except (DimensionIssue, AnswerError) as error:
        return f"the formula {expected!r} has no dimension: {error}"
    wanted = unit_info(target_unit)[1]
    if not same(got, wanted, ignore_angle=True):
        return (f"the formula {expected!r} has the dimension {show(got)}, the part it "
                f"equals {show(wanted)}")
    return None
