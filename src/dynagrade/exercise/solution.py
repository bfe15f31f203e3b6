"""An exercise's worked solution: a jinja2 template of Markdown with ``$...$`` math,
filled with one variant's numbers.

The template's context (docs/authoring.md, "Worked solutions"):

- every parameter as the statement shows it: ``{{ v0 }}`` prints ``12.5 m/s``,
  ``{{ v0.value }}`` the number, ``{{ v0.unit }}``, ``{{ v0.symbol }}``;
- ``{{ answers.x_max }}``: a part's reference answer as the key prints it, with its unit
  (a Symbolic part's expected formula, a choice part's option);
- ``{{ si.t_peak }}``: any value the solver returned -- the parts' answers and the extra
  keys it returns beside them (intermediate quantities, never graded) -- in SI, printed
  with the project's number formatter and without a unit; ``{{ si.alpha }}`` is also every
  parameter in SI (a value the solver returns under the same name wins);
  ``{{ si.alpha | deg }}`` prints an angle in degrees, ``{{ si.a | abs }}`` a magnitude,
  ``{{ si.r[0] }}`` a vector's component;
- ``{{ checks.frictionless }}``: what the exercise's check of that name recomputed by its
  own route (:mod:`.checks`), in SI like ``si``: the number a closing sanity line
  ("with mu -> 0 this is the frictionless ...") prints, which ``verify`` has compared with
  the key. The checks run only when the template names ``checks``.

The solution is rendered from the parameter values alone (the solver runs again), so an
exam manifest, which stores each variant's parameters, is all a later rendering needs.
Its template is checked when the exercise is built (:mod:`.solution_template`); jinja2 is
imported when a solution is first checked or rendered, as for statements.
"""

from __future__ import annotations

import re
from typing import Any, Iterator, Mapping

from .model import Exercise, Variant
from .numbers import answer_text
from .solution_template import SolutionError, compile_solution, map_value
from .statement import ShownValue

class SiValue:
    """A value the solver returned (or a parameter), in SI, as a solution prints it."""

    def __init__(self, value: Any):
        self.value = value.tolist() if hasattr(value, "tolist") else value

    def __str__(self) -> str:
        return answer_text(self.value)

    def __float__(self) -> float:
        return float(self.value)

    def __abs__(self) -> SiValue:
        return SiValue(map_value(abs, self.value))

    def __neg__(self) -> SiValue:
        return SiValue(map_value(lambda v: -v, self.value))

    def __getitem__(self, index: int) -> SiValue:
        if not isinstance(self.value, (list, tuple)):
            raise SolutionError(f"{self} is not a vector: it has no component {index}")
        return SiValue(self.value[index])

    def __len__(self) -> int:
        return len(self.value) if isinstance(self.value, (list, tuple)) else 1


class _Named(Mapping[str, Any]):
    """``answers`` or ``si`` in the template: values by name, read as ``si.name``; a name
    it lacks is an error saying which names there are."""

    def __init__(self, what: str, values: Mapping[str, Any]):
        self._what = what
        self._values = dict(values)

    def __getattr__(self, name: str):
        if name.startswith("_"):
            raise AttributeError(name)
        return self[name]

    def __getitem__(self, name: str):
        try:
            return self._values[name]
        except KeyError:
            raise SolutionError(f"{self._what} has no {name!r}; it has "
                                f"{sorted(self._values)}") from None

    def __iter__(self) -> Iterator[str]:
        return iter(self._values)

    def __len__(self) -> int:
        return len(self._values)


def solution_context(exercise: Exercise, variant: Variant) -> dict[str, Any]:
    """The names a solution template sees for ``variant`` (see the module's docstring)."""
    answers = {part.name: part.shown_answer(variant.answers[part.name])
               for part in exercise.parts}
    si = {name: SiValue(value) for name, value in solver_values(exercise, variant).items()}
    shown = {p.name: ShownValue(p, variant.params[p.name]) for p in exercise.params}
    return {**shown, "answers": _Named("answers", answers), "si": _Named("si", si),
            "checks": _Checks(exercise, variant)}


class _Checks(_Named):
    """``checks`` in the template: each check's recomputed value, computed when the
    template first reads one (most solutions print none)."""

    def __init__(self, exercise: Exercise, variant: Variant):
        super().__init__("checks", {})
        self._source: tuple[Exercise, Variant] | None = (exercise, variant)

    def __getitem__(self, name: str):
        if self._source is not None:
            exercise, variant = self._source
            self._source = None
            self._values = {name: SiValue(value) for name, value
                            in check_values(exercise, variant).items()}
        return super().__getitem__(name)


_CHECKS_IN_TEMPLATE = re.compile(r"\{\{[^}]*\bchecks\b")


def prints_checks(exercise: Exercise) -> bool:
    """Whether the exercise's worked solution prints a check's value (``{{ checks.x }}``)."""
    return exercise.solution is not None and bool(_CHECKS_IN_TEMPLATE.search(exercise.solution))


#: the latest variant's check values, as (exercise, its parameters, values): rendering a
#: solution and checking its numbers ask for the same variant's, which run integrations
_LATEST_CHECKS: list = []


def check_values(exercise: Exercise, variant: Variant) -> dict[str, Any]:
    """Each of the exercise's checks' recomputed value for ``variant``, in SI, by the
    check's name (the latest variant's are kept)."""
    from .checks.run import recomputed_values

    params = dict(variant.params)
    if _LATEST_CHECKS and _LATEST_CHECKS[0] is exercise and _LATEST_CHECKS[1] == params:
        return dict(_LATEST_CHECKS[2])
    values = recomputed_values(exercise, exercise.si(variant.params))
    _LATEST_CHECKS[:] = [exercise, params, values]
    return dict(values)


def solver_values(exercise: Exercise, variant: Variant) -> dict[str, Any]:
    """Every value a solution may print for ``variant``, in SI: the parameters and all the
    solver returned."""
    si_params = exercise.si(variant.params)
    return {**si_params, **exercise.solve(si_params)}


def render_solution(exercise: Exercise, variant: Variant) -> str | None:
    """The worked solution of ``variant`` as Markdown, or ``None`` when the exercise has
    none; :class:`SolutionError` names the exercise and seed when it cannot be rendered."""
    import jinja2

    if exercise.solution is None:
        return None
    where = f"exercise {exercise.id!r}, seed {variant.seed}: solution template"
    template = compile_solution(exercise.solution)
    try:
        return template.render(**solution_context(exercise, variant)).strip() + "\n"
    except (jinja2.UndefinedError, TypeError, ValueError) as error:
        raise SolutionError(f"{where}: {error}") from None



def as_comments(exercise: Exercise, solution: str | None) -> str:
    """The worked solution as comment lines closing a fill-in file (a practice sheet):
    a fill-in file is read as data, so comments never change what is graded."""
    lines = (solution or f"{exercise.id} has no worked solution yet.").splitlines()
    body = "\n".join(f"# {line}".rstrip() for line in lines)
    return (f"\n# -- Worked solution (try the exercise first) {'-' * 40}\n#\n"
            f"{body}\n")
