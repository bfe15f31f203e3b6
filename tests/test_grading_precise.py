"""Formulas whose float values cancel: decided in high precision, never accepted wrongly.

The identities are exact (trigonometric half angle, cosh² − sinh² = 1, rationalising
a difference of roots); the float64 values of one side lose most of their digits in
the given ranges, which is what used to make them "not equivalent".
"""

import time

import numpy as np
import pytest

from dynagrade.grading import grade
from dynagrade.grading.parser import parse_expression
from dynagrade.grading.precise import agree_precisely
from dynagrade.grading.spec import SymbolicSpec, Variable
from dynagrade.grading.timing import Deadline

TINY = SymbolicSpec({"x": Variable(1e-7, 3e-7)})
LARGE = SymbolicSpec({"x": Variable(10, 30)})
HUGE = SymbolicSpec({"x": Variable(1e10, 1e12)})
PLAIN = SymbolicSpec({"x": Variable(0.5, 2)})


@pytest.mark.parametrize("spec, reference, answer", [
    (TINY, "2*sin(x/2)^2", "1-cos(x)"),
    (TINY, "1-cos(x)", "2*sin(x/2)^2"),
    (LARGE, "1", "cosh(x)^2 - sinh(x)^2"),
    (LARGE, "cosh(x)^2 - sinh(x)^2", "1"),
    (SymbolicSpec({"x": Variable(100, 300)}), "1", "cosh(x)^2 - sinh(x)^2"),
    (HUGE, "1/(sqrt(x+1)+sqrt(x))", "sqrt(x+1)-sqrt(x)"),
    (PLAIN, "x", "x + (1e300 + x) - 1e300 - x"),
])
def test_exact_identities_that_cancel_in_floating_point_are_right(spec, reference, answer):
    assert grade(spec, reference, answer).correct


@pytest.mark.parametrize("spec, reference, answer", [
    (TINY, "2*sin(x/2)^2", "1.001*(1-cos(x))"),
    (TINY, "2*sin(x/2)^2", "1-cos(1.001*x)"),
    (LARGE, "1", "cosh(x)^2 - sinh(x)^2 + 0.01"),
    (LARGE, "0", "cosh(x)^2 - sinh(x)^2"),          # float64 says 0 at many points; it is 1
    (HUGE, "1/(sqrt(x+1)+sqrt(x))", "sqrt(x+2)-sqrt(x)"),
    (PLAIN, "x", "x + (1e300 + x) - 1e300"),
])
def test_near_identities_that_cancel_stay_wrong(spec, reference, answer):
    assert not grade(spec, reference, answer).correct


def test_a_real_difference_is_found_without_high_precision():
    # The float values are right at the worst point: no mpmath evaluation at all.
    reference, answer = parse_expression("x^2", ("x",)), parse_expression("1.01*x^2", ("x",))
    env = {"x": np.linspace(0.5, 2, 16)}
    e, a = env["x"] ** 2, 1.01 * env["x"] ** 2
    start = time.perf_counter()
    assert agree_precisely(answer, reference, env, a, e, 1e-6 * e, 1e-6, Deadline()) is False
    assert time.perf_counter() - start < 0.05


def test_values_beyond_any_float_give_up_quietly_and_quickly():
    reference, answer = parse_expression("x", ("x",)), parse_expression("x + 0*exp(exp(exp(10*x)))", ("x",))
    env = {"x": np.linspace(0.5, 2, 16)}
    start = time.perf_counter()
    result = agree_precisely(answer, reference, env, env["x"] + 1, env["x"], 1e-6 * env["x"], 1e-6, Deadline())
    assert result is None and time.perf_counter() - start < 0.1


def test_the_time_budget_bounds_the_high_precision_check():
    reference = parse_expression("1", ("x",))
    answer = parse_expression("cosh(x)^2 - sinh(x)^2", ("x",))
    env = {"x": np.linspace(100, 300, 16)}
    ones = np.ones(16)
    assert agree_precisely(answer, reference, env, 0 * ones, ones, 1e-6 * ones, 1e-6, Deadline(0.0)) is None


def test_a_number_with_a_leading_point_is_read_as_python_reads_it():
    """``.0`` is 0 (mpmath alone refuses the spelling: grade() raised ValueError on
    ``6666666666-.0``, issue 26): a verdict, worked out by hand, never an exception."""
    from dynagrade.grading import grade
    from dynagrade.grading.compare import build

    def verdict(expected, answer):
        return grade(*build({"kind": "symbolic", "expected": expected, "answer": answer,
                             "variables": {"x": {"min": 1, "max": 2}}}))

    assert verdict("x", "6666666666-.0").correct is False  # a constant is not x in [1, 2]
    assert verdict("6666666666+x", "6666666666-.0+x").correct is True
    assert verdict("x", ".000+x").correct is True
    assert verdict("x/2", "x*.5").correct is True
