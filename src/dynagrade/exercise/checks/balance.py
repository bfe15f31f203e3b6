"""A balance that the variant's numbers must satisfy: energy before and after, momentum
before and after a collision, a work--energy balance. Both sides are computed from the
parameters and the solver's values; the balance checks how they fit together."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Callable, Mapping

from ..params import ParamValues
from .base import RTOL, Check, CheckCase, Outcome

Side = Callable[[ParamValues, Mapping[str, Any]], Any]


@dataclass(frozen=True)
class Balance(Check):
    """``before(p, solved)`` must equal ``after(p, solved)`` (numbers or vectors, in SI);
    ``what`` names the balanced quantity in the report ("energy", "momentum")."""

    what: str
    before: Side
    after: Side
    name: str
    rtol: float = RTOL
    atol: float = 0.0

    def outcome(self, case: CheckCase) -> Outcome:
        return Outcome(self.name, self.what, self.before(case.params, case.solved),
                       self.after(case.params, case.solved), self.rtol, self.atol)
