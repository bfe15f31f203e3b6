"""Checking an exercise for variants that cannot tell right from wrong.

For each seed: the constraints can be met, the statement renders, the reference answers
are finite and pass their own part, the part's near misses (an answer 5 % off, another
option) fail, every declared misconception fails, and each symbolic part's expression
reproduces the numeric part it ``equals`` at the variant's parameters (a cross-check of
formula against mechanics core). A misconception is tried only where it ``applies``; the
report counts the variants an exam would redraw and the draws the constraints reject
(:mod:`.redraws`). Once per exercise: every part answers a numbered question of the
statement and every question has a part, and every variable of a formula is shown in the
statement under a name the grader accepts (:mod:`.asked`), and every formula has the
dimension of the part it ``equals`` (:mod:`.checks.dimensions`). The exercise's
independent checks (:mod:`.checks`) run on every variant: a failing one is named with the
seed, the key's number, the recomputed one and the tolerance. What each kind tries is its
own (:mod:`dynagrade.exercise.parts`). The worked solution of every variant is checked too
(:mod:`.solution_check`), its math once per exercise by ``math_check`` (the render
layer's, handed in by the command); an exercise without a solution is a finding when
``require_solution`` is set (the command sets it once the shipped bank is complete, or
on request), otherwise a note. With ``render_figure`` (the render layer's SVG writer,
handed in by the command as ``math_check`` is), every variant's figure is drawn and
checked (:mod:`.figure_checks`): it does not fail, its SVG is well formed, and its text
shows no reference answer.

Variety (:mod:`.variety`): two parts whose numbers can be swapped and score are a problem
of the variant (an exam redraws it); a part whose answer is one answer in more than 90 %
of the variants checked (50 or more) fails the exercise, unless it declares the reason
(``constant_answer=``).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, Callable, Iterable

from ..grading.dispatch import accepts
from .asked import question_problems, unshown_variables
from .checks.dimensions import formula_dimension_problems
from .checks.run import check_problems
from .figure_checks import figure_problems
from .model import ConstraintError, Exercise, SolverError, Variant
from .params import ParamValues
from .parts import Part
from .redraws import NO_DRAW, RedrawShare
from .solution import SolutionError, render_solution
from .solution_check import missing_solution, solution_problems
from .statement import referenced_names
from .variety import coincidences, one_answer_problems


@dataclass
class VerifyReport:
    """What ``dynagrade verify`` found for one exercise."""

    exercise_id: str
    variants: int = 0
    failures: list[str] = field(default_factory=list)
    notes: list[str] = field(default_factory=list)
    redraws: RedrawShare = field(default_factory=RedrawShare)

    @property
    def ok(self) -> bool:
        return not self.failures


def verify_exercise(exercise: Exercise, seeds: Iterable[int], require_solution: bool = False,
                    math_check: Callable[[str], list[str]] | None = None,
                    render_figure: Callable[[Exercise, Variant], str | None] | None = None
                    ) -> VerifyReport:
    """Every check of the module docstring, for each of ``seeds``."""
    report = VerifyReport(exercise.id)
    report.failures += static_problems(exercise)
    missing = missing_solution(exercise)
    if missing:
        (report.failures if require_solution else report.notes).append(missing)
    math_checked = math_check is None or missing is not None
    drawn: list[tuple[int, dict]] = []  # (seed, answers) of every variant, for variety
    for seed in seeds:
        report.variants += 1
        try:
            variant = exercise.variant(seed, tally=report.redraws.tally)
        except ConstraintError as error:
            report.redraws.record([NO_DRAW])
            report.failures.append(str(error))
            continue
        except SolverError as error:  # one line that names file, exercise and seed
            report.failures.append(str(error))
            continue
        except Exception as error:  # an author's template failing is a finding too
            report.failures.append(f"seed {seed}: {type(error).__name__}: {error}")
            continue
        drawn.append((seed, variant.answers))
        problems = variant_problems(exercise, variant)
        report.redraws.record(problems)
        report.failures += [f"seed {seed}: {p}" for p in problems]
        report.failures += [f"seed {seed}: {p}"
                            for p in check_problems(exercise, exercise.si(variant.params))]
        report.failures += [f"seed {seed}: {p}" for p in solution_problems(exercise, variant)]
        if render_figure is not None:
            report.failures += figure_problems(exercise, variant, render_figure)
        if not math_checked and math_check is not None:
            math_checked = True
            report.failures += [f"seed {seed}: solution: {p}"
                                for p in _solution_math(exercise, variant, math_check)]
    report.failures += one_answer_problems(exercise, [seed for seed, _ in drawn],
                                           [answers for _, answers in drawn])
    return report


def _solution_math(exercise: Exercise, variant: Variant,
                   math_check: Callable[[str], list[str]]) -> list[str]:
    try:
        solution = render_solution(exercise, variant)
        return math_check(solution) if solution is not None else []
    except SolutionError:  # solution_problems reported it
        return []


def static_problems(exercise: Exercise) -> list[str]:
    """Problems that do not depend on the seed: parameters the statement never shows,
    and what it asks against the parts (:mod:`.asked`)."""
    shown = referenced_names(exercise.statement)
    return [f"the statement never shows the parameter {p.name!r}"
            for p in exercise.params if p.varies and p.name not in shown] + \
        question_problems(exercise) + unshown_variables(exercise) + \
        list(formula_dimension_problems(exercise))


#: the signature of :func:`part_own_problems`, which a cache of it shares
OwnProblems = Callable[[Exercise, Part, ParamValues, Any], tuple[str, ...]]


def variant_problems(exercise: Exercise, variant: Variant,
                     own_problems: OwnProblems | None = None) -> list[str]:
    """Why ``variant`` cannot be handed out; empty when it can. ``own_problems`` is
    :func:`part_own_problems` (the default) or a run's cache of it."""
    if own_problems is None:
        own_problems = part_own_problems
    params = exercise.si(variant.params)
    problems: list[str] = []
    for part in exercise.parts:
        problems += own_problems(exercise, part, params, variant.answers[part.name])
        problems += part.cross_check(params, variant.answers, exercise.part)
    return problems + coincidences(exercise, variant.answers)


def part_own_problems(exercise: Exercise, part: Part, params: ParamValues,
                      expected) -> tuple[str, ...]:
    """What is wrong with ``part`` on its own in the variant with ``params`` (in SI) and
    reference ``expected``: the reference fails its own part, a near miss or a
    misconception that applies is accepted. The outcome depends on no more than
    :meth:`Part.own_checks_key <dynagrade.exercise.parts.Part.own_checks_key>` says (with
    the part itself, which ``exercise`` holds)."""
    spec = part.spec(params)
    problems = []
    if not accepts(spec, expected, part.answer_text(expected)):
        problems.append(f"part {part.name}: the reference answer fails its own part")
    for wrong, what in part.near_misses(expected):
        if accepts(spec, expected, wrong):
            problems.append(f"part {part.name}: {what} is accepted")
    for misconception in part.misconceptions_for(params):
        wrong = part.misconception_answer(misconception, params)
        if accepts(spec, expected, wrong):
            problems.append(f"part {part.name}: the misconception "
                            f"'{misconception.name}' gives the right answer")
    return tuple(problems)
