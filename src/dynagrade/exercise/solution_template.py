"""An exercise's worked-solution template: its environment, compiling it, and the check
that it names only what a solution's context holds (docs/authoring.md, "Worked
solutions"). The model checks an exercise's template here when it is built; rendering it
for a variant is :mod:`.solution`.

jinja2 is imported when a solution is first checked or rendered, as for statements.
"""

from __future__ import annotations

import math
from functools import lru_cache
from typing import TYPE_CHECKING, Iterable, Iterator

from ..errors import DefinitionError
from .numbers import answer_text

if TYPE_CHECKING:
    import jinja2
    from jinja2 import nodes


#: the names a solution template may use besides the exercise's parameters
CONTEXT_NAMES = ("answers", "si", "checks")


class SolutionError(DefinitionError):
    """A solution template that does not compile, names what it cannot have, or fails to
    render for a variant; the message names the exercise and what is wrong."""


def degrees(value) -> str:
    """The ``deg`` filter: an angle in radians (a number or an ``si`` value) in degrees."""
    return answer_text(map_value(math.degrees, getattr(value, "value", value)))


def map_value(function, value):
    """``function`` of a number, or of each component of a vector."""
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


def check_solution(exercise_id: str, source: str | None, params: Iterable[str],
                   parts: Iterable[str]) -> None:
    """Refuse the solution template ``source`` of exercise ``exercise_id`` if it does not
    compile or names context it cannot have: a top-level name that is no parameter,
    ``answers``, ``si`` or ``checks``, or ``answers.X`` for an ``X`` that is no part. (``si.X`` depends
    on what the solver returns; rendering checks it, and ``dynagrade verify`` renders every
    variant.)"""
    from jinja2 import meta

    if source is None:
        return
    where = f"exercise {exercise_id!r}"
    try:
        compile_solution(source)
    except SolutionError as error:
        raise SolutionError(f"{where}: {error}") from None
    tree = _environment().parse(source)
    known = set(params) | set(CONTEXT_NAMES)
    unknown = sorted(meta.find_undeclared_variables(tree) - known)
    if unknown:
        raise SolutionError(f"{where}: the solution template names {unknown}, which are "
                            f"neither parameters nor {' or '.join(CONTEXT_NAMES)}")
    parts = set(parts)
    asked = sorted(set(_members(tree, "answers")) - parts)
    if asked:
        raise SolutionError(f"{where}: the solution template prints answers.{asked[0]}, but "
                            f"the exercise has no part {asked[0]!r}; its parts are "
                            f"{sorted(parts)}")


def _members(tree: nodes.Template, name: str) -> Iterator[str]:
    """Every ``X`` of ``name.X`` and ``name["X"]`` in the template."""
    from jinja2 import nodes

    for node in tree.find_all((nodes.Getattr, nodes.Getitem)):
        if not (isinstance(node, (nodes.Getattr, nodes.Getitem))
                and isinstance(node.node, nodes.Name) and node.node.name == name):
            continue
        if isinstance(node, nodes.Getattr):
            yield node.attr
        elif isinstance(node.arg, nodes.Const) and isinstance(node.arg.value, str):
            yield node.arg.value
