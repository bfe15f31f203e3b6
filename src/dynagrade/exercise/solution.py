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
  ``{{ si.r[0] }}`` a vector's component.

The solution is rendered from the parameter values alone (the solver runs again), so an
exam manifest, which stores each variant's parameters, is all a later rendering needs.
jinja2 is imported when a solution is first checked or rendered, as for statements.
"""

from __future__ import annotations

import math
from functools import lru_cache
from typing import TYPE_CHECKING, Any, Iterator, Mapping

from ..errors import DefinitionError
from .numbers import answer_text
from .statement import ShownValue

if TYPE_CHECKING:
    import jinja2
    from jinja2 import nodes

    from .model import Exercise, Variant

#: the names a solution template may use besides the exercise's parameters
CONTEXT_NAMES = ("answers", "si")


class SolutionError(DefinitionError):
    """A solution template that does not compile, names what it cannot have, or fails to
    render for a variant; the message names the exercise and what is wrong."""


class SiValue:
    """A value the solver returned (or a parameter), in SI, as a solution prints it."""

    def __init__(self, value: Any):
        self.value = value.tolist() if hasattr(value, "tolist") else value

    def __str__(self) -> str:
        return answer_text(self.value)

    def __float__(self) -> float:
        return float(self.value)

    def __abs__(self) -> SiValue:
        return SiValue(_map(abs, self.value))

    def __neg__(self) -> SiValue:
        return SiValue(_map(lambda v: -v, self.value))

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


def degrees(value) -> str:
    """The ``deg`` filter: an angle in radians (a number or an ``si`` value) in degrees."""
    return answer_text(_map(math.degrees, getattr(value, "value", value)))


def _map(function, value):
    if isinstance(value, (list, tuple)):
        return tuple(function(float(v)) for v in value)
    return function(float(value))


@lru_cache(maxsize=1)
def _environment() -> jinja2.Environment:
    import jinja2

    environment = jinja2.Environment(undefined=jinja2.StrictUndefined, autoescape=False,
                                     keep_trailing_newline=False)
    environment.filters["deg"] = degrees
    return environment


@lru_cache(maxsize=512)
def compile_solution(source: str) -> jinja2.Template:
    """The compiled template; a syntax error (or an unknown filter) names the line."""
    import jinja2

    try:
        return _environment().from_string(source)
    except jinja2.TemplateSyntaxError as error:
        raise SolutionError(f"solution template, line {error.lineno}: "
                            f"{error.message}") from None


def check_solution(exercise: Exercise) -> None:
    """Refuse a solution template that does not compile or names context it cannot have:
    a top-level name that is no parameter, ``answers`` or ``si``, or ``answers.X`` for an
    ``X`` that is no part. (``si.X`` depends on what the solver returns; rendering checks
    it, and ``dynagrade verify`` renders every variant.)"""
    from jinja2 import meta

    if exercise.solution is None:
        return
    where = f"exercise {exercise.id!r}"
    try:
        compile_solution(exercise.solution)
    except SolutionError as error:
        raise SolutionError(f"{where}: {error}") from None
    tree = _environment().parse(exercise.solution)
    known = {p.name for p in exercise.params} | set(CONTEXT_NAMES)
    unknown = sorted(meta.find_undeclared_variables(tree) - known)
    if unknown:
        raise SolutionError(f"{where}: the solution template names {unknown}, which are "
                            f"neither parameters nor {' or '.join(CONTEXT_NAMES)}")
    parts = {p.name for p in exercise.parts}
    asked = sorted(set(_members(tree, "answers")) - parts)
    if asked:
        raise SolutionError(f"{where}: the solution template prints answers.{asked[0]}, but "
                            f"the exercise has no part {asked[0]!r}; its parts are "
                            f"{sorted(parts)}")


def _members(tree: nodes.Template, name: str) -> Iterator[str]:
    """Every ``X`` of ``name.X`` and ``name["X"]`` in the template."""
    from jinja2 import nodes

    for node in tree.find_all((nodes.Getattr, nodes.Getitem)):
        if isinstance(node.node, nodes.Name) and node.node.name == name:
            if isinstance(node, nodes.Getattr):
                yield node.attr
            elif isinstance(node.arg, nodes.Const) and isinstance(node.arg.value, str):
                yield node.arg.value


def solution_context(exercise: Exercise, variant: Variant) -> dict[str, Any]:
    """The names a solution template sees for ``variant`` (see the module's docstring)."""
    answers = {part.name: part.shown_answer(variant.answers[part.name])
               for part in exercise.parts}
    si = {name: SiValue(value) for name, value in solver_values(exercise, variant).items()}
    shown = {p.name: ShownValue(p, variant.params[p.name]) for p in exercise.params}
    return {**shown, "answers": _Named("answers", answers), "si": _Named("si", si)}


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
