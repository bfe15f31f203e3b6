"""The Moodle export read back as Moodle's importer reads it: every field that importer
takes (category, info, name, question text and its files, idnumber, penalty, the cloze
fields), the misconceptions' feedback, the figures, the numbers' precision, the marks as
Moodle computes them, and the roster-free pool (issue 15, item 4).

The cloze fields are read by tests/moodle_reader.py, written from Moodle's grammar
without dynagrade's writer."""

from __future__ import annotations

import base64
import math
import re
import xml.etree.ElementTree as ET
from fractions import Fraction

import pytest
from click.testing import CliRunner
from hypothesis import given, settings
from hypothesis import strategies as st

from dynagrade.cli import main
from dynagrade.exam.manifest import ExerciseEntry, PartEntry, VariantEntry
from dynagrade.generation.pool import pool_categories
from dynagrade.render.cloze import cloze_text, number_text
from dynagrade.render.cloze_marks import field_weights
from dynagrade.render.moodle import exercise_marks, pool_xml, variant_idnumber
from moodle_reader import (ClozeSyntaxError, moodle_mark, read_fields,
                           significant_figures)

SECRET = "fedcba9876543210" * 4
POOL = ("release-under-gravity", "degrees-of-freedom", "block-sliding-down-incline",
        "projectile-range")
VARIANTS = 3


@pytest.fixture(scope="module")
def pool(bank):
    exercises = [bank.get(i) for i in POOL]
    categories, notices = pool_categories(exercises, VARIANTS, SECRET)
    export = pool_xml("Pool & <Co>", categories)
    root = ET.fromstring(export.xml)
    return {"bank": bank, "categories": categories, "notices": notices, "root": root,
            "questions": _questions_by_category(root)}


def _questions_by_category(root) -> dict[str, list]:
    grouped, current = {}, None
    for question in root.findall("question"):
        if question.get("type") == "category":
            current = question.findtext("category/text").rsplit("/", 1)[1]
            grouped[current] = []
        else:
            grouped[current].append(question)
    return grouped


def _variant(pool, question) -> VariantEntry:
    idnumber = question.findtext("idnumber")
    return next(v for c in pool["categories"] for v in c.variants
                if variant_idnumber(v) == idnumber)


# -- the importer's fields ---------------------------------------------------------------


def test_every_exercise_has_its_category_with_a_staff_description(pool):
    categories = [q for q in pool["root"].findall("question") if q.get("type") == "category"]
    assert [c.findtext("category/text") for c in categories] == \
        [f"$course$/top/Pool & <Co>/{i}" for i in POOL]
    for category in categories:
        assert category.find("info").get("format") == "html"
        assert "Set the quiz slot's maximum mark to" in category.findtext("info/text")


def test_every_question_carries_what_the_importer_reads(pool):
    for exercise_id, questions in pool["questions"].items():
        for question in questions:
            assert question.get("type") in ("cloze", "numerical")
            assert question.findtext("name/text").strip()
            assert question.find("questiontext").get("format") == "html"
            assert question.findtext("penalty") == "0"
            assert question.findtext("hidden") == "0"
            assert re.fullmatch(rf"{exercise_id}-[0-9a-f]{{12}}", question.findtext("idnumber"))


def test_the_pool_has_as_many_distinct_variants_as_asked_or_says_why_not(pool):
    sizes = {i: len(q) for i, q in pool["questions"].items()}
    # degrees-of-freedom has one parameter, d in {2, 3}: two variants exist
    assert sizes == {"release-under-gravity": 3, "degrees-of-freedom": 2,
                     "block-sliding-down-incline": 3, "projectile-range": 3}
    assert pool["notices"] == ["exercise 'degrees-of-freedom' has only 2 distinct variants "
                               "of the 3 asked for; all of them are in the pool"]
    for questions in pool["questions"].values():
        ids = [q.findtext("idnumber") for q in questions]
        assert len(set(ids)) == len(ids)


def test_idnumbers_hold_no_seed_and_are_the_same_in_every_export(pool):
    """Importing twice duplicated every question unseen: now the same variant has the
    same idnumber in every export, so Moodle's importer drops it from the copies."""
    for category in pool["categories"]:
        for variant in category.variants:
            idnumber = variant_idnumber(variant)
            assert str(variant.seed) not in idnumber
            again = VariantEntry(variant.exercise, 12345, dict(variant.params), {})
            assert variant_idnumber(again) == idnumber
            moved = dict(variant.params)
            name = next(iter(moved))
            moved[name] = moved[name] + 1.0
            assert variant_idnumber(VariantEntry(variant.exercise, variant.seed, moved, {})) \
                != idnumber


def test_the_same_secret_gives_the_same_pool_and_another_secret_another(bank):
    exercises = [bank.get("projectile-range")]
    first = pool_xml("P", pool_categories(exercises, 2, SECRET)[0]).xml
    assert pool_xml("P", pool_categories(exercises, 2, SECRET)[0]).xml == first
    assert pool_xml("P", pool_categories(exercises, 2, "0" * 64)[0]).xml != first


# -- the question text -------------------------------------------------------------------


def test_every_field_is_well_formed_cloze_with_numbers_of_at_most_ten_figures(pool):
    for questions in pool["questions"].values():
        for question in questions:
            if question.get("type") != "cloze":
                continue
            fields = read_fields(question.findtext("questiontext/text"))
            assert fields
            for found in fields:
                assert any(a.fraction == 1.0 for a in found.answers) or \
                    found.kind == "MULTIRESPONSE"
                for answer in found.answers:
                    if found.kind == "NUMERICAL":
                        number, _, allowed = answer.raw.partition(":")
                        assert significant_figures(number) <= 10, answer.raw
                        assert significant_figures(allowed) <= 10, answer.raw
                        assert answer.tolerance > 0


def test_the_float_noise_of_the_old_export_is_gone():
    assert number_text(39.24000000000001) == "39.24"
    assert number_text(0.1 + 0.2) == "0.3"
    assert number_text(-1.5e-05) == "-1.5e-05"
    assert number_text(-0.0) == "0"
    assert significant_figures(number_text(2 / 3)) == 10


def test_the_reader_refuses_what_moodle_would_misread():
    for broken in ("{1:NUMERICAL:=1:0.1", "{:NUMERICAL:=1}", "{1:NUMERICAL:=1e:0.1}",
                   "{1:MULTICHOICE:=a\\}b~c}", "{1:MULTICHOICE:=a#x#y~b}"):
        with pytest.raises(ClozeSyntaxError):
            read_fields(broken)


def test_text_with_the_separators_reads_back_as_written():
    text = "a } b # c ~ d \\ e { f < g & h"
    (found,) = read_fields("{1:MULTICHOICE:=" + cloze_text(text) + "#" + cloze_text(text)
                           + "~other}")
    assert found.answers[0].answer_text == text
    assert found.answers[0].feedback_text == text
    assert found.answers[1].answer_text == "other"


def test_every_misconception_the_grader_tries_is_a_wrong_answer_with_its_feedback(pool):
    """Every declared misconception that the grader tries in a variant (values in the
    part's unit) is, wherever the grader can tell it from the right answer, a wrong
    answer of the part's field with the misconception's feedback and score."""
    bank, checked = pool["bank"], 0
    for exercise_id, questions in pool["questions"].items():
        exercise = bank.get(exercise_id)
        for question in questions:
            variant = _variant(pool, question)
            fields = iter(read_fields(question.findtext("questiontext/text")))
            params = exercise.si(variant.params)
            for part in exercise.parts:
                if part.kind == "symbolic":
                    continue
                own = [next(fields) for _ in range(part.size if part.kind == "vector" else 1)]
                for known in getattr(part.spec(params), "misconceptions", ()):
                    wrong = known.value if isinstance(known.value, tuple) else (known.value,)
                    right = variant.answers[part.name]
                    right = right if isinstance(right, tuple) else (right,)
                    for found, w, r in zip(own, wrong, right):
                        if abs(w - r) <= found.answers[0].tolerance:
                            continue  # the grader cannot tell it from the right answer here
                        matching = [a for a in found.answers[1:]
                                    if abs(a.value - w) <= a.tolerance + 1e-12 * abs(w)]
                        assert matching, (exercise_id, part.name, known.name)
                        assert matching[0].feedback_text == known.feedback
                        assert matching[0].fraction == known.score
                        checked += 1
    assert checked > 20


def test_choices_show_their_options_text(pool):
    for question in pool["questions"]["degrees-of-freedom"]:
        fields = read_fields(question.findtext("questiontext/text"))
        assert [a.answer_text for a in fields[4].answers] == [
            "free particle", "particle sliding on a flat ground",
            "particle on a rigid link about a fixed point",
            "particle on a spring about a fixed point"]
        assert fields[4].kind == "MULTIRESPONSE"
        assert [a.answer_text for a in fields[0].answers] == ["0", "1", "2", "3"]


def test_formula_parts_are_left_out_of_the_students_text_and_named_for_the_staff(pool):
    bank = pool["bank"]
    for exercise_id, questions in pool["questions"].items():
        formulas = [p for p in bank.get(exercise_id).parts if p.kind == "symbolic"]
        for question in questions:
            shown = question.findtext("questiontext/text") + \
                question.findtext("generalfeedback/text")
            assert "fill-in file" not in shown and "not part of this quiz" not in shown
            for part in formulas:
                assert f"<li>{part.label}:" not in shown
    info = _category_info(pool["root"], "release-under-gravity")
    assert ("Not in Moodle (grade them from the fill-in files or by hand): height as a "
            "formula (question 4, x2_formula, a formula, 1 point); together 1 point, "
            "16.6667 % of the exercise.") in info


def test_each_part_is_numbered_as_the_statements_question_it_answers(pool):
    """projectile-range asks questions 1-3 for numbers and 4 for the formula: Moodle's
    list keeps 1, 2, 3, so the numbers match the statement with the formula left out."""
    for question in pool["questions"]["projectile-range"]:
        text = question.findtext("questiontext/text")
        fields_list = text[text.rindex("<ol>"):]
        assert re.findall(r'<li value="(\d+)">', fields_list) == ["1", "2", "3"]


def _category_info(root, exercise_id: str) -> str:
    return next(q.findtext("info/text") for q in root.findall("question")
                if q.get("type") == "category"
                and q.findtext("category/text").endswith("/" + exercise_id))


def test_every_figure_is_an_embedded_svg_file_that_the_text_shows(pool):
    bank = pool["bank"]
    for exercise_id, questions in pool["questions"].items():
        draws = bank.get(exercise_id).figure is not None
        for question in questions:
            files = question.findall("questiontext/file")
            assert len(files) == (1 if draws else 0), exercise_id
            for file in files:
                assert file.get("path") == "/" and file.get("encoding") == "base64"
                svg = base64.b64decode(file.text, validate=True).decode("utf-8")
                assert ET.fromstring(svg).tag == "{http://www.w3.org/2000/svg}svg"
                assert f'src="@@PLUGINFILE@@/{file.get("name")}"' in \
                    question.findtext("questiontext/text")


# -- marks --------------------------------------------------------------------------------


def test_weights_keep_the_parts_proportions_by_hand():
    assert field_weights([2.4, 1.2, 2.4]).weights == (2, 1, 2)
    assert field_weights([2, 2, 2]).weights == (2, 2, 2)       # whole points stay
    assert field_weights([2, 2 / 3, 2 / 3, 2 / 3]).weights == (3, 1, 1, 1)
    assert field_weights([5 / 7, 10 / 7]).weights == (1, 2)
    assert field_weights([0.0, 0.0]).weights == (1, 1)
    # thousandths of three primes need weights summing to millions: approximated to 100
    rough = field_weights([1 / 997, 1 / 991, 1 / 983])
    assert rough.weights == (33, 33, 34) and not rough.exact


@settings(max_examples=200, deadline=None)
@given(st.lists(st.integers(1, 10_000), min_size=1, max_size=8))
def test_points_in_hundredths_get_whole_weights_with_exactly_their_shares(hundredths):
    """Points rounded to hundredths, as exams round them, get whole-number weights whose
    shares of the full mark are exactly the points' shares of the exported points."""
    points = [h / 100 for h in hundredths]
    found = field_weights(points)
    assert found.exact
    assert all(isinstance(w, int) and w > 0 for w in found.weights)
    assert [Fraction(w, found.total) for w in found.weights] == \
        [Fraction(h, sum(hundredths)) for h in hundredths]


def _exercise_entry(parts, points) -> ExerciseEntry:
    return ExerciseEntry("e", "E", "Example 1.1", points, {}, "f.py", "0", tuple(parts))


def test_a_vector_part_shares_its_weight_among_its_components_by_hand():
    """release-under-gravity at 4 exam points: r_t and v_t (vectors of 2) 4/3 points
    each, x2_t 2/3, x2_formula 2/3 (left out). Each component carries 2/3, like x2_t:
    weights 1+1, 1+1, 1, full mark 5, and r_t's share 2/5 = (4/3)/(10/3). The old export
    gave every component the whole part's weight, counting vectors double."""
    parts = [PartEntry("r_t", "position", "vector", "m", 4 / 3, 0.01, None, 2),
             PartEntry("v_t", "velocity", "vector", "m/s", 4 / 3, 0.01, None, 2),
             PartEntry("x2_t", "height", "numeric", "m", 2 / 3, 0.01, None),
             PartEntry("x2_formula", "formula", "symbolic", None, 2 / 3)]
    marks = exercise_marks(_exercise_entry(parts, 4.0))
    assert marks.weights == {"r_t": [1, 1], "v_t": [1, 1], "x2_t": [1]}
    assert marks.full_mark == 5
    assert math.isclose(marks.exported_points, 10 / 3)
    assert [p.name for p in marks.left_out] == ["x2_formula"]


def test_the_example_exams_marks_add_up_to_its_points_by_hand():
    """The example exam's sliding-up-a-slope (6 points; parts 2, 1, 1 and a formula of
    1 in the exercise): 2.4, 1.2, 1.2 in Moodle and 1.2 left out; weights 2, 1, 1 (the
    old export: 6 points became 4 with nothing to say so)."""
    parts = [PartEntry("delta_x", "d", "numeric", "m", 2.4, 0.01, None),
             PartEntry("a_up", "a", "numeric", "m/s^2", 1.2, 0.01, None),
             PartEntry("t_stop", "t", "numeric", "s", 1.2, 0.01, None),
             PartEntry("delta_x_formula", "f", "symbolic", None, 1.2)]
    marks = exercise_marks(_exercise_entry(parts, 6.0))
    assert [w for p in marks.exported for w in marks.weights[p.name]] == [2, 1, 1]
    assert math.isclose(marks.exported_points + sum(p.points for p in marks.left_out), 6.0)
    assert math.isclose(marks.exported_points, 4.8)


def test_moodle_marks_the_key_full_and_each_part_by_its_share_of_the_points(pool):
    """Moodle's scoring (moodle_reader.moodle_mark) of the key's answers is the full mark;
    with only one part right, the mark is that part's share of the exported points."""
    bank = pool["bank"]
    for category in pool["categories"]:
        exercise = bank.get(category.described.id)
        marks = exercise_marks(category.described)
        for question in pool["questions"][exercise.id]:
            if question.get("type") != "cloze":
                continue
            variant = _variant(pool, question)
            fields = read_fields(question.findtext("questiontext/text"))
            key = _responses(marks.exported, variant.answers)
            assert math.isclose(moodle_mark(fields, key), 1.0)
            start = 0
            for part in marks.exported:
                n = len(marks.weights[part.name])
                only = [r if start <= i < start + n else _wrong(r)
                        for i, r in enumerate(key)]
                share = Fraction(part.points / marks.exported_points).limit_denominator(1000)
                assert math.isclose(moodle_mark(fields, only), share, rel_tol=1e-9), \
                    (exercise.id, part.name)
                start += n


def _responses(parts, answers) -> list:
    responses = []
    for part in parts:
        value = answers[part.name]
        if part.kind == "vector":
            responses += list(value)
        elif part.kind == "choice" and part.multiple:
            responses.append(set(value))
        else:
            responses.append(value)
    return responses


def _wrong(response):
    if isinstance(response, set):
        return set()
    if isinstance(response, str):
        return "no such option"
    return 1e9


# -- the command --------------------------------------------------------------------------


def test_dynagrade_moodle_writes_the_pool_asked_for(tmp_path):
    secret = tmp_path / "pool.secret"
    out = tmp_path / "pool.xml"
    runner = CliRunner()
    result = runner.invoke(main, ["moodle", "sliding-up-a-slope", "--variants", "4",
                                  "-o", str(out), "--secret-file", str(secret)])
    assert result.exit_code == 0, result.output
    assert "wrote" in result.output and "4 questions in 1 categories" in result.output
    questions = [q for q in ET.parse(out).getroot().findall("question")
                 if q.get("type") != "category"]
    assert len(questions) == 4
    first = out.read_bytes()
    again = runner.invoke(main, ["moodle", "sliding-up-a-slope", "--variants", "4",
                                 "-o", str(out), "--secret-file", str(secret)])
    assert again.exit_code == 0 and out.read_bytes() == first


def test_dynagrade_moodle_names_an_unknown_exercise_without_a_traceback(tmp_path):
    result = CliRunner().invoke(main, ["moodle", "no-such-exercise", "-o",
                                       str(tmp_path / "p.xml")])
    assert result.exit_code == 1
    assert "no exercise with id 'no-such-exercise'" in result.output
    assert "Traceback" not in result.output


def test_a_partial_credit_misconception_keeps_its_percentage():
    from dynagrade.render.cloze import Alternative, field

    (found,) = read_fields(field(2, "NUMERICAL", [Alternative(1.0, 1.0, 0.01),
                                                   Alternative(2.0, 0.5, 0.02, "half")]))
    assert found.answers[1].fraction == 0.5 and found.answers[1].feedback_text == "half"


LONE_NUMBER = '''
"""A single numeric part with a half-credit misconception, and a formula-only exercise."""
from dynagrade.exercise import Choice, Exercise, Misconception, Numeric, Symbolic


def solve(p):
    return {"y": 3 * p.x}


EXERCISE = Exercise(
    id="triple-of-x", title="Triple", source="Section 1.1",
    params=(Choice("x", (1.0, 2.0), unit="m"),),
    statement="What is three times $x$ = {{ x }}?",
    solve=solve,
    parts=(Numeric("y", "triple", unit="m", points=3,
                   misconceptions=(Misconception("doubled", lambda p: 2 * p.x,
                                                 "Twice {x} is not # three ~ times", 0.5),)),),
)
'''

FORMULA_ONLY = '''
"""Only a formula: Moodle can check none of it."""
from dynagrade.exercise import Choice, Exercise, Symbolic


EXERCISE = Exercise(
    id="formula-of-x", title="Formula", source="Section 1.1",
    params=(Choice("x", (1.0, 2.0), unit="m"),),
    statement="Write three times $x$.",
    solve=lambda p: {},
    parts=(Symbolic("f", "three x", expected="3*x", variables=("x",)),),
)
'''


def test_a_lone_number_is_a_numerical_question_with_its_misconception_and_points(tmp_path):
    from dynagrade.exercise.loader import open_bank

    (tmp_path / "triple.py").write_text(LONE_NUMBER, encoding="utf-8")
    (tmp_path / "formula.py").write_text(FORMULA_ONLY, encoding="utf-8")
    bank = open_bank([tmp_path])
    categories, notices = pool_categories([bank.get("triple-of-x"), bank.get("formula-of-x")],
                                          2, SECRET)
    export = pool_xml("P", categories)
    assert notices == []
    assert export.notices == ["exercise 'formula-of-x' is not in the Moodle export: none of "
                              "its parts can be checked by Moodle"]
    root = ET.fromstring(export.xml)
    assert [q.findtext("category/text") for q in root.findall("question")
            if q.get("type") == "category"] == ["$course$/top/P/triple-of-x"]
    questions = [q for q in root.findall("question") if q.get("type") != "category"]
    assert sorted(_variant_x(q) for q in questions) == [1.0, 2.0]
    for question in questions:
        x = _variant_x(question)
        assert question.get("type") == "numerical"
        assert question.findtext("defaultgrade") == "3"          # numerical questions use it
        right, doubled = question.findall("answer")
        assert (right.get("fraction"), float(right.findtext("text")),
                float(right.findtext("tolerance"))) == ("100", 3 * x, 0.03 * x)
        assert (doubled.get("fraction"), float(doubled.findtext("text")),
                float(doubled.findtext("tolerance"))) == ("50", 2 * x, 0.02 * x)
        assert doubled.findtext("feedback/text") == "Twice {x} is not # three ~ times"


def _variant_x(question) -> float:
    return float(re.search(r"= ([\d.]+)", question.findtext("questiontext/text")).group(1))
