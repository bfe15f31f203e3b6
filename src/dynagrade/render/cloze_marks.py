"""The whole-number weights of a cloze question's fields, in the exam's proportions.

Moodle ignores a cloze question's ``<defaultgrade>``: its full mark is the sum of the
fields' weights (``{N:...}``, whole numbers; ``qtype_multianswer_extract_question`` adds
them up into the question's default mark), and each field's share of the question is its
weight over that sum. :func:`field_weights` chooses weights proportional to the points
each field carries in the exam, so that every part keeps its share:

- points that are whole numbers are the weights themselves (2, 2, 2 stay 2, 2, 2: the
  question's full mark is then the exercise's points);
- otherwise the points are scaled by the least common denominator and reduced by the
  greatest common divisor (2.4, 1.2, 2.4 become 2, 1, 2);
- a vector part's points are split evenly over its components first (2 points over three
  components: 2/3 each), as dynagrade scores the share of right components.

A proportion that needs weights summing to more than :data:`MAX_TOTAL` (points with
awkward decimals) is approximated by weights summing to :data:`APPROXIMATE_TOTAL`
(largest remainders); :class:`Weights` says whether the shares are exact.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from fractions import Fraction

#: the largest sum of exact weights written; beyond it the proportions are approximated
#: (points in hundredths, as exams round them, stay exact up to 1000 points)
MAX_TOTAL = 100_000
#: the sum of approximate weights
APPROXIMATE_TOTAL = 100
#: the largest denominator a point value is read with (0.714286 is 5/7)
_DENOMINATOR = 1000


@dataclass(frozen=True)
class Weights:
    """The fields' weights, their sum (Moodle's full mark of the question) and whether
    they only approximate the points' proportions."""

    weights: tuple[int, ...]
    exact: bool = True

    @property
    def total(self) -> int:
        return sum(self.weights)


def field_points(part_points: float, fields: int) -> list[float]:
    """The points of each of a part's ``fields`` (a vector's components share them)."""
    return [part_points / fields] * fields


def field_weights(points: list[float]) -> Weights:
    """Whole-number weights proportional to ``points`` (each >= 0), as described above;
    fields that all carry 0 points weigh 1 each."""
    if not points:
        return Weights(())
    if any(p < 0 or not math.isfinite(p) for p in points):
        raise ValueError(f"points must be finite and >= 0, got {points}")
    exact = [Fraction(p).limit_denominator(_DENOMINATOR) for p in points]
    if not any(exact):
        return Weights((1,) * len(points))
    denominator = math.lcm(*(f.denominator for f in exact))
    scaled = [int(f * denominator) for f in exact]
    if denominator > 1:
        divisor = math.gcd(*scaled)
        scaled = [s // divisor for s in scaled]
    if sum(scaled) > MAX_TOTAL:
        scaled = list(_largest_remainders(points, APPROXIMATE_TOTAL))
    return Weights(tuple(scaled), exact=_same_shares(scaled, points))


def _same_shares(weights: list[int], points: list[float]) -> bool:
    """Whether every field's share of the weights is its share of the points (to 1e-5)."""
    total_weight, total_points = sum(weights), sum(points)
    return all(abs(w / total_weight - p / total_points) <= 1e-5
               for w, p in zip(weights, points))


def _largest_remainders(points: list[float], total: int) -> tuple[int, ...]:
    """Whole numbers summing to ``total`` in the proportions of ``points`` (Hamilton's
    method), none below 1 where the points are positive."""
    whole = sum(points)
    quotas = [total * p / whole for p in points]
    weights = [max(1, math.floor(q)) if p > 0 else 0 for q, p in zip(quotas, points)]
    order = sorted(range(len(points)), key=lambda i: quotas[i] - math.floor(quotas[i]),
                   reverse=True)
    for index in order[:max(0, total - sum(weights))]:
        weights[index] += 1
    return tuple(weights)
