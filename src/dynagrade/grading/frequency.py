"""One frequency rule: Hz and rpm count cycles, rad/s counts radians, and ω = 2π·f.

The notes write the angular frequency ω in rad/s and the frequency f = ω/(2π) in Hz
(Section 4.3.1, :func:`dynagrade.mechanics.vibrations.frequency`). In SI both are 1/s, so a
unit table alone cannot tell ``10.47 Hz`` (65.8 rad/s) from ``10.47 rad/s``. The rule:

- **Hz counts cycles per second.** Where the other side of a comparison carries an angle
  (an answer in rad/s or rpm, a part in rad/s, deg/s or rpm) or counts cycles too, a Hz is
  read as one turn per second (2π rad/s): ``1.667 Hz`` is ω = 10.47 rad/s, and ``10.47 rad/s``
  is f = 1.667 Hz. rpm and rev already carry their turn (:mod:`.units`).
- **1/s takes the part's meaning** (SI's own ambiguity): in a Hz part it is Hz, in a rad/s
  part rad/s. A part in plain 1/s reads Hz as 1/s.
- **per minute is a rotational speed**: ``1/min``, ``min^-1``, ``min⁻¹`` alone are rev/min
  (rpm), as on a motor plate, never rad/min (:func:`per_minute`).

:func:`align` applies the rule to a pair of dimensions; the graders convert with it, and
the number that would have been right under the other reading names the confusion
(``10.47 Hz`` for ω = 10.47 rad/s: a value in rad/s labelled Hz).
"""

from __future__ import annotations

import math

from . import units
from .evaluate import evaluate_constant
from .nodes import BinOp, Expr, Unit, has_units

TWO_PI = 2 * math.pi
_ANGLE = (0.0,) * 7 + (1.0,)
_HERTZ = ("Hz", "hertz")


#: the spellings of a frequency an export offers besides the part's own unit
SPELLINGS = ("rad/s", "s^-1", "Hz", "rpm", "U/min", "min^-1")


def is_frequency(dim: tuple) -> bool:
    """Whether a dimension is a frequency of either kind (1/s, with or without an angle)."""
    return units.same(dim, (0.0, 0.0, -1.0, 0.0, 0.0, 0.0, 0.0, 0.0), ignore_angle=True)


def unit_powers(unit_part: Expr | None) -> dict[str, float] | None:
    """The powers of the unit names in a unit part (``U/min`` -> {U: 1, min: -1}); None when
    the part is no plain product of powers of units."""
    powers: dict[str, float] = {}

    def collect(node: Expr, sign: float) -> bool:
        if isinstance(node, BinOp) and node.op in "*/":
            return collect(node.left, sign) and collect(
                node.right, sign if node.op == "*" else -sign)
        if isinstance(node, Unit):
            powers[node.id] = powers.get(node.id, 0.0) + sign
            return True
        if isinstance(node, BinOp) and node.op == "^" and isinstance(node.left, Unit) \
                and not has_units(node.right):
            powers[node.left.id] = powers.get(node.left.id, 0.0) + sign * evaluate_constant(node.right)
            return True
        return not has_units(node)  # a number written inside the unit part: 1/min

    if unit_part is None or not collect(unit_part, 1.0):
        return None
    return powers


def cycles(powers: dict[str, float] | None) -> float:
    """How many times a unit part counts cycles per time: the power of its Hz units."""
    if not powers:
        return 0.0
    return sum(p for name, p in powers.items() if name.endswith(_HERTZ))


def per_minute(powers: dict[str, float] | None) -> bool:
    """Whether a unit part is exactly per minute (``1/min``, ``min^-1``, ``min⁻¹``), which
    is read as revolutions per minute."""
    return powers is not None and powers.keys() == {"min"} and abs(powers["min"] + 1) < 1e-12


def as_turns(dim: tuple, count: float) -> tuple:
    """``dim`` with ``count`` cycles read as turns (one angle exponent each)."""
    return units.add(dim, units.scale(_ANGLE, count))


def align(given: tuple, given_cycles: float, wanted: tuple,
          wanted_cycles: float) -> tuple[tuple, tuple, float]:
    """The given and wanted dimensions with Hz read as turns where the rule says so, and
    the power ``k`` of 2π that converts: the given value in the wanted unit is
    ``value · (2π)^k / factor`` (k = 1: Hz read as rad/s; k = -1: rad/s read as Hz)."""
    k = 0.0
    if given_cycles and (units.has_angle(wanted) or wanted_cycles):
        given = as_turns(given, given_cycles)
        k += given_cycles
    if wanted_cycles and (units.has_angle(given) or given_cycles):
        wanted = as_turns(wanted, wanted_cycles)
        k -= wanted_cycles
    return given, wanted, k
