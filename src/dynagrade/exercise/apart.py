"""Keys that stay apart: a constraint helper against parts whose numbers coincide.

Two parts of different meaning whose numbers agree within a tolerance in a variant (a
speed and an angular speed both 2.31 in SI) let a student who swaps the formulas score.
An exercise keeps them apart with a constraint:
``Constraint("the keys differ by over 5 %", lambda p: numbers_apart(solve(p).values()))``.
"""

from __future__ import annotations

from collections.abc import Iterable
from itertools import combinations


def numbers_apart(values: Iterable[float], rtol: float = 0.05) -> bool:
    """True if the magnitudes of every two of ``values`` differ by more than ``rtol`` of
    the larger one (zero and zero do not differ)."""
    magnitudes = [abs(float(v)) for v in values]
    return all(abs(a - b) > rtol * max(a, b) for a, b in combinations(magnitudes, 2))
