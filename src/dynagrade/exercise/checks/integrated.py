"""A key read off the equations of motion integrated numerically (``scipy``'s
``solve_ivp``): the peak height where the vertical speed turns, the range where the
height returns to zero, the period between two upward zero crossings, the speed at an
event. No closed form is used: only the equations of motion and the initial state."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Callable, Mapping, Sequence

from ..params import ParamValues
from .base import Check, CheckCase, Outcome

RightHandSide = Callable[[float, Any, ParamValues], Sequence[float]]
Reading = Callable[[float, Any, ParamValues], Any]

#: the integrator's own tolerances: far below the check's, so the check measures the key
_INTEGRATION_RTOL = 1e-9
_INTEGRATION_ATOL = 1e-12
#: a crossing this close to where the integration started (a fraction of the horizon) is
#: the start itself; after a crossing the integration moves on by _NUDGE before it looks
#: for the next
_SAME_TIME = 1e-9
_NUDGE = 1e-7


@dataclass(frozen=True)
class Integrated(Check):
    """Integrate ``y' = rhs(t, y, p)`` from ``start(p)`` over ``[0, horizon(p, solved)]``
    and compare ``read(t, y, p)`` with the solver's ``key``: at the ``occurrence``-th time
    ``event(t, y, p)`` crosses zero (in ``direction``: +1 upward, -1 downward, 0 either)
    after the start, or at the horizon when there is no ``event``. An event that never
    comes within the horizon is a disagreement (the recomputed value is ``nan``).

    ``from_keys`` names solver values the equations of motion take beside the parameters
    (``p.k`` then reads the solver's ``k``): keys identified from a measurement must
    reproduce it when the motion they describe is integrated."""

    key: str
    rhs: RightHandSide
    start: Callable[[ParamValues], Sequence[float]]
    horizon: Callable[[ParamValues, Mapping[str, Any]], float]
    read: Reading
    name: str
    event: Callable[[float, Any, ParamValues], float] | None = None
    direction: float = 0.0
    occurrence: int = 1
    from_keys: tuple[str, ...] = ()
    rtol: float = 1e-6
    atol: float = 0.0

    def outcome(self, case: CheckCase) -> Outcome:
        return Outcome(self.name, self.key, case.value(self.key), self.recompute(case),
                       self.rtol, self.atol)

    def recompute(self, case: CheckCase) -> Any:
        """What ``read`` gives at the event (or the horizon); ``nan`` when the event does
        not come. Checks of the variant that integrate the same motion to the same event
        share one integration."""
        p = self._params(case)
        key = (self.rhs, self.start, self.horizon, self.event, self.direction,
               self.occurrence, self.from_keys)
        reached = case.once(key, lambda: self._integrate(p, case.solved))
        return float("nan") if reached is None else self.read(reached[0], reached[1], p)

    def _params(self, case: CheckCase) -> ParamValues:
        if not self.from_keys:
            return case.params
        return ParamValues({**case.params,
                            **{key: float(case.value(key)) for key in self.from_keys}})

    def _integrate(self, p: ParamValues, solved: Mapping[str, Any]) -> tuple[float, Any] | None:
        """``(t, y)`` at the event (or the horizon), ``None`` when the event does not come."""
        from scipy.integrate import solve_ivp  # here: listing the bank imports no scipy

        horizon = float(self.horizon(p, solved))

        def run(t0, y0, until, events=None):
            return solve_ivp(lambda t, y: self.rhs(t, y, p), (t0, until), y0,
                             method="DOP853", events=events,
                             rtol=_INTEGRATION_RTOL, atol=_INTEGRATION_ATOL)

        if self.event is None:
            solution = run(0.0, list(self.start(p)), horizon)
            return float(solution.t[-1]), solution.y[:, -1]
        event = self.event

        def crossing(t, y):
            return event(t, y, p)

        crossing.terminal = True  # type: ignore[attr-defined]
        crossing.direction = self.direction  # type: ignore[attr-defined]
        t0, y0, seen = 0.0, list(self.start(p)), 0
        while True:  # from one crossing to the next, stopping at each
            solution = run(t0, y0, horizon, [crossing])
            if solution.status != 1:  # the horizon came first
                return None
            t, y = float(solution.t_events[0][0]), solution.y_events[0][0]
            if t > t0 + _SAME_TIME * horizon:  # a start on the event is no crossing
                seen += 1
                if seen == self.occurrence:
                    return t, y
            step = run(t, y, t + _NUDGE * horizon)  # past the crossing, to look for the next
            t0, y0 = float(step.t[-1]), step.y[:, -1]
