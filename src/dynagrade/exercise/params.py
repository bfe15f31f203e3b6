"""Parameters of an exercise: how each is drawn, its unit and its printed symbol.

A parameter's value lives in its declared unit (``alpha`` in degrees when ``unit="deg"``);
the solver sees it in SI. Draws are taken from a ``numpy.random.Generator`` so that a
variant is fully determined by its seed.
"""

from __future__ import annotations

import functools
import math
from collections import Counter
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Callable, Mapping

from ..errors import DefinitionError
from ..grading.spec import Variable
from .units import si_factor

if TYPE_CHECKING:
    import numpy as np


@dataclass(frozen=True)
class Domain:
    """The physically meaningful values of a parameter, e.g. ``g > 0`` or ``0 ≤ e ≤ 1``;
    a value set by hand outside it is refused (it would give a variant with, say, a
    negative flight time)."""

    low: float = -math.inf
    high: float = math.inf
    low_open: bool = False
    high_open: bool = False

    def __contains__(self, value: float) -> bool:
        above = value > self.low if self.low_open else value >= self.low
        below = value < self.high if self.high_open else value <= self.high
        return math.isfinite(value) and above and below

    def describe(self, name: str) -> str:
        """The domain as a condition on ``name``: "g > 0", "0 ≤ e ≤ 1"."""
        low = f"{self.low:g} {'<' if self.low_open else '≤'} " if self.low > -math.inf else ""
        high = f" {'<' if self.high_open else '≤'} {self.high:g}" if self.high < math.inf \
            else ""
        if not low and not high:
            return f"{name} finite"
        if low and not high:  # read "g > 0" rather than "0 < g"
            return f"{name} {'>' if self.low_open else '≥'} {self.low:g}"
        return f"{low}{name}{high}"


POSITIVE = Domain(0.0, low_open=True)
NON_NEGATIVE = Domain(0.0)
UNIT_INTERVAL = Domain(0.0, 1.0)


def conventional_domain(name: str, unit: str | None) -> Domain | None:
    """The domain the course's conventions give a parameter that declares none: masses
    (kg) and the gravitational acceleration ``g`` are positive, a coefficient of
    restitution ``e`` (no unit) lies in [0, 1], friction coefficients ``mu...`` are not
    negative."""
    if unit == "kg" or (name == "g" and unit == "m/s^2"):
        return POSITIVE
    if name == "e" and unit is None:
        return UNIT_INTERVAL
    if name.startswith("mu") and unit is None:
        return NON_NEGATIVE
    return None


@dataclass(frozen=True)
class Parameter:
    """What every parameter has: a name (an identifier), a unit, a printed symbol and,
    optionally, its physical domain (:class:`Domain`; else :func:`conventional_domain`)."""

    name: str
    unit: str | None = None
    symbol: str | None = None
    domain: Domain | None = None

    @property
    def allowed(self) -> Domain | None:
        """The domain a value set by hand must lie in (declared or conventional)."""
        return self.domain or conventional_domain(self.name, self.unit)

    def __post_init__(self):
        if not self.name.isidentifier():
            raise DefinitionError(f"parameter name {self.name!r} is not an identifier")

    def draw(self, rng: np.random.Generator) -> float:
        """One value in the parameter's unit."""
        raise TypeError(f"{type(self).__name__} cannot be drawn")

    @property
    def varies(self) -> bool:
        """Whether different seeds can give different values."""
        return True

    def bounds(self) -> tuple[float, float]:
        """The least and the greatest value a draw can give, in the parameter's unit."""
        raise TypeError(f"{type(self).__name__} has no bounds")


@dataclass(frozen=True)
class Uniform(Parameter):
    """A value drawn uniformly from the grid ``low, low + step, ..., high``.

    Usage: ``Uniform("v0", 5, 30, step=0.5, unit="m/s", symbol="v_0")``.
    """

    low: float = 0.0
    high: float = 1.0
    step: float | None = None

    def __init__(self, name, low, high, step=None, unit=None, symbol=None, domain=None):
        object.__setattr__(self, "low", float(low))
        object.__setattr__(self, "high", float(high))
        object.__setattr__(self, "step", None if step is None else float(step))
        super().__init__(name, unit, symbol, domain)
        if not self.low <= self.high:
            raise DefinitionError(f"parameter {name!r}: low {low} is above high {high}")
        if self.step is not None and self.step <= 0:
            raise DefinitionError(f"parameter {name!r}: step must be positive, got {step}")

    def bounds(self):
        return self.low, self.high

    def draw(self, rng):
        if self.step is None:
            return float(rng.uniform(self.low, self.high))
        count = math.floor((self.high - self.low) / self.step + 1e-9) + 1
        value = self.low + int(rng.integers(count)) * self.step
        return _round_to_step(value, self.step)


@dataclass(frozen=True)
class Choice(Parameter):
    """A value drawn from a fixed list. Usage: ``Choice("m", (0.2, 0.5, 1.0), unit="kg")``."""

    values: tuple = ()

    def __init__(self, name, values, unit=None, symbol=None, domain=None):
        object.__setattr__(self, "values", tuple(float(v) for v in values))
        super().__init__(name, unit, symbol, domain)
        if not self.values:
            raise DefinitionError(f"parameter {name!r}: a Choice needs at least one value")

    def draw(self, rng):
        return self.values[int(rng.integers(len(self.values)))]

    def bounds(self):
        return min(self.values), max(self.values)

    @property
    def varies(self):
        return len(set(self.values)) > 1


@dataclass(frozen=True)
class Constant(Parameter):
    """A fixed value, e.g. ``Constant("g", 9.81, unit="m/s^2")``."""

    value: float = 0.0

    def __init__(self, name, value, unit=None, symbol=None, domain=None):
        object.__setattr__(self, "value", float(value))
        super().__init__(name, unit, symbol, domain)

    def draw(self, rng):
        return self.value

    def bounds(self):
        return self.value, self.value

    @property
    def varies(self):
        return False


@dataclass(frozen=True)
class Constraint:
    """A condition every variant's parameters must meet, stated in words.

    ``check`` receives the parameters in SI (``p.alpha`` in radians).
    Usage: ``Constraint("the block slides down", lambda p: p.mu < np.tan(p.alpha))``.
    """

    description: str
    check: Callable[["ParamValues"], bool]


@dataclass
class DrawTally:
    """Parameter draws counted as an exercise takes them: how many were taken, how many
    broke a constraint, and how often each constraint was broken (a draw that breaks two
    counts once in ``rejected`` and once for each). ``dynagrade verify`` reports from it
    the share of draws the constraints throw away (:mod:`.redraws`)."""

    draws: int = 0
    rejected: int = 0
    broken: Counter = field(default_factory=Counter)

    def record(self, broken: list[str]) -> None:
        """One draw, with the descriptions of the constraints it broke (none: accepted)."""
        self.draws += 1
        if broken:
            self.rejected += 1
            self.broken.update(broken)


class ParamValues(Mapping[str, float]):
    """Parameter values by name, readable as attributes (``p.v0``) and as a mapping.

    One instance stands for one draw: functions decorated with :func:`per_draw` keep
    their result on it, so the constraints, the solver and the misconceptions of a draw
    share one solution.
    """

    def __init__(self, values: Mapping[str, float]):
        self._values = dict(values)
        self._results: dict[Callable, object] = {}

    def once(self, function: Callable[["ParamValues"], object]):
        """``function(self)``, computed on the first call for this draw only."""
        if function not in self._results:
            self._results[function] = function(self)
        return self._results[function]

    def __getattr__(self, name):
        try:
            return self._values[name]
        except KeyError:
            raise AttributeError(f"no parameter named {name!r}") from None

    def __getitem__(self, name):
        return self._values[name]

    def __iter__(self):
        return iter(self._values)

    def __len__(self):
        return len(self._values)

    def __repr__(self):
        return f"ParamValues({self._values!r})"


def symbol_domain(parameter: Parameter) -> Variable:
    """The domain over which a symbolic answer is tested in this parameter's symbol: the
    parameter's unit, and its bounds widened by a quarter of their span on each side (by
    half the value for a constant), without crossing zero: a formula must hold beyond the
    values the variants happen to draw, and a quantity that is never negative stays so
    (so that ``sqrt(h)`` stays defined). The parameter's printed symbol comes along: a
    formula may use it (:func:`dynagrade.grading.names.typed_forms`).
    """
    low, high = parameter.bounds()
    margin = (high - low) / 4 if high > low else abs(low) / 2 or 1.0
    wide_low, wide_high = low - margin, high + margin
    if low >= 0:
        wide_low = max(wide_low, low / 2)
    if high <= 0:
        wide_high = min(wide_high, high / 2)
    return Variable(wide_low, wide_high, parameter.unit, symbol=parameter.symbol)


def per_draw(function: Callable[[ParamValues], object]) -> Callable[[ParamValues], object]:
    """Compute ``function(p)`` once per draw, however many constraints, misconceptions and
    the solver ask for it. Usage in an exercise file::

        @per_draw
        def solve(p):
            ...

        Constraint("the string stays taut", lambda p: solve(p)["S"] > 0)

    The result is shared, so callers must not change it.
    """
    @functools.wraps(function)
    def once_per_draw(p):
        return p.once(function) if isinstance(p, ParamValues) else function(p)

    return once_per_draw


def to_si_values(params: tuple[Parameter, ...], values: Mapping[str, float]) -> ParamValues:
    """The parameters' values (in their declared units) converted to SI."""
    return ParamValues({p.name: values[p.name] * si_factor(p.unit) for p in params})


def _round_to_step(value: float, step: float) -> float:
    """``value`` without the float noise of repeated steps (0.1 * 3 -> 0.3)."""
    decimals = max(0, -math.floor(math.log10(step)) + 6)
    return round(value, decimals)
