"""Conversion of author-declared units to SI and back.

Parameters and answer parts declare a unit (``"m/s"``, ``"deg"``, ``"kN"``). Solvers work
in SI (angles in radians), so the model converts each parameter into SI before calling the
solver and each answer out of SI into its part's unit. Unit strings here are written by
exercise authors, never by students.
"""

from __future__ import annotations

import re
from functools import lru_cache


@lru_cache(maxsize=1)
def _registry():
    import pint  # imported on first use: pint costs a few hundred ms to load

    return pint.UnitRegistry()


@lru_cache(maxsize=256)
def si_factor(unit: str | None) -> float:
    """The factor that turns a value in ``unit`` into SI base units (radian for angles)."""
    if not unit:
        return 1.0
    try:
        quantity = _registry().Quantity(1.0, unit).to_base_units()
    except Exception as error:  # pint raises several unrelated types for a bad unit
        raise ValueError(f"unknown unit {unit!r}: {error}") from None
    return float(quantity.magnitude)


def to_si(value: float, unit: str | None) -> float:
    """``value`` given in ``unit``, expressed in SI."""
    return value * si_factor(unit)


def from_si(value: float, unit: str | None) -> float:
    """``value`` given in SI, expressed in ``unit``."""
    return value / si_factor(unit)


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
    """``value`` in ``from_unit`` expressed in ``to_unit``; ``ValueError`` when the
    dimensions differ (angles count as their own dimension here)."""
    if (from_unit or "") == (to_unit or ""):
        return value
    registry = _registry()
    source, target = registry.Unit(from_unit or ""), registry.Unit(to_unit or "")
    if source.dimensionality != target.dimensionality or _is_angle(source) != _is_angle(target):
        raise ValueError(f"cannot convert {from_unit or 'a bare number'} to {to_unit or 'a bare number'}")
    return float(registry.Quantity(value, source).to(target).magnitude)


def _is_angle(unit) -> bool:
    """Whether ``unit`` measures angles (pint reduces radian to a dimensionless unit)."""
    return "radian" in str((1 * unit).to_base_units().units)
