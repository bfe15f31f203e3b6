"""Specifications of answer parts: what kind of answer, in which unit, how strict.

All specs are frozen dataclasses so a part can be shared, hashed and stored. The
field order of the first fields is part of the public API; later fields are
additive and always have defaults.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from functools import lru_cache
from types import MappingProxyType
from typing import Mapping

from .names import NameClash, alias_table
from .units import BUILTIN as BUILTIN_UNITS
from .tolerance import DEFAULT_RTOL

#: How a declared basis vector is named: ``e_r``, ``e_phi``, ``e_t``.
_BASIS_NAME = re.compile(r"[A-Za-z][A-Za-z0-9_]*")

#: Form tests a symbolic part may require on top of equivalence.
FORM_TESTS = ("no_decimals", "simplified", "no_functions")


@dataclass(frozen=True)
class KnownWrong:
    """A declared misconception: a wrong answer that earns its own feedback and score.

    ``value`` is a number in the part's unit (numeric parts), an expression string in
    the declared variables (symbolic parts) or a tuple of numbers (vector parts).
    """

    name: str
    value: float | str | tuple
    feedback: str
    score: float = 0.0

    def __post_init__(self) -> None:
        if not 0.0 <= self.score <= 1.0:
            raise ValueError(f"KnownWrong score must lie in [0, 1], got {self.score}")


@dataclass(frozen=True)
class NumericSpec:
    """A number, optionally with a unit.

    Correct when |a - e| <= max(atol, rtol*|e|) with ``a`` converted to ``unit``;
    ``atol=None`` means the default floor :data:`dynagrade.grading.tolerance.DEFAULT_ATOL`.
    With ``sigfigs=N`` the answer must instead round to the same N significant figures.
    ``unit_credit`` (0..1) splits the score between value and unit; ``require_unit``
    makes a bare number wrong (a bare number is otherwise read in ``unit``).
    """

    unit: str | None = None
    rtol: float = DEFAULT_RTOL
    atol: float | None = None
    sigfigs: int | None = None
    misconceptions: tuple[KnownWrong, ...] = ()
    require_unit: bool = False
    unit_credit: float | None = None
    reveal: bool = False
    generic_misconceptions: bool = True

    def __post_init__(self) -> None:
        _check_tolerances(self.rtol, self.atol)
        if self.sigfigs is not None and not (isinstance(self.sigfigs, int) and 1 <= self.sigfigs <= 15):
            raise ValueError(f"sigfigs must be an integer in 1..15, got {self.sigfigs!r}")
        if self.unit_credit is not None and not 0.0 <= self.unit_credit <= 1.0:
            raise ValueError(f"unit_credit must lie in [0, 1], got {self.unit_credit}")
        object.__setattr__(self, "misconceptions", tuple(self.misconceptions))


@dataclass(frozen=True)
class Variable:
    """A symbol of a symbolic answer: the domain [min, max] sampled for equivalence,
    in ``unit`` (used for dimensional analysis; samples are converted to SI).

    ``symbol`` is the symbol as the statement prints it (LaTeX: ``v_{02}``, ``\\lambda``)
    and ``aliases`` are further spellings a student may type (``"v_2(0)"``); the answer is
    read with every spelling :func:`.names.spellings_of` derives from both. An exercise
    may leave ``min`` and ``max`` out for a variable that is one of its parameters: the
    parameter's domain fills them in.
    """

    min: float | None = None
    max: float | None = None
    unit: str | None = None
    symbol: str | None = None
    aliases: tuple[str, ...] = ()

    def __post_init__(self) -> None:
        if isinstance(self.aliases, str):
            object.__setattr__(self, "aliases", (self.aliases,))
        object.__setattr__(self, "aliases", tuple(self.aliases))
        if self.min is None or self.max is None:
            return
        if not (float(self.min) <= float(self.max)):
            raise ValueError(f"Variable domain needs min <= max, got [{self.min}, {self.max}]")

    @property
    def has_domain(self) -> bool:
        """Whether both bounds are given."""
        return self.min is not None and self.max is not None

    @property
    def domain(self) -> tuple[float, float]:
        """(min, max), for a variable that has both (every variable of a SymbolicSpec)."""
        if self.min is None or self.max is None:
            raise ValueError("this variable has no domain: Variable(min, max)")
        return self.min, self.max


@dataclass(frozen=True)
class SymbolicSpec:
    """An expression in the declared variables.

    Equivalence is decided by evaluation at seeded random points of the variables'
    domains: relative tolerance ``rtol`` (default 1e-6) with a floor scaled to the
    reference's magnitude. ``up_to_constant`` names the variables an additive constant
    does not depend on, which the answer may then differ by (``True``: all of them; a
    potential energy V(θ) takes ``("theta",)``: its zero level is a convention). ``form`` lists extra form tests from :data:`FORM_TESTS`;
    an equivalent answer that fails one earns ``form_credit``.
    """

    variables: Mapping[str, Variable] = field(default_factory=dict)
    rtol: float = 1e-6
    misconceptions: tuple[KnownWrong, ...] = ()
    form: tuple[str, ...] = ()
    form_credit: float = 0.5
    reveal: bool = False
    points: int = 16
    generic_misconceptions: bool = True
    up_to_constant: bool | tuple[str, ...] = ()
    #: spelling -> variable name for every spelling besides the names (:func:`.names.alias_table`)
    spellings: Mapping[str, str] = field(init=False, repr=False, compare=False)

    def __post_init__(self) -> None:
        _check_tolerances(self.rtol, None)
        variables = {}
        for name, var in dict(self.variables).items():
            if not isinstance(var, Variable):
                lo, hi, *rest = var
                var = Variable(lo, hi, rest[0] if rest else None)
            if not var.has_domain:
                raise ValueError(f"the variable {name!r} needs a domain: Variable(min, max)")
            variables[name] = var
        object.__setattr__(self, "variables", MappingProxyType(variables))
        try:
            table = _spellings(tuple(variables.items()))
        except NameClash as clash:
            raise ValueError(str(clash)) from None
        object.__setattr__(self, "spellings", table)
        constant_in = tuple(variables) if self.up_to_constant is True else \
            tuple(self.up_to_constant or ())
        unknown = [n for n in constant_in if n not in variables]
        if unknown:
            raise ValueError(f"up_to_constant names {unknown}, which are no variables")
        object.__setattr__(self, "up_to_constant", constant_in)
        object.__setattr__(self, "misconceptions", tuple(self.misconceptions))
        object.__setattr__(self, "form", tuple(self.form))
        for test in self.form:
            if test not in FORM_TESTS:
                raise ValueError(f"unknown form test {test!r}; choose from {', '.join(FORM_TESTS)}")
        if not 0.0 <= self.form_credit <= 1.0:
            raise ValueError(f"form_credit must lie in [0, 1], got {self.form_credit}")
        if not 4 <= self.points <= 200:
            raise ValueError(f"points must be in 4..200, got {self.points}")

    @property
    def constant_in(self) -> tuple[str, ...]:
        """The variables named by ``up_to_constant``, ``True`` spelled out as all of them."""
        if isinstance(self.up_to_constant, bool):  # not after __post_init__, which spells it out
            return tuple(self.variables) if self.up_to_constant else ()
        return self.up_to_constant

    def __hash__(self) -> int:
        return hash((tuple(sorted(self.variables.items())), self.rtol, self.misconceptions,
                     self.form, self.form_credit, self.reveal, self.points, self.up_to_constant))


@dataclass(frozen=True)
class VectorSpec:
    """A vector of ``size`` numbers sharing ``unit``; graded component by component.

    Component i is right when |a_i - e_i| <= max(atol, rtol*max(|e_i|, 0.01*|e|)), with
    |e| the Euclidean norm of the reference, so a zero component is gradable.
    The score is the fraction of right components.

    ``basis`` names the basis vectors of the components, one per component, when they are
    not the Cartesian e1, e2, e3 of the notes (``("e_r", "e_phi")`` for polar components,
    ``("e_t", "e_n")`` for path components): the answer may then be written ``3 e_r + 2
    e_φ`` (:mod:`.basis`). Without it a part of 2 or 3 components reads ``3 e1 + 2 e2``.
    """

    size: int
    unit: str | None = None
    rtol: float = DEFAULT_RTOL
    atol: float | None = None
    misconceptions: tuple[KnownWrong, ...] = ()
    require_unit: bool = False
    reveal: bool = False
    generic_misconceptions: bool = True
    basis: tuple[str, ...] = ()

    def __post_init__(self) -> None:
        _check_tolerances(self.rtol, self.atol)
        if not (isinstance(self.size, int) and 1 <= self.size <= 100):
            raise ValueError(f"size must be an integer in 1..100, got {self.size!r}")
        object.__setattr__(self, "misconceptions", tuple(self.misconceptions))
        basis = tuple(self.basis)
        if basis and (len(basis) != self.size or len(set(basis)) != len(basis) or not all(
                isinstance(b, str) and _BASIS_NAME.fullmatch(b) for b in basis)):
            raise ValueError(f"basis must name {self.size} different basis vectors like "
                             f"'e_r' (letters, digits, '_'), got {self.basis!r}")
        object.__setattr__(self, "basis", basis)


@dataclass(frozen=True)
class ChoiceSpec:
    """One option (``multiple=False``) or a set of options out of ``options`` (labels).

    ``aliases`` are (spelling, option) pairs: further ways to name an option, such as
    the number or letter the statement gives it (``("2", "on the ground")``).
    """

    options: tuple[str, ...]
    multiple: bool = False
    reveal: bool = False
    aliases: tuple[tuple[str, str], ...] = ()

    def __post_init__(self) -> None:
        options = tuple(str(o) for o in self.options)
        if not options:
            raise ValueError("a choice part needs at least one option")
        object.__setattr__(self, "options", options)
        aliases = tuple((str(a), str(o)) for a, o in self.aliases)
        object.__setattr__(self, "aliases", aliases)
        named = {_option_key(o): o for o in options}
        for alias, option in aliases:
            if option not in options:
                raise ValueError(f"the alias {alias!r} names {option!r}, which is no option")
            other = named.setdefault(_option_key(alias), option)
            if other != option:
                raise ValueError(f"the alias {alias!r} of the option {option!r} also names "
                                 f"the option {other!r}")


def _option_key(label: str) -> str:
    """How a label is compared: without spaces, ignoring case."""
    return "".join(str(label).split()).casefold()


def _check_tolerances(rtol: float, atol: float | None) -> None:
    if not (rtol >= 0.0) or rtol != rtol:
        raise ValueError(f"rtol must be >= 0, got {rtol!r}")
    if atol is not None and (not (atol >= 0.0) or atol != atol):
        raise ValueError(f"atol must be >= 0, got {atol!r}")


@lru_cache(maxsize=512)
def _spellings(variables: tuple[tuple[str, Variable], ...]) -> Mapping[str, str]:
    """:func:`.names.alias_table` of ``variables`` (name, variable) with the built-in
    units, kept: a formula part's spec is made again for every answer read or graded."""
    return MappingProxyType(alias_table(dict(variables), BUILTIN_UNITS))
