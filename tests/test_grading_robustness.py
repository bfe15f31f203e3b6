"""grade() answers every answer with a verdict, whatever the units, exponents or ranges.

The reproducers are answers that used to raise out of ``grade()`` (EvaluationError,
ZeroDivisionError, OverflowError) and so could stop the grading of a whole class;
the hypothesis tests extend the fuzzing to unit powers, unit-only answers, extreme
exponents and extreme variable ranges.
"""

import subprocess
import sys

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from dynagrade.grading import SpecError, grade
from dynagrade.grading.compare import compare_record
from dynagrade.grading.spec import NumericSpec, SymbolicSpec, Variable, VectorSpec

SPECS = [
    (NumericSpec(unit="m"), 1.0),
    (NumericSpec(), 1.0),
    (NumericSpec(unit="rad"), 1.0),
    (VectorSpec(2, unit="m"), (1.0, 2.0)),
]


def _answer_for(spec, text):
    return f"[{text}, 2 m]" if isinstance(spec, VectorSpec) else text


@pytest.mark.parametrize("answer, message", [
    ("deg^deg", "exponent must be a pure number"),
    ("rad^rad", "exponent must be a pure number"),
    ("1 km^-200", "too large or too small"),
    ("1 deg^200", "too large or too small"),
    ("12.5 blargs", "'blargs' is not a unit I know"),
])
def test_answers_that_used_to_raise_get_an_unreadable_verdict(answer, message):
    for spec, expected in SPECS:
        verdict = grade(spec, expected, _answer_for(spec, answer))
        assert not verdict.correct and verdict.score == 0.0
        assert message in (verdict.error or verdict.feedback), (spec, verdict)


@pytest.mark.parametrize("low, high", [(-1e308, 1e308), (-1.7e308, 1.7e308), (1e307, 1.7e308)])
def test_a_variable_range_near_the_float_limit_gets_a_verdict_or_a_spec_error(low, high):
    spec = SymbolicSpec({"x": Variable(low, high)})
    assert grade(spec, "x", "x").correct
    assert grade(spec, "2*x", "x+x").correct
    assert not grade(spec, "2*x", "3*x").correct
    with pytest.raises(SpecError, match="undefined on almost all"):
        grade(spec, "x^2", "x*x")  # x² overflows nearly everywhere in this range
    line = compare_record({"id": "q", "kind": "symbolic", "expected": "x^2", "answer": "x*x",
                           "variables": {"x": {"min": low, "max": high}}})
    assert line["correct"] is False and "undefined" in line["error"]


def test_a_factor_within_rounding_of_one_is_a_constant_factor_not_a_power_of_ten():
    spec = SymbolicSpec({"x": Variable(0.5, 2)})
    near_one = grade(spec, "x", "1.000002*x")
    assert near_one.misconception == "constant factor" and "10^0" not in near_one.feedback
    assert grade(spec, "x", "10*x").misconception == "power of ten"


def test_after_prepare_no_verdict_spends_its_budget_loading_pint():
    # A fresh process: the first answer with a unit pint must look up (lbf) is timed.
    code = ("import time\n"
            "from dynagrade.grading import grade, prepare\n"
            "from dynagrade.grading.spec import NumericSpec\n"
            "prepare()\n"
            "start = time.perf_counter()\n"
            "verdict = grade(NumericSpec(unit='N'), 4.4482216, '1 lbf')\n"
            "print(verdict.correct, time.perf_counter() - start)\n")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    correct, seconds = out.stdout.split()
    assert correct == "True" and float(seconds) < 0.2


# -- fuzzing ---------------------------------------------------------------------------------
UNITS = ["m", "km", "deg", "rad", "rev", "s", "N", "lbf", "rpm", "blargs", "kg", "Hz"]
units = st.sampled_from(UNITS)
exponents = st.one_of(st.integers(-400, 400), st.sampled_from(["1/0", "0.5", "-1e300", "1e300", "deg", "m"]))


def _must_answer(spec, expected, text):
    verdict = grade(spec, expected, _answer_for(spec, text))
    assert 0.0 <= verdict.score <= 1.0 and verdict.feedback


@settings(max_examples=150, deadline=None)
@given(st.floats(min_value=0, max_value=1e6), units, exponents, units)
def test_any_unit_power_gets_a_verdict(number, unit, exponent, other):
    for spec, expected in SPECS:
        _must_answer(spec, expected, f"{number} {unit}^{exponent}")
        _must_answer(spec, expected, f"{number} {unit}^({exponent}) / {other}")


@settings(max_examples=100, deadline=None)
@given(st.lists(st.tuples(units, st.sampled_from(["*", "/", "^2 ", "^-1 ", " "])), min_size=1, max_size=5))
def test_an_answer_of_units_without_a_number_gets_a_verdict(parts):
    text = "".join(unit + op for unit, op in parts).rstrip("*/^ ")
    for spec, expected in SPECS:
        _must_answer(spec, expected, text)


@settings(max_examples=150, deadline=None)
@given(st.floats(min_value=0, max_value=10), st.integers(-5000, 5000), st.sampled_from(["", " m", " km", " deg"]))
def test_any_exponent_of_ten_gets_a_verdict(mantissa, exponent, unit):
    for text in (f"{mantissa}e{exponent}{unit}", f"{mantissa}*10^{exponent}{unit}", f"10^10^{exponent}{unit}"):
        for spec, expected in SPECS:
            _must_answer(spec, expected, text)


REFERENCES = ["x", "x^2", "exp(x)", "1/x", "sqrt(x)", "sin(x)", "x^x"]
finite = st.floats(allow_nan=False, allow_infinity=False)


@settings(max_examples=100, deadline=None)
@given(finite, finite, st.sampled_from(REFERENCES), st.sampled_from(["x", "2*x", "x^3", "ln(x)", "x^1e300"]))
def test_any_finite_variable_range_gets_a_verdict_or_a_spec_error(a, b, reference, answer):
    spec = SymbolicSpec({"x": Variable(min(a, b), max(a, b))})
    try:
        verdict = grade(spec, reference, answer)
    except SpecError:
        return
    assert 0.0 <= verdict.score <= 1.0 and verdict.feedback
