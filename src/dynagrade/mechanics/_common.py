"""Helpers and type aliases shared by the modules of the mechanics core.

Private to the package: callers use the principle modules, which import from here (never
the other way round), so this module imports nothing of dynagrade.
"""
from __future__ import annotations

from typing import Callable, TypeAlias

import numpy as np
import numpy.typing as npt

Quantity: TypeAlias = float | np.ndarray
"""A quantity, given or computed: a float, or a numpy array of values evaluated element by
element.  Functions that compute with an argument directly (``E / (2 (1 + nu))``) take it
as a Quantity, and return one: a float for floats, an array when an input was an array."""

ArrayLike: TypeAlias = npt.ArrayLike
"""Anything numpy turns into an array: a float, a sequence of floats (a vector, a list of
times) or an array.  Only for arguments a function first converts with ``as_floats`` (or
another numpy function); a sequence or a string supports no arithmetic, so an argument
that is computed with directly is a Quantity instead."""

Field: TypeAlias = Callable[..., Quantity]
"""A function of position, time or state that returns a quantity (a force or a field)."""

Function: TypeAlias = Callable[[float], float]
"""A real function of one real variable (an acceleration a(t), a shape psi(x)): what
scipy's quadrature and root finding call, one float at a time."""


def as_floats(values: ArrayLike) -> np.ndarray:
    """The values as a float array (a 0-d array for a scalar)."""
    return np.asarray(values, dtype=float)


def as_vectors(vectors: ArrayLike, n: int) -> np.ndarray:
    """n vectors as an (n, d) float array; a flat sequence is split into n equal rows."""
    arr = as_floats(vectors)
    if arr.ndim == 1:
        arr = arr.reshape(n, -1)
    return arr


def spatial_vector(vector: ArrayLike) -> np.ndarray:
    """Three Cartesian components of a vector; a planar (2-component) vector is taken in the
    e1-e2 plane with zero e3 component (the convention of eqs. (1.52) and (1.129))."""
    vector = as_floats(vector)
    if vector.shape[-1] == 2:
        vector = np.concatenate([vector, np.zeros(vector.shape[:-1] + (1,))], axis=-1)
    return vector


def cross(a: ArrayLike, b: ArrayLike) -> np.ndarray:
    """Cross product a x b of two 3-vectors (or stacks of them), as floats."""
    return np.cross(as_floats(a), as_floats(b))


def spatial_cross(a: ArrayLike, b: ArrayLike) -> np.ndarray:
    """Cross product with planar (2-component) vectors taken in the e1-e2 plane."""
    return np.cross(spatial_vector(a), spatial_vector(b))
