"""What every independent check shares: the variant it is run on, the comparison, the
finding it reports.

A check compares two numbers (or vectors) for one variant: usually the solver's value of
a key against the check's own recomputation of it. :class:`Outcome` holds both, with the
tolerance, and says in one line what disagrees.
"""

from __future__ import annotations

import math
from abc import ABC, abstractmethod
from dataclasses import dataclass, field
from typing import Any, Callable, Mapping

from ...errors import DefinitionError
from ..numbers import answer_text
from ..params import ParamValues

#: the default relative tolerance: a check recomputes the same physics, so the two routes
#: agree to rounding (a numerical integration declares a looser one)
RTOL = 1e-6


@dataclass(frozen=True)
class CheckCase:
    """One variant as a check sees it: ``params`` in SI, ``solved`` what the solver returned
    (SI), and ``resolve`` the solver run again with some parameters changed (SI).
    ``shared`` keeps what several checks of the variant compute alike (one integration
    read for the range and for the flight time), by a key the check chooses."""

    params: ParamValues
    solved: Mapping[str, Any]
    resolve: Callable[[Mapping[str, float]], Mapping[str, Any]]
    shared: dict = field(default_factory=dict, compare=False)

    def once(self, key: Any, compute: Callable[[], Any]) -> Any:
        """``compute()``, the first time a check of this variant asks for ``key``."""
        if key not in self.shared:
            self.shared[key] = compute()
        return self.shared[key]

    def value(self, key: str) -> Any:
        """The solver's value of ``key``; a key the solver does not return is the check's
        error, said with the keys there are."""
        if key not in self.solved:
            raise DefinitionError(f"the solver returns no {key!r}; it returns "
                                  f"{sorted(self.solved)}")
        return self.solved[key]


@dataclass(frozen=True)
class Outcome:
    """A check's comparison: ``expected`` (the key's value, or a balance's one side)
    against ``recomputed`` (the other route's), within ``rtol`` relative to the larger
    magnitude (and ``atol`` absolute)."""

    check: str
    key: str
    expected: Any
    recomputed: Any
    rtol: float
    atol: float = 0.0

    @property
    def ok(self) -> bool:
        return agree(self.expected, self.recomputed, self.rtol, self.atol)

    def problem(self) -> str:
        """The one line ``verify`` prints when the two disagree."""
        return (f"check '{self.check}' on {self.key}: the key gives "
                f"{answer_text(_plain(self.expected))}, the check recomputes "
                f"{answer_text(_plain(self.recomputed))} (rtol {self.rtol:g})")


class Check(ABC):
    """One independent check of an exercise. Subclasses are frozen dataclasses with a
    ``name`` (what ``verify`` reports) and :meth:`outcome`."""

    name: str

    @abstractmethod
    def outcome(self, case: CheckCase) -> Outcome:
        """The comparison this check makes for ``case``."""


def agree(a: Any, b: Any, rtol: float, atol: float = 0.0) -> bool:
    """Whether ``a`` and ``b`` (numbers or equal-length vectors) differ by at most
    ``rtol`` times the larger magnitude plus ``atol`` (a vector by its Euclidean norm)."""
    a, b = _vector(a), _vector(b)
    if len(a) != len(b):
        return False
    if not all(math.isfinite(x) for x in a + b):
        return False
    gap = math.sqrt(sum((x - y) ** 2 for x, y in zip(a, b)))
    scale = max(math.sqrt(sum(x * x for x in a)), math.sqrt(sum(y * y for y in b)))
    return gap <= rtol * scale + atol


def _vector(value: Any) -> list[float]:
    value = _plain(value)
    if isinstance(value, (list, tuple)):
        return [float(v) for v in value]
    return [float(value)]


def _plain(value: Any) -> Any:
    """A numpy array or number as Python's own."""
    return value.tolist() if hasattr(value, "tolist") else value
