"""Conversion of author-declared units to SI and back.

Parameters and answer parts declare a unit (``"m/s"``, ``"deg"``, ``"kN"``). Solvers work
in SI (angles in radians), so the model converts each parameter into SI before calling the
solver and each answer out of SI into its part's unit. Unit strings here are written by
exercise authors, never by students.
"""

from __future__ import annotations

import re
from functools import lru_cache

from ..errors import UnitError
from ..grading import units as _dimensions


def si_factor(unit: str | None) -> float:
    """The factor that turns a value in ``unit`` into SI base units (radian for angles).

    Units are read by the grader's unit table, so parameters, answers and students'
    units share one definition; ``ValueError`` for a unit it does not know.
    """
    return _unit_info(unit)[0]


def to_si(value: float, unit: str | None) -> float:
    """``value`` given in ``unit``, expressed in SI."""
    return value * si_factor(unit)


def from_si(value: float, unit: str | None) -> float:
    """``value`` given in SI, expressed in ``unit``."""
    return value / si_factor(unit)


def _unit_info(unit: str | None):
    """(factor to SI, dimension) from the grader's unit table, imported on first use: it
    evaluates with numpy, which reading the bank's listing does not need."""
    from ..grading.quantity import unit_info

    return unit_info(unit)


_SUPERSCRIPTS = str.maketrans("-0123456789", "⁻⁰¹²³⁴⁵⁶⁷⁸⁹")
_POWER = re.compile(r"\s*(?:\*\*|\^)\s*(-?\d+)")


@lru_cache(maxsize=256)
def pretty_unit(unit: str | None) -> str:
    """A unit as printed on a sheet, in the author's order: ``m/s²``, ``°``, ``N·m``."""
    if not unit:
        return ""
    if unit.strip() in ("deg", "degree"):
        return "°"
    shown = _POWER.sub(lambda m: m.group(1).translate(_SUPERSCRIPTS), unit.strip())
    return re.sub(r"\s*\*\s*", "·", shown)


def with_unit(number: str, unit: str | None) -> str:
    """A formatted number followed by its unit, the degree sign without a space."""
    shown = pretty_unit(unit)
    if not shown:
        return number
    return f"{number}{shown}" if shown == "°" else f"{number} {shown}"


def convert(value: float, from_unit: str | None, to_unit: str | None) -> float:
    """``value`` in ``from_unit`` expressed in ``to_unit``; ``UnitError`` (a ``ValueError``)
    when the dimensions differ (the angle counts as a dimension of its own)."""
    factor = conversion_factor(from_unit, to_unit)
    if factor is None:
        raise UnitError(f"cannot convert {from_unit or 'a bare number'} "
                         f"to {to_unit or 'a bare number'}")
    return value * factor


@lru_cache(maxsize=1024)
def conversion_factor(from_unit: str | None, to_unit: str | None) -> float | None:
    """The factor that turns a value in ``from_unit`` into ``to_unit``; None when the
    dimensions differ (the angle counts as a dimension of its own). Remembered: verify
    asks it for every pair of parts in every variant."""
    (source, source_dim), (target, target_dim) = _unit_info(from_unit), _unit_info(to_unit)
    if not _dimensions.same(source_dim, target_dim):
        return None
    return source / target
