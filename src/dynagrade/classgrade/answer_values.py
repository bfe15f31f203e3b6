"""The numbers behind a class's numeric and vector answers, and the one closeness rule
that copy detection (:mod:`.copies`) and misconception discovery (:mod:`.discover`)
compare them with: the part's own tolerance, as the grader judges an answer
(:func:`dynagrade.grading.tolerance.is_close`; a vector component by component, each
against ``max(|e_i|, 0.01·|e|)``, :func:`dynagrade.grading.vector.component_scale`).

A value is a float (a numeric part) or a tuple of floats (a vector part), in the part's
unit. Answers are read by the grader's own reader (never evaluated as code); one that
cannot be read has no value and takes part in neither feature.
"""

from __future__ import annotations

from typing import Any, Union

import numpy as np

from ..exam.manifest import PartEntry
from ..exercise.parts import PART_KINDS
from ..grading.tolerance import DEFAULT_RTOL, allowed_error

Value = Union[float, tuple[float, ...]]


def compared(entry: PartEntry) -> bool:
    """Whether the part's answers are numbers (its kind's ``compares_numbers``)."""
    return PART_KINDS[entry.kind].compares_numbers


def answer_value(entry: PartEntry, text: str | None) -> Value | None:
    """The value of the answer ``text`` in the part's unit (None: unreadable or empty),
    as the part's kind reads it."""
    if not text or not text.strip():
        return None
    return PART_KINDS[entry.kind].answer_number(entry, text)


def key_value(entry: PartEntry, key: Any) -> Value | None:
    """The manifest's reference answer as a value (None: not a number)."""
    return PART_KINDS[entry.kind].key_number(key)


def as_rows(values: list[Value]) -> np.ndarray:
    """Values as a 2-D array, one row per value (a number is a row of one)."""
    return np.array([[v] if isinstance(v, float) else list(v) for v in values],
                    dtype=np.float64).reshape(len(values), -1)


def window(entry: PartEntry, targets: np.ndarray) -> np.ndarray:
    """Per target row and component, the largest distance at which a value is still
    close to it: the part's tolerance, as the grader allows it (a value of several
    components, a vector's, component by component against ``max(|e_i|, 0.01·|e|)``)."""
    if targets.shape[1] > 1:
        scale = np.maximum(np.abs(targets),
                           0.01 * np.linalg.norm(targets, axis=1, keepdims=True))
        return np.asarray(allowed_error(targets, _rtol(entry), entry.atol, scale))
    return np.asarray(allowed_error(targets, _rtol(entry), entry.atol))


def close_to(entry: PartEntry, value: Value, targets: np.ndarray,
             widen: float = 1.0) -> np.ndarray:
    """For each row of ``targets``, whether ``value`` lies within ``widen`` times the
    part's tolerance around it (every component, for a vector)."""
    if len(targets) == 0:
        return np.zeros(0, dtype=bool)
    row = as_rows([value])[0]
    if row.shape[0] != targets.shape[1]:
        return np.zeros(len(targets), dtype=bool)
    allowed = widen * window(entry, targets) + 1e-12 * np.abs(targets)
    with np.errstate(invalid="ignore"):
        return np.all(np.abs(targets - row) <= allowed, axis=1) & np.all(np.isfinite(targets),
                                                                         axis=1)


def is_near(entry: PartEntry, value: Value, target: Value, widen: float = 1.0) -> bool:
    """Whether ``value`` lies within ``widen`` times the part's tolerance of ``target``."""
    return bool(close_to(entry, value, as_rows([target]), widen)[0])


def _rtol(entry: PartEntry) -> float:
    return DEFAULT_RTOL if entry.rtol is None else entry.rtol
