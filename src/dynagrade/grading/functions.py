"""The one table of functions a formula may call: name, arguments, values, units.

Each entry says everything the grader needs about one function, so that the parser,
the float evaluation (numpy, vectorised), the high-precision evaluation (mpmath), the
exact check (sympy) and the dimension rules can never disagree about what a name
means. All functions are **real**: where the real function is undefined (``sqrt`` or
``ln`` of a negative number, ``asin(2)``) the value is NaN, never a complex number,
and ``cbrt`` is the real cube root (``cbrt(-8) = -2``) in all three evaluations.

``dims`` names the dimension rule (see :mod:`dims`):

* ``"trig"``: an angle or a pure number in, a pure number out;
* ``"inverse_trig"``: a pure number in, an angle out;
* ``"pure"``: a pure number in and out (hyperbolic, exponential, logarithms);
* ``"atan2"``: two arguments of the same units, an angle out;
* ``"power"``: the argument's units raised to ``power`` (roots, ``abs`` with 1).

``sample`` is an interval inside the real domain, where the tests hold the three
evaluations equal. Spellings (``arcsin``, ``log``) live in :mod:`names`.

Importing the table imports no numpy: an entry's ``numpy`` looks its function up when
first called, so that what reads only names (``dynagrade list`` checks the formulas an
exercise file writes) starts without numpy.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Callable


@dataclass(frozen=True)
class Function:
    """One function: ``numpy(*arrays)``, ``mpmath(mp, *numbers)``, ``sympy(sp, *exprs)``."""

    name: str
    arity: int
    numpy: Callable
    mpmath: Callable
    sympy: Callable
    dims: str
    power: float = 1.0
    sample: tuple[float, float] = (-3.0, 3.0)


def _real(mp, value):
    """A real mpmath result, or NaN where the real function is undefined."""
    if isinstance(value, mp.mpc):
        return mp.nan if value.imag != 0 else value.real
    return value


def _mp_log(base):
    def log(mp, x):
        return mp.log(x, base) if x > 0 else mp.nan
    return log


def _mp_sqrt(mp, x):
    return mp.sqrt(x) if x >= 0 else mp.nan


def _mp_cbrt(mp, x):
    return mp.cbrt(x) if x >= 0 else -mp.cbrt(-x)


def _mp_inverse(name):
    def inverse(mp, x):
        return getattr(mp, name)(x) if -1 <= x <= 1 else mp.nan
    return inverse


def _mp_reciprocal(name):
    def reciprocal(mp, x):
        value = getattr(mp, name)(x)
        return 1 / value if value != 0 else mp.nan
    return reciprocal


def _np(name: str) -> Callable:
    """numpy's function ``name``, imported on the first call."""
    def call(*arrays):
        import numpy as np

        return getattr(np, name)(*arrays)
    call.__name__ = call.__qualname__ = f"numpy.{name}"
    return call


def _np_reciprocal(name: str) -> Callable:
    ufunc = _np(name)

    def reciprocal(x):
        return 1.0 / ufunc(x)
    return reciprocal


def _table(*entries: Function) -> dict[str, Function]:
    return {f.name: f for f in entries}


#: Canonical function name -> its entry.
FUNCTIONS: dict[str, Function] = _table(
    Function("sin", 1, _np("sin"), lambda mp, x: mp.sin(x), lambda sp, x: sp.sin(x), "trig"),
    Function("cos", 1, _np("cos"), lambda mp, x: mp.cos(x), lambda sp, x: sp.cos(x), "trig"),
    Function("tan", 1, _np("tan"), lambda mp, x: mp.tan(x), lambda sp, x: sp.tan(x), "trig", sample=(-1.5, 1.5)),
    Function("cot", 1, _np_reciprocal("tan"), _mp_reciprocal("tan"), lambda sp, x: sp.cot(x), "trig",
             sample=(0.1, 3.0)),
    Function("sec", 1, _np_reciprocal("cos"), _mp_reciprocal("cos"), lambda sp, x: sp.sec(x), "trig",
             sample=(-1.5, 1.5)),
    Function("csc", 1, _np_reciprocal("sin"), _mp_reciprocal("sin"), lambda sp, x: sp.csc(x), "trig",
             sample=(0.1, 3.0)),
    Function("asin", 1, _np("arcsin"), _mp_inverse("asin"), lambda sp, x: sp.asin(x), "inverse_trig",
             sample=(-1.0, 1.0)),
    Function("acos", 1, _np("arccos"), _mp_inverse("acos"), lambda sp, x: sp.acos(x), "inverse_trig",
             sample=(-1.0, 1.0)),
    Function("atan", 1, _np("arctan"), lambda mp, x: mp.atan(x), lambda sp, x: sp.atan(x), "inverse_trig"),
    Function("atan2", 2, _np("arctan2"), lambda mp, y, x: mp.atan2(y, x), lambda sp, y, x: sp.atan2(y, x), "atan2"),
    Function("sinh", 1, _np("sinh"), lambda mp, x: mp.sinh(x), lambda sp, x: sp.sinh(x), "pure"),
    Function("cosh", 1, _np("cosh"), lambda mp, x: mp.cosh(x), lambda sp, x: sp.cosh(x), "pure"),
    Function("tanh", 1, _np("tanh"), lambda mp, x: mp.tanh(x), lambda sp, x: sp.tanh(x), "pure"),
    Function("exp", 1, _np("exp"), lambda mp, x: mp.exp(x), lambda sp, x: sp.exp(x), "pure"),
    Function("ln", 1, _np("log"), _mp_log(None), lambda sp, x: sp.log(x), "pure", sample=(0.01, 100.0)),
    Function("log10", 1, _np("log10"), _mp_log(10), lambda sp, x: sp.log(x, 10), "pure", sample=(0.01, 100.0)),
    Function("log2", 1, _np("log2"), _mp_log(2), lambda sp, x: sp.log(x, 2), "pure", sample=(0.01, 100.0)),
    Function("sqrt", 1, _np("sqrt"), _mp_sqrt, lambda sp, x: sp.sqrt(x), "power", power=0.5, sample=(0.0, 100.0)),
    Function("cbrt", 1, _np("cbrt"), _mp_cbrt, lambda sp, x: sp.real_root(x, 3), "power", power=1.0 / 3.0,
             sample=(-100.0, 100.0)),
    Function("abs", 1, _np("abs"), lambda mp, x: abs(x), lambda sp, x: sp.Abs(x), "power"),
)


def mp_call(mp, function: Function, args):
    """``function`` applied in mpmath with real semantics (NaN outside the domain)."""
    return _real(mp, function.mpmath(mp, *args))
