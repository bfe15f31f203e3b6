"""The names a student may give a formula's variables: the name, the printed symbol as
typed (Greek spelled out or in Unicode, subscripts with or without ``_`` and braces, in
Unicode), and declared aliases; and the numbers and letters of a choice's cases."""

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from dynagrade.grading import grade
from dynagrade.grading.names import NameClash, alias_table, typed_forms
from dynagrade.grading.parser import parse_expression
from dynagrade.grading.nodes import Name, names_in
from dynagrade.grading.spec import ChoiceSpec, SymbolicSpec, Variable


@pytest.mark.parametrize("symbol, forms", [
    (r"\lambda", ["lambda"]),
    (r"\Omega_E", ["Omega_E", "OmegaE"]),
    ("v_{02}", ["v_{02}", "v_02", "v02"]),
    ("v_{2}(0)", ["v_{2}(0)", "v_2(0)", "v2(0)", "v₂(0)"]),
    ("I_0", ["I_0", "I0"]),
    (r"\dot\varphi", ["phidot"]),
    (r"\dot{\varphi}_0", ["phidot_0", "phidot0"]),
    (r"\Delta x", ["Deltax"]),
    (r"\omega(0)", ["omega(0)", "ω(0)"]),
])
def test_a_printed_symbol_is_typed_as_a_student_reads_it(symbol, forms):
    assert typed_forms(symbol) == forms


LATITUDE = {"lat": Variable(0.1, 1.4, "rad", symbol=r"\lambda"), "h": Variable(1, 100, "m")}


@pytest.mark.parametrize("typed", ["lat", "lambda", "λ"])
def test_the_latitude_is_read_under_its_name_its_greek_spelling_and_its_letter(typed):
    tree = parse_expression(f"h*cos({typed})", set(LATITUDE), {"lambda": "lat"})
    assert names_in(tree) == {"h", "lat"}


@pytest.mark.parametrize("typed", ["I", "I_0", "I0", "I₀"])
def test_a_subscripted_symbol_is_read_with_and_without_its_underscore(typed):
    spec = SymbolicSpec({"I": Variable(1, 4, "kg*m^2", symbol="I_0"), "m": Variable(1, 9, "kg")})
    assert grade(spec, "I + m", f"{typed} + m").correct


@pytest.mark.parametrize("typed", ["v02", "v_{02}", "v_02", "v_2(0)", "v_{2}(0)", "v2(0)", "v₂(0)"])
def test_the_initial_velocity_is_read_as_the_statement_prints_it(typed):
    spec = SymbolicSpec({"v02": Variable(1, 10, "m/s", symbol="v_{2}(0)", aliases=("v_{02}",)),
                         "t": Variable(0, 2, "s"), "g": Variable(9, 10, "m/s^2")})
    verdict = grade(spec, "v02*t - g*t^2/2", f"{typed} t - g t^2/2")
    assert verdict.correct, verdict.feedback


def test_a_printed_spelling_is_one_name_only_at_a_word_boundary():
    """``xv_2(0)`` is no product x·v₂(0): the spelling starts inside a longer name."""
    spec = SymbolicSpec({"v02": Variable(1, 10, symbol="v_{2}(0)"), "x": Variable(1, 2)})
    assert not grade(spec, "x*v02", "xv_2(0)").correct
    assert grade(spec, "x*v02", "x v_2(0)").correct


def test_unicode_subscript_digits_read_as_an_underscore_and_digits():
    tree = parse_expression("x₁ + x₂", {"x_1", "x_2"})
    assert names_in(tree) == {"x_1", "x_2"}


def test_an_alias_names_the_variable_and_nothing_is_evaluated():
    assert parse_expression("lambda", {"lat"}, {"lambda": "lat"}) == Name("lat")


def test_lambda_stays_refused_where_no_variable_is_printed_lambda():
    with pytest.raises(ValueError, match="not allowed"):
        parse_expression("lambda", {"lat"})


@pytest.mark.parametrize("variables, message", [
    ({"a": Variable(0, 1, aliases=("b",)), "b": Variable(0, 1)}, "is the variable 'b'"),
    ({"a": Variable(0, 1, aliases=("sin",))}, "is the function 'sin'"),
    ({"a": Variable(0, 1, aliases=("kg",))}, "is the unit 'kg'"),
    ({"a": Variable(0, 1, aliases=("c",)), "b": Variable(0, 1, aliases=("c",))},
     "is also a spelling of 'a'"),
])
def test_a_declared_alias_that_clashes_is_refused(variables, message):
    with pytest.raises(NameClash, match=message):
        alias_table(variables, ("kg", "m", "s"))
    with pytest.raises(ValueError, match=message.split("'")[0]):
        SymbolicSpec(variables)


def test_a_derived_spelling_that_is_another_variable_stays_that_variable():
    """``v_2``'s spelling ``v2`` is the variable ``v2`` itself, which keeps it."""
    table = alias_table({"v_2": Variable(0, 1, symbol="v_2"), "v2": Variable(0, 1)})
    assert "v2" not in table


SPELLINGS = ["lat", "lambda", "λ"]


@settings(max_examples=30, deadline=None)
@given(st.sampled_from(SPELLINGS), st.sampled_from(["h*cos(L)", "h*sin(L)", "2*h*cos(L)", "h/cos(L)"]))
def test_a_formula_gets_the_same_verdict_whichever_spelling_of_a_variable_it_uses(spelling, answer):
    """Writing the latitude as lat, lambda or λ never changes the verdict."""
    spec = SymbolicSpec(LATITUDE)
    by_name = grade(spec, "h*cos(lat)", answer.replace("L", "lat"))
    assert grade(spec, "h*cos(lat)", answer.replace("L", spelling)) == by_name


CASES = ("free particle", "on the ground", "on a rigid link", "on a spring")
NUMBERED = tuple((str(k), c) for k, c in enumerate(CASES, 1)) + \
    tuple((letter, c) for letter, c in zip("abcd", CASES))


@pytest.mark.parametrize("answer", ["2, 3", "b, c", "(b) (c)", "2 and 3", "on the ground, on a rigid link"])
def test_the_cases_of_a_choice_are_named_by_their_numbers_or_letters(answer):
    spec = ChoiceSpec(CASES, multiple=True, aliases=NUMBERED)
    assert grade(spec, (CASES[1], CASES[2]), answer).correct


def test_a_wrong_case_number_earns_the_partial_credit_of_the_wrong_case():
    spec = ChoiceSpec(CASES, multiple=True, aliases=NUMBERED)
    verdict = grade(spec, (CASES[1], CASES[2]), "2, 4")
    assert not verdict.correct and verdict.score == 0.0  # (1 right - 1 wrong) / 2


def test_an_unknown_case_lists_the_numbers_too():
    spec = ChoiceSpec(CASES, multiple=True, aliases=NUMBERED)
    assert "(or 1, 2, 3, 4, a, b, c, d)" in grade(spec, (CASES[1],), "5").feedback


def test_a_case_number_that_names_another_option_is_refused():
    with pytest.raises(ValueError, match="also names the option '1'"):
        ChoiceSpec(("0", "1", "2"), aliases=(("1", "0"),))


def test_a_compare_record_carries_symbols_aliases_and_the_constant_rule():
    from dynagrade.grading.compare import compare_record

    latitude = {"id": "d", "kind": "symbolic", "expected": "h*cos(lat)", "answer": "h cos(λ) + 2",
                "variables": {"h": {"min": 1, "max": 2}, "lat": {"min": 0, "max": 1, "symbol": "\\lambda"}},
                "up_to_constant": True}
    cases = {"id": "c", "kind": "choice", "expected": ["y", "z"], "answer": "2, 3",
             "choices": ["x", "y", "z"], "aliases": {"1": "x", "2": "y", "3": "z"}}
    clash = {"id": "x", "kind": "symbolic", "expected": "h", "answer": "h",
             "variables": {"h": {"min": 1, "max": 2, "aliases": ["sin"]}}}
    assert compare_record(latitude)["correct"] and compare_record(cases)["correct"]
    assert compare_record(clash)["error"] == "the alias 'sin' of 'h' is the function 'sin'"


@pytest.mark.parametrize("symbol, printed", [
    (r"\lambda", "λ"), ("I_0", "I₀"), ("v_{2}(0)", "v₂(0)"), (r"\Delta x", "Δx"),
    (r"\dot\varphi_0", "φ\u0307₀"), (r"\Omega_E", "Ω_E"),
])
def test_a_printed_symbol_reads_as_plain_text_for_the_fill_in_file(symbol, printed):
    from dynagrade.grading.names import printed_form

    assert printed_form(symbol) == printed


def test_a_spelling_two_symbols_share_is_left_out_unless_an_author_declared_it():
    """Both x_1 and x1 (printed x_{1}) would give `x_1`, so nobody gets it; declared as an
    alias of one of them, it is that one's."""
    derived = alias_table({"xa": Variable(0, 1, symbol="x_1"), "xb": Variable(0, 1, symbol="x_{1}")})
    assert "x_1" not in derived
    declared = alias_table({"xa": Variable(0, 1, aliases=("x_1",)), "xb": Variable(0, 1, symbol="x_{1}")})
    assert declared["x_1"] == "xa"
