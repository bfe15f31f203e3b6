"""Checking an exercise for variants that cannot tell right from wrong.

For each seed: the constraints can be met, the statement renders, the reference answers
are finite and pass their own part, an answer 5 % off fails, every declared
misconception fails, and each symbolic part's expression reproduces the numeric part it
``equals`` at the variant's parameters (a cross-check of formula against mechanics core).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Iterable

from ..grading import evaluate_expression, grade
from .model import ConstraintError, Exercise, Variant
from .numbers import format_number
from .params import ParamValues
from .parts import Numeric, Options, Part, Symbolic, Vector
from .statement import referenced_names
from .units import to_si

PERTURBATION = 0.05
CROSS_CHECK_RTOL = 1e-6


@dataclass
class VerifyReport:
    """What ``dynagrade verify`` found for one exercise."""

    exercise_id: str
    variants: int = 0
    failures: list[str] = field(default_factory=list)

    @property
    def ok(self) -> bool:
        return not self.failures


def verify_exercise(exercise: Exercise, seeds: Iterable[int]) -> VerifyReport:
    """Every check of the module docstring, for each of ``seeds``."""
    report = VerifyReport(exercise.id)
    report.failures += static_problems(exercise)
    for seed in seeds:
        report.variants += 1
        try:
            variant = exercise.variant(seed)
        except ConstraintError as error:
            report.failures.append(str(error))
            continue
        except Exception as error:  # an author's solver or template failing is a finding
            report.failures.append(f"seed {seed}: {type(error).__name__}: {error}")
            continue
        report.failures += [f"seed {seed}: {p}" for p in variant_problems(exercise, variant)]
    return report


def static_problems(exercise: Exercise) -> list[str]:
    """Problems that do not depend on the seed: parameters the statement never shows."""
    shown = referenced_names(exercise.statement)
    return [f"the statement never shows the parameter {p.name!r}"
            for p in exercise.params if p.varies and p.name not in shown]


def variant_problems(exercise: Exercise, variant: Variant) -> list[str]:
    """Why ``variant`` cannot be handed out; empty when it can."""
    params = exercise.si(variant.params)
    problems = []
    for part in exercise.parts:
        expected = variant.answers[part.name]
        spec = part.spec(params)
        if not grade(spec, expected, _as_text(part, expected)).correct:
            problems.append(f"part {part.name}: the reference answer fails its own part")
        for wrong, what in _nearby_wrong_answers(part, expected):
            if grade(spec, expected, wrong).correct:
                problems.append(f"part {part.name}: {what} is accepted")
        for misconception in part.misconceptions:
            value = misconception.value
            wrong = value if isinstance(value, str) else _as_text(part, part.in_part_unit(value(params)))
            if grade(spec, expected, wrong).correct:
                problems.append(f"part {part.name}: the misconception "
                                f"'{misconception.name}' gives the right answer")
        if isinstance(part, Symbolic) and part.equals:
            problems += _cross_check(exercise, part, variant, params)
    return problems


def _cross_check(exercise: Exercise, part: Symbolic, variant: Variant,
                 params: ParamValues) -> list[str]:
    target = exercise.part(part.equals)
    value = to_si(variant.answers[target.name], target.unit)
    formula = evaluate_expression(part.expected, dict(params))
    if abs(formula - value) > CROSS_CHECK_RTOL * max(abs(value), 1e-300):
        return [f"part {part.name}: the formula gives {format_number(formula)} in SI but "
                f"the core gives {format_number(value)} for part {target.name}"]
    return []


def _nearby_wrong_answers(part: Part, expected) -> list[tuple[str, str]]:
    """Answers that must be wrong: 5 % off, or another option."""
    factor = 1 + PERTURBATION
    if isinstance(part, Numeric) and expected != 0:
        return [(_as_text(part, expected * factor), "an answer 5 % too large")]
    if isinstance(part, Vector) and any(expected):
        return [(_as_text(part, tuple(v * factor for v in expected)),
                 "a vector 5 % too long")]
    if isinstance(part, Symbolic):
        return [(f"{factor}*({expected})", "the formula times 1.05")]
    if isinstance(part, Options) and not part.multiple:
        return [(option, f"option {option!r}") for option in part.options if option != expected]
    if isinstance(part, Options):
        others = [o for o in part.options if o not in expected]
        wrong = expected[:-1] if len(expected) > 1 else expected + tuple(others[:1])
        return [(", ".join(wrong), "a different set of options")] if others or len(expected) > 1 else []
    return []


def _as_text(part: Part, value) -> str:
    """A reference value written as a student would write it, to 12 significant figures."""
    if isinstance(part, Vector):
        return "[" + ", ".join(format_number(v, 12) for v in value) + "]"
    if isinstance(part, Numeric):
        return format_number(value, 12)
    if isinstance(value, tuple):
        return ", ".join(value)
    return str(value)
