"""Independent checks of an exercise's key: each recomputes something by another route.

An exercise's ``solve`` reaches its key through the mechanics core; a check reaches the
same number another way -- the equations of motion integrated numerically, an energy or
momentum balance, a limit the notes state, a symmetry -- and never through the core
function that produced the key. What a check catches is the glue of ``solve``: which
relation, which argument, which unit. ``dynagrade verify`` runs every check on every
variant it draws and names the failing check, the seed and both numbers.

Usage, in an exercise file::

    from dynagrade.exercise.checks import Integrated, Limit, Recompute

    EXERCISE = Exercise(..., checks=(
        Recompute("x_max", _range_from_flight_time, name="range from the flight time"),
        Limit("x_max", {"mu": 0.0}, _frictionless_range, name="mu -> 0"),
    ))

One kind of check per module, behind :class:`~.base.Check`; :mod:`.dimensions` is the
check ``verify`` runs on every formula by itself (imported by ``verify`` alone: an
exercise file that imports its checks stays as light to load as before, scipy included).
"""

from .balance import Balance
from .base import Check, CheckCase, Outcome
from .integrated import Integrated
from .limit import Limit
from .recompute import Recompute
from .symmetry import Symmetry

__all__ = ["Check", "CheckCase", "Outcome", "Recompute", "Balance", "Integrated", "Limit",
           "Symmetry"]
