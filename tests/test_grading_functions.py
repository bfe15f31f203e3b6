"""The function table: every entry means the same in numpy, mpmath and sympy.

Values are checked against each other at points spread over each entry's sample
interval, and a few against values known by hand, so a table entry that pointed at
the wrong function in any of the three would fail here.
"""

import math

import mpmath
import numpy as np
import pytest
import sympy

from dynagrade.grading.functions import FUNCTIONS, mp_call
from dynagrade.grading.names import FUNCTION_ALIASES, canonical_function

POINTS = 7


def _points(entry):
    lo, hi = entry.sample
    inner = np.linspace(lo, hi, POINTS + 2)[1:-1]
    if entry.arity == 1:
        return [(float(x),) for x in inner]
    return [(float(y), float(x)) for y, x in zip(inner, inner[::-1] + 0.25)]


@pytest.mark.parametrize("name", sorted(FUNCTIONS))
def test_numpy_and_sympy_give_the_same_value_at_sample_points(name):
    entry = FUNCTIONS[name]
    for args in _points(entry):
        by_numpy = float(entry.numpy(*[np.float64(a) for a in args]))
        exact = entry.sympy(sympy, *[sympy.Float(a, 30) for a in args])
        by_sympy = complex(exact.evalf(30))
        assert by_sympy.imag == 0, (name, args, exact)
        assert by_numpy == pytest.approx(by_sympy.real, rel=1e-12, abs=1e-14), (name, args)


@pytest.mark.parametrize("name", sorted(FUNCTIONS))
def test_numpy_and_mpmath_give_the_same_value_at_sample_points(name):
    entry = FUNCTIONS[name]
    with mpmath.workdps(30):
        for args in _points(entry):
            by_numpy = float(entry.numpy(*[np.float64(a) for a in args]))
            by_mpmath = mp_call(mpmath.mp, entry, [mpmath.mpf(a) for a in args])
            assert by_numpy == pytest.approx(float(by_mpmath), rel=1e-12, abs=1e-14), (name, args)


def test_values_known_by_hand():
    def value(name, *args):
        return float(FUNCTIONS[name].numpy(*[np.float64(a) for a in args]))

    assert value("sin", math.pi / 6) == pytest.approx(0.5)
    assert value("cot", math.pi / 4) == pytest.approx(1.0)
    assert value("sec", math.pi / 3) == pytest.approx(2.0)
    assert value("csc", math.pi / 6) == pytest.approx(2.0)
    assert value("atan2", 1.0, -1.0) == pytest.approx(3 * math.pi / 4)
    assert value("log10", 1000.0) == pytest.approx(3.0)
    assert value("log2", 8.0) == pytest.approx(3.0)
    assert value("cbrt", -8.0) == pytest.approx(-2.0)


def test_outside_the_real_domain_every_evaluation_is_undefined_not_complex():
    with np.errstate(all="ignore"):
        for name, args in [("sqrt", (-4.0,)), ("ln", (-1.0,)), ("asin", (2.0,)), ("acos", (-1.5,))]:
            entry = FUNCTIONS[name]
            assert math.isnan(float(entry.numpy(*[np.float64(a) for a in args])))
            assert mpmath.isnan(mp_call(mpmath.mp, entry, [mpmath.mpf(a) for a in args]))


def test_the_real_cube_root_is_used_by_the_exact_check_too():
    assert FUNCTIONS["cbrt"].sympy(sympy, sympy.Integer(-8)) == -2


def test_every_spelling_leads_to_an_entry_and_every_entry_has_a_dimension_rule():
    for alias in FUNCTION_ALIASES:
        assert canonical_function(alias) in FUNCTIONS
    rules = {"trig", "inverse_trig", "pure", "atan2", "power"}
    assert all(entry.dims in rules and entry.name == name for name, entry in FUNCTIONS.items())
