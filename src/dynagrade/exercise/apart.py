"""Whether a variant's numbers lie far enough apart that none can be handed in for another.

Two parts of different meaning whose keys coincide in a variant (a distance and a time
both 0.2548 in SI) let a student score with the wrong formula. An exercise states the
condition as a constraint on its answers::

    Constraint("the three answers differ by over 5 %",
               lambda p: clearly_apart([abs(x) for x in solve(p).values()]))
"""
from __future__ import annotations

from typing import Iterable

#: the default share: five times the default 1 % tolerance of a numeric part
SHARE = 0.05


def clearly_apart(values: Iterable[float], share: float = SHARE) -> bool:
    """Whether every two of ``values`` differ by more than ``share`` of the larger of the
    two (compare magnitudes by passing ``abs`` of each where the sign is no part of it).

    >>> clearly_apart([1.0, 1.2, 2.0]), clearly_apart([1.0, 1.04, 2.0])
    (True, False)
    """
    numbers = [float(value) for value in values]
    return all(abs(a - b) > share * max(abs(a), abs(b))
               for i, a in enumerate(numbers) for b in numbers[i + 1:])
