"""The JSON-lines interface of the grader (``dynagrade compare``).

Each input line is one record::

    {"id": str, "kind": "numeric"|"symbolic"|"vector"|"choice", "expected": ..., "answer": str,
     "rtol"?: number, "atol"?: number, "sigfigs"?: int, "unit"?: str,
     "variables"?: {name: {"min": number, "max": number, "unit"?: str, "symbol"?: str,
                           "aliases"?: [str]}}, "up_to_constant"?: bool | [str],
     "require_unit"?: bool, "unit_credit"?: number, "reveal"?: bool, "form"?: [str],
     "size"?: int, "choices"?: [str], "multiple"?: bool, "aliases"?: {str: str},
     "misconceptions"?: [{"name": str, "value": ..., "feedback": str, "score"?: number}]}

and gives one output line ``{"id", "correct", "score", "feedback", "error"}``. A
malformed line (bad JSON, missing field, wrong type, unusable spec) gives an output
line with ``error`` set and ``correct: false`` (``id`` null when unknown); the stream
never stops. Blank input lines are skipped. Unknown fields are ignored, so fields
can be added without breaking old readers.
"""

from __future__ import annotations

import json
import math
from dataclasses import dataclass
from typing import Iterable, Iterator, TypedDict

from ..errors import DynagradeError
from .dispatch import grade
from .errors import AnswerError, SpecError
from .preparation import prepare
from .spec import ChoiceSpec, KnownWrong, NumericSpec, SymbolicSpec, Variable, VectorSpec



class RecordError(DynagradeError, ValueError):
    """A record that does not follow the contract."""


def _number(record: dict, key: str, *, required: bool = False, integer: bool = False):
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


def _string(record: dict, key: str, *, required: bool = False):
    if key not in record or record[key] is None:
        if required:
            raise RecordError(f"missing field '{key}'")
        return None
    if not isinstance(record[key], str):
        raise RecordError(f"field '{key}' must be a string")
    return record[key]


def _flag(record: dict, key: str) -> bool:
    value = record.get(key, False)
    if value is None:
        return False
    if not isinstance(value, bool):
        raise RecordError(f"field '{key}' must be true or false")
    return value


def _misconceptions(record: dict) -> tuple[KnownWrong, ...]:
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
        score = _number(item, "score") or 0.0
        out.append(KnownWrong(item["name"], value, item["feedback"], float(score)))
    return tuple(out)


def _numeric_expected(record: dict, unit: str | None):
    """The reference as a float in the part's unit, and the unit (which a string
    reference like "12.5 m/s" may define)."""
    expected = record["expected"]
    if isinstance(expected, bool):
        raise RecordError("field 'expected' must be a number or a string with a unit")
    if isinstance(expected, (int, float)):
        if not math.isfinite(expected):
            raise RecordError("field 'expected' must be finite")
        return float(expected), unit
    if not isinstance(expected, str):
        raise RecordError("field 'expected' must be a number or a string with a unit")
    from .quantity import read_quantity, unit_info
    from . import units

    try:
        q = read_quantity(expected)
    except AnswerError as error:
        raise RecordError(f"cannot read 'expected': {error.message}") from None
    if q.dim is None:
        return q.value, unit
    if unit is None:
        if q.unit_text is None:
            raise RecordError("cannot tell the unit of 'expected'; give the field 'unit'")
        return q.value / q.unit_factor, q.unit_text.replace(" ", "")
    factor, dim = unit_info(unit)
    if not units.compatible(q.dim, dim):
        raise RecordError(f"'expected' ({expected}) cannot be converted to '{unit}'")
    return q.value / factor, unit


def _variables(record: dict) -> dict:
    raw = record.get("variables")
    if raw is None:
        return {}
    if not isinstance(raw, dict):
        raise RecordError("field 'variables' must be an object")
    out = {}
    for name, domain in raw.items():
        if not isinstance(domain, dict):
            raise RecordError(f"variable '{name}' must be an object with 'min' and 'max'")
        lo = _number(domain, "min", required=True)
        hi = _number(domain, "max", required=True)
        out[name] = Variable(float(lo), float(hi), _string(domain, "unit"),
                             symbol=_string(domain, "symbol"),
                             aliases=tuple(_strings(domain, "aliases", f"variable '{name}'")))
    return out


def _strings(record: dict, key: str, where: str) -> list[str]:
    """An optional list of strings (empty when absent)."""
    value = record.get(key) or []
    if not isinstance(value, list) or not all(isinstance(v, str) for v in value):
        raise RecordError(f"field '{key}' of {where} must be a list of strings")
    return value


def _constant_in(record: dict) -> bool | tuple[str, ...]:
    """``up_to_constant``: true (every variable), or the variables it is constant in."""
    value = record.get("up_to_constant")
    if value is None or isinstance(value, bool):
        return bool(value)
    return tuple(_strings(record, "up_to_constant", "the record"))


class _RelativeTolerance(TypedDict, total=False):
    rtol: float


class _Tolerances(_RelativeTolerance, total=False):
    atol: float


@dataclass(frozen=True)
class _Common:
    """The fields every kind of record may carry, already checked."""

    unit: str | None
    rtol: float | None
    atol: float | None
    reveal: bool
    misconceptions: tuple[KnownWrong, ...]

    def tolerances(self) -> _Tolerances:
        """The tolerances the record sets (a spec keeps its own default for the others)."""
        found: _Tolerances = {}
        if self.rtol is not None:
            found["rtol"] = float(self.rtol)
        if self.atol is not None:
            found["atol"] = float(self.atol)
        return found

    def relative_tolerance(self) -> _RelativeTolerance:
        """The relative tolerance if the record sets one (a symbolic part has no other)."""
        return {} if self.rtol is None else {"rtol": float(self.rtol)}


def _numeric(record: dict, common: _Common):
    expected, unit = _numeric_expected(record, common.unit)
    sigfigs = _number(record, "sigfigs", integer=True)
    unit_credit = _number(record, "unit_credit")
    spec = NumericSpec(unit=unit, **common.tolerances(), sigfigs=sigfigs,
                       misconceptions=common.misconceptions,
                       require_unit=_flag(record, "require_unit"),
                       unit_credit=None if unit_credit is None else float(unit_credit),
                       reveal=common.reveal)
    return spec, expected


def _symbolic(record: dict, common: _Common):
    expected = _string(record, "expected", required=True)
    form = record.get("form") or ()
    if not isinstance(form, (list, tuple)) or not all(isinstance(f, str) for f in form):
        raise RecordError("field 'form' must be a list of strings")
    spec = SymbolicSpec(_variables(record), **common.relative_tolerance(),
                        misconceptions=common.misconceptions, form=tuple(form),
                        reveal=common.reveal, up_to_constant=_constant_in(record))
    return spec, expected


def _vector(record: dict, common: _Common):
    expected = record["expected"]
    if not isinstance(expected, list) or not all(
            isinstance(x, (int, float)) and not isinstance(x, bool) for x in expected):
        raise RecordError("field 'expected' of a vector must be a list of numbers")
    size = _number(record, "size", integer=True) or len(expected)
    spec = VectorSpec(size, unit=common.unit, **common.tolerances(),
                      misconceptions=common.misconceptions,
                      require_unit=_flag(record, "require_unit"), reveal=common.reveal)
    return spec, tuple(float(x) for x in expected)


def _choice(record: dict, common: _Common):
    choices = record.get("choices")
    if not isinstance(choices, list) or not choices or not all(isinstance(c, str) for c in choices):
        raise RecordError("field 'choices' must be a non-empty list of strings")
    expected = record["expected"]
    if isinstance(expected, list):
        expected = tuple(expected)
    if not (isinstance(expected, str) or (isinstance(expected, tuple) and all(isinstance(x, str) for x in expected))):
        raise RecordError("field 'expected' of a choice must be a label or a list of labels")
    aliases = record.get("aliases") or {}
    if not isinstance(aliases, dict) or not all(isinstance(v, str) for v in aliases.values()):
        raise RecordError("field 'aliases' must be an object of labels")
    spec = ChoiceSpec(tuple(choices), multiple=_flag(record, "multiple") or isinstance(expected, tuple),
                      reveal=common.reveal, aliases=tuple(aliases.items()))
    return spec, expected


#: the spec and reference of a record, by its ``kind`` (one builder per kind)
BUILDERS = {"numeric": _numeric, "symbolic": _symbolic, "vector": _vector, "choice": _choice}
KINDS = tuple(BUILDERS)


def build(record: dict):
    """(spec, expected, answer) from a record; RecordError when malformed."""
    kind = _string(record, "kind", required=True)
    if kind not in BUILDERS:
        raise RecordError(f"field 'kind' must be one of {', '.join(KINDS)}, got {kind!r}")
    if "expected" not in record:
        raise RecordError("missing field 'expected'")
    answer = _string(record, "answer", required=True)
    common = _Common(_string(record, "unit"), _number(record, "rtol"), _number(record, "atol"),
                     _flag(record, "reveal"), _misconceptions(record))
    spec, expected = BUILDERS[kind](record, common)
    return spec, expected, answer


def _failure(record_id, message: str) -> dict:
    return {"id": record_id, "correct": False, "score": 0.0, "feedback": message, "error": message}


def compare_record(record: dict) -> dict:
    """Grade one record of the contract; never raises."""
    if not isinstance(record, dict):
        return _failure(None, "a record must be a JSON object")
    record_id = record.get("id")
    if not isinstance(record_id, str):
        if "id" not in record:
            return _failure(None, "missing field 'id'")
        return _failure(None, "field 'id' must be a string")
    try:
        spec, expected, answer = build(record)
        verdict = grade(spec, expected, answer)
    except (RecordError, SpecError, ValueError, TypeError) as error:
        return _failure(record_id, str(error))
    return {"id": record_id, "correct": verdict.correct, "score": verdict.score,
            "feedback": verdict.feedback, "error": verdict.error}


def compare_lines(lines: Iterable[str]) -> Iterator[str]:
    """Grade JSON lines; yields one JSON text (without newline) per non-blank input line.

    What any answer may need (pint's registry, the exact and high-precision checks) is
    loaded before the first line, so no verdict spends its time budget on imports."""
    prepare()
    for number, line in enumerate(lines, start=1):
        if not line.strip():
            continue
        try:
            record = json.loads(line)
        except (json.JSONDecodeError, RecursionError) as error:
            message = f"line {number}: not valid JSON ({getattr(error, 'msg', 'too deeply nested')})"
            yield json.dumps(_failure(None, message), ensure_ascii=False)
            continue
        result = compare_record(record)
        if result["error"] and result["id"] is None:
            result["error"] = result["feedback"] = f"line {number}: {result['error']}"
        yield json.dumps(result, ensure_ascii=False)
