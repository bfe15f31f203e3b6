"""Points of an exam: the rounding it declares and the split of an exercise's points
over its parts.

``exam.toml`` says how points are rounded, with ``round = 0.5`` (multiples of a step) or
``decimals = 2`` (the default: hundredths). Every number a person or a gradebook reads
is a multiple of that step: the parts' points (sheet, fill-in file, key, feedback), each
part's score and, summed from those, the exercise and exam totals.

An exercise's points are split over its parts in proportion to the parts' own points
(the weights the exercise declares) by the largest-remainder method, so that the parts
are multiples of the step and add up to the exercise's points exactly::

    >>> split_points(10, (1, 2, 4), Rounding(0.5))
    (1.5, 3.0, 5.5)

(20 half points; the quotas 2.857, 5.714, 11.43 are cut to 2, 5, 11 and the two half
points left go to the largest remainders, 0.857 and 0.714.) An exam may instead give
every part's points itself (``[exercise.points]``, :mod:`.spec`).

:func:`exam_part_points` is the one function that decides a part's points in an exam;
the generation (:func:`dynagrade.generation.generate.exercise_parts`) and any export that
needs the parts' share call it.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from decimal import Decimal
from fractions import Fraction
from typing import Mapping, Sequence

#: the default rounding of points: hundredths (``decimals = 2``)
DEFAULT_STEP = 0.01
#: a value this close to a multiple of the step counts as that multiple (float noise)
_SLACK = 1e-9


@dataclass(frozen=True)
class Rounding:
    """Points are multiples of ``step`` (0.5 for ``round = 0.5``; 0.01 for ``decimals =
    2``); rounding goes to the nearest multiple, a half step upwards."""

    step: float = DEFAULT_STEP

    def __post_init__(self):
        if not (math.isfinite(self.step) and self.step > 0):
            raise ValueError(f"a rounding step must be a positive number, not {self.step!r}")

    @classmethod
    def to_decimals(cls, decimals: int) -> Rounding:
        """Rounding to ``decimals`` decimal places."""
        return cls(float(Decimal(1).scaleb(-decimals)))

    @property
    def decimals(self) -> int:
        """The decimal places a multiple of the step needs (0.5 → 1, 0.25 → 2, 1 → 0)."""
        exponent = Decimal(repr(self.step)).normalize().as_tuple().exponent
        return max(0, -int(exponent))

    def steps(self, value: float) -> int:
        """``value`` as a whole number of steps, rounded to the nearest (half up)."""
        return math.floor(float(value) / self.step + 0.5 + _SLACK)

    def points(self, steps: int) -> float:
        """``steps`` steps as points, without a float's noise (3 × 0.1 is 0.3)."""
        return round(steps * self.step, self.decimals)

    def round(self, value: float) -> float:
        """``value`` rounded to the nearest multiple of the step."""
        return self.points(self.steps(value))

    def total(self, values: Sequence[float]) -> float:
        """The sum of values that are multiples of the step, summed in steps (exact)."""
        return self.points(sum(self.steps(v) for v in values))

    def is_multiple(self, value: float) -> bool:
        """Whether ``value`` is a whole number of steps."""
        return abs(float(value) / self.step - self.steps(value)) <= 1e-6

    def describe(self) -> str:
        """How the exam's points are rounded, for messages (``multiples of 0.5``)."""
        return f"multiples of {self.text(self.step)}"

    def text(self, value: float) -> str:
        """``value`` rounded and written with the step's decimals, trailing zeros dropped
        (``2.5``, ``3``, ``1.14``)."""
        shown = f"{self.round(value):.{self.decimals}f}"
        if "." in shown:
            shown = shown.rstrip("0").rstrip(".")
        return "0" if shown == "-0" else shown


def split_points(total: float, weights: Sequence[float], rounding: Rounding) -> tuple[float, ...]:
    """``total`` points split over parts in proportion to ``weights``, each a multiple of
    the rounding's step and together exactly ``total`` (largest-remainder method; a tie
    goes to the earlier part).

    ``total`` must itself be a multiple of the step and the weights must be non-negative
    with a positive sum; otherwise :class:`ValueError` says which."""
    if not rounding.is_multiple(total):
        raise ValueError(f"{total:g} points cannot be split into {rounding.describe()}")
    if any(w < 0 for w in weights) or sum(weights) <= 0:
        raise ValueError(f"the weights {list(weights)} must be non-negative with a "
                         "positive sum")
    steps = rounding.steps(total)
    whole = sum(Fraction(w) for w in weights)
    quotas = [steps * Fraction(w) / whole for w in weights]
    shares = [math.floor(q) for q in quotas]
    left = steps - sum(shares)
    by_remainder = sorted(range(len(quotas)), key=lambda i: (-(quotas[i] - shares[i]), i))
    for index in by_remainder[:left]:
        shares[index] += 1
    return tuple(rounding.points(s) for s in shares)


def exam_part_points(weights: Mapping[str, float], points: float,
                     given: Mapping[str, float] | None, rounding: Rounding) -> dict[str, float]:
    """Each part's points in the exam, by part name in the order of ``weights`` (the
    exercise's own part points): the points the exam gives each part (``given``, from
    ``[exercise.points]``) or else ``points`` split over ``weights``
    (:func:`split_points`)."""
    if given:
        return {name: float(given[name]) for name in weights}
    return dict(zip(weights, split_points(points, list(weights.values()), rounding)))
