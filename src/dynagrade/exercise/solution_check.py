"""What ``dynagrade verify`` checks in a variant's worked solution.

- it renders;
- every part's reference answer appears in it as the key prints it;
- every number it prints is a value of the variant: a parameter (as the statement shows
  it or in SI), a value the solver returned (in SI, its magnitude, in degrees), or a
  part's answer, or what one of the exercise's checks recomputed (a closing sanity line
  prints it) -- or a small integer of a formula (2 in ``v^2/(2g)``). References to the
  notes ("eq. (1.80)", "Example 1.9", "Section 4.3.2") are not numbers of the variant.

So a number retyped into the template, which would hold for one variant only, is found.
"""

from __future__ import annotations

import math
import re
from pathlib import Path
from typing import Any, Iterable, Iterator

from .loader import builtin_bank, exercise_files, load_file
from .model import Exercise, Variant
from .solution import (SolutionError, check_values, prints_checks, render_solution,
                       solver_values)

#: integers up to this are the formulas' own numbers (2, 1/2, 4 pi^2, ...)
SMALL_INTEGER = 12
#: how closely a printed number must match a value of the variant (6 significant figures
#: are printed)
MATCH_RTOL = 1e-5

_REFERENCE = re.compile(
    r"(?:\b(?:eqs?|Eqs?|equations?|Equations?)\.?\s*|\b(?:Examples?|Sections?|Sect\.|"
    r"Chapters?|Fig\.|Figures?|Tables?|Problems?)\s+)\(?\d+(?:\.\d+)*[a-z]?\)?"
    r"|\(\d+\.\d+[a-z]?\)")
_NUMBER = re.compile(r"\d+(?:\.\d+)?(?:[eE][+-]?\d+)?")


def solution_problems(exercise: Exercise, variant: Variant) -> list[str]:
    """Why the worked solution of ``variant`` cannot be handed out; empty when it can (or
    when the exercise has no solution: :func:`missing_solution` reports that)."""
    try:
        text = render_solution(exercise, variant)
    except SolutionError as error:
        return [str(error)]
    if text is None:
        return []
    problems = []
    for part in exercise.parts:
        shown = part.shown_answer(variant.answers[part.name])
        if shown not in text:
            problems.append(f"solution: part {part.name}'s answer {shown!r} does not "
                            "appear in it")
    allowed = sorted(set(_variant_numbers(exercise, variant)))
    for number in stray_numbers(text, allowed):
        problems.append(f"solution: it prints {number}, which is no value of this "
                        "variant (write the solver's value, e.g. {{ si.name }}, not a "
                        "number)")
    return problems


def missing_solution(exercise: Exercise) -> str | None:
    """The finding for an exercise without a worked solution, ``None`` when it has one."""
    if exercise.solution is None:
        return "no worked solution (solution=...) yet"
    return None


def bank_is_complete(folder: Path | None = None) -> bool:
    """Whether every exercise file in ``folder`` (the shipped bank by default) declares a
    worked solution: from then on, ``verify`` fails an exercise without one."""
    folder = folder or builtin_bank()
    return all(load_file(path).solution is not None for path in exercise_files(folder))


def stray_numbers(text: str, allowed: Iterable[float]) -> list[str]:
    """The numbers in ``text`` that are neither small integers nor within
    :data:`MATCH_RTOL` of a value in ``allowed`` (compared by magnitude)."""
    values = sorted({abs(v) for v in allowed})
    stray = []
    for token in _NUMBER.findall(_REFERENCE.sub(" ", text)):
        number = float(token)
        if number.is_integer() and number <= SMALL_INTEGER:
            continue
        if not any(math.isclose(number, v, rel_tol=MATCH_RTOL) for v in values):
            if token not in stray:
                stray.append(token)
    return stray


def _variant_numbers(exercise: Exercise, variant: Variant) -> Iterator[float]:
    """Every value a solution may print for ``variant`` (see the module docstring)."""
    yield from _floats(variant.params.values())
    yield from _floats(variant.answers.values())
    printed = list(solver_values(exercise, variant).values())
    if prints_checks(exercise):
        printed += check_values(exercise, variant).values()
    for value in printed:
        for number in _floats([value]):
            yield number
            yield math.degrees(number)


def _floats(values: Iterable[Any]) -> Iterator[float]:
    for value in values:
        if hasattr(value, "tolist"):  # a numpy array or number
            value = value.tolist()
        if isinstance(value, (list, tuple)):
            yield from _floats(value)
        elif isinstance(value, (int, float)) and not isinstance(value, bool):
            if math.isfinite(float(value)):
                yield float(value)
