"""``verify``'s checks of what a statement asks and shows: every part answers a numbered
question and every question has a part; every variable of a formula is shown in the
statement under a name the grader accepts."""

import pytest

from dynagrade.errors import DefinitionError
from dynagrade.exercise import Exercise, Numeric, Options, Symbolic, Uniform, Variable
from dynagrade.exercise.asked import numbered_questions, question_problems, unshown_variables
from dynagrade.exercise.verify import static_problems

TWO_QUESTIONS = """
A stone falls from $h$ = {{ h }} at latitude $\\lambda$ = {{ lat }}.
1. How long does it fall?
2. Give the time as a formula in $h$ and $g$.
"""


def _exercise(statement=TWO_QUESTIONS, parts=None, lat_symbol=r"\lambda", **changes):
    parts = parts or (Numeric("t", unit="s", question=1),
                      Symbolic("t_formula", question=2, expected="sqrt(2*h/g)",
                               variables={"h": None, "g": Variable(9, 10, "m/s^2", symbol="g")}))
    fields = dict(id="falling", title="Falling", source="Example 1.1",
                  params=(Uniform("h", 1, 9, step=1, unit="m", symbol="h"),
                          Uniform("lat", 10, 80, step=1, unit="deg", symbol=lat_symbol)),
                  statement=statement, solve=lambda p: {"t": (2 * p.h / 9.81) ** 0.5},
                  parts=parts)
    return Exercise(**{**fields, **changes})


def test_the_questions_are_the_statements_numbered_lines():
    text = "Intro 1. no\n1. a?\n  2) b?\n{% if x %}\n3. c?\n{% endif %}\n{{ n }}. d?\n"
    assert numbered_questions(text) == [1, 2, 3]
    assert numbered_questions(TWO_QUESTIONS) == [1, 2]


def test_an_exercise_whose_parts_answer_its_questions_has_no_problem():
    assert question_problems(_exercise()) == [] and unshown_variables(_exercise()) == []


def test_a_part_no_question_asks_is_a_problem():
    """pendulum-torsion-spring-lagrange graded omega_formula that no question asked."""
    exercise = _exercise(parts=(Numeric("t", unit="s", question=1),
                                Numeric("t2", unit="s", question=3),
                                Numeric("t3", unit="s", question=2)),
                         solve=lambda p: {"t": 1.0, "t2": 1.0, "t3": 1.0})
    assert question_problems(exercise) == [
        "part t2: answers question 3, which the statement does not have (it numbers "
        "questions 1, 2)"]


def test_a_question_no_part_grades_is_a_problem():
    exercise = _exercise(parts=(Numeric("t", unit="s", question=1),))
    assert question_problems(exercise) == [
        "question 2 of the statement has no part that grades it (give a part question=2, "
        "or take the question out)"]


def test_a_part_that_says_no_question_is_a_problem_when_the_statement_numbers_them():
    exercise = _exercise(parts=(Numeric("t", unit="s"), Numeric("u", unit="s", question=2)),
                         solve=lambda p: {"t": 1.0, "u": 1.0})
    assert question_problems(exercise)[0] == ("part t: says no question it answers; the "
                                              "statement numbers questions 1, 2: add question=N")


def test_a_statement_without_numbered_questions_takes_parts_without_a_question():
    plain = "How long does a stone take to fall from $h$ = {{ h }} ({{ lat }})?"
    assert question_problems(_exercise(plain, parts=(Numeric("t", unit="s"),))) == []
    assert "numbers no questions" in question_problems(
        _exercise(plain, parts=(Numeric("t", unit="s", question=1),)))[0]


def test_a_question_number_is_a_whole_number_from_one():
    with pytest.raises(DefinitionError, match="question must be a whole number from 1"):
        Numeric("t", question=0)


LATITUDE_FORMULA = """
At latitude $\\lambda$ = {{ lat }} and height $h$ = {{ h }}:
1. Give the deflection as a formula in $h$ and $\\lambda$.
"""


def _latitude_part(variable):
    return (Symbolic("d", question=1, expected="h*cos(lat)", variables={"h": None, "lat": variable}),)


def test_a_variable_the_statement_prints_under_a_refused_name_is_a_problem():
    """coriolis-falling-body printed λ, but only `lat` was accepted: here the parameter
    declares no symbol, so nothing says that λ is `lat`."""
    exercise = _exercise(LATITUDE_FORMULA, parts=_latitude_part(Variable(0.1, 1.4, "rad")),
                         solve=lambda p: {}, lat_symbol=None)
    assert unshown_variables(exercise) == [
        "part d: the variable 'lat' is not shown in the statement under a name the grader "
        "accepts; print its symbol there, or give it symbol= or aliases= as the statement "
        "writes it"]


@pytest.mark.parametrize("variable, parameter_symbol", [
    (Variable(0.1, 1.4, "rad", symbol=r"\lambda"), None),
    (Variable(0.1, 1.4, "rad", aliases=("lambda",)), None),
    (None, r"\lambda"),  # the parameter's symbol
])
def test_a_variable_printed_as_its_symbol_or_alias_is_shown(variable, parameter_symbol):
    exercise = _exercise(LATITUDE_FORMULA, parts=_latitude_part(variable), solve=lambda p: {},
                         lat_symbol=parameter_symbol)
    assert unshown_variables(exercise) == []


def test_a_name_in_code_counts_as_shown():
    statement = LATITUDE_FORMULA.replace("$\\lambda$ = {{ lat }}", "`lat` = {{ lat }}")
    exercise = _exercise(statement, parts=_latitude_part(Variable(0.1, 1.4, "rad")),
                         solve=lambda p: {}, lat_symbol=None)
    assert unshown_variables(exercise) == []


def test_verify_reports_both_checks_once_per_exercise():
    exercise = _exercise(LATITUDE_FORMULA.replace("1. Give", "1. Give\n2. And?"),
                         parts=_latitude_part(Variable(0.1, 1.4, "rad")), solve=lambda p: {},
                         lat_symbol=None)
    problems = static_problems(exercise)
    assert any(p.startswith("question 2 of the statement has no part") for p in problems)
    assert any(p.startswith("part d: the variable 'lat' is not shown") for p in problems)


def test_an_alias_that_clashes_fails_when_the_exercise_is_built():
    with pytest.raises(DefinitionError, match=r"exercise 'falling', part 'd': .*alias 'sin'"):
        _exercise(LATITUDE_FORMULA, parts=_latitude_part(Variable(0.1, 1.4, "rad", aliases=("sin",))),
                  solve=lambda p: {})


def test_case_numbers_that_name_two_options_fail_when_the_exercise_is_built():
    with pytest.raises(DefinitionError, match=r"part 'n': the alias '1' of the option '0'"):
        _exercise(parts=(Options("n", question=1, options=("0", "1"), numbered=True),
                         Numeric("t", unit="s", question=2)),
                  solve=lambda p: {"n": "0", "t": 1.0})


def test_the_fill_in_line_names_the_question():
    assert Numeric("t", "fall time", unit="s", question=2).describe(1) == \
        "question 2, fall time: a number in s (1 point)"
