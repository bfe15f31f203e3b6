"""A limit the notes state: the solver run again with a parameter at its limit (mu -> 0,
e = 1, zeta -> 0, a small angle) must give the limit's closed form (the frictionless
range, the elastic speeds, the undamped frequency)."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Callable, Mapping

from ..params import ParamValues
from .base import RTOL, Check, CheckCase, Outcome


@dataclass(frozen=True)
class Limit(Check):
    """The solver's ``key`` with the parameters ``at`` (SI values, e.g. ``{"mu": 0.0}``)
    must equal ``expect(p)``, ``p`` being the parameters with ``at`` in place. A limit that
    is approached rather than reached (``zeta`` of 1e-6) declares the ``rtol`` that the
    remaining distance allows."""

    key: str
    at: Mapping[str, float]
    expect: Callable[[ParamValues], Any]
    name: str
    rtol: float = RTOL
    atol: float = 0.0

    def outcome(self, case: CheckCase) -> Outcome:
        at_limit = ParamValues({**case.params, **self.at})
        solved = case.resolve(self.at)
        return Outcome(self.name, self.key, solved[self.key], self.expect(at_limit),
                       self.rtol, self.atol)
