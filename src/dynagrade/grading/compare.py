"""The JSON-lines interface of the grader (``dynagrade compare``).

Each input line is one record::

    {"id": str, "kind": "numeric"|"symbolic"|"vector"|"choice", "expected": ..., "answer": str,
     "rtol"?: number, "atol"?: number, "sigfigs"?: int, "unit"?: str,
     "variables"?: {name: {"min": number, "max": number, "unit"?: str, "symbol"?: str,
                           "aliases"?: [str]}}, "up_to_constant"?: bool | [str],
     "require_unit"?: bool, "unit_credit"?: number, "reveal"?: bool, "form"?: [str],
     "size"?: int, "basis"?: [str], "choices"?: [str], "multiple"?: bool, "aliases"?: {str: str},
     "misconceptions"?: [{"name": str, "value": ..., "feedback": str, "score"?: number}]}

and gives one output line ``{"id", "correct", "score", "feedback", "error"}``. A
malformed line (bad JSON, missing field, wrong type, unusable spec) gives an output
line with ``error`` set and ``correct: false`` (``id`` null when unknown); the stream
never stops. Blank input lines are skipped. Unknown fields are ignored, so fields
can be added without breaking old readers. Each kind builds its own spec from a record
(the ``build`` of its :class:`~dynagrade.grading.kinds.GradingKind`, with the field
checks of :mod:`.records`).
"""

from __future__ import annotations

import json
from typing import Iterable, Iterator

from .dispatch import grade
from .errors import SpecError
from .kinds import GRADING_KINDS
from .preparation import prepare
from .records import Common, RecordError, flag, misconceptions, number, string


def kinds() -> tuple[str, ...]:
    """The kinds a record may name: every registered part kind (:mod:`.kinds`)."""
    return tuple(GRADING_KINDS)


def build(record: dict):
    """(spec, expected, answer) from a record; RecordError when malformed."""
    kind = string(record, "kind", required=True)
    if kind not in GRADING_KINDS:
        raise RecordError(f"field 'kind' must be one of {', '.join(kinds())}, got {kind!r}")
    if "expected" not in record:
        raise RecordError("missing field 'expected'")
    answer = string(record, "answer", required=True)
    common = Common(string(record, "unit"), number(record, "rtol"), number(record, "atol"),
                    flag(record, "reveal"), misconceptions(record))
    spec, expected = GRADING_KINDS[kind].function("build")(record, common)
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
