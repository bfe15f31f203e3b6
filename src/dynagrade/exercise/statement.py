"""Rendering an exercise's statement (a jinja2 template of Markdown with ``$...$`` math).

jinja2 is imported when a statement is first compiled, so that reading the bank's
listing, which builds no exercise, does not pay for it.
"""

from __future__ import annotations

from functools import lru_cache
from typing import TYPE_CHECKING, Mapping

from ..errors import DefinitionError
from .numbers import format_number
from .params import Parameter
from .units import pretty_unit, with_unit

if TYPE_CHECKING:
    import jinja2


class ShownValue:
    """A parameter as the statement shows it: ``{{ v0 }}`` prints ``12.5 m/s``,
    ``{{ v0.value }}`` the number, ``{{ v0.unit }}`` the unit, ``{{ v0.symbol }}`` the symbol."""

    def __init__(self, parameter: Parameter, value: float):
        self.number = value
        self.value = format_number(value)
        self.unit = pretty_unit(parameter.unit)
        self.symbol = parameter.symbol or parameter.name
        self._text = with_unit(self.value, parameter.unit)

    def __str__(self):
        return self._text


@lru_cache(maxsize=1)
def _environment() -> jinja2.Environment:
    import jinja2

    return jinja2.Environment(undefined=jinja2.StrictUndefined, autoescape=False,
                              keep_trailing_newline=False)


@lru_cache(maxsize=512)
def compile_statement(source: str) -> jinja2.Template:
    """The compiled template; a syntax error names the line in the statement."""
    import jinja2

    try:
        return _environment().from_string(source)
    except jinja2.TemplateSyntaxError as error:
        raise DefinitionError(f"statement template, line {error.lineno}: {error.message}") from None


def referenced_names(source: str) -> set[str]:
    """Every top-level name the statement template uses."""
    from jinja2 import meta

    return meta.find_undeclared_variables(_environment().parse(source))


def render_statement(source: str, params: tuple[Parameter, ...],
                     values: Mapping[str, float]) -> str:
    """The statement with the variant's parameter values filled in."""
    import jinja2

    shown = {p.name: ShownValue(p, values[p.name]) for p in params}
    try:
        return compile_statement(source).render(**shown).strip() + "\n"
    except jinja2.UndefinedError as error:
        raise DefinitionError(f"statement template: {error.message}") from None
