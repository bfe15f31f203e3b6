"""A symmetry of the physics: the solver run again at mirrored parameters (the
complementary launch angle, the two bodies swapped, a reversed sign) must give the key
back, or the key transformed as the symmetry says."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Callable, Mapping

from ..params import ParamValues
from .base import RTOL, Check, CheckCase, Outcome


def _same(value: Any) -> Any:
    return value


@dataclass(frozen=True)
class Symmetry(Check):
    """``mirror(p)`` gives the changed parameters (SI); the solver's ``key`` there must be
    ``relate(key here)`` (the same value by default)."""

    key: str
    mirror: Callable[[ParamValues], Mapping[str, float]]
    name: str
    relate: Callable[[Any], Any] = _same
    rtol: float = RTOL
    atol: float = 0.0

    def outcome(self, case: CheckCase) -> Outcome:
        mirrored = case.resolve(self.mirror(case.params))
        return Outcome(self.name, self.key, mirrored[self.key],
                       self.relate(case.value(self.key)), self.rtol, self.atol)
