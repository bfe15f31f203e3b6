"""How far a match on one part of an exercise makes a match on another part likely,
measured on the class's own keys: what copy detection (:mod:`.copies`) needs to combine
the matching parts of one exercise into one chance.

The parts of one exercise are worked out from the same few parameters, so their keys are
not independent: in the projectile exercise the flight time is ``√(8 h / g)`` of the peak
height, and two students whose peak heights agree have the same flight time too. An
honest student whose mistake carries through every part (a misread speed) hands in the
keys of another variant; any classmate who holds that variant then matches on every
part, and multiplying the parts' chances as if they were independent coincidences
would call that a copy.

For two compared parts ``i`` and ``j`` of an exercise, over the class's ordered pairs of
different students ``(u, v)`` with a variant: ``m_i`` pairs whose keys agree on ``i``
(``u``'s key within the part's tolerance of ``v``'s), ``m_ij`` on both, and
``π_j = m_j / (N (N − 1))`` the share of all pairs that agree on ``j``. The chance that
a pair agreeing on ``i`` agrees on ``j`` too is

    q(j | i) = (m_ij + 1) / (m_i + 1 / π_j)

the share ``m_ij / m_i``, drawn towards ``π_j`` (what independent parts give) by one
pair's weight: with few agreeing pairs the estimate stays near ``π_j``; with many it is
the share seen (``√(8 h / g)``: every pair that agrees on the peak height agrees on the
flight time, ``q`` near 1). Near-twin variants are counted like any others: a classmate
who holds the same variant as the one an answer was worked out for matches every part.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Mapping

import numpy as np

from ..exam.manifest import ExerciseEntry, Manifest
from .answer_values import as_rows, close_to, compared, key_value


@dataclass(frozen=True)
class PartDependence:
    """The counts behind ``q(j | i)`` for the compared parts of one exercise."""

    #: ordered pairs of students with a variant (``N (N − 1)``)
    pairs: int = 0
    #: ``m_i``: pairs whose keys agree on part ``i``
    agree: Mapping[str, int] = field(default_factory=dict)
    #: ``m_ij``: pairs whose keys agree on both parts (keyed ``(j, i)``; symmetric)
    both: Mapping[tuple[str, str], int] = field(default_factory=dict)

    def conditional(self, part: str, given: str) -> float:
        """``q(part | given)``; 1 (no evidence) for a part whose keys were not counted."""
        if part not in self.agree or given not in self.agree or self.pairs == 0:
            return 1.0
        share = max(self.agree[part], 1) / self.pairs
        return (self.both[(part, given)] + 1) / (self.agree[given] + 1 / share)


def part_dependence(manifest: Manifest, described: ExerciseEntry) -> PartDependence:
    """The counts of the module's docstring for one exercise of the manifest."""
    agreeing: dict[str, np.ndarray] = {}
    variants = [v for v in (s.variant(described.id) for s in manifest.students) if v]
    for entry in described.parts:
        if not compared(entry):
            continue
        keys = [key_value(entry, v.answers.get(entry.name)) for v in variants]
        known = [k for k in keys if k is not None]
        if len(known) < 2 or len(known) < len(keys):
            continue
        rows = as_rows(known)
        close = np.array([close_to(entry, key, rows) for key in known])
        np.fill_diagonal(close, False)
        agreeing[entry.name] = close
    both = {(j, i): int((agreeing[i] & agreeing[j]).sum())
            for i in agreeing for j in agreeing if i != j}
    return PartDependence(len(variants) * (len(variants) - 1),
                          {name: int(m.sum()) for name, m in agreeing.items()}, both)
