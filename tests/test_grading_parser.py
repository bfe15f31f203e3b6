"""The expression parser: accepted syntax, positioned errors, limits, and fuzzing.

Student text must never reach eval/exec/sympify: the parser is our own, so these tests
hold it to its grammar and to its promise of only ever raising AnswerError.
"""

import math
import time

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from dynagrade.grading import AnswerError, grade
from dynagrade.grading.nodes import BinOp, Call, Const, Name, Neg, Num, to_text
from dynagrade.grading.parser import MAX_DEPTH, parse_expression, parse_quantity, parse_vector
from dynagrade.grading.spec import ChoiceSpec, NumericSpec, SymbolicSpec, Variable, VectorSpec

VARS = ("m", "g", "v0", "t", "alpha", "a", "b", "k", "e", "x")


def read(text, variables=VARS):
    return to_text(parse_expression(text, variables))


@pytest.mark.parametrize("text, canonical", [
    ("2g", "2 * g"),
    ("m g", "m * g"),
    ("2(a+b)", "2 * (a + b)"),
    ("(a)(b)", "a * b"),
    ("v0 t cos(alpha)", "v0 * t * cos(alpha)"),
    ("mg", "m * g"),
    ("mv0^2", "m * v0^2"),
    ("v0", "v0"),
    ("v_0", "v0"),
    ("a^b^x", "a^b^x"),
    ("a**2", "a^2"),
    ("-a^2", "-a^2"),
    ("a^-2", "a^(-2)"),
    ("α·m × g", "alpha * m * g"),
    ("a²·b³", "a^2 * b^3"),
    ("√(k/m)", "sqrt(k / m)"),
    ("√k/√m", "sqrt(k) / sqrt(m)"),
    ("arctan(a/b)", "atan(a / b)"),
    ("log(x)", "ln(x)"),
    ("π a", "pi * a"),
    ("e^x", "e^x"),            # e is declared here: a variable
    ("a − b", "a - b"),
    ("msin(alpha)", "m * sin(alpha)"),
    ("1/2 m v0^2", "1 / 2 * m * v0^2"),
    ("x = 2a", "2 * a"),
])
def test_accepted_syntax_reads_as_the_canonical_text(text, canonical):
    assert read(text) == canonical


def test_e_is_eulers_number_unless_declared():
    assert parse_expression("e^x", ("x",)) == BinOp("^", Const("e"), Name("x"))
    assert parse_expression("e^x", ("x", "e")) == BinOp("^", Name("e"), Name("x"))


def test_pi_is_a_constant_unless_declared():
    assert parse_expression("pi", ("x",)) == Const("pi")
    assert parse_expression("pi", ("pi",)) == Name("pi")


@pytest.mark.parametrize("text, fragment, position", [
    ("2*(a+b", "missing ')'", 2),
    ("2*(a+b))", "unexpected ')'", 7),
    ("2 3", "missing operator", 2),
    ("a +* b", "two operators", 3),
    ("a.b", "attribute access", 1),
    ("a[0]", "subscripts", 1),
    ("__import__(x)", "names starting with '_'", 0),
    ("'a'", "quotes", 0),
    ("lambda x: x", "':'", 8),
    ("f(x)", "unknown function 'f'", 0),
    ("sine(x)", "did you mean 'sin'", 0),
    ("alhpa", "did you mean 'alpha'", 0),
    ("sin -x", "brackets", 0),  # "sin x" is read as on paper (grading/onpaper.py)
    ("a, b", "comma", 1),
    ("atan2(a)", "takes 2 arguments", 0),
    ("a!", "factorial", 1),
    ("", "empty", None),
    ("2*", "ends too early", 2),
])
def test_errors_name_the_problem_and_where_it_is(text, fragment, position):
    with pytest.raises(AnswerError) as info:
        parse_expression(text, VARS)
    assert fragment in info.value.message
    assert info.value.position == position


@pytest.mark.parametrize("text, value", [
    ("1.2e3", 1200.0), ("1.2E+03", 1200.0), ("1.2×10^3", 1200.0), ("1.2·10⁻³", 1.2e-3),
    ("12,5", 12.5), ("−3", -3.0), ("981/100", 9.81), ("sqrt(2)", math.sqrt(2)), ("2*pi", 2 * math.pi),
    (".5", 0.5), ("5.", 5.0),
])
def test_number_formats(text, value):
    from dynagrade.grading.evaluate import evaluate_constant

    assert evaluate_constant(parse_quantity(text)) == pytest.approx(value, rel=1e-12)


def test_vectors_split_on_commas_or_semicolons():
    components, unit = parse_vector("(1,5; -2,5) m/s")
    assert [to_text(c) for c in components] == ["1.5", "-2.5"] and to_text(unit) == "m / s"
    components, unit = parse_vector("[1.2, -3.4]")
    assert len(components) == 2 and unit is None


def test_nesting_beyond_the_limit_is_refused_without_recursion_error():
    deep = "(" * (MAX_DEPTH + 5) + "x" + ")" * (MAX_DEPTH + 5)
    with pytest.raises(AnswerError, match="nested too deeply"):
        parse_expression(deep, ("x",))
    assert read("(" * (MAX_DEPTH - 5) + "x" + ")" * (MAX_DEPTH - 5)) == "x"


def _bracketed(levels):
    """``((x)^2*y+1)^2*y+1`` for 2: each bracket adds one level of brackets and three
    levels to the tree (a sum, a product and a power)."""
    text = "x"
    for _ in range(levels):
        text = "(" + text + ")^2*y+1"
    return text


def test_a_tree_deeper_than_the_limit_is_refused_though_its_brackets_are_not():
    """With k brackets the tree is 3k + 1 levels high (x at the bottom): k = 33 gives
    100, the limit, and is read; k = 34 gives 103 and is refused as too complex,
    although its 34 brackets are far within the limit of brackets."""
    assert nesting_and_terms(parse_expression(_bracketed(33), ("x", "y")))[0] == 100
    with pytest.raises(AnswerError, match="too complex \\(nested more than 100 levels\\)"):
        parse_expression(_bracketed(34), ("x", "y"))


def test_an_unknown_name_longer_than_30_characters_is_shown_cut_with_an_ellipsis():
    with pytest.raises(AnswerError) as info:
        parse_expression("distancetravelledbytheblockalongtheslope", ("v0", "g"))
    assert info.value.message == \
        "unknown name 'distancetravelledbytheblockalo…' (the variables are: g, v0)"


# -- hostile answers: every one gets a clear verdict within a second ------------------------
HOSTILE = [
    "(" * 10000 + "x" + ")" * 10000,
    "(" * 1900,
    "-" * 1999 + "x",
    "9**9**9**9",
    "9^9^9^9^9^9^9^9",
    "10^10^10^10 m",
    "factorial(10^7)",
    "__import__('os').system('echo hi')",
    "().__class__.__bases__[0].__subclasses__()",
    "exec('1')", "eval('2')", "lambda: 1", "open('/etc/passwd')",
    "x" * 5000, "sin(" * 500 + "x" + ")" * 500, "x^" * 900 + "x",
    "1e999999", "1" * 1999, "nan", "inf", "-inf", "NaN m/s", "∞", "", "   ", "\x00", "\u202e1",
    "'; DROP TABLE answers; --", "${7*7}", "{{7*7}}", "%s%s%s", "\\frac{1}{2}",
    "[" * 800, "1,2,3,4,5", "(1;;2)", "a.b.c", "x[0][1]", "sqrt(-1)", "ln(0)", "1/0", "0/0",
    "exp(exp(exp(exp(exp(x)))))", ".²", "1.²", "x.²", "x" + "+x" * 700, "(x)" * 500, "√" * 900 + "x",
]
SPECS = [
    (NumericSpec(unit="m/s"), 12.5),
    (NumericSpec(), 0.0),
    (SymbolicSpec({"x": Variable(0.5, 2.0, "m"), "m": Variable(1, 2, "kg")}), "x"),
    (SymbolicSpec({"x": Variable(0.5, 2.0)}), "sin(x)"),
    (VectorSpec(2, unit="m"), (1.0, 2.0)),
    (ChoiceSpec(("a", "b", "c"), multiple=True), ("a", "b")),
]


@pytest.mark.parametrize("answer", HOSTILE, ids=[repr(h[:20]) for h in HOSTILE])
def test_hostile_answers_get_a_wrong_verdict_within_a_second(answer):
    for spec, expected in SPECS:
        start = time.perf_counter()
        verdict = grade(spec, expected, answer)
        elapsed = time.perf_counter() - start
        assert elapsed < 1.0, (answer[:30], spec, elapsed)
        assert not verdict.correct and verdict.score == 0.0
        assert verdict.feedback


# -- fuzzing --------------------------------------------------------------------------------
ALPHABET = "0123456789.,+-*/^()[]{} abegmtxv_αμπ√²³⁻·×−=!'\"e:;°"


@settings(max_examples=200, deadline=None)
@given(st.text(alphabet=ALPHABET, max_size=60))
def test_arbitrary_text_only_ever_raises_answer_error(text):
    for parse in (lambda s: parse_expression(s, ("m", "g", "x", "v0")), parse_quantity, parse_vector):
        try:
            parse(text)
        except AnswerError:
            pass


@settings(max_examples=150, deadline=None)
@given(st.text(max_size=80))
def test_grade_never_raises_on_any_unicode_text(text):
    for spec, expected in SPECS:
        verdict = grade(spec, expected, text)
        assert 0.0 <= verdict.score <= 1.0


NAMES = ("m", "g", "v0", "alpha", "x")
leaves = st.one_of(
    st.builds(Num, st.floats(min_value=0, max_value=1e6, allow_nan=False, allow_infinity=False)),
    st.sampled_from([Name(n) for n in NAMES]),
    st.sampled_from([Const("pi"), Const("e")]),
)


def _extend(children):
    return st.one_of(
        st.builds(Neg, children),
        st.builds(BinOp, st.sampled_from("+-*/^"), children, children),
        st.builds(lambda f, a: Call(f, (a,)), st.sampled_from(["sin", "cos", "sqrt", "exp", "ln", "abs"]), children),
        st.builds(lambda a, b: Call("atan2", (a, b)), children, children),
    )


trees = st.recursive(leaves, _extend, max_leaves=25)


@settings(max_examples=200, deadline=None)
@given(trees)
def test_random_trees_round_trip_through_print_and_parse(tree):
    assert parse_expression(to_text(tree), NAMES) == tree


# -- minus signs, exponents, names and limits ------------------------------------------------
from dynagrade.grading import read_number  # noqa: E402
from dynagrade.grading.names import MINUS_SIGNS  # noqa: E402
from dynagrade.grading.nodes import nesting_and_terms  # noqa: E402
from dynagrade.grading.parser import MAX_TERMS, check_limits  # noqa: E402


@pytest.mark.parametrize("minus", list(MINUS_SIGNS), ids=[f"U+{ord(c):04X}" for c in MINUS_SIGNS])
def test_every_documented_minus_sign_works_in_a_sign_an_exponent_and_a_formula(minus):
    assert read_number(f"1.2e{minus}3") == 0.0012
    assert read_number(f"1.2E{minus}03") == 0.0012
    assert read_number(f"{minus}4.5") == -4.5
    assert read_number(f"7 {minus} 2") == 5.0
    assert parse_expression(f"x*1e{minus}3", ("x",)) == BinOp("*", Name("x"), Num(0.001))


@settings(max_examples=300, deadline=None)
@given(st.floats(allow_nan=False, allow_infinity=False), st.sampled_from(list(MINUS_SIGNS)),
       st.sampled_from(["{!r}", "{:e}", "{:.3E}", "{:.17g}"]))
def test_a_number_printed_with_any_documented_minus_sign_reads_as_with_ascii_minus(x, minus, form):
    def reading(text):
        try:
            return read_number(text)
        except AnswerError as error:  # rounding 1.7975e308 to 1.798E+308 overflows either way
            return error.message

    text = form.format(x)
    assert reading(text.replace("-", minus)) == reading(text)
    if form == "{!r}":
        assert read_number(text.replace("-", minus)) == x


def test_the_unicode_minus_in_an_exponent_is_never_read_as_a_product_with_e():
    # 1.2e−3 used to be 1.2·e − 3 = 0.2619 without a word.
    assert read_number("1.2e−3") == pytest.approx(1.2e-3, rel=1e-15)
    assert read_number("1.2 e − 3") == pytest.approx(1.2 * math.e - 3)  # spaced: Euler's number


@pytest.mark.parametrize("text, position", [("2e", 1), ("1.2e−", 3), ("3E", 1), ("4e+", 1), ("5e*x", 1), ("6e)", 1)])
def test_a_number_glued_to_a_lone_e_is_an_unfinished_number(text, position):
    with pytest.raises(AnswerError) as info:
        parse_expression(text, ("x",))
    assert "unfinished number" in info.value.message and info.value.position == position
    with pytest.raises(AnswerError, match="unfinished number"):
        parse_quantity(text.replace("*x", ""))


def test_a_declared_e_may_follow_a_number():
    assert parse_expression("2e", ("e",)) == BinOp("*", Num(2.0), Name("e"))
    assert parse_expression("2E", ("E",)) == BinOp("*", Num(2.0), Name("E"))


DYNAMICS_NAMES = ("omega_n", "zeta", "mu_k", "theta_0", "phi_1", "g")


@pytest.mark.parametrize("text, canonical", [
    ("ω_n√(1-ζ²)", "omega_n * sqrt(1 - zeta^2)"),
    ("omega_n", "omega_n"),
    ("ωn", "omega_n"),
    ("μ_k g", "mu_k * g"),
    ("μ_kg", "mu_k * g"),
    ("θ_0", "theta_0"),
    ("theta0", "theta_0"),
    ("φ_1", "phi_1"),
])
def test_a_greek_letter_with_a_suffix_is_one_name(text, canonical):
    assert to_text(parse_expression(text, DYNAMICS_NAMES)) == canonical


def test_a_greek_letter_followed_by_letters_splits_into_declared_names():
    assert parse_expression("ωt", ("omega", "t")) == BinOp("*", Name("omega"), Name("t"))
    assert parse_expression("2πr", ("r",)) == BinOp("*", BinOp("*", Num(2.0), Const("pi")), Name("r"))


def test_an_undeclared_greek_name_is_named_in_the_message():
    with pytest.raises(AnswerError, match="unknown name 'omega_m'"):
        parse_expression("ω_m", DYNAMICS_NAMES)


@pytest.mark.parametrize("text, nesting, terms", [
    ("x", 1, 1), ("x+x", 2, 2), ("x-x+x", 2, 3), ("(x+x)*x", 3, 2), ("((x+x)*x)^2", 4, 2),
    ("x-x+x*x*x/x", 3, 4), ("sin(x+x+x)", 3, 3), ("+".join(["x"] * 300), 2, 300),
])
def test_nesting_counts_flattened_chains_once_and_terms_count_the_longest_chain(text, nesting, terms):
    assert nesting_and_terms(parse_expression(text, ("x",))) == (nesting, terms)


def test_a_flat_sum_of_hundreds_of_terms_is_not_nesting():
    # 150 terms used to be refused as "nested more than 100 levels".
    tree = parse_expression("+".join(["x"] * 150), ("x",))
    assert nesting_and_terms(tree) == (2, 150)
    assert read_number("*".join(["1"] * 400)) == 1.0


def test_more_terms_than_the_term_limit_are_refused():
    tree = Name("x")
    for _ in range(MAX_TERMS):
        tree = BinOp("+", tree, Name("x"))
    with pytest.raises(AnswerError, match=f"more than {MAX_TERMS} terms"):
        check_limits(tree)
    check_limits(tree.left)  # exactly MAX_TERMS terms
