"""Functions as written on paper (grading/onpaper.py): powers after the name, the power
-1 as the inverse function, and arguments without brackets where paper is unambiguous.

Each spelling is compared with the plain form a reader of the paper writes by hand, so
the tree is checked, not the printer.
"""

import math

import pytest
from hypothesis import given
from hypothesis import strategies as st

from dynagrade.grading import AnswerError, grade
from dynagrade.grading.nodes import BinOp, Call, Name, Num
from dynagrade.grading.parser import parse_expression, parse_quantity
from dynagrade.grading.quantity import read_quantity
from dynagrade.grading.readability import readability
from dynagrade.grading.spec import SymbolicSpec, Variable

VARS = ("x", "alpha", "beta", "omega", "t", "m", "g", "h", "L", "a")


def tree(text):
    return parse_expression(text, VARS)


@pytest.mark.parametrize("text", ["sin^2(alpha)", "cos^-1(h/L)"])
def test_a_function_with_a_power_and_brackets_is_not_told_to_write_brackets(text):
    """The issue's bug: these got "write sin(...) with brackets around its argument"
    although the brackets are there."""
    tree(text)  # raises before the fix


@pytest.mark.parametrize("on_paper, by_hand", [
    ("sin^2(alpha)", "sin(alpha)^2"),
    ("sin**2(alpha)", "sin(alpha)^2"),
    ("sin^(2)(alpha)", "sin(alpha)^2"),
    ("sin^{2}(alpha)", "sin(alpha)^2"),
    ("sin²(alpha)", "sin(alpha)^2"),
    ("sin²x", "sin(x)^2"),
    ("sin^2 x", "sin(x)^2"),
    ("cos³ x", "cos(x)^3"),
    ("cos^-1(h/L)", "acos(h/L)"),
    ("cos^(-1)(h/L)", "acos(h/L)"),
    ("cos^{-1}(h/L)", "acos(h/L)"),
    ("cos⁻¹(h/L)", "acos(h/L)"),
    ("sin^-1 x", "asin(x)"),
    ("tan^-1(h/L)", "atan(h/L)"),
    ("sin x", "sin(x)"),
    ("sin 2α", "sin(2*alpha)"),
    ("sin 2 alpha", "sin(2*alpha)"),
    ("m g sin alpha", "m*g*sin(alpha)"),
    ("mg sin alpha", "m*g*sin(alpha)"),
    ("sin ωt", "sin(omega*t)"),
    ("sin ω t", "sin(omega*t)"),
    ("sin x^2", "sin(x^2)"),
    ("sin α cos β", "sin(alpha)*cos(beta)"),
    ("sin α cos(β)", "sin(alpha)*cos(beta)"),
    ("sin x + 1", "sin(x) + 1"),
    ("sin x - cos x", "sin(x) - cos(x)"),
    ("(sin x)^2", "sin(x)^2"),
    ("a/sin x", "a/sin(x)"),
    ("ln x", "ln(x)"),
    ("sqrt x", "sqrt(x)"),
    ("atan2(h, sin x)", "atan2(h, sin(x))"),
])
def test_a_function_written_on_paper_reads_as_the_plain_form(on_paper, by_hand):
    assert tree(on_paper) == tree(by_hand)


def test_a_power_after_the_name_is_a_power_of_the_value():
    assert tree("sin^2(alpha)") == BinOp("^", Call("sin", (Name("alpha"),)), Num(2.0))


@pytest.mark.parametrize("text, fix, position", [
    ("sin x/2", "write sin(x / …) or sin(x) / …", 5),
    ("sin x*m", "write sin(x * …) or sin(x) * …", 5),
    ("sin x (a+h)", "write sin(x · …) or sin(x) · …", 6),
    ("sin 2 α/2", "write sin(2 α / …) or sin(2 α) / …", 7),
    ("sin^-2 x", "write 1/sin(x)^2", 0),
    ("ln^-1(x)", "write 1/ln(x) for the reciprocal", 0),
    ("sin^x(t)", "sin(x)^...", 0),
    ("sin^2.5(x)", "must be a whole number", 0),
    ("sin -x", "write sin(...) with brackets", 0),
    ("m g sin", "write sin(...) with brackets", 4),
])
def test_an_ambiguous_function_on_paper_is_refused_with_the_fix(text, fix, position):
    with pytest.raises(AnswerError) as info:
        tree(text)
    assert fix in info.value.message
    assert info.value.position == position


def test_a_declared_variable_named_like_a_function_stays_a_variable():
    assert parse_expression("sin x", ("sin", "x")) == BinOp("*", Name("sin"), Name("x"))


def test_in_a_number_with_a_unit_a_power_needs_the_bracket_and_units_keep_theirs():
    assert read_quantity("sin^2(0.5)").value == pytest.approx(0.229848847065930)  # 0.4794255386²
    assert read_quantity("cos^-1(0.5)").value == pytest.approx(math.pi / 3)
    assert read_quantity("9.81 m/sec^2").value == pytest.approx(9.81)
    assert parse_quantity("2 sec") == BinOp("*", Num(2.0), parse_quantity("sec"))


SPEC = SymbolicSpec({"h": Variable(0.1, 1.0, "m"), "L": Variable(1.5, 3.0, "m")})


def test_the_inverse_read_from_a_power_is_graded_and_noted():
    right = grade(SPEC, "acos(h/L)", "cos^-1(h/L)")
    assert right.correct and "arccos" in right.feedback and "1/cos(...)" in right.feedback
    preview = readability(SPEC, "cos^-1(h/L)")
    assert preview.readable and "acos(h / L)" in preview.message and "arccos" in preview.message


def test_the_reciprocal_is_not_the_inverse():
    """cos^-1 as the reciprocal is a different function: 1/cos(0.5) = 1.1395 while
    arccos(0.5) = 1.0472, so an answer meaning one is wrong for the other."""
    assert not grade(SPEC, "1/cos(h/L)", "cos^-1(h/L)").correct


def test_no_note_when_no_inverse_was_read():
    assert "Note" not in grade(SPEC, "sin(h/L)^2", "sin^2(h/L)").feedback


@given(st.integers(min_value=1, max_value=9), st.sampled_from(["sin", "cos", "tan", "exp", "ln"]))
def test_a_whole_power_after_any_function_name_is_the_power_of_its_value(n, function):
    assert tree(f"{function}^{n}(x)") == tree(f"{function}(x)^{n}")
    assert tree(f"{function}^{n} x") == tree(f"({function}(x))^{n}")
