"""Answer parts of an exercise: what is asked, in which unit, for how many points.

Each part turns a variant's reference answer into the grader's specification
(:mod:`dynagrade.grading.spec`). Reference answers arrive from the solver in SI; a part
converts them into its own unit, which is also the unit a bare number is read in.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, Callable, Mapping

from ..grading.spec import (
    ChoiceSpec,
    KnownWrong,
    NumericSpec,
    SymbolicSpec,
    Variable,
    VectorSpec,
)
from ..errors import DefinitionError
from .params import ParamValues
from .units import from_si

__all__ = ["Misconception", "Numeric", "Vector", "Symbolic", "Options", "Variable", "Part"]


@dataclass(frozen=True)
class Misconception:
    """A known wrong answer and the feedback it earns.

    ``value`` is a function of the parameters (in SI) returning the wrong answer in SI for
    numeric and vector parts, or an expression string for symbolic parts.
    """

    name: str
    value: Callable[[ParamValues], Any] | str
    feedback: str
    score: float = 0.0


@dataclass(frozen=True)
class Part:
    """What every part has: a name (the variable on the student's sheet), a label, points."""

    name: str
    label: str = ""
    points: float = 1.0
    misconceptions: tuple[Misconception, ...] = ()

    kind = "part"

    def __post_init__(self):
        if not self.name.isidentifier():
            raise ValueError(f"part name {self.name!r} is not an identifier")
        if self.points < 0:
            raise ValueError(f"part {self.name!r}: points must not be negative")

    def reference(self, solved: Mapping[str, Any]) -> Any:
        """This part's reference answer, in the part's unit, from the solver's SI output."""
        try:
            return self.in_part_unit(solved[self.name])
        except KeyError:
            raise DefinitionError(f"the solver returned no answer for part {self.name!r}; "
                                  f"it returned {sorted(solved)}") from None

    def spec(self, params: ParamValues):
        """The grader's specification for this part in the variant with ``params``."""
        raise TypeError(f"{type(self).__name__} has no grading specification")

    def in_part_unit(self, value):
        """A value the solver gives in SI, as this part states and grades it."""
        return value

    def _known_wrong(self, params: ParamValues) -> tuple[KnownWrong, ...]:
        return tuple(
            KnownWrong(m.name, self.in_part_unit(m.value(params)), m.feedback, m.score)
            for m in self.misconceptions
        )

    @property
    def unit(self) -> str | None:
        return None


@dataclass(frozen=True)
class Numeric(Part):
    """A number with a unit, correct within ``max(atol, rtol*|expected|)``.

    ``follow_through(p, answers)`` recomputes the reference (in SI) from the student's
    earlier answers (``answers[name]`` in SI), so a part is not lost for an error made
    before it. ``require_unit`` makes a bare number wrong; ``unit_credit`` (0..1) is the
    share of the points that the unit alone earns (docs/grading.md).
    """

    unit: str | None = None
    rtol: float = 1e-2
    atol: float | None = None
    sigfigs: int | None = None
    follow_through: Callable[[ParamValues, Mapping[str, float]], float] | None = None
    uses: tuple[str, ...] = ()
    require_unit: bool = False
    unit_credit: float | None = None

    kind = "numeric"

    def in_part_unit(self, value):
        return from_si(float(value), self.unit)

    def spec(self, params):
        return NumericSpec(unit=self.unit, rtol=self.rtol, atol=self.atol,
                           sigfigs=self.sigfigs, misconceptions=self._known_wrong(params),
                           require_unit=self.require_unit, unit_credit=self.unit_credit)


@dataclass(frozen=True)
class Vector(Part):
    """A vector of ``size`` components in one unit, graded component by component."""

    unit: str | None = None
    size: int = 2
    rtol: float = 1e-2
    atol: float | None = None

    kind = "vector"

    def in_part_unit(self, value):
        values = tuple(from_si(float(v), self.unit) for v in value)
        if len(values) != self.size:
            raise ValueError(f"part {self.name!r} expects {self.size} components, "
                             f"the solver gave {len(values)}")
        return values

    def spec(self, params):
        return VectorSpec(size=self.size, unit=self.unit, rtol=self.rtol, atol=self.atol,
                          misconceptions=self._known_wrong(params))


@dataclass(frozen=True)
class Symbolic(Part):
    """An expression in declared variables, judged by evaluation over their domains.

    ``expected`` is the reference expression (the exercise's own text); ``equals`` names a
    numeric part that this expression must reproduce at the variant's parameters, which
    ``dynagrade verify`` checks against the mechanics core. ``form`` lists form tests
    (``"no_decimals"``, ``"simplified"``, ``"no_functions"``) graded apart from
    equivalence: an equivalent answer that fails one earns ``form_credit``.
    """

    expected: str = ""
    variables: Mapping[str, Variable] = field(default_factory=dict)
    equals: str | None = None
    form: tuple[str, ...] = ()
    form_credit: float = 0.5

    kind = "symbolic"

    def reference(self, solved):
        return self.expected

    def spec(self, params):
        known = tuple(KnownWrong(m.name, m.value, m.feedback, m.score)
                      for m in self.misconceptions)
        return SymbolicSpec(variables=dict(self.variables), misconceptions=known,
                            form=tuple(self.form), form_credit=self.form_credit)


@dataclass(frozen=True)
class Options(Part):
    """A choice among labelled options; ``multiple=True`` allows several correct ones."""

    options: tuple[str, ...] = ()
    multiple: bool = False

    kind = "choice"

    def in_part_unit(self, value):
        chosen = (value,) if isinstance(value, str) else tuple(value)
        unknown = [c for c in chosen if c not in self.options]
        if unknown:
            raise ValueError(f"part {self.name!r}: the solver chose {unknown}, "
                             f"not among the options {list(self.options)}")
        return chosen if self.multiple else chosen[0]

    def spec(self, params):
        return ChoiceSpec(options=tuple(self.options), multiple=self.multiple)
