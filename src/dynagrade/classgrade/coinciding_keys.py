"""When two variants' keys are the same number for a reason, not by chance: what copy
detection (:mod:`.copies`) needs before it counts an answer that agrees with a
classmate's key to every digit it shows as a rare coincidence.

An honest student who misreads one number of their statement (or swaps two) and works
every part out right hands in, to every digit, the keys of another variant. Two things
follow, and both are measured on the class's own variants:

- **Related variants.** A classmate who holds that variant has numbers that are all but
  one the student's own, or theirs with two swapped: :func:`related_variants`. A digit agreement with a related
  variant's key is no rarer than an agreement within the tolerance.
- **Identical keys of different variants.** Some parts give the same key on different
  variants: the range of a projectile is the same at α and 90° − α. The misread variant
  may then share that part's key, to every digit, with a classmate whose numbers are
  not the student's own. :func:`identical_key_share` is, per part, the share of the
  ordered pairs of students with different variants whose keys are the same number (to
  10⁻⁹ relative), smoothed by one pair: a digit agreement on that part is at least that
  likely. The smoothing also means that an agreement on one part alone never makes a pair
  stand out in a class: it takes two.
"""

from __future__ import annotations

import math
from typing import Any, Mapping

import numpy as np

from ..exam.manifest import ExerciseEntry, Manifest
from .answer_values import compared, key_value

#: keys (and parameter values) closer than this, relative, are the same number
SAME = 1e-9


def changes(mine: Mapping[str, Any], theirs: Mapping[str, Any]) -> int:
    """How many changes turn the variant ``mine`` into ``theirs``: a parameter given
    another number is one change, two parameters whose numbers are swapped are one."""
    differ = [name for name in mine.keys() | theirs.keys()
              if not _same_number(mine.get(name), theirs.get(name))]
    count, left = len(differ), set(differ)
    for a in differ:
        for b in differ:
            if a < b and {a, b} <= left and _same_number(mine.get(a), theirs.get(b)) \
                    and _same_number(mine.get(b), theirs.get(a)):
                left -= {a, b}
                count -= 1
    return count


def related_variants(mine: Mapping[str, Any], theirs: Mapping[str, Any]) -> bool:
    """Whether one change at most turns ``mine`` into ``theirs`` (:func:`changes`)."""
    return changes(mine, theirs) <= 1


def _same_number(a: Any, b: Any) -> bool:
    if _is_number(a) and _is_number(b):
        return math.isclose(float(a), float(b), rel_tol=SAME, abs_tol=1e-300)
    return a == b


def identical_key_share(manifest: Manifest, described: ExerciseEntry) -> dict[str, float]:
    """Per compared part, ``(m + 1) / (M + 1)``: ``m`` of the ``M`` ordered pairs of
    students with different variants have keys that are the same number."""
    variants = [v for v in (s.variant(described.id) for s in manifest.students) if v]
    numbers = [tuple(_numbers(v.params)) for v in variants]
    kinds = {n: k for k, n in enumerate(dict.fromkeys(numbers))}
    variant_of = np.array([kinds[n] for n in numbers])
    different = variant_of[:, None] != variant_of[None, :]
    pairs = int(different.sum())
    shares = {}
    for entry in described.parts:
        if not compared(entry):
            continue
        keys = [key_value(entry, v.answers.get(entry.name)) for v in variants]
        same = 0
        if all(isinstance(k, float) for k in keys):
            column = np.array(keys, dtype=np.float64)
            with np.errstate(invalid="ignore"):
                equal = np.abs(column[:, None] - column[None, :]) <= \
                    SAME * np.maximum(np.abs(column[:, None]), np.abs(column[None, :]))
            same = int((equal & different).sum())
        shares[entry.name] = (same + 1) / (pairs + 1)
    return shares


def _numbers(params: Mapping[str, Any]) -> list[float]:
    return [float(v) for v in params.values() if _is_number(v)]


def _is_number(value: Any) -> bool:
    return isinstance(value, (int, float)) and not isinstance(value, bool)
