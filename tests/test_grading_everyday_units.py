"""Units in the order a student means them, and one frequency rule (issue 27, items 3 and 4).

Every expected value is worked out by hand in the test (or its docstring): a newton metre
is 1 N·m, a revolution 2π rad, a minute 60 s, a degree π/180 rad, and ω = 2π·f.
"""

from __future__ import annotations

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from dynagrade.grading import NumericSpec, VectorSpec, grade, read_number
from dynagrade.grading.everyday_units import DENIED, EVERYDAY
from dynagrade.grading.quantity import read_quantity

TORQUE = (1.0, 2.0, -2.0, 0.0, 0.0, 0.0, 0.0, 0.0)
RAD_PER_S = (0.0, 0.0, -1.0, 0.0, 0.0, 0.0, 0.0, 1.0)


# -- the bugs the issue names ----------------------------------------------------------------
def test_12_kNm_is_twelve_kilonewton_metres_not_a_yarn_count():
    q = read_quantity("12 kNm")
    assert q.value == pytest.approx(12_000.0) and q.dim == TORQUE
    assert grade(NumericSpec(unit="kN*m"), 12, "12 kNm").correct


def test_37_Grad_is_37_degrees_not_giga_radians():
    assert read_quantity("37 Grad").value == pytest.approx(37 * math.pi / 180)
    assert grade(NumericSpec(unit="deg"), 37, "37 Grad").correct


def test_1500_U_per_min_is_the_motor_plates_rotational_speed():
    """1500 rev/min = 1500 · 2π rad / 60 s = 157.08 rad/s."""
    assert read_quantity("1500 U/min").value == pytest.approx(157.0796, rel=1e-6)
    assert grade(NumericSpec(unit="rpm"), 1500, "1500 U/min").correct


@pytest.mark.parametrize("answer", ["1500 min^-1", "1500 min⁻¹", "1500 1/min", "1500/min"])
def test_per_minute_alone_is_revolutions_per_minute_not_radians(answer):
    q = read_quantity(answer)
    assert q.value == pytest.approx(1500 * 2 * math.pi / 60) and q.dim == RAD_PER_S
    assert grade(NumericSpec(unit="rad/s"), 157.08, answer).correct


def test_metres_per_minute_keep_their_minute():
    assert read_quantity("60 m/min").value == pytest.approx(1.0)


def test_a_degree_sign_inside_sin_keeps_the_answer_in_the_parts_unit():
    """144·sin(70°)/9.81 = 144 · 0.9396926 / 9.81 = 13.7937 m."""
    verdict = grade(NumericSpec(unit="m"), 13.794, "144*sin(70°)/9.81")
    assert verdict.correct, verdict
    assert read_quantity("144*sin(70°)/9.81").dim is None      # a bare number


def test_a_unit_outside_the_function_is_still_the_answers_unit():
    verdict = grade(NumericSpec(unit="m"), 1.0, "sin(30°)*2 s")
    assert not verdict.correct and verdict.misconception == "unit"


# -- the deny-list ---------------------------------------------------------------------------
@pytest.mark.parametrize("answer, meaning", [
    ("3.2 M/s", "molar"), ("3.2 M/s", "MN"),
    ("37 grad", "gradian"), ("37 grad", "deg"),
    ("1 krad", "prefixed angle"),
    ("12 k", "Boltzmann"), ("12 k", "kN"),
    ("2 kU", "enzyme"),
    ("5 G", "gauss"), ("5 T", "tesla"), ("5 P", "poise"),
    ("3 c", "physical constant"),
])
def test_a_pint_unit_no_student_means_is_refused_naming_the_likely_meaning(answer, meaning):
    verdict = grade(NumericSpec(unit="kN"), 1.0, answer)
    assert not verdict.correct and verdict.error, verdict
    assert meaning in verdict.feedback, verdict.feedback


def test_the_refused_units_are_what_pint_would_have_read():
    """The deny-list names pint's own units: each typed example resolves to one of them."""
    from dynagrade.grading import units

    ureg = units.registry()
    for typed in ("M", "U", "Nm", "grad", "gon", "k", "G", "T", "P", "c"):
        assert {unit for _, unit, _ in ureg.parse_unit_name(typed)} & set(DENIED), typed


def test_the_everyday_table_is_read_before_pint():
    """pint reads kNm as kilo-number_meter (m/kg), Grad as giga-radian and U as an enzyme
    unit; the table must shadow each, so its readings differ from pint's."""
    from dynagrade.grading import units

    for name, (factor, dim) in (("kNm", (1e3, TORQUE)), ("Grad", (math.pi / 180, units._dim(rad=1))),
                                ("U", (2 * math.pi, units._dim(rad=1)))):
        assert name in EVERYDAY
        assert units.lookup(name) == (pytest.approx(factor), dim)


# -- one frequency rule ----------------------------------------------------------------------
def test_a_frequency_in_Hz_for_an_angular_frequency_is_converted_with_two_pi():
    """ω = 10.47 rad/s; f = ω/(2π) = 1.6664 Hz; 1.667 Hz · 2π = 10.474 rad/s (within 1 %)."""
    verdict = grade(NumericSpec(unit="rad/s"), 10.47, "1.667 Hz")
    assert verdict.correct and "2π" in verdict.feedback, verdict


def test_omegas_number_labelled_Hz_is_wrong_and_the_feedback_names_the_confusion():
    """10.47 Hz is ω = 65.8 rad/s: the only wrong acceptance the issue found."""
    verdict = grade(NumericSpec(unit="rad/s"), 10.47, "10.47 Hz")
    assert not verdict.correct and verdict.misconception == "Hz for rad/s", verdict
    assert "f = ω/(2π)" in verdict.feedback


def test_omegas_number_labelled_Hz_is_named_in_a_part_whose_unit_is_not_si():
    """100 rpm is ω = 100·2π/60 = 10.472 rad/s: a student who writes ω's number with Hz,
    10.47 Hz, made the same confusion in an rpm part, and it is named there too (the
    number is compared in the part's unit: 10.47 rad/s = 99.98 rpm; a mutation run found
    the conversion untested in a unit whose factor is not 1)."""
    verdict = grade(NumericSpec(unit="rpm"), 100.0, "10.47 Hz")
    assert not verdict.correct and verdict.misconception == "Hz for rad/s", verdict
    assert grade(NumericSpec(unit="rpm"), 100.0, "1.667 Hz").correct  # 1.667·60 = 100.0


def test_the_mirror_rule_holds_for_a_part_in_Hz():
    assert grade(NumericSpec(unit="Hz"), 1.667, "10.47 rad/s").correct      # 10.47/(2π) = 1.6664
    assert grade(NumericSpec(unit="Hz"), 1.667, "100 rpm").correct          # 100/60 = 1.6667
    wrong = grade(NumericSpec(unit="Hz"), 1.667, "1.667 rad/s")
    assert not wrong.correct and wrong.misconception == "Hz for rad/s"
    assert "ω = 2π·f" in wrong.feedback


def test_one_over_second_takes_the_parts_meaning():
    assert grade(NumericSpec(unit="Hz"), 1.667, "1.667 1/s").correct
    assert grade(NumericSpec(unit="rad/s"), 10.47, "10.47 1/s").correct
    assert grade(NumericSpec(unit="1/s"), 2.0, "2 Hz").correct


def test_a_vector_part_in_Hz_reads_rad_per_second_by_the_same_rule():
    """(10.47, 18.85) rad/s / (2π) = (1.6664, 3.0001) Hz."""
    assert grade(VectorSpec(2, unit="Hz"), (1.667, 3.0), "(10.47, 18.85) rad/s").correct
    assert not grade(VectorSpec(2, unit="rad/s"), (10.47, 18.85), "(10.47, 18.85) Hz").correct


def test_the_exercise_models_reader_uses_the_same_rule():
    assert read_number("1.667 Hz", "rad/s") == pytest.approx(1.667 * 2 * math.pi)
    assert read_number("60 rpm", "Hz") == pytest.approx(1.0)


# -- any documented spelling of the same quantity parses to the same value --------------------
_SPELLINGS = {
    "torque (kN·m)": (["{x} kNm", "{x} kN m", "{x} kN*m", "{x} kN·m", "{x}kNm"], 1e3),
    "rotational speed (rev/min)": (["{x} rpm", "{x} U/min", "{x} min^-1", "{x} min⁻¹",
                                    "{x} 1/min", "{x}/min", "{x} Upm", "{x} rev/min"],
                                   2 * math.pi / 60),
    "angle (degree)": (["{x}°", "{x} deg", "{x} Grad", "{x} degree", "{x} degrees"],
                       math.pi / 180),
}


@settings(max_examples=60, deadline=None)
@given(st.sampled_from(sorted(_SPELLINGS)), st.floats(min_value=0.01, max_value=1e4),
       st.data())
def test_any_documented_spelling_of_the_same_quantity_parses_to_the_same_value(kind, x, data):
    spellings, factor = _SPELLINGS[kind]
    spelling = data.draw(st.sampled_from(spellings))
    assert read_quantity(spelling.format(x=repr(x))).value == pytest.approx(x * factor, rel=1e-12)


@settings(max_examples=60, deadline=None)
@given(st.floats(min_value=0.01, max_value=1e4))
def test_a_frequency_and_its_angular_frequency_grade_alike_in_either_part(f):
    omega = 2 * math.pi * f
    assert grade(NumericSpec(unit="rad/s"), omega, f"{f!r} Hz").correct
    assert grade(NumericSpec(unit="Hz"), f, f"{omega!r} rad/s").correct
    assert grade(NumericSpec(unit="rpm"), 60 * f, f"{f!r} Hz").correct
