"""Part kinds own their behaviour: no module outside the kinds' own code asks which kind a
part is, a kind that lacks a piece (grading kind, reader, compare builder, Moodle form)
cannot be defined, and what a kind says about itself (fill-in line, answer text, near
misses, hints) is what the sheets and verify use."""

from __future__ import annotations

import ast
import textwrap
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from dynagrade.exercise import Exercise, Numeric, Options, Symbolic, Variable, Vector
from dynagrade.exercise.parts import PART_KINDS, shortened
from dynagrade.exercise.sheet import parse_sheet, write_sheet

SRC = Path(__file__).resolve().parent.parent / "src" / "dynagrade"
KIND_NAMES = set(PART_KINDS)
KIND_CLASSES = {"Part", "Numeric", "Vector", "Symbolic", "Options", "NumericSpec",
                "VectorSpec", "SymbolicSpec", "ChoiceSpec"}
#: the kinds' own code: the part kinds, and the grader of each kind of spec
OWN_CODE = {"exercise/parts.py", "grading/numeric.py", "grading/vector.py",
            "grading/symbolic.py", "grading/choice.py"}


def _is_kind_literal(node: ast.AST) -> bool:
    if isinstance(node, ast.Constant):
        return node.value in KIND_NAMES
    if isinstance(node, (ast.Tuple, ast.List, ast.Set)):
        return any(_is_kind_literal(element) for element in node.elts)
    return False


def _names(node: ast.AST) -> set[str]:
    if isinstance(node, ast.Name):
        return {node.id}
    if isinstance(node, ast.Attribute):
        return {node.attr}
    if isinstance(node, ast.Tuple):
        return set().union(*(_names(e) for e in node.elts))
    return set()


def kind_branches(source: str) -> list[tuple[int, str]]:
    """Every place in ``source`` that compares with a part kind's name or asks
    ``isinstance`` of a part or spec class, as (line, code)."""
    found = []
    for node in ast.walk(ast.parse(source)):
        if isinstance(node, ast.Compare) and any(
                _is_kind_literal(side) for side in (node.left, *node.comparators)):
            found.append((node.lineno, ast.unparse(node)))
        elif (isinstance(node, ast.Call) and isinstance(node.func, ast.Name)
              and node.func.id in ("isinstance", "issubclass") and len(node.args) == 2
              and _names(node.args[1]) & KIND_CLASSES):
            found.append((node.lineno, ast.unparse(node)))
    return found


def test_the_scan_finds_the_switches_it_is_meant_to_forbid():
    source = ('if part.kind == "numeric": pass\n'
              'ok = p["kind"] in ("vector", "choice")\n'
              'if isinstance(part, (Numeric, Vector)): pass\n'
              'if isinstance(spec, grading.SymbolicSpec): pass\n'
              'if token.kind == "ident": pass\n')
    assert [line for line, _ in kind_branches(source)] == [1, 2, 3, 4]


def test_no_module_outside_the_kinds_branches_on_the_kind_of_a_part():
    offenders = []
    for path in sorted(SRC.rglob("*.py")):
        relative = path.relative_to(SRC).as_posix()
        if relative in OWN_CODE:
            continue
        offenders += [f"{relative}:{line}: {code}"
                      for line, code in kind_branches(path.read_text(encoding="utf-8"))]
    assert offenders == []


def test_every_kind_has_every_piece_and_each_piece_exists():
    """The registry's type is the completeness check; this only finds what the type
    names: each grading function imports, each part builds a spec of its kind's class,
    each Moodle form has a writer, each manifest setting a field."""
    from dynagrade.exam.manifest import PartEntry
    from dynagrade.exercise.kinds import NotExported
    from dynagrade.grading.kinds import GRADING_KINDS, PIECES
    from dynagrade.render.moodle import FORMS

    assert set(GRADING_KINDS) == KIND_NAMES
    for name, kind in PART_KINDS.items():
        assert kind.kind == name and kind.grading is GRADING_KINDS[name]
        for piece in PIECES:
            if getattr(kind.grading, piece) is not None:
                assert callable(kind.grading.function(piece)), (name, piece)
        assert type(kind("x", **_required(kind)).spec({})) is kind.grading.spec
        assert isinstance(kind.moodle, NotExported) or kind.moodle in FORMS, name
        assert set(kind.manifest_fields) <= set(PartEntry.__dataclass_fields__), name


def test_every_moodle_form_a_kind_may_take_has_a_writer():
    from dynagrade.exercise.kinds import MoodleForm
    from dynagrade.render.moodle import FORMS

    assert set(FORMS) == set(MoodleForm)


def _numeric_pieces(**changed) -> dict:
    pieces = {"grade": "numeric:grade_numeric", "accepts": "numeric:accepts_numeric",
              "read": "numeric:read_numeric", "build": "numeric:build_numeric"}
    return {**pieces, **changed}


def test_a_kind_without_a_reader_cannot_be_defined():
    """A kind used to need a reader in grading/readability.py's READERS, which neither the
    completeness test nor the authoring guide named: a new kind passed the tests and then
    read "NOT READABLE" everywhere. Now the reader is a piece of the kind."""
    from dynagrade.errors import DefinitionError
    from dynagrade.grading.kinds import GradingKind, register
    from dynagrade.grading.spec import NumericSpec

    class AngleSpec(NumericSpec):
        pass

    with pytest.raises(TypeError):  # left out
        GradingKind("angle", AngleSpec, "numeric:grade_numeric", "numeric:accepts_numeric",
                    build="numeric:build_numeric")
    for missing in (None, "", "read_numeric"):  # or given as nothing
        with pytest.raises(DefinitionError, match="no read function"):
            GradingKind("angle", AngleSpec, **_numeric_pieces(read=missing))
    with pytest.raises(DefinitionError, match="no build function"):
        GradingKind("angle", AngleSpec, **_numeric_pieces(build=None))
    complete = GradingKind("angle", AngleSpec, **_numeric_pieces())
    assert complete.function("read")(AngleSpec(unit="deg"), "90").readable
    with pytest.raises(DefinitionError, match="clashes"):
        register(complete, GradingKind("angle", NumericSpec, **_numeric_pieces()))


def test_a_part_kind_without_its_grading_kind_or_moodle_form_cannot_be_defined():
    """The part class is the kind: declaring ``kind`` checks the other pieces at once, and
    a refused class is never registered."""
    from dynagrade.errors import DefinitionError
    from dynagrade.exercise.kinds import MoodleForm
    from dynagrade.exercise.parts import Part
    from dynagrade.grading.kinds import GRADING_KINDS

    before = dict(PART_KINDS)
    with pytest.raises(DefinitionError, match="no grading kind"):
        class NoGrader(Part):
            kind = "angle"
            moodle = MoodleForm.NUMBER
    with pytest.raises(DefinitionError, match="registered as 'angle'"):
        class BorrowedGrader(Part):
            kind = "angle"
            grading = GRADING_KINDS["numeric"]
            moodle = MoodleForm.NUMBER
    with pytest.raises(DefinitionError, match="nothing of Moodle"):
        class NoMoodle(Part):
            kind = "numeric"
            grading = GRADING_KINDS["numeric"]
    with pytest.raises(DefinitionError, match="already Numeric"):
        class Twice(Part):
            kind = "numeric"
            grading = GRADING_KINDS["numeric"]
            moodle = MoodleForm.NUMBER
    assert PART_KINDS == before


def test_a_kind_cannot_ask_for_a_numerical_question_apart_from_its_form():
    """``MoodleKind(numerical=True)`` on any kind but Numeric made ``dynagrade exam`` crash
    with a TypeError (a vector's answer is no number). A lone part's question type is now
    part of the form: a numerical question only for the form of one number, and a flag
    beside the form cannot be declared."""
    from dynagrade.errors import DefinitionError
    from dynagrade.exercise.kinds import MoodleForm
    from dynagrade.exercise.parts import Part
    from dynagrade.grading.kinds import GRADING_KINDS
    from dynagrade.render.moodle import FORMS

    assert [form for form, written in FORMS.items() if written.numerical] == [MoodleForm.NUMBER]
    before = dict(PART_KINDS)
    with pytest.raises(DefinitionError, match="nothing of Moodle"):
        class NumericalVector(Part):
            kind = "vector"
            grading = GRADING_KINDS["vector"]
            moodle = {"form": MoodleForm.COMPONENTS, "numerical": True}
    assert PART_KINDS == before


@pytest.mark.parametrize("part", [Numeric("v", "speed", unit="m/s"),
                                  Vector("r", "position", unit="m"),
                                  Options("c", "case", options=("a", "b")),
                                  Symbolic("f", "formula", expected="v0",
                                           variables={"v0": Variable(1, 2)})],
                         ids=lambda part: part.kind)
def test_an_exercise_of_one_part_of_any_kind_exports_to_moodle(part):
    """Each kind alone in its exercise: a numerical question for a number, a cloze
    question with its fields for a vector or a choice, a notice for a formula."""
    import xml.etree.ElementTree as ET

    from dynagrade.generation.pool import pool_categories
    from dynagrade.render.moodle import pool_xml

    exercise = _exercise((part,))
    export = pool_xml("Kinds", pool_categories([exercise], 1, "0" * 64)[0])
    types = [q.get("type") for q in ET.fromstring(export.xml).findall("question")
             if q.get("type") != "category"]
    expected = {"numeric": ["numerical"], "vector": ["cloze"], "choice": ["cloze"],
                "symbolic": []}[part.kind]
    assert types == expected
    assert bool(export.notices) == (part.kind == "symbolic")


def _required(kind) -> dict:
    return {"options": ("a", "b")} if kind is Options else {}


def _exercise(parts) -> Exercise:
    from dynagrade.exercise import Constant

    return Exercise(id="kinds", title="Kinds", source="Example 1.1",
                    params=(Constant("v0", 10.0, unit="m/s", symbol="v_0"),),
                    statement="A speed $v_0 = {{ v0 }}$.",
                    solve=lambda p: {"v": p.v0, "r": (p.v0, 0.0), "c": "a"}, parts=parts)


def test_the_fill_in_file_states_the_points_the_printed_sheet_shows():
    """An exercise whose parts carry 2 and 1 points, in an exam worth 6: the sheet prints
    4 and 2 points, and so must the fill-in file (it used to print "(2 points)")."""
    exercise = _exercise((Numeric("v", "speed", points=2, unit="m/s"),
                          Vector("r", "position", points=1, unit="m")))
    variant = exercise.variant(1)
    text = write_sheet(exercise, variant, "s1", points={"v": 4.0, "r": 2.0})
    assert "# speed: a number in m/s (4 points)" in text
    assert "# position: a vector of 2 components in m (2 points)" in text
    third = write_sheet(exercise, variant, "s1", points={"v": 8 / 3, "r": 4 / 3})
    assert "(2.6667 points)" in third and "(1.3333 points)" in third
    practice = write_sheet(exercise, variant, "s1")
    assert "(2 points)" in practice and "(1 point)" in practice
    assert parse_sheet(text).answers == {"v": None, "r": None}


def test_a_generated_exam_prints_the_same_points_on_sheet_fill_in_file_and_key(tmp_path, bank,
                                                                          exam_toml):
    """car-in-a-looping has parts of 2, 1, 1, 1, 1, 1 points and 8 points in the exam,
    split in hundredths by largest remainder: shares 2.2857 and 1.1429 cut to 2.28 and
    1.14 (7.98), the two hundredths left going to the largest remainders (the first part,
    then the first of the tied others): 2.29, 1.15, 1.14, 1.14, 1.14, 1.14 on the sheet,
    in the fill-in file and in the key."""
    from dynagrade.generation.generate import generate_exam

    exam = tmp_path / "exam.toml"
    exam.write_text(exam_toml, encoding="utf-8")
    roster = tmp_path / "roster.csv"
    roster.write_text("student_id,name\na,A\n", encoding="utf-8")
    generate_exam(exam, roster, tmp_path / "out", bank=bank, jobs=1, pdf=False)
    folder = tmp_path / "out" / "students" / "a"
    fill_in = (folder / "car-in-a-looping.py").read_text(encoding="utf-8")
    sheet = (folder / "sheet.md").read_text(encoding="utf-8")
    assert "(2.29 points)" in fill_in and "— 2.29 points" in sheet
    assert "(1.15 points)" in fill_in and "— 1.15 points" in sheet
    assert fill_in.count("(1.14 points)") == 4 and sheet.count("— 1.14 points") == 4
    key = (tmp_path / "out" / "key.csv").read_text(encoding="utf-8").splitlines()
    looping = [line.rsplit(",", 1)[1] for line in key if ",car-in-a-looping," in line]
    assert looping == ["2.29", "1.15"] + ["1.14"] * 4  # the key prints points the same way


@pytest.mark.parametrize("part, value, typed, shown", [
    (Numeric("v", unit="km/h"), 45.0, "45", "45 km/h"),
    (Vector("r", unit="m", size=2), (1.5, -0.25), "[1.5, -0.25]", "[1.5, -0.25] m"),
    (Symbolic("f", expected="v0*t"), "v0*t", "v0*t", "v0*t"),
    (Options("c", options=("a", "b", "c"), multiple=True), ("a", "c"), "a, c", "a, c"),
])
def test_each_kind_writes_its_answer_as_a_student_types_it_and_a_person_reads_it(
        part, value, typed, shown):
    assert part.answer_text(value) == typed
    assert part.shown_answer(value) == shown


def test_near_misses_are_the_wrong_answers_each_kind_must_refuse():
    assert Numeric("v").near_misses(2.0) == [("2.1", "an answer 5 % too large")]
    assert Numeric("v").near_misses(0.0) == []
    assert Vector("r").near_misses((2.0, -4.0)) == [("[2.1, -4.2]", "a vector 5 % too long")]
    assert Symbolic("f", expected="g*t").near_misses("g*t") == [("1.05*(g*t)",
                                                                 "the formula times 1.05")]
    single = Options("c", options=("a", "b", "c"))
    assert single.near_misses("b") == [("a", "option 'a'"), ("c", "option 'c'")]
    several = Options("c", options=("a", "b", "c"), multiple=True)
    assert several.near_misses(("a", "c")) == [("a", "a different set of options")]
    assert several.near_misses(("a",)) == [("a, b", "a different set of options")]


def test_input_hooks_give_a_placeholder_and_the_options_to_pick_from():
    assert Numeric("v", unit="m").input_hint() == ""
    assert Vector("r", size=3).input_hint() == "3 components"
    options = Options("c", options=("a", "b"))
    assert options.input_hint() == "one of a, b" and options.input_options() == ("a", "b")
    assert Numeric("v").input_options() == ()


def test_a_part_line_too_long_for_a_fill_in_file_is_cut_at_a_word():
    label = "the horizontal distance from the launch point " * 6
    line = Numeric("x", label, unit="m", question=1).describe(2)
    assert len(line) <= 240 and line.endswith(" [...]")
    assert line.startswith("question 1, the horizontal distance from the launch point")
    assert Numeric("x", "a  label\twith\nbreaks", unit="m").describe(1) == \
        "a label with breaks: a number in m (1 point)"


_TEXTS = st.lists(st.sampled_from(["word", "a-b", " ", "  ", "\t", "\n", "\xa0", "x" * 50,
                                   "é", "[...]", "-", "(2 points)"]),
                  max_size=40).map("".join)


@settings(max_examples=300, deadline=None)
@given(_TEXTS, st.sampled_from([12, 40, 240]))
def test_a_shortened_line_is_what_textwrap_shorten_gives(text, width):
    assert shortened(text, width) == textwrap.shorten(text, width)
