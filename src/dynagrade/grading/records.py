"""Reading the fields of a ``dynagrade compare`` record (:mod:`.compare`): the checks every
kind's builder shares (a number, a string, a flag, the misconceptions, the variables)
and :class:`Common`, the fields every kind may carry. A kind's builder (``build`` of its
:class:`~dynagrade.grading.kinds.GradingKind`) turns a record into its spec and reference
with these; a malformed field is a :class:`RecordError` naming it."""

from __future__ import annotations

import json
import math
from dataclasses import dataclass
from typing import TypedDict

from ..errors import DynagradeError
from .spec import KnownWrong, Variable


class RecordError(DynagradeError, ValueError):
    """A record that does not follow the contract."""


def number(record: dict, key: str, *, required: bool = False, integer: bool = False):
    """A finite number (an integer with ``integer``) or None when absent."""
    if key not in record or record[key] is None:
        if required:
            raise RecordError(f"missing field '{key}'")
        return None
    value = record[key]
    if isinstance(value, bool) or not isinstance(value, (int, float)) or \
            (integer and not isinstance(value, int)) or not math.isfinite(value):
        kind = "an integer" if integer else "a finite number"
        raise RecordError(f"field '{key}' must be {kind}, got {json.dumps(value)[:40]}")
    return value


def string(record: dict, key: str, *, required: bool = False):
    """A string, or None when absent."""
    if key not in record or record[key] is None:
        if required:
            raise RecordError(f"missing field '{key}'")
        return None
    if not isinstance(record[key], str):
        raise RecordError(f"field '{key}' must be a string")
    return record[key]


def flag(record: dict, key: str) -> bool:
    """True or false (false when absent)."""
    value = record.get(key, False)
    if value is None:
        return False
    if not isinstance(value, bool):
        raise RecordError(f"field '{key}' must be true or false")
    return value


def misconceptions(record: dict) -> tuple[KnownWrong, ...]:
    """The declared misconceptions (a list becomes a tuple of numbers, for a vector)."""
    items = record.get("misconceptions") or []
    if not isinstance(items, list):
        raise RecordError("field 'misconceptions' must be a list")
    out = []
    for item in items:
        if not isinstance(item, dict) or not isinstance(item.get("name"), str) or \
                not isinstance(item.get("feedback"), str) or "value" not in item:
            raise RecordError("each misconception needs 'name', 'value' and 'feedback'")
        value = item["value"]
        if isinstance(value, list):
            value = tuple(value)
        score = number(item, "score") or 0.0
        out.append(KnownWrong(item["name"], value, item["feedback"], float(score)))
    return tuple(out)


def variables(record: dict) -> dict:
    """A symbolic record's variables, each a :class:`Variable` with its domain."""
    raw = record.get("variables")
    if raw is None:
        return {}
    if not isinstance(raw, dict):
        raise RecordError("field 'variables' must be an object")
    out = {}
    for name, domain in raw.items():
        if not isinstance(domain, dict):
            raise RecordError(f"variable '{name}' must be an object with 'min' and 'max'")
        lo = number(domain, "min", required=True)
        hi = number(domain, "max", required=True)
        out[name] = Variable(float(lo), float(hi), string(domain, "unit"),
                             symbol=string(domain, "symbol"),
                             aliases=tuple(strings(domain, "aliases", f"variable '{name}'")))
    return out


def strings(record: dict, key: str, where: str) -> list[str]:
    """An optional list of strings (empty when absent)."""
    value = record.get(key) or []
    if not isinstance(value, list) or not all(isinstance(v, str) for v in value):
        raise RecordError(f"field '{key}' of {where} must be a list of strings")
    return value


def constant_in(record: dict) -> bool | tuple[str, ...]:
    """``up_to_constant``: true (every variable), or the variables it is constant in."""
    value = record.get("up_to_constant")
    if value is None or isinstance(value, bool):
        return bool(value)
    return tuple(strings(record, "up_to_constant", "the record"))


class RelativeTolerance(TypedDict, total=False):
    """A relative tolerance, where a record sets one (a spec's keyword argument)."""

    rtol: float


class Tolerances(RelativeTolerance, total=False):
    """The tolerances a record sets, as a spec's keyword arguments."""

    atol: float


@dataclass(frozen=True)
class Common:
    """The fields every kind of record may carry, already checked."""

    unit: str | None
    rtol: float | None
    atol: float | None
    reveal: bool
    misconceptions: tuple[KnownWrong, ...]

    def tolerances(self) -> Tolerances:
        """The tolerances the record sets (a spec keeps its own default for the others)."""
        found: Tolerances = {}
        if self.rtol is not None:
            found["rtol"] = float(self.rtol)
        if self.atol is not None:
            found["atol"] = float(self.atol)
        return found

    def relative_tolerance(self) -> RelativeTolerance:
        """The relative tolerance if the record sets one (a formula has no other)."""
        return {} if self.rtol is None else {"rtol": float(self.rtol)}
