"""Units, tolerances, significant figures, the compare contract and lazy imports."""

import json
import math
import subprocess
import sys
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from dynagrade.grading import grade, read_number
from dynagrade.grading import units
from dynagrade.grading.everyday_units import EVERYDAY
from dynagrade.grading.compare import compare_lines, compare_record
from dynagrade.grading.quantity import unit_info
from dynagrade.grading.spec import NumericSpec, SymbolicSpec, Variable
from dynagrade.grading.tolerance import count_sigfigs, round_sig

SRC = Path(__file__).resolve().parent.parent / "src"


@pytest.mark.parametrize("name", sorted(units.BUILTIN))
def test_builtin_unit_table_agrees_with_pint(name):
    factor, dim = units.BUILTIN[name]
    parts = EVERYDAY.get(name, ((name, 1),))
    pint_factor, pint_dim = 1.0, units.DIMENSIONLESS
    for unit, power in parts:
        f, d = units._pint_unit(unit)
        pint_factor *= f ** power
        pint_dim = units.add(pint_dim, units.scale(d, power))
    assert math.isclose(factor, pint_factor, rel_tol=1e-12) and dim == pint_dim


def test_angle_is_tracked_but_radian_reads_as_one():
    rad_s = unit_info("rad/s")[1]
    assert units.compatible(unit_info("1/s")[1], rad_s)       # 1/s read as rad/s
    assert units.compatible(unit_info("rpm")[1], unit_info("1/s")[1])
    assert not units.compatible(unit_info("m")[1], unit_info("rad")[1])
    assert units.describe_dimension(unit_info("deg/s")[1]) == "an angular velocity"


@settings(max_examples=50, deadline=None)
@given(st.floats(min_value=0.01, max_value=1e4), st.sampled_from(["km/h", "cm/s", "mm/s", "m/min"]))
def test_a_value_written_in_another_unit_of_the_same_dimension_is_correct(value_si, unit):
    factor = unit_info(unit)[0]
    answer = f"{value_si / factor!r} {unit}"
    assert grade(NumericSpec(unit="m/s"), value_si, answer).correct


@settings(max_examples=50, deadline=None)
@given(st.floats(min_value=-1e6, max_value=1e6).filter(lambda x: abs(x) > 1e-6))
def test_a_five_percent_perturbation_is_always_wrong_and_a_half_percent_one_right(e):
    spec = NumericSpec()
    assert not grade(spec, e, repr(e * 1.05)).correct
    assert grade(spec, e, repr(e * 1.005)).correct


@pytest.mark.parametrize("literal, digits", [("0.0120", 3), ("1200", 2), ("1.2e3", 2), ("12,50", 4), ("0", 1), ("100.", 3)])
def test_significant_figures_of_typed_numbers(literal, digits):
    assert count_sigfigs(literal) == digits


def test_rounding_is_half_away_from_zero():
    assert str(round_sig(0.125, 2)) == "0.13" and str(round_sig(-0.125, 2)) == "-0.13"


def test_too_few_digits_gets_a_hint_and_the_reference_is_not_revealed():
    verdict = grade(NumericSpec(unit="m"), 9.8765, "10")
    assert "give at least 3" in verdict.feedback and "9.87" not in verdict.feedback
    revealed = grade(NumericSpec(unit="m", reveal=True), 9.8765, "10")
    assert "9.877 m" in revealed.feedback


def test_dimension_feedback_names_both_dimensions():
    spec = SymbolicSpec({"v": Variable(1, 10, "m/s"), "t": Variable(1, 10, "s")})
    verdict = grade(spec, "v*t", "v^2*t")
    assert "units of m²/s, expected m" in verdict.feedback


def test_read_number_converts_into_the_requested_unit():
    assert read_number("45 km/h", "m/s") == pytest.approx(12.5)
    assert read_number("30 deg", "rad") == pytest.approx(math.pi / 6)


def test_compare_contract_fields_and_malformed_lines():
    lines = [
        json.dumps({"id": "ok", "kind": "numeric", "expected": 2, "unit": "N", "answer": "2000 mN"}),
        "{not json",
        json.dumps({"id": "x", "kind": "numeric", "expected": True, "answer": "1"}),
        json.dumps({"id": "y", "kind": "numeric", "expected": 1, "answer": 5}),
        json.dumps({"id": "z", "kind": "weird", "expected": 1, "answer": "1"}),
        json.dumps([1, 2]),
        "",
        json.dumps({"id": "s", "kind": "symbolic", "expected": "x^2", "answer": "x*x",
                    "variables": {"x": {"min": 1, "max": 2}}}),
    ]
    out = [json.loads(line) for line in compare_lines(lines)]
    assert len(out) == 7
    assert all(set(o) == {"id", "correct", "score", "feedback", "error"} for o in out)
    assert out[0]["correct"] is True and out[0]["error"] is None
    assert out[1]["id"] is None and "line 2" in out[1]["error"]
    assert [o["id"] for o in out[2:5]] == ["x", "y", "z"] and all(o["error"] for o in out[2:5])
    assert out[5]["id"] is None and out[5]["error"]
    assert out[6]["correct"] is True


def test_compare_reports_a_bad_reference_without_stopping():
    out = compare_record({"id": "r", "kind": "symbolic", "expected": "x +", "answer": "x",
                          "variables": {"x": {"min": 1, "max": 2}}})
    assert out["correct"] is False and "reference" in out["error"]


def test_importing_the_grader_loads_neither_sympy_nor_pint():
    code = ("import sys, dynagrade.grading as g; "
            "g.grade(g.NumericSpec(unit='m/s'), 12.5, '45 km/h'); "
            "g.grade(g.SymbolicSpec({'x': g.Variable(1, 2)}), 'x^2', 'x x'); "
            "print('sympy' in sys.modules, 'pint' in sys.modules)")
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                          env={"PYTHONPATH": str(SRC), "PATH": ""}, timeout=60)
    assert done.stdout.split() == ["False", "False"], done.stderr


def test_a_division_followed_by_a_written_together_product_gets_a_reading_hint():
    spec = SymbolicSpec({"v": Variable(1, 10, "m/s"), "g": Variable(9, 10, "m/s^2")})
    verdict = grade(spec, "v^2/(2*g)", "v^2/2g")
    assert not verdict.correct and "a/2g is read as (a/2)·g" in verdict.feedback
