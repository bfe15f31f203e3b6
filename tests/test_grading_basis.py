"""Vectors written with the notes' basis vectors (issue 27, class 2): ``3 e1 + 2 e2``,
``3e_1+2e_2``, ``3i+2j``, and ``3 e_r + 2 e_φ`` in a part that declares the polar basis.

The expected components are read off the answers by hand: the coefficient of each basis
vector is its component, a missing basis vector is a zero component."""

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from dynagrade.grading import grade
from dynagrade.grading.basis import examples
from dynagrade.grading.compare import build
from dynagrade.grading.dispatch import accepts
from dynagrade.grading.readability import readability
from dynagrade.grading.spec import NumericSpec, SymbolicSpec, Variable, VectorSpec

PLANE = VectorSpec(2, unit="m/s")
POLAR = VectorSpec(2, unit="m/s", basis=("e_r", "e_phi"))
PATH = VectorSpec(2, unit="m/s", basis=("e_t", "e_n"))
SPACE = VectorSpec(3)


@pytest.mark.parametrize("answer", [
    "3 e1 + 2 e2", "3e_1+2e_2", "3*e1 + 2*e2", "3i+2j", "3 i + 2 j", "3 e₁ + 2 e₂",
    "3 e_x + 2 e_y", "2 e2 + 3 e1", "(3 e1 + 2 e2) m/s", "3 m/s e1 + 200 cm/s e2",
    "e1*3 + 2e_2", "3î + 2ĵ", "3,0 e1 + 2 e2", "3 e1 + 1 e2 + 1 e2",
])
def test_the_notes_basis_vectors_read_as_the_components_3_and_2(answer):
    verdict = grade(PLANE, (3.0, 2.0), answer)
    assert verdict.correct, verdict
    assert readability(PLANE, answer).message.startswith("reads as (3, 2) m/s")


def test_3e1_plus_2e2_in_a_vector_part_is_3_e1_plus_2_e2_not_the_number_230():
    # before issue 27 the tokenizer read 3e1 = 30 and 2e2 = 200: one component, 230
    verdict = grade(PLANE, (3.0, 2.0), "3e1+2e2")
    assert verdict.correct, verdict
    assert "basis vectors" in verdict.feedback and "3 e1+2 e2" in verdict.feedback
    assert "basis vectors" in readability(PLANE, "3e1+2e2").message


def test_a_glued_number_stays_a_number_in_the_bracket_form_and_with_a_signed_exponent():
    assert grade(PLANE, (30.0, 200.0), "(3e1, 2e2)").correct
    assert grade(PLANE, (1.5e-3, 2.0), "1.5e-3 e1 + 2 e2").correct


@pytest.mark.parametrize("answer", ["3 e_r + 2 e_φ", "3 e_r + 2 e_phi", "3*e_r+2*e_{φ}",
                                    "3e_r + 2e_ϕ", "2 e_φ + 3 e_r", "(3, 2)"])
def test_a_part_with_the_polar_basis_reads_e_r_and_e_phi(answer):
    assert grade(POLAR, (3.0, 2.0), answer).correct


def test_a_part_with_the_path_basis_reads_e_t_and_e_n_in_any_order():
    assert grade(PATH, (4.0, -1.5), "-1.5 e_n + 4 e_t").correct
    assert grade(PATH, (4.0, -1.5), "4e_t-1.5e_n").correct


@pytest.mark.parametrize("answer", ["2i - k", "2 e1 - e3", "2e1-1e3", "-e_z + 2 e_x"])
def test_a_basis_vector_left_out_is_a_zero_component(answer):
    assert grade(SPACE, (2.0, 0.0, -1.0), answer).correct


def test_a_sign_in_front_of_a_bracket_flips_every_term():
    assert grade(PLANE, (-3.0, 2.0), "-(3 e1 - 2 e2)").correct


def test_physics_mistakes_in_basis_notation_stay_wrong():
    sign = grade(PLANE, (3.0, 2.0), "3 e1 - 2 e2")
    assert not sign.correct and sign.score == pytest.approx(0.5)
    swapped = grade(PLANE, (3.0, 2.0), "2 e1 + 3 e2")
    assert not swapped.correct and swapped.misconception == "swapped components"
    unit = grade(PLANE, (3.0, 2.0), "3 m e1 + 2 m e2")
    assert not unit.correct and unit.misconception == "unit"


@pytest.mark.parametrize("answer, words", [
    ("3 e1 + 2", ["'2' has no basis vector", "1 e1 + 2 e2", "(1, 2)"]),
    ("e1^2 + e2", ["inside a function or a power", "1 e1 + 2 e2"]),
    ("3/e1 + e2", ["divides by a basis vector", "1 e1 + 2 e2"]),
    ("3 e1 e2", ["multiplies basis vectors", "1 e1 + 2 e2"]),
    ("(3 e1, 2 e2)", ["either with basis vectors (1 e1 + 2 e2) or in brackets ((1, 2))"]),
    ("3 e1 + 2 e3", ["'e3' is not a basis vector of this part", "1 e1 + 2 e2", "(1, 2)"]),
    ("3 e_r + 2 e_phi", ["'e_r' is not a basis vector of this part", "1 e1 + 2 e2"]),
])
def test_a_basis_vector_written_wrongly_is_refused_with_how_to_write_the_vector(answer, words):
    verdict = grade(PLANE, (3.0, 2.0), answer)
    assert verdict.error, verdict
    for word in words:
        assert word in verdict.feedback


def test_a_vector_without_basis_vectors_is_shown_as_its_first_three_numbers_then_an_ellipsis():
    """examples() for a part with no declared basis and neither 2 nor 3 components: the
    bracket form numbered 1, 2, 3, and "…" only when components are left out."""
    assert examples(4) == {"example": "(1, 2, 3, …)", "bracket": "(1, 2, 3, …)"}
    assert examples(1) == {"example": "(1)", "bracket": "(1)"}


def test_the_cartesian_basis_in_a_polar_part_is_refused_naming_the_polar_basis():
    verdict = grade(POLAR, (3.0, 2.0), "3 e1 + 2 e2")
    assert verdict.error and "1 e_r + 2 e_φ" in verdict.feedback


@pytest.mark.parametrize("answer, name", [("3 e1 + 2 e2", "e1"), ("3 e_r", "e_r"),
                                          ("3i + 2j", "i")])
def test_a_number_part_given_a_vector_says_it_wants_a_number(answer, name):
    # before issue 27: "'e1' is not a number", which does not say what went wrong
    verdict = grade(NumericSpec(unit="m/s"), 3.0, answer)
    assert verdict.error
    assert "this part wants a number; a vector was given" in verdict.feedback
    assert f"'{name}' is a basis vector" in verdict.feedback
    assert "a vector was given" in readability(NumericSpec(unit="m/s"), answer).message


def test_a_formula_part_given_a_vector_says_it_wants_a_formula():
    spec = SymbolicSpec({"m": Variable(1, 2), "g": Variable(9, 10)})
    verdict = grade(spec, "m*g", "3 e1")
    assert verdict.error and "this part wants a formula; a vector was given" in verdict.feedback


def test_a_number_glued_to_e1_in_a_number_part_stays_a_number():
    assert grade(NumericSpec(unit="m/s"), 230.0, "3e1+2e2").correct


def test_a_basis_that_does_not_fit_the_part_is_an_authoring_error():
    for basis in (("e_r",), ("e_r", "e_r"), ("e_r", "2x")):
        with pytest.raises(ValueError):
            VectorSpec(2, basis=basis)


def test_a_compare_record_declares_its_basis():
    spec, expected, answer = build({"kind": "vector", "expected": [3, 2], "unit": "m/s",
                                    "basis": ["e_r", "e_phi"], "answer": "3 e_r + 2 e_φ"})
    assert spec.basis == ("e_r", "e_phi") and grade(spec, expected, answer).correct


_SPELLINGS = {
    0: ["e1", "e_1", "e_x", "i", "e₁"], 1: ["e2", "e_2", "e_y", "j", "e₂"],
    2: ["e3", "e_3", "e_z", "k", "e₃"],
}
_coefficient = st.decimals(min_value=-999, max_value=999, places=3, allow_nan=False,
                           allow_infinity=False)


@st.composite
def _basis_sums(draw):
    size = draw(st.sampled_from([2, 3]))
    values = draw(st.lists(_coefficient, min_size=size, max_size=size))
    order = draw(st.permutations(range(size)))
    terms = []
    for k in order:
        name = draw(st.sampled_from(_SPELLINGS[k]))
        joiner = draw(st.sampled_from([" ", "*", " * ", ""]))  # "" glues: 3e1, 3i
        magnitude = format(abs(values[k]), "f")
        terms.append(("-" if values[k] < 0 else "+", f"{magnitude}{joiner}{name}"))
    text = "".join(f" {sign} {term}" for sign, term in terms).strip()
    return size, [float(v) for v in values], text.lstrip("+ ")


@settings(max_examples=150, deadline=None)
@given(_basis_sums())
def test_a_basis_vector_sum_equals_its_bracket_form(case):
    size, values, text = case
    spec = VectorSpec(size, rtol=1e-12, atol=1e-12)
    bracket = "(" + ", ".join(repr(v) for v in values) + ")"
    assert accepts(spec, tuple(values), bracket)
    assert accepts(spec, tuple(values), text), text
    assert readability(spec, text).message.split(". Read")[0] == readability(spec, bracket).message
