"""Whether a variant's answers of different meaning can be told apart by their numbers.

Two answers that print (nearly) the same number — a time of 0.2548 s and a distance of
0.2548 m, or 80 MPa and 80 µs — let a student who swaps the formulas score. An exercise
whose answers can come close says so in a constraint (issue 31)::

    from dynagrade.exercise.apart import answers_apart

    UNITS = {"sigma": 1e6, "t_c": 1e-6, "v2": 1.0}  # each part's unit as a factor of SI
    Constraint("the answers are over 10 % apart", lambda p: answers_apart(solve(p), UNITS))
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Mapping


def answers_apart(solved: Mapping[str, float], units: Mapping[str, float],
                  ratio: float = 1.1) -> bool:
    """True when every two of the answers named in ``units`` (values of ``solved``, in
    SI) differ by more than the factor ``ratio``, both in SI and in their parts' units
    (``units`` maps each name to its unit's factor of SI: 1e-3 for mm and ms)."""
    for a, b in itertools.combinations(units, 2):
        x, y = abs(float(solved[a])), abs(float(solved[b]))
        for x_shown, y_shown in ((x, y), (x / units[a], y / units[b])):
            if x_shown == 0 or y_shown == 0:
                if x_shown == y_shown:
                    return False
                continue
            if abs(math.log(x_shown / y_shown)) <= math.log(ratio):
                return False
    return True
