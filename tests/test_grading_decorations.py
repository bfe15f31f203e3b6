"""Decorations stripped with a note (issue 27, classes 7 and 8): ``ω₂ = 4.5 rad/s``,
``v(0) = 3.2 m/s``, ``ca. 3.2 m/s``, ``3.2 m/s (to the right)``, Swiss thousands
``1'200 N``, invisible characters, ``3.2x10^-3``, ``2Pi``, ``9,81 m/s2``; and that no
decoration makes a wrong value right or reads a formula's own bracket as a remark."""

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from dynagrade.grading import grade
from dynagrade.grading.decorations import FORMULA, QUANTITY, mode_for, strip
from dynagrade.grading.dispatch import accepts
from dynagrade.grading.readability import readability
from dynagrade.grading.spec import ChoiceSpec, NumericSpec, SymbolicSpec, Variable, VectorSpec

SPEED = NumericSpec(unit="m/s")
RATE = NumericSpec(unit="rad/s")
FORCE = NumericSpec(unit="N")


@pytest.mark.parametrize("spec, expected, answer, left_out", [
    (RATE, 4.5, "ω₂ = 4.5 rad/s", "left out 'ω₂ ='"),
    (SPEED, 3.2, "v(0) = 3.2 m/s", "left out 'v(0) ='"),
    (SPEED, 3.2, "|v_B| = 3.2 m/s", "left out '|v_B| ='"),
    (SPEED, 3.2, "v_{B} ≈ 3.2 m/s", "left out 'v_{B} ≈'"),
    (SPEED, 3.2, "ca. 3.2 m/s", "left out 'ca.'"),
    (SPEED, 3.2, "≈ 3.2 m/s", "left out '≈'"),
    (SPEED, 3.2, "~3.2 m/s", "left out '~'"),
    (SPEED, 3.2, "3.2 m/s.", "left out the final full stop"),
    (SPEED, 3.2, "Answer: 3.2 m/s", "left out 'Answer:'"),
    (SPEED, 3.2, "Antwort: 3.2 m/s", "left out 'Antwort:'"),
    (SPEED, 3.2, "3.2 m/s (to the right)", "left out the remark '(to the right)'"),
    (SPEED, 3.2, "3.2 m/s (nach rechts).", "left out the remark '(nach rechts)'"),
    (FORCE, 1200, "1'200 N", "read '1'200' as '1200'"),
    (FORCE, 1200, "1’200 N", "read '1’200' as '1200'"),
    (FORCE, 1_250_000, "1'250'000 N", "read '1'250'000' as '1250000'"),
    (SPEED, 3.2, "3.2\u200b m/s", "U+200B"),
    (SPEED, 3.2, "\ufeff3.2 m/s\u2060", "U+2060, U+FEFF"),
    (NumericSpec(), 3.2e-3, "3.2x10^-3", "read 'x10' as '*10'"),
    (NumericSpec(), 3.2e-3, "3.2 X 10^-3", "read 'X 10' as '*10'"),
    (NumericSpec(), 2 * math.pi, "2Pi", "read 'Pi' as 'pi'"),
    (NumericSpec(unit="m/s^2"), 9.81, "9,81 m/s2", "read 's2' as 's^2'"),
    (NumericSpec(unit="m/s^2"), -9.81, "-9.81 m/s2", "read 's2' as 's^2'"),  # a sign before the number
    (NumericSpec(unit="m^2"), 0.5, "0.5 m2", "read 'm2' as 'm^2'"),
])
def test_a_decorated_right_answer_is_right_and_the_feedback_says_what_was_left_out(
        spec, expected, answer, left_out):
    verdict = grade(spec, expected, answer)
    assert verdict.correct, verdict
    assert "Read as" in verdict.feedback and left_out in verdict.feedback
    assert left_out in readability(spec, answer).message
    assert accepts(spec, expected, answer)


def test_the_already_written_forms_need_no_note():
    assert grade(NumericSpec(), 3.2e-3, "3.2·10⁻³").feedback == "Correct."
    assert grade(SPEED, 3.2, "3.2\u00a0m/s").feedback == "Correct."


@pytest.mark.parametrize("spec, expected, answer", [
    (SPEED, 3.2, "v = 3.0 m/s"),                 # a stripped name does not make 3.0 right
    (SPEED, 3.2, "ca. 3.0 m/s"),
    (SPEED, 3.2, "3.0 m/s (to the right)"),
    (RATE, 4.5, "ω₂ = 4.5 m/s"),                 # the unit stays checked
    (FORCE, 1200, "1'200 kN"),
    (NumericSpec(unit="kN*m"), 12, "12 (N m)"),  # a bracket of units is no remark
    (NumericSpec(), 2.0, "2 (pi)"),              # nor is a bracket around π
])
def test_a_stripped_decoration_does_not_make_a_wrong_answer_right(spec, expected, answer):
    assert not grade(spec, expected, answer).correct


@pytest.mark.parametrize("answer", ["1'20 N", "12'00 N", "1'2000 N", "1''200 N"])
def test_quotes_between_groups_other_than_three_digits_stay_refused(answer):
    verdict = grade(FORCE, 1200, answer)
    assert verdict.error and "quotes are not allowed" in verdict.feedback


@pytest.mark.parametrize("answer", ["2v = 6.4 m/s", "x = y = 3.2 m/s", "v = "])
def test_an_equation_that_is_more_than_a_name_stays_refused(answer):
    assert grade(SPEED, 3.2, answer).error


def test_a_bracket_of_units_and_a_function_s_bracket_stay_part_of_the_answer():
    assert grade(NumericSpec(unit="N*m"), 12, "12 (N m)").feedback == "Correct."
    assert grade(NumericSpec(), 2 * math.pi, "2 (pi)").feedback == "Correct."
    assert grade(NumericSpec(), 0.0, "sin(pi)").correct


def test_a_whole_number_with_a_point_is_a_number_not_a_full_stop():
    assert strip("12.", QUANTITY).changes == ()
    assert grade(SPEED, 12, "12.").feedback == "Correct."


def test_x10_is_read_only_right_after_a_digit():
    assert strip("x10^3", QUANTITY).text == "x10^3"
    assert strip("3.2 x 10", QUANTITY).changes == ()  # no power: not scientific notation


def test_s2_is_read_only_after_the_number():
    assert strip("m2 3", QUANTITY).text == "m2 3"


def test_a_formula_keeps_its_variables_but_loses_answer_labels_names_and_full_stops():
    spec = SymbolicSpec({"m": Variable(1, 2), "g": Variable(9, 10), "h": Variable(1, 2)})
    for answer in ("Answer: m*g*h.", "E_p = m g h", "V(h) = m g h", "m\u200bgh"):
        verdict = grade(spec, "m*g*h", answer)
        assert verdict.correct and "Read as" in verdict.feedback, (answer, verdict)
    assert strip("2Pi x10^3 m2 (a b)", FORMULA).changes == ()


def test_a_vector_answer_is_stripped_too():
    verdict = grade(VectorSpec(2, unit="m/s"), (3.0, 2.0), "v_B = (3, 2) m/s.")
    assert verdict.correct and "left out 'v_B ='" in verdict.feedback


def test_a_choice_is_read_as_typed():
    assert mode_for(ChoiceSpec(("up", "down"))) is None
    assert strip("Answer: up.", None).text == "Answer: up."


_NAMES = ["", "a = ", "a_C = ", "a₂ = ", "|a_C| = ", "a(0) = ", "a ≈ "]
_LABELS = ["", "Answer: ", "Antwort: "]
_APPROX = ["", "ca. ", "≈ ", "~"]
_UNITS = ["m/s^2", "m/s2", "m/s²", "m s^-2"]
_ENDS = ["", ".", " (downwards)", " (nach unten)."]


@st.composite
def _spellings(draw):
    """A value in m/s² and one documented spelling of it."""
    whole = draw(st.integers(0, 9_999_999))
    decimals = draw(st.sampled_from(["", ".5", ".25", ",75"]))
    value = float(f"{whole}{decimals.replace(',', '.')}")
    digits = str(whole)
    if whole >= 1000 and draw(st.booleans()):
        groups = []
        while len(digits) > 3:
            groups.insert(0, digits[-3:])
            digits = digits[:-3]
        digits = digits + "".join(draw(st.sampled_from(["'", "’"])) + g for g in groups)
    number = digits + decimals
    if draw(st.booleans()):
        number = f"{number}x10^0"
    text = (draw(st.sampled_from(_LABELS)) + draw(st.sampled_from(_NAMES)) +
            draw(st.sampled_from(_APPROX)) + number + " " + draw(st.sampled_from(_UNITS)) +
            draw(st.sampled_from(_ENDS)))
    if draw(st.booleans()):
        at = draw(st.integers(0, len(text)))
        text = text[:at] + "\u200b" + text[at:]
    return value, text


@settings(max_examples=200, deadline=None)
@given(_spellings())
def test_any_documented_spelling_of_the_same_quantity_parses_to_the_same_value(case):
    value, text = case
    spec = NumericSpec(unit="m/s^2", rtol=1e-12, atol=1e-12)
    assert accepts(spec, value, text), text
    assert not accepts(spec, value * 1.01 + 0.01, text), text
