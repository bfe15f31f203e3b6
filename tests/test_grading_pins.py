"""Tests that pin what mutation testing of the grader showed unpinned (issue 29): how a
misconception's credit combines with unit credit, symmetry under a sign, which generic
mistakes are tried for which units, the angle-exponent rule of unit conversion, the
sign in the formula tolerance, the feedback of vector and choice parts with ``reveal`` and
of a formula in the wrong units, and the domains the exact check of formulas assumes. Each
expected verdict and feedback line is written from docs/grading.md's rules by hand."""
import math

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

from dynagrade.grading import grade
from dynagrade.grading import units
from dynagrade.grading.nodes import BinOp, Call, Name, Num
from dynagrade.grading.quantity import unit_info
from dynagrade.grading.readability import readability
from dynagrade.grading.spec import ChoiceSpec, KnownWrong, NumericSpec, SymbolicSpec, Variable, VectorSpec
from dynagrade.grading.symbolic import _reference
from dynagrade.grading.tolerance import point_tolerance
from dynagrade.grading.tosympy import exactly_equal, to_sympy

SETTINGS = settings(max_examples=150, deadline=None)

finite = st.floats(-1e6, 1e6, allow_nan=False).filter(lambda x: abs(x) > 1e-3)
factors = st.sampled_from([1.0, 1.004, 1.02, -1.0, 2.0, 0.5, 10.0, 1e-3, 2 * math.pi, 1.3])


# --- a verdict that is not correct scores below 1 -----------------------------------------

@SETTINGS
@given(e=finite, factor=factors, u=st.one_of(st.none(), st.floats(0.05, 0.95)),
       known_score=st.floats(0.0, 0.99), known_factor=st.sampled_from([1.3, -0.7, 3.0]),
       unit=st.sampled_from(["", " m", " cm", " s", " kg"]), reveal=st.booleans(),
       require_unit=st.booleans(), bare_known=st.booleans())
def test_a_verdict_that_is_not_correct_scores_below_1(e, factor, u, known_score, known_factor,
                                                       unit, reveal, require_unit, bare_known):
    # With unit credit u in (0, 1) the score is u + (1 - u) * credit (docs/grading.md,
    # "Separate credit for value and unit"): below 1 whenever the credit is.
    known = KnownWrong("slip", e * known_factor, "A slip.", score=known_score)
    spec = NumericSpec(unit="m", unit_credit=u, misconceptions=(known,), reveal=reveal,
                       require_unit=require_unit)
    for answer in (f"{e * factor!r}{unit}", f"{e * known_factor!r}" + ("" if bare_known else " m")):
        verdict = grade(spec, e, answer)
        assert verdict.correct or verdict.score < 1.0, (answer, verdict)


def test_a_misconception_with_partial_credit_and_unit_credit_scores_by_the_documented_rule():
    # unit credit 0.5 for the right unit, half the value credit: 0.5 + 0.5 * 0.5 = 0.75
    spec = NumericSpec(unit="m", unit_credit=0.5,
                       misconceptions=(KnownWrong("slip", 4.0, "A slip.", score=0.5),))
    verdict = grade(spec, 2.0, "4 m")
    assert (verdict.correct, verdict.score, verdict.misconception) == (False, 0.75, "slip")


# --- negating key and answer keeps the verdict --------------------------------------------

@SETTINGS
@given(e=finite, factor=factors, unit=st.sampled_from([None, "m", "rad/s", "1/s", "rad"]),
       rtol=st.sampled_from([0.01, 0.001]), sigfigs=st.sampled_from([None, 3]))
def test_negating_key_and_answer_keeps_the_verdict(e, factor, unit, rtol, sigfigs):
    spec = NumericSpec(unit=unit, rtol=rtol, sigfigs=sigfigs)
    a = e * factor
    plus, minus = grade(spec, e, repr(a)), grade(spec, -e, repr(-a))
    assert (plus.correct, plus.score, plus.misconception) == \
        (minus.correct, minus.score, minus.misconception)


# --- which generic misconceptions are tried for which units -------------------------------
# For a reference of 3 (in the part's unit) each candidate value, typed as a bare number
# (read in the part's unit), is named as the mistake docs/grading.md ("Feedback") lists
# for that family, or is just "not correct" where the family does not try it.

E = 3.0
ALWAYS = {"sign": -E, "factor 2": 2 * E, "factor 1/2": E / 2, "reciprocal": 1 / E,
          "power of ten": E * 1000}
TWO_PI = {"factor 2π": E * 2 * math.pi}
DEGREES = {"degrees for radians": E * 180 / math.pi}
RADIANS = {"radians for degrees": E * math.pi / 180}

#: (part unit, the mistakes tried beyond ALWAYS). Rotational parts (an angle in the unit,
#: or 1/s) try a factor 2π; angle parts also degrees for radians (or back).
FAMILIES = [
    (None, {}),
    ("1/s", TWO_PI),
    ("rad/s", TWO_PI),
    ("N*m/rad", TWO_PI),
    ("rad", {**TWO_PI, **DEGREES}),
    ("deg", {**TWO_PI, **RADIANS}),
    ("m/s", {}),
]
#: Hz parts: kept apart, since the reading of Hz against rad/s is being reconsidered.
HZ_FAMILIES = [("Hz", TWO_PI)]
EVERY_CANDIDATE = {**ALWAYS, **TWO_PI, **DEGREES, **RADIANS}


def _named_mistakes(unit):
    named = {}
    for name, value in EVERY_CANDIDATE.items():
        verdict = grade(NumericSpec(unit=unit), E, repr(value))
        assert not verdict.correct
        named[name] = verdict.misconception
    return named


@pytest.mark.parametrize("unit, extra", FAMILIES + HZ_FAMILIES,
                         ids=[str(u) for u, _ in FAMILIES + HZ_FAMILIES])
def test_each_unit_family_tries_its_documented_misconceptions(unit, extra):
    tried = {**ALWAYS, **extra}
    expected = {name: (name if name in tried else None) for name in EVERY_CANDIDATE}
    assert _named_mistakes(unit) == expected


# --- the angle-exponent rule of units.compatible ------------------------------------------

@pytest.mark.parametrize("given_unit, wanted_unit, convertible", [
    ("rad/s", "1/s", True),        # an angle exponent of 0 on one side: the SI radian is 1
    ("1/s", "rad/s", True),
    ("rad", None, True),
    ("deg", "rad", True),          # equal angle exponents
    ("N*m/rad", "N*m", True),
    ("rad^2", "rad", False),       # both carry an angle, with different exponents
    ("rad/s", "rad^2/s", False),
    ("rad^2", None, True),
    ("m", "rad", False),           # other dimensions must agree
    ("rad/s", "m/s", False),
])
def test_units_convert_when_their_angle_exponents_agree_or_one_is_zero(given_unit, wanted_unit,
                                                                      convertible):
    assert units.compatible(unit_info(given_unit)[1], unit_info(wanted_unit)[1]) is convertible


# --- the sign in tolerance.point_tolerance ------------------------------------------------

def test_the_formula_tolerance_is_positive_for_negative_targets():
    # rtol * max(|t_i|, 1e-3 * median |t|): median |t| = 4, so the floor is 0.004
    tol = point_tolerance(np.array([-2.0, -4.0, -6.0, -1e-4]), 0.01)
    assert tol == pytest.approx([0.02, 0.04, 0.06, 0.01 * 0.003], rel=1e-12)


def test_the_formula_tolerance_of_a_target_that_is_zero_everywhere_is_1e_12():
    assert point_tolerance(np.zeros(3), 0.01) == pytest.approx([1e-12] * 3, rel=1e-12)


# --- golden feedback of vector parts with reveal ------------------------------------------

REVEALED = " The expected answer is (1, -2, 0.5) m."
VECTOR_FEEDBACK = [
    ("(1, -2, 0.5) m", True, 1.0, None, "Correct."),
    ("(1, 2, 0.5) m", False, 2 / 3, None,
     "Not correct: 2 of 3 components are right (1: ✓ right, 2: ✗ wrong, 3: ✓ right)." + REVEALED),
    ("(-1, 2, -0.5) m", False, 0.0, "sign",
     "Your vector points the opposite way: check the signs of the components." + REVEALED),
    ("(0.5, -2, 1) m", False, 1 / 3, "swapped components",
     "Your components are in the wrong order." + REVEALED),
    ("(2, -4, 1) m", False, 0.0, "factor 2",
     "Your vector is twice the expected one: check for an extra factor of 2." + REVEALED),
    ("(0.5, -1, 0.25) m", False, 0.0, "factor 1/2",
     "Your vector is half the expected one: check for a missing factor of 2." + REVEALED),
    ("(100, -200, 50) cm", True, 1.0, None, "Correct."),
]


@pytest.mark.parametrize("answer, correct, score, misconception, feedback", VECTOR_FEEDBACK,
                         ids=[row[0] for row in VECTOR_FEEDBACK])
def test_vector_feedback_with_reveal_reads_as_written_by_hand(answer, correct, score,
                                                               misconception, feedback):
    verdict = grade(VectorSpec(3, unit="m", reveal=True), (1.0, -2.0, 0.5), answer)
    assert (verdict.correct, verdict.misconception, verdict.feedback) == (correct, misconception, feedback)
    assert verdict.score == pytest.approx(score, abs=1e-12)


# --- golden feedback of choice parts with reveal ------------------------------------------
# Options a, b, c, d; right: a and c. Score (hits - wrong) / 2, never below 0.

CHOICE_FEEDBACK = [
    ("a, c", True, 1.0, "Correct."),
    ("a", False, 0.5, "Not correct: 1 of your 1 choices are right, and 1 right option is missing."
     " The right options are a, c."),
    ("a, b", False, 0.0, "Not correct: 1 of your 2 choices are right, and 1 right option is missing."
     " The right options are a, c."),
    ("a, c, d", False, 0.5, "Not correct: 2 of your 3 choices are right. The right options are a, c."),
    ("b, d", False, 0.0, "Not correct: 0 of your 2 choices are right, and 2 right options are missing."
     " The right options are a, c."),
]


@pytest.mark.parametrize("answer, correct, score, feedback", CHOICE_FEEDBACK,
                         ids=[row[0] for row in CHOICE_FEEDBACK])
def test_choice_feedback_with_reveal_reads_as_written_by_hand(answer, correct, score, feedback):
    spec = ChoiceSpec(("a", "b", "c", "d"), multiple=True, reveal=True)
    verdict = grade(spec, ("a", "c"), answer)
    assert (verdict.correct, verdict.feedback) == (correct, feedback)
    assert verdict.score == pytest.approx(score, abs=1e-12)


def test_a_single_choice_reveals_the_one_right_option():
    spec = ChoiceSpec(("up", "down"), reveal=True)
    assert grade(spec, "up", "down").feedback == "Not correct. The right option is up."
    assert grade(spec, "up", "up, down").feedback == "Choose only one option. The right option is up."


# --- survivors of the grader's mutation run, each pinned by its documented rule -----------

def test_with_a_unit_of_the_wrong_kind_the_number_is_compared_as_typed():
    # docs/grading.md, "Separate credit for value and unit": 5 ms for 5 m is the right number
    # in the wrong kind of unit, so it earns 1 - unit_credit = 0.8.
    verdict = grade(NumericSpec(unit="m", unit_credit=0.2), 5.0, "5 ms")
    assert not verdict.correct and verdict.misconception == "unit"
    assert verdict.score == pytest.approx(0.8, abs=1e-12)
    assert verdict.feedback.endswith("The number is right.")


@pytest.mark.parametrize("answer", ["1.2*10^3", "1.2e3", "1.2 × 10^3"])
def test_a_coarsely_rounded_reference_in_powers_of_ten_gets_the_digits_hint(answer):
    # 1234 at 1 %: 3 figures always land within 1 % (log10(5 / 0.01) = 2.7); 1.2 × 10³ is
    # 1234 correctly rounded to the 2 figures given.
    verdict = grade(NumericSpec(), 1234.0, answer)
    assert verdict.feedback == ("Not correct: 1200 is not within the tolerance (1 %). "
                                "You gave 2 significant figures; give at least 3.")


def test_a_formula_that_leaves_out_an_allowed_name_is_readable():
    spec = SymbolicSpec({"x": Variable(0.5, 2.0), "m": Variable(1.0, 2.0)})
    assert readability(spec, "2*x").readable
    unknown = readability(spec, "2*x*q")
    assert not unknown.readable and "'q'" in unknown.message


# --- golden feedback of a formula in the wrong units ----------------------------------------
# h = v0²/(2g) in m. v0/2g is read as (v0/2)·g: (m/s)·(m/s²) = m²/s³; v0 alone is in m/s.
LIFT = {"v0": Variable(1, 50, "m/s"), "g": Variable(9, 10, "m/s^2")}
A_2G = " Note: a/2g is read as (a/2)·g; write a/(2g) if you mean to divide by 2g."


@pytest.mark.parametrize("answer, reveal, feedback", [
    ("v0/2g", False, "Not correct: your expression has units of m²/s³, expected m." + A_2G),
    ("v0/2g", True, "Not correct: your expression has units of m²/s³, expected m." + A_2G
     + " The expected answer is v0^2 / (2 * g)."),
    ("v0", True, "Not correct: your expression has units of m/s, expected m."
     " The expected answer is v0^2 / (2 * g)."),
])
def test_a_formula_in_the_wrong_units_gets_the_units_the_reading_note_and_the_reveal(
        answer, reveal, feedback):
    verdict = grade(SymbolicSpec(LIFT, reveal=reveal), "v0^2/(2*g)", answer)
    assert (verdict.correct, verdict.misconception, verdict.feedback) == (False, "dimensions", feedback)


def test_the_exact_check_sees_each_variable_s_declared_domain_in_si_units():
    # 2 cm to 5 cm is 0.02 m to 0.05 m; a domain from 0 or across 0 is kept as declared,
    # so neither is taken for a positive variable.
    spec = SymbolicSpec({"h": Variable(2, 5, "cm"), "x": Variable(0, 1, "m"),
                         "y": Variable(-2, 3)})
    domains = _reference(spec, "h + x + y").domains
    assert domains["h"] == pytest.approx((0.02, 0.05), rel=1e-12)
    assert domains["x"] == (0.0, 1.0) and domains["y"] == (-2.0, 3.0)


def test_a_variable_whose_whole_domain_is_positive_is_positive_in_the_exact_check_below_1_too():
    # k in [0.5, 2], m in [0.2, 0.9]: both positive, so sqrt(k)/sqrt(m) is sqrt(k/m);
    # for x in [-1, 1], sqrt(x^2) is |x|, not x.
    k, m, x = Name("k"), Name("m"), Name("x")
    domains = {"k": (0.5, 2.0), "m": (0.2, 0.9), "x": (-1.0, 1.0)}
    assert to_sympy(k, domains).is_positive and to_sympy(m, domains).is_positive
    assert to_sympy(x, domains).is_positive is None
    assert exactly_equal(BinOp("/", Call("sqrt", (k,)), Call("sqrt", (m,))),
                         Call("sqrt", (BinOp("/", k, m),)), domains, 5.0) is True


def test_the_exact_check_proves_sin_squared_plus_cos_squared_is_1_and_not_2():
    x = Name("x")
    square = {f: BinOp("^", Call(f, (x,)), Num(2.0)) for f in ("sin", "cos")}
    pythagoras = BinOp("+", square["sin"], square["cos"])
    assert exactly_equal(pythagoras, Num(1.0), {"x": (-3.0, 3.0)}, 5.0) is True
    assert exactly_equal(pythagoras, Num(2.0), {"x": (-3.0, 3.0)}, 5.0) is False
