"""A key recomputed by another route from the variant's parameters: a closed form of the
notes the solver does not use, a balance of energy or momentum solved for the key, the key
read back from another key (a range from the flight time)."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Callable, Mapping

from ..params import ParamValues
from .base import RTOL, Check, CheckCase, Outcome


@dataclass(frozen=True)
class Recompute(Check):
    """``route(p, solved)`` must give the solver's ``key``. ``route`` receives the
    parameters in SI and what the solver returned (to read another key back from), and
    must reach ``key`` without the core function that produced it; its docstring cites
    the notes' equation it uses."""

    key: str
    route: Callable[[ParamValues, Mapping[str, Any]], Any]
    name: str
    rtol: float = RTOL
    atol: float = 0.0

    def outcome(self, case: CheckCase) -> Outcome:
        return Outcome(self.name, self.key, case.value(self.key),
                       self.route(case.params, case.solved), self.rtol, self.atol)
