"""The exercise and its variants.

Usage (an exercise file defines ``EXERCISE``)::

    variant = EXERCISE.variant(seed=7)
    variant.params      # {"v0": 12.5, "alpha": 30.0, ...} in the declared units
    variant.answers     # {"x_max": 13.8, "x_max_formula": "v0^2*sin(2*alpha)/g"}
    variant.statement   # Markdown with the numbers filled in
"""

from __future__ import annotations

import math
import re
from contextlib import contextmanager
from contextvars import ContextVar
from dataclasses import dataclass, field, replace
from typing import Any, Callable, Mapping

from ..errors import DefinitionError, DynagradeError, UnknownParameter, UnknownPart
from .checks.base import Check
from .listing import chapter_of, summary
from .params import (Constraint, DrawTally, Parameter, ParamValues, symbol_domain,
                     to_si_values)
from .parts import Part, Variable
from .solution_template import check_solution
from .source_lines import failure_line
from .statement import compile_statement, render_statement

_ID = re.compile(r"^[a-z0-9]+(-[a-z0-9]+)*$")
_MAX_DRAWS = 1000

#: True while the loader runs an exercise file: the exercises it builds leave their
#: templates to the loader (:func:`templates_checked_by_caller`).
_CALLER_CHECKS_TEMPLATES: ContextVar[bool] = ContextVar("caller_checks_templates",
                                                        default=False)


@contextmanager
def templates_checked_by_caller():
    """Within this block, building an :class:`Exercise` does not compile its statement and
    solution templates; whoever builds it calls :meth:`Exercise.check_templates` when
    it needs them. The loader runs exercise files so, and checks the templates right
    after, unless the command renders neither (``grade FILE`` only grades, and so does
    not import jinja2)."""
    token = _CALLER_CHECKS_TEMPLATES.set(True)
    try:
        yield
    finally:
        _CALLER_CHECKS_TEMPLATES.reset(token)


class SolverError(DynagradeError, ValueError):
    """An exercise's solver raised for a variant; the message is one line naming the file
    and line, the exercise and the seed."""


class ConstraintError(DynagradeError, ValueError):
    """No draw of the parameters met the exercise's constraints."""


@dataclass(frozen=True)
class Variant:
    """One exercise with its numbers: fully determined by ``(exercise_id, seed)``.

    ``params`` are in the parameters' declared units, ``answers`` in the parts' units
    (symbolic parts hold their expression, choice parts their option label).
    ``warnings`` lists constraints that overridden values broke. ``statement`` is empty
    in a variant made only to be graded (``grade FILE``, a class's grading).
    """

    exercise_id: str
    seed: int
    params: dict[str, float]
    answers: dict[str, Any]
    statement: str
    warnings: tuple[str, ...] = ()

    def to_json(self) -> dict:
        answers = {k: list(v) if isinstance(v, tuple) else v for k, v in self.answers.items()}
        return {"id": self.exercise_id, "seed": self.seed, "params": dict(self.params),
                "statement": self.statement, "answers": answers}


@dataclass(frozen=True)
class Exercise:
    """An exercise template: parameters, constraints, statement, solver and parts.

    ``solve(p)`` receives the parameters in SI (``p.alpha`` in radians) and returns the
    reference answer of every non-symbolic part, in SI, by calling the mechanics core;
    it may return extra keys beside the parts' names (intermediate quantities for the
    worked ``solution``, never graded). ``solution`` is a jinja2 template of Markdown
    (:mod:`.solution`). ``figure(p)`` draws the variant; ``figure_to_scale`` says whether
    its lengths and angles are those of the variant (the caption says "drawn to scale"
    only then) or it is a schematic. ``checks`` recompute keys by other routes than the
    solver's (:mod:`.checks`); ``dynagrade verify`` runs them on every variant.

    The loader sets ``path`` (the file it came from) and ``fingerprint`` (the SHA-256 of
    that file's bytes): the exercise's identity, the key for anything cached about it.
    """

    id: str
    title: str
    source: str
    params: tuple[Parameter, ...]
    statement: str
    solve: Callable[[ParamValues], Mapping[str, Any]]
    parts: tuple[Part, ...]
    topics: tuple[str, ...] = ()
    constraints: tuple[Constraint, ...] = ()
    chapter: int | None = None
    figure: Callable[[ParamValues], Any] | None = None
    figure_to_scale: bool = False
    solution: str | None = None
    checks: tuple[Check, ...] = ()
    path: str | None = field(default=None, compare=False)
    fingerprint: str | None = field(default=None, compare=False)
    _draw: list = field(default_factory=list, init=False, repr=False, compare=False)
    _templates_checked: bool = field(default=False, init=False, repr=False, compare=False)

    def __post_init__(self):
        if not _ID.match(self.id):
            raise DefinitionError(f"exercise id {self.id!r} is not kebab-case (a-z, 0-9, '-')")
        _require_unique("parameter", [p.name for p in self.params], self.id)
        _require_unique("part", [p.name for p in self.parts], self.id)
        clash = {p.name for p in self.params} & {p.name for p in self.parts}
        if clash:
            raise DefinitionError(f"exercise {self.id!r}: {sorted(clash)} name both a "
                                  "parameter and a part")
        if not self.parts:
            raise DefinitionError(f"exercise {self.id!r} has no answer parts")
        _require_earlier_references(self.id, self.parts)
        object.__setattr__(self, "parts", tuple(
            _with_parameter_domains(self.id, part, self.params) for part in self.parts))
        for part in self.parts:
            _require_readable_names(self.id, part)
        if self.chapter is None:
            object.__setattr__(self, "chapter", chapter_of(self.source))
        object.__setattr__(self, "topics", tuple(self.topics))
        object.__setattr__(self, "checks", tuple(self.checks))
        _require_check_names(self.id, self.checks)
        if not _CALLER_CHECKS_TEMPLATES.get():
            self.check_templates()

    def check_templates(self) -> None:
        """Refuse a statement or worked-solution template that does not compile or names
        what it cannot have (:func:`~.solution_template.check_solution`); checked once per exercise,
        when it is built (or, for an exercise file, when the loader has run it)."""
        if self._templates_checked:
            return
        compile_statement(self.statement)
        check_solution(self.id, self.solution, (p.name for p in self.params),
                       (p.name for p in self.parts))
        object.__setattr__(self, "_templates_checked", True)

    # -- parameters -------------------------------------------------------------------

    @property
    def file(self) -> str:
        """The file the exercise was loaded from (``path``); an exercise built in code,
        which has none, cannot go into an exam's manifest."""
        if self.path is None:
            raise DefinitionError(f"exercise {self.id!r} was not loaded from a file")
        return self.path

    def parameter(self, name: str) -> Parameter:
        for p in self.params:
            if p.name == name:
                return p
        raise UnknownParameter(f"exercise {self.id!r} has no parameter {name!r}; "
                               f"it has {[p.name for p in self.params]}")

    def part(self, name: str) -> Part:
        for p in self.parts:
            if p.name == name:
                return p
        raise UnknownPart(f"exercise {self.id!r} has no part {name!r}; "
                          f"it has {[p.name for p in self.parts]}")

    def draw(self, seed: int, overrides: Mapping[str, float] | None = None,
             strict: bool = True, tally: DrawTally | None = None,
             ) -> tuple[dict[str, float], tuple[str, ...]]:
        """Parameter values (declared units) for ``seed`` that meet every constraint.

        Values in ``overrides`` are fixed; the others are redrawn until the constraints
        hold. With ``strict=False`` a draw whose overridden values break a constraint is
        returned with the broken constraints' descriptions instead of raising. ``tally``,
        when given, counts every draw taken and the constraints it broke.
        """
        import numpy as np  # here, not at import: listing the bank builds no draw

        overrides = dict(overrides or {})
        for name in overrides:
            self.parameter(name)
        rng = np.random.default_rng(seed)
        first: tuple[dict[str, float], list[str]] | None = None
        broken_counts: dict[str, int] = {}
        for _ in range(_MAX_DRAWS):
            values = {p.name: p.draw(rng) for p in self.params}
            values.update(overrides)
            broken = self.broken_constraints(values)
            if tally is not None:
                tally.record(broken)
            if not broken:
                return values, ()
            first = first or (values, broken)
            for description in broken:
                broken_counts[description] = broken_counts.get(description, 0) + 1
            if not any(p.varies for p in self.params if p.name not in overrides):
                break
        # every draw that is not returned is remembered, so ``first`` is set here
        if not strict and first is not None:
            return first[0], tuple(first[1])
        worst = max(broken_counts, key=broken_counts.__getitem__)
        raise ConstraintError(f"exercise {self.id!r}, seed {seed}: no draw of the parameters "
                              f"meets the constraint '{worst}'")

    def broken_constraints(self, values: Mapping[str, float]) -> list[str]:
        """Descriptions of the constraints that ``values`` (declared units) break."""
        si = self.si(values)
        return [c.description for c in self.constraints if not c.check(si)]

    # -- variants ---------------------------------------------------------------------

    def si(self, values: Mapping[str, float]) -> ParamValues:
        """Parameter values in SI, as the solver and the misconceptions receive them.

        The values of the latest draw give the same :class:`ParamValues` again, so what
        the constraints computed with :func:`~dynagrade.exercise.params.per_draw` the
        solver reuses when the draw becomes a variant.
        """
        key = tuple(sorted((name, float(values[name])) for name in values))
        if self._draw and self._draw[0] == key:
            return self._draw[1]
        si = to_si_values(self.params, values)
        self._draw[:] = [key, si]
        return si

    def solve_in_part_units(self, values: Mapping[str, float],
                            finite: bool = True) -> dict[str, Any]:
        """Every part's reference answer for ``values``, in the part's unit; a
        non-finite one is a :class:`DefinitionError` unless ``finite`` is false."""
        solved = self.solve(self.si(values))
        answers = {}
        for part in self.parts:
            answer = part.reference(solved)
            if finite:
                _require_finite(answer, self.id, part.name)
            answers[part.name] = answer
        return answers

    def variant(self, seed: int, overrides: Mapping[str, float] | None = None,
                strict: bool = True, tally: DrawTally | None = None,
                with_statement: bool = True) -> Variant:
        """The variant for ``seed`` (with ``overrides`` fixed, in declared units);
        ``tally`` counts the draws it takes (:meth:`draw`). ``with_statement=False``
        leaves the statement empty, for a variant that is only graded."""
        values, warnings = self.draw(seed, overrides, strict=strict, tally=tally)
        return self.variant_from_params(seed, values, warnings, with_statement)

    def variant_set(self, seed: int, overrides: Mapping[str, float],
                    finite: bool = True) -> Variant:
        """The variant of ``seed`` with ``overrides`` fixed (declared units) and every
        other parameter as the seed alone draws it, so that setting one value changes
        nothing else (``dynagrade solve --seed S --set X=...``). The constraints the
        values break are the variant's warnings; ``finite=False`` keeps a non-finite
        reference answer instead of refusing it."""
        for name in overrides:
            self.parameter(name)
        values, _ = self.draw(seed, strict=False)
        values.update(overrides)
        return self.variant_from_params(seed, values, tuple(self.broken_constraints(values)),
                                        finite=finite)

    def variant_from_params(self, seed: int, values: Mapping[str, float],
                            warnings: tuple[str, ...] = (),
                            with_statement: bool = True, finite: bool = True) -> Variant:
        """The variant with these parameter values, e.g. as stored in an exam manifest. A
        solver that raises is a :class:`SolverError` of one line naming the file, the
        exercise and the seed; a non-finite reference answer is refused unless
        ``finite`` is false."""
        values = {p.name: float(values[p.name]) for p in self.params}
        try:
            answers = self.solve_in_part_units(values, finite)
        except DynagradeError:
            raise
        except Exception as error:  # the author's solver: reported, never a traceback
            raise SolverError(failure_line(
                self.path, self.solve, error,
                f"exercise {self.id!r}, seed {int(seed)}: the solver fails")) from None
        return Variant(
            exercise_id=self.id,
            seed=int(seed),
            params=values,
            answers=answers,
            statement=(render_statement(self.statement, self.params, values)
                       if with_statement else ""),
            warnings=tuple(warnings),
        )

    def summary(self) -> dict:
        """The exercise's identity and parts, as ``dynagrade list --json`` prints them."""
        return summary(self)





def _require_unique(what: str, names: list[str], exercise_id: str) -> None:
    seen = set()
    for name in names:
        if name in seen:
            raise DefinitionError(f"exercise {exercise_id!r} declares the {what} {name!r} "
                                  "twice")
        seen.add(name)


def _require_check_names(exercise_id: str, checks: tuple[Check, ...]) -> None:
    """Every check has a name a worked solution can print it by (``{{ checks.name }}``),
    and no two share one."""
    for check in checks:
        if not isinstance(check, Check):
            raise DefinitionError(f"exercise {exercise_id!r}: {check!r} in checks= is no "
                                  "check (dynagrade.exercise.checks)")
        if not check.name.isidentifier():
            raise DefinitionError(f"exercise {exercise_id!r}: the check name "
                                  f"{check.name!r} is no identifier (letters, digits, _)")
    _require_unique("check", [c.name for c in checks], exercise_id)


def _with_parameter_domains(exercise_id: str, part: Part,
                            params: tuple[Parameter, ...]) -> Part:
    """The part with a domain and a printed symbol for each of its symbols that names a
    parameter.

    A symbolic part's ``variables`` may be a sequence of names, or map a name to ``None``
    or to a ``Variable`` without bounds (``Variable(aliases=("v_2(0)",))``): such a symbol
    must be a parameter, and takes the parameter's unit and widened bounds
    (:func:`~dynagrade.exercise.params.symbol_domain`). A symbol that names a parameter
    takes the parameter's printed symbol unless it declares its own. ``Variable(min, max,
    unit)`` is written only where the domain differs, or for a symbol that is no parameter.
    """
    variables = getattr(part, "variables", None)
    if variables is None:
        return part
    named = dict(variables) if isinstance(variables, Mapping) else dict.fromkeys(variables)
    by_name = {p.name: p for p in params}
    missing = [name for name, v in named.items()
               if (v is None or not v.has_domain) and name not in by_name]
    if missing:
        raise DefinitionError(
            f"exercise {exercise_id!r}, part {part.name!r}: the symbols {missing} are no "
            f"parameters, so they need a domain: Variable(min, max, unit); the parameters "
            f"are {list(by_name)}")
    return part.with_variables({
        name: _with_parameter(variable, by_name.get(name)) for name, variable in named.items()})


def _with_parameter(variable: Variable | None, parameter: Parameter | None) -> Variable:
    """A formula's variable completed from the parameter of the same name (if any)."""
    if parameter is None:
        if variable is None:  # refused by the caller: a symbol no parameter names
            raise DefinitionError("a formula's symbol that is no parameter needs a domain")
        return variable
    if variable is None:
        return symbol_domain(parameter)
    if not variable.has_domain:
        domain = symbol_domain(parameter)
        return replace(domain, unit=variable.unit or domain.unit,
                       symbol=variable.symbol or domain.symbol, aliases=variable.aliases)
    if variable.symbol is None:
        return replace(variable, symbol=parameter.symbol)
    return variable


def _require_readable_names(exercise_id: str, part: Part) -> None:
    """The part's names make a specification the grader accepts: no alias of a formula's
    variable is another variable, a function or a unit; no number or alias of a choice
    names two options."""
    try:
        part.check_names()
    except ValueError as error:
        raise DefinitionError(f"exercise {exercise_id!r}, part {part.name!r}: {error}") from None


def _require_earlier_references(exercise_id: str, parts: tuple[Part, ...]) -> None:
    """Every part that another part's ``equals`` or ``uses`` names is declared before it.

    A Symbolic part's ``equals`` is checked against an earlier numeric answer, and a
    Numeric part's ``uses`` are the earlier answers its follow-through recomputes from:
    both are read when a variant is verified or a student graded, so a typo must fail
    here, when the exercise is built, and not there.
    """
    for index, part in enumerate(parts):
        earlier = [p.name for p in parts[:index]]
        equals = getattr(part, "equals", None)
        named = [("equals", equals)] if equals is not None else []
        named += [("uses", name) for name in getattr(part, "uses", ())]
        for field_name, name in named:
            if name not in earlier:
                where = ("comes after it" if name in {p.name for p in parts}
                         else "does not exist")
                raise DefinitionError(
                    f"exercise {exercise_id!r}, part {part.name!r}: {field_name}={name!r} "
                    f"names a part that {where}; the parts before it are {earlier}")


def _require_finite(answer: Any, exercise_id: str, part: str) -> None:
    values = answer if isinstance(answer, tuple) else (answer,)
    for value in values:
        if isinstance(value, float) and not math.isfinite(value):
            raise DefinitionError(f"exercise {exercise_id!r}: the reference answer of part "
                                  f"{part!r} is {value}")
