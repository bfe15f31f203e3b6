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
from dataclasses import dataclass, field
from typing import Any, Callable, Mapping

import numpy as np

from .params import Constraint, Parameter, ParamValues, to_si_values
from .parts import Part
from .solution import check_solution
from .statement import compile_statement, render_statement

_ID = re.compile(r"^[a-z0-9]+(-[a-z0-9]+)*$")
_SOURCE_CHAPTER = re.compile(r"(\d+)(?:\.\d+)*")
_MAX_DRAWS = 1000


class ConstraintError(ValueError):
    """No draw of the parameters met the exercise's constraints."""


@dataclass(frozen=True)
class Variant:
    """One exercise with its numbers: fully determined by ``(exercise_id, seed)``.

    ``params`` are in the parameters' declared units, ``answers`` in the parts' units
    (symbolic parts hold their expression, choice parts their option label).
    ``warnings`` lists constraints that overridden values broke.
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
    (:mod:`.solution`).
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
    solution: str | None = None
    path: str | None = field(default=None, compare=False)

    def __post_init__(self):
        if not _ID.match(self.id):
            raise ValueError(f"exercise id {self.id!r} is not kebab-case (a-z, 0-9, '-')")
        _require_unique("parameter", [p.name for p in self.params], self.id)
        _require_unique("part", [p.name for p in self.parts], self.id)
        clash = {p.name for p in self.params} & {p.name for p in self.parts}
        if clash:
            raise ValueError(f"exercise {self.id!r}: {sorted(clash)} name both a parameter "
                             "and a part")
        if not self.parts:
            raise ValueError(f"exercise {self.id!r} has no answer parts")
        if self.chapter is None:
            match = _SOURCE_CHAPTER.search(self.source)
            object.__setattr__(self, "chapter", int(match.group(1)) if match else 0)
        object.__setattr__(self, "topics", tuple(self.topics))
        compile_statement(self.statement)
        check_solution(self)

    # -- parameters -------------------------------------------------------------------

    def parameter(self, name: str) -> Parameter:
        for p in self.params:
            if p.name == name:
                return p
        raise KeyError(f"exercise {self.id!r} has no parameter {name!r}; "
                       f"it has {[p.name for p in self.params]}")

    def part(self, name: str) -> Part:
        for p in self.parts:
            if p.name == name:
                return p
        raise KeyError(f"exercise {self.id!r} has no part {name!r}")

    def draw(self, seed: int, overrides: Mapping[str, float] | None = None,
             strict: bool = True) -> tuple[dict[str, float], tuple[str, ...]]:
        """Parameter values (declared units) for ``seed`` that meet every constraint.

        Values in ``overrides`` are fixed; the others are redrawn until the constraints
        hold. With ``strict=False`` a draw whose overridden values break a constraint is
        returned with the broken constraints' descriptions instead of raising.
        """
        overrides = dict(overrides or {})
        for name in overrides:
            self.parameter(name)
        rng = np.random.default_rng(seed)
        first = None
        broken_counts: dict[str, int] = {}
        for _ in range(_MAX_DRAWS):
            values = {p.name: p.draw(rng) for p in self.params}
            values.update(overrides)
            broken = self.broken_constraints(values)
            if not broken:
                return values, ()
            first = first or (values, broken)
            for description in broken:
                broken_counts[description] = broken_counts.get(description, 0) + 1
            if not any(p.varies for p in self.params if p.name not in overrides):
                break
        if not strict:
            return first[0], tuple(first[1])
        worst = max(broken_counts, key=broken_counts.get)
        raise ConstraintError(f"exercise {self.id!r}, seed {seed}: no draw of the parameters "
                              f"meets the constraint '{worst}'")

    def broken_constraints(self, values: Mapping[str, float]) -> list[str]:
        """Descriptions of the constraints that ``values`` (declared units) break."""
        si = to_si_values(self.params, values)
        return [c.description for c in self.constraints if not c.check(si)]

    # -- variants ---------------------------------------------------------------------

    def si(self, values: Mapping[str, float]) -> ParamValues:
        """Parameter values in SI, as the solver and the misconceptions receive them."""
        return to_si_values(self.params, values)

    def solve_in_part_units(self, values: Mapping[str, float]) -> dict[str, Any]:
        """Every part's reference answer for ``values``, in the part's unit."""
        solved = self.solve(self.si(values))
        answers = {}
        for part in self.parts:
            answer = part.reference(solved)
            _require_finite(answer, self.id, part.name)
            answers[part.name] = answer
        return answers

    def variant(self, seed: int, overrides: Mapping[str, float] | None = None,
                strict: bool = True) -> Variant:
        """The variant for ``seed`` (with ``overrides`` fixed, in declared units)."""
        values, warnings = self.draw(seed, overrides, strict=strict)
        return self.variant_from_params(seed, values, warnings)

    def variant_from_params(self, seed: int, values: Mapping[str, float],
                            warnings: tuple[str, ...] = ()) -> Variant:
        """The variant with these parameter values, e.g. as stored in an exam manifest."""
        values = {p.name: float(values[p.name]) for p in self.params}
        return Variant(
            exercise_id=self.id,
            seed=int(seed),
            params=values,
            answers=self.solve_in_part_units(values),
            statement=render_statement(self.statement, self.params, values),
            warnings=tuple(warnings),
        )

    def summary(self) -> dict:
        """The exercise's identity and parts, as ``dynagrade list --json`` prints them."""
        return {
            "id": self.id, "title": self.title, "source": self.source,
            "chapter": self.chapter, "topics": list(self.topics),
            "parts": [{"name": p.name, "kind": p.kind, "unit": p.unit, "points": p.points,
                       "label": p.label} for p in self.parts],
            "params": [{"name": p.name, "unit": p.unit, "symbol": p.symbol or p.name}
                       for p in self.params],
        }


def _require_unique(what: str, names: list[str], exercise_id: str) -> None:
    seen = set()
    for name in names:
        if name in seen:
            raise ValueError(f"exercise {exercise_id!r} declares the {what} {name!r} twice")
        seen.add(name)


def _require_finite(answer: Any, exercise_id: str, part: str) -> None:
    values = answer if isinstance(answer, tuple) else (answer,)
    for value in values:
        if isinstance(value, float) and not math.isfinite(value):
            raise ValueError(f"exercise {exercise_id!r}: the reference answer of part "
                             f"{part!r} is {value}")
