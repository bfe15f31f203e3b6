"""The readability check (grading/readability.py): what exam mode shows before the key
is released. It reads like the grader, says how, and never needs the reference."""

from __future__ import annotations

import pytest

from dynagrade.grading.readability import readability
from dynagrade.grading.spec import ChoiceSpec, NumericSpec, SymbolicSpec, VectorSpec


def test_a_number_with_a_unit_is_converted_to_the_parts_unit():
    # 45 km/h = 45000 m / 3600 s = 12.5 m/s
    found = readability(NumericSpec(unit="m/s"), "45 km/h")
    assert found.readable and found.message == "reads as 45 km/h = 12.5 m/s"


def test_a_bare_number_is_read_in_the_parts_unit():
    found = readability(NumericSpec(unit="m"), "12,5")
    assert found.readable and "12.5 m" in found.message and "bare number" in found.message


def test_a_unit_of_another_dimension_is_not_readable():
    found = readability(NumericSpec(unit="m/s"), "3 kg")
    assert not found.readable and "mass" in found.message and "velocity" in found.message


def test_a_required_unit_must_be_given():
    assert not readability(NumericSpec(unit="m", require_unit=True), "3").readable


@pytest.mark.parametrize("text", ["", "   ", "1 +", "9^9^9^9", "deg^deg", "(" * 500,
                                  "x" * 5000, "__import__('os')"])
def test_unreadable_or_hostile_text_gets_a_message_never_an_exception(text):
    found = readability(NumericSpec(unit="m"), text)
    assert found.readable is False and found.message


def test_vectors_need_their_number_of_components():
    # (1, 2) cm = (0.01, 0.02) m
    assert readability(VectorSpec(2, unit="m"), "(1, 2) cm").message == "reads as (0.01, 0.02) m"
    found = readability(VectorSpec(2, unit="m"), "(1, 2, 3)")
    assert not found.readable and "2 components" in found.message


def test_formulas_may_use_only_the_declared_names():
    spec = SymbolicSpec({"g": (1, 10), "h": (1, 2)})
    assert readability(spec, "sqrt(2 g h)") == readability(spec, "sqrt(2*g*h)")
    assert readability(spec, "sqrt(2 g h)").readable
    found = readability(spec, "sqrt(2 g x)")
    assert not found.readable and "x" in found.message


def test_choices_must_be_among_the_options():
    spec = ChoiceSpec(("A", "B"))
    assert readability(spec, " b ").message == "reads as B"
    assert not readability(spec, "C").readable
    assert not readability(spec, "A, B").readable  # one option only
    assert readability(ChoiceSpec(("A", "B"), multiple=True), "A, B").readable


def test_the_check_is_the_same_whatever_the_reference():
    # it takes no reference: a right and a wrong answer of the same form read alike
    spec = NumericSpec(unit="m")
    assert readability(spec, "28.9 m").readable == readability(spec, "2.89 m").readable


def test_a_spec_of_no_registered_kind_is_not_readable_rather_than_a_crash():
    assert readability(object(), "12").message == "this kind of answer cannot be checked here"


@pytest.mark.parametrize("text, names, tex", [
    ("sqrt(2 g h)", ("g", "h"), r"\sqrt{2 \cdot g \cdot h}"),
    ("v0^2*sin(2*alpha)/g", ("v0", "alpha", "g"),
     r"\frac{{v_{0}}^{2} \cdot \sin\left(2 \cdot \alpha\right)}{g}"),
    ("m g (1 - cos(phi))", ("m", "g", "phi"),
     r"m \cdot g \cdot \left(1 - \cos\left(\phi\right)\right)"),
    ("-(a+b)^2", ("a", "b"), r"-{\left(a + b\right)}^{2}"),
])
def test_a_formula_is_typeset_back_as_it_was_read(text, names, tex):
    from dynagrade.grading.parser import parse_expression
    from dynagrade.serve.formula import formula_mathml, to_tex

    assert to_tex(parse_expression(text, names)) == tex
    assert formula_mathml(text, names).startswith('<math display="inline"')
    assert formula_mathml("sqrt(2 g x)", ("g", "h")) is None  # not readable: nothing shown


def test_the_preview_typesets_a_formula_written_with_the_statements_symbol():
    # release-under-gravity prints v_2(0) for the variable v02: a student who types the
    # printed form sees it typeset, as the grader reads it, instead of no preview at all
    from dynagrade.grading.spec import Variable
    from dynagrade.serve.formula import formula_mathml

    spec = SymbolicSpec(variables={"v02": Variable(0, 10, symbol="v_2(0)"), "t": Variable(0, 5)})
    assert formula_mathml("v_2(0)*t", ("v02", "t")) is None
    shown = formula_mathml("v_2(0)*t", ("v02", "t"), spec.spellings)
    assert shown is not None and "<msub>" in shown and "<mi>t</mi>" in shown
