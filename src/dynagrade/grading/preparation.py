"""Loading, ahead of time, everything a verdict may need.

Importing :mod:`dynagrade.grading` stays light (neither pint nor sympy), so a single
answer is graded quickly. A caller about to grade many answers -- a class, a
``compare`` stream, a benchmark -- calls :func:`prepare` first, so that no verdict
spends its time budget importing pint's unit registry, sympy or mpmath.
"""

from __future__ import annotations


def prepare() -> None:
    """Load the graders of every kind of part, pint's registry, mpmath and sympy, then
    move everything loaded so far out of the garbage collector's way (``gc.freeze``):
    sympy and pint hold millions of objects, and a full collection that walks them
    would otherwise land, some 100 ms long, inside one unlucky verdict."""
    import gc

    from . import choice, numeric, symbolic, units, vector  # noqa: F401
    import mpmath  # noqa: F401  (the precision check of formulas)
    import sympy  # noqa: F401  (the exact check of formulas)

    units.registry().get_root_units("meter")  # pint parses its definitions lazily
    gc.collect()
    gc.freeze()
