"""Keys that stay apart: a constraint helper against parts whose numbers coincide.

Two parts of different meaning whose numbers agree within a tolerance in a variant (a
speed and an angular speed both 2.31 in SI) let a student who swaps the formulas score.
An exercise keeps them apart with a constraint:
``Constraint("the keys differ by over 5 %", lambda p: numbers_apart(solve(p).values()))``;
where answers are asked in units other than SI (mm, ms, MPa), :func:`answers_apart`
compares the numbers as typed too.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from itertools import combinations


#: how far apart :func:`apart` keeps two numbers by default: twice the 1 % tolerance
APART = 0.02


def apart(a: float, b: float, share: float = APART) -> bool:
    """Whether ``a`` and ``b`` differ by more than ``share`` of the larger magnitude: a
    :class:`Constraint` that keeps two answers from coinciding, which ``dynagrade verify``
    refuses (:mod:`.variety`); the sign counts (-1 and 1 are apart)::

        Constraint("the distance and the time differ as numbers",
                   lambda p: apart(solve(p)["dx"], solve(p)["t_stop"]))
    """
    return abs(a - b) > share * max(abs(a), abs(b))


def numbers_apart(values: Iterable[float], rtol: float = 0.05) -> bool:
    """True if the magnitudes of every two of ``values`` differ by more than ``rtol`` of
    the larger one (zero and zero do not differ)."""
    magnitudes = [abs(float(v)) for v in values]
    return all(abs(a - b) > rtol * max(a, b) for a, b in combinations(magnitudes, 2))


def answers_apart(solved: Mapping[str, float], units: Mapping[str, float],
                  ratio: float = 1.1) -> bool:
    """True when every two of the answers named in ``units`` (values of ``solved``, in
    SI) differ by more than the factor ``ratio``, both in SI and in their parts' units
    (``units`` maps each name to its unit's factor of SI: 1e-3 for mm and ms), so that
    neither the numbers a student computes nor the ones they type coincide:
    ``Constraint("the answers are over 10 % apart", lambda p: answers_apart(solve(p),
    {"sigma": 1e6, "t_c": 1e-3, "v2": 1.0}))``.

    >>> answers_apart({"t": 0.5, "x": 0.0005}, {"t": 1.0, "x": 1e-3})  # 0.5 s and 0.5 mm
    False
    """
    share = 1 - 1 / ratio  # a ratio over ``ratio`` is a difference over this share
    return (numbers_apart((solved[name] for name in units), share)
            and numbers_apart((solved[name] / units[name] for name in units), share))
