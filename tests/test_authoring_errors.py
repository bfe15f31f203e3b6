"""What an exercise author gets wrong is reported on one line naming the file and line,
by every command that looks at the bank, never as a traceback and never in silence:
a file that defines no exercise, an id that is not kebab-case, two files with one id,
a Symbolic formula naming an unknown variable; a figure that raises, that shows an
answer or that is not well formed SVG."""

from __future__ import annotations

import re
import textwrap
from pathlib import Path

import pytest
from click.testing import CliRunner

from dynagrade.cli import grade_main, main

EXERCISE_FILE = textwrap.dedent('''\
    from dynagrade.exercise import Exercise, Numeric, Uniform
    {draw}
    EXERCISE = Exercise(
        id="{id}", title="An exercise", source="Example 1.1",
        params=(Uniform("x", 1, 2, step=0.25, unit="m"),),
        statement="The length is x = {{{{ x }}}}.",
        solve=lambda p: {{"y": 2 * p.x}},
        parts=(Numeric("y", unit="m"),),{figure}
    )
''')  # without a figure: the Exercise(...) call is on line 3, its id on line 4

DRAW = textwrap.dedent('''\
    from dynagrade.exercise.figure import arrow, new_drawing


    def draw(p):
        figure, axes = new_drawing()
        arrow(axes, (0, 0), (p.x, 0), "x = {{x}} m".format(x=p.x))
        {body}
        return figure

''')  # in the exercise file: "def draw" on line 5, the body on line 8


def exercise_file(exercise_id: str, figure_body: str | None = None) -> str:
    """An exercise file of one parameter x and one answer y = 2 x; with ``figure_body``,
    a figure that labels x and then runs that line."""
    if figure_body is None:
        return EXERCISE_FILE.format(id=exercise_id, draw="", figure="")
    draw = DRAW.format(body=figure_body).rstrip("\n") + "\n\n"
    return EXERCISE_FILE.format(id=exercise_id, draw=draw, figure="\n    figure=draw,")


UNKNOWN_NAME = textwrap.dedent('''\
    from dynagrade.exercise import Exercise, Numeric, Symbolic, Uniform

    EXERCISE = Exercise(
        id="unknown-name", title="Unknown name", source="Example 1.1",
        params=(Uniform("x", 1, 2, step=0.5, unit="m"),),
        statement="The length is x = {{ x }}. 1. Find y. 2. Give y as a formula in x.",
        solve=lambda p: {"y": 2 * p.x},
        parts=(
            Numeric("y", unit="m"),
            Symbolic("y_formula", expected="2*x*k", variables=("x",)),
        ),
    )
''')  # the part y_formula is written on line 10, and k is no variable of it

RAISING = exercise_file("raising-figure", "axes.plot(p.nothing)")
NO_FIGURE = exercise_file("no-figure", "figure = None")
CONTROL_CHARACTER = exercise_file("control-figure", 'axes.text(0, 1, "a\\x01b")')
TELLING = exercise_file("telling-figure", 'axes.text(0, 1, "y = {y:g} m".format(y=2 * p.x))')


@pytest.fixture
def run():
    runner = CliRunner()

    def invoke(command, *args):
        return runner.invoke(command, [str(a) for a in args])

    return invoke


def _error_line(result) -> str:
    """The one line of a command that failed cleanly: exit status 1, no exception
    escaping, a single ``Error: ...`` line."""
    assert result.exit_code == 1, result.output
    assert result.exception is None or isinstance(result.exception, SystemExit), \
        result.exception
    assert "Traceback" not in result.output
    errors = [line for line in result.output.splitlines() if line.startswith("Error: ")]
    assert len(errors) == 1, result.output
    return errors[0]


def _folder(tmp_path, **files) -> Path:
    """An exercise folder with a good exercise beside the given files."""
    (tmp_path / "fine.py").write_text(exercise_file("fine-exercise"), encoding="utf-8")
    for name, text in files.items():
        (tmp_path / f"{name}.py").write_text(text, encoding="utf-8")
    return tmp_path


def _exam_files(tmp_path, exercise_id):
    exam = tmp_path.parent / f"{tmp_path.name}-exam.toml"
    exam.write_text(f'id = "q"\ntitle = "Q"\ndate = 2025-01-01\n[[exercise]]\n'
                    f'id = "{exercise_id}"\npoints = 2\n', encoding="utf-8")
    roster = tmp_path.parent / f"{tmp_path.name}-roster.csv"
    roster.write_text("student_id,name\ns1,Ada\ns2,Bea\n", encoding="utf-8")
    return exam, roster


def _every_command(run, folder, tmp_path, exercise_id="fine-exercise"):
    """The results of ``list``, ``show``, ``verify``, ``exam``, ``grade FILE`` (both
    spellings) with ``folder`` on the search path, each asked about ``exercise_id`` (the
    fill-in file graded is ``sheet.py`` beside ``folder``, made before it broke)."""
    exam, roster = _exam_files(tmp_path, exercise_id)
    out = tmp_path.parent / f"{tmp_path.name}-out"
    sheet = _sheet(tmp_path)
    return {
        "list": run(main, "--exercises", folder, "list"),
        "show": run(main, "--exercises", folder, "show", exercise_id),
        "verify": run(main, "--exercises", folder, "verify", "--variants", 2),
        "exam": run(main, "--exercises", folder, "exam", exam, "--roster", roster,
                    "-o", out, "--no-pdf", "--jobs", 1),
        "grade": run(main, "--exercises", folder, "grade", sheet),
        "grade FILE": run(grade_main, sheet, "--exercises", folder),
    }


def _sheet(tmp_path):
    return tmp_path.parent / f"{tmp_path.name}-sheet.py"


def _make_sheet(run, folder, tmp_path, exercise_id):
    made = run(main, "--exercises", folder, "sheet", exercise_id, "--student", "s1",
               "-o", _sheet(tmp_path))
    assert made.exit_code == 0, made.output


# -- the loader ---------------------------------------------------------------------------


def test_a_file_that_defines_no_exercise_is_named_by_every_command(run, tmp_path):
    _make_sheet(run, _folder(tmp_path), tmp_path, "fine-exercise")
    folder = _folder(tmp_path, notes="RATIO = 2\n")
    for command, result in _every_command(run, folder, tmp_path).items():
        line = _error_line(result)
        assert f"{folder / 'notes.py'}: defines no EXERCISE" in line, command
        assert "name starting with '_'" in line, command


@pytest.mark.parametrize("bad_id", ["Fine_Exercise", "fine--exercise"])
def test_an_id_that_is_not_kebab_case_is_named_with_its_file_and_line(run, tmp_path,
                                                                       bad_id):
    _make_sheet(run, _folder(tmp_path), tmp_path, "fine-exercise")
    folder = _folder(tmp_path, shouting=exercise_file(bad_id))
    for command, result in _every_command(run, folder, tmp_path).items():
        line = _error_line(result)
        # the frame in the file is the Exercise(...) call, on line 3
        assert f"{folder / 'shouting.py'}, line 3: exercise id '{bad_id}' is not " \
               "kebab-case" in line, command


def test_two_files_with_one_id_are_both_named_with_their_lines(run, tmp_path):
    _make_sheet(run, _folder(tmp_path), tmp_path, "fine-exercise")
    folder = _folder(tmp_path, copy=exercise_file("fine-exercise"))
    for command, result in _every_command(run, folder, tmp_path).items():
        line = _error_line(result)
        assert f"exercise id 'fine-exercise' is declared by both {folder / 'copy.py'}, " \
               f"line 4 and {folder / 'fine.py'}, line 4" in line, command


def test_an_unknown_name_in_an_expected_formula_is_named_with_its_part_and_line(
        run, tmp_path):
    readable = _folder(tmp_path, formula=UNKNOWN_NAME.replace("2*x*k", "2*x"))
    _make_sheet(run, readable, tmp_path, "unknown-name")
    folder = _folder(tmp_path, formula=UNKNOWN_NAME)
    results = _every_command(run, folder, tmp_path, "unknown-name")
    for command, result in results.items():
        line = _error_line(result)
        assert f"{folder / 'formula.py'}, line 10: exercise 'unknown-name', part " \
               "'y_formula': the expected formula '2*x*k' cannot be read" in line, command
        assert "'k'" in line, command


MISCONCEIVED = UNKNOWN_NAME.replace(
    'expected="2*x*k"', 'expected="2*x", misconceptions=(Misconception("half", "x/q", '
    '"half of it"),)').replace("Exercise, Numeric,", "Exercise, Misconception, Numeric,")
COMPUTED_VARIABLES = UNKNOWN_NAME.replace('variables=("x",)', 'variables=tuple("x")')


@pytest.mark.parametrize("text, what", [
    (MISCONCEIVED, "misconception 'half' 'x/q'"),
    (COMPUTED_VARIABLES, "expected formula '2*x*k'")])
def test_list_and_the_loader_name_an_unreadable_formula_however_it_is_written(
        run, tmp_path, text, what):
    # the listing reads a misconception's formula from the text; variables computed by
    # the file make list load the file, which checks the formula all the same
    from dynagrade.exercise import ExerciseFileError, load_file

    folder = _folder(tmp_path, formula=text)
    expected = f"{folder / 'formula.py'}, line 10: exercise 'unknown-name', part " \
               f"'y_formula': the {what} cannot be read"
    assert expected in _error_line(run(main, "--exercises", folder, "list"))
    with pytest.raises(ExerciseFileError) as error:
        load_file(folder / "formula.py")
    assert expected in str(error.value)


def test_helper_modules_and_init_files_are_tolerated(run, tmp_path):
    folder = _folder(tmp_path, _shared="RATIO = 2\n", __init__="")
    (folder / "sub").mkdir()
    (folder / "sub" / "__init__.py").write_text("", encoding="utf-8")
    result = run(main, "--exercises", folder, "list", "--json")
    assert result.exit_code == 0, result.output
    assert "fine-exercise" in result.output


# -- figures ------------------------------------------------------------------------------


def test_verify_names_the_exercise_file_line_and_seed_of_a_figure_that_raises(
        run, tmp_path):
    folder = _folder(tmp_path, raising=RAISING)
    result = run(main, "--exercises", folder, "verify", "raising-figure", "--variants", 2,
                 "--allow-missing-solutions")
    assert result.exit_code == 1 and result.exception is None or \
        isinstance(result.exception, SystemExit)
    assert "Traceback" not in result.output
    for seed in (0, 1):
        assert f"{folder / 'raising.py'}, line 8: exercise 'raising-figure', seed {seed}: " \
               "the figure fails: AttributeError" in result.output


def test_an_exam_with_a_figure_that_raises_stops_with_one_line(run, tmp_path):
    folder = _folder(tmp_path, raising=RAISING)
    exam, roster = _exam_files(tmp_path, "raising-figure")
    for jobs in (1, 2):
        result = run(main, "--exercises", folder, "exam", exam, "--roster", roster,
                     "-o", tmp_path.parent / f"{tmp_path.name}-out{jobs}", "--no-pdf",
                     "--jobs", jobs)
        line = _error_line(result)
        assert f"Error: {folder / 'raising.py'}, line 8: exercise 'raising-figure', seed " \
            in line
        assert "the figure fails: AttributeError" in line


def test_show_figure_of_a_figure_that_raises_is_one_line(run, tmp_path):
    folder = _folder(tmp_path, raising=RAISING)
    result = run(main, "--exercises", folder, "show", "raising-figure", "--seed", 3,
                 "--figure", tmp_path / "f.svg")
    assert f"{folder / 'raising.py'}, line 8: exercise 'raising-figure', seed 3: the " \
           "figure fails" in _error_line(result)


def test_verify_fails_a_figure_that_shows_a_reference_answer(run, tmp_path):
    folder = _folder(tmp_path, telling=TELLING)
    result = run(main, "--exercises", folder, "verify", "telling-figure", "--variants", 3,
                 "--allow-missing-solutions")
    assert result.exit_code == 1
    # seeds 0, 1, 2 draw x = 2, 1.5, 2 m (checked below), so the answer y = 2 x is 4, 3, 4
    from dynagrade.exercise import open_bank

    exercise = open_bank([folder]).get("telling-figure")
    xs = [exercise.variant(seed).params["x"] for seed in range(3)]
    for seed, x in enumerate(xs):
        assert f"seed {seed}: the figure shows the reference answer {2 * x:g}; a figure " \
               "may label given values only" in result.output


def test_verify_passes_a_figure_that_labels_given_values_only(run, tmp_path):
    folder = _folder(tmp_path, plain=exercise_file("plain-figure", "pass"))
    result = run(main, "--exercises", folder, "verify", "plain-figure", "--variants", 3,
                 "--allow-missing-solutions")
    assert result.exit_code == 0, result.output
    assert "1 of 1 exercises passed" in result.output


def test_a_figure_that_fails_outside_the_exercise_file_is_named_at_its_def_line(
        run, tmp_path):
    # a figure function that returns no figure fails where the figure is rendered, in
    # dynagrade's code: the line named is the one of "def draw" (line 5)
    folder = _folder(tmp_path, no_figure=NO_FIGURE)
    assert NO_FIGURE.splitlines()[4] == "def draw(p):"
    result = run(main, "--exercises", folder, "verify", "no-figure", "--variants", 1,
                 "--allow-missing-solutions")
    assert result.exit_code == 1 and "Traceback" not in result.output
    assert f"{folder / 'no_figure.py'}, line 5: exercise 'no-figure', seed 0: the " \
           "figure fails: AttributeError" in result.output


def test_a_label_with_a_control_character_makes_svg_that_is_not_well_formed(run, tmp_path):
    # XML 1.0 allows no U+0001 in text, even escaped: the SVG's description carries it
    folder = _folder(tmp_path, control=CONTROL_CHARACTER)
    result = run(main, "--exercises", folder, "verify", "control-figure", "--variants", 1,
                 "--allow-missing-solutions")
    assert result.exit_code == 1
    assert "seed 0: the figure is not well formed SVG: not well-formed (invalid token)" \
        in result.output


def test_a_figure_that_is_not_well_formed_svg_fails_verify(tmp_path):
    from dynagrade.exercise import open_bank
    from dynagrade.exercise.verify import verify_exercise

    folder = _folder(tmp_path, plain=exercise_file("plain-figure", "pass"))
    exercise = open_bank([folder]).get("plain-figure")
    broken = verify_exercise(exercise, range(1),
                             render_figure=lambda e, v: "<svg><g></svg>")
    # the closing tag's name starts at offset 10 of the line (counted from 0): </svg>
    # closes the <g> opened at offset 5
    assert broken.failures == ["seed 0: the figure is not well formed SVG: "
                               "mismatched tag: line 1, column 10"]
    html = verify_exercise(exercise, range(1), render_figure=lambda e, v: "<html/>")
    assert html.failures == ["seed 0: the figure's root element is <html>, not <svg>"]


# -- show --figure ------------------------------------------------------------------------


def test_show_writes_the_figure_of_the_seed_or_the_students_variant(run, tmp_path, bank):
    from dynagrade.exercise.seeds import student_seed
    from dynagrade.render.figures import figure_svg

    exercise = bank.get("car-in-a-looping")
    by_seed = tmp_path / "seed.svg"
    result = run(main, "show", "car-in-a-looping", "--seed", 4, "--figure", by_seed)
    assert result.exit_code == 0, result.output
    assert by_seed.read_text(encoding="utf-8") == figure_svg(exercise, exercise.variant(4))
    by_student = tmp_path / "student.svg"
    result = run(main, "show", "car-in-a-looping", "--student", "s7", "--figure", by_student)
    assert result.exit_code == 0, result.output
    seed = student_seed("car-in-a-looping", "s7")
    assert by_student.read_text(encoding="utf-8") == \
        figure_svg(exercise, exercise.variant(seed))
    # the looping's radius R of that variant is what the figure labels
    radius = exercise.variant(seed).params["R"]
    assert f"R = {radius:g} m" in by_student.read_text(encoding="utf-8")


def test_show_figure_of_an_exercise_without_one_is_an_error(run, tmp_path, bank):
    plain = next(e.id for e in bank.listing() if not e.figured)
    result = run(main, "show", plain, "--figure", tmp_path / "f.svg")
    assert f"{plain} draws no figure" in _error_line(result)
    assert not (tmp_path / "f.svg").exists()


BROKEN_SOLVER = '''\
from dynagrade.exercise import Exercise, Numeric, Uniform


def solve(p):
    return {"v": 1.0 / (p.a - p.a)}


EXERCISE = Exercise(
    id="broken-solver", title="Broken", source="Example 1.1", topics=("test",),
    params=[Uniform("a", 1, 2, step=1, unit="m")],
    statement="a = {{ a }}",
    solve=solve,
    parts=[Numeric("v", "speed", unit="m/s", points=1)],
)
'''


@pytest.mark.parametrize("command", [
    ["show", "broken-solver", "--seed", "7"],
    ["verify", "broken-solver", "--variants", "2"],
    ["exam", "{folder}/exam.toml", "--roster", "{folder}/roster.csv", "-o", "{folder}/out",
     "--no-pdf"],
])
def test_a_solver_that_raises_is_one_line_naming_file_exercise_and_seed(tmp_path, command):
    """A solver that fails for a variant once gave a traceback from ``dynagrade exam``;
    each command now says on one line where (file and line), which exercise and which
    seed, as it does for a failing figure."""
    folder = tmp_path / "bank"
    folder.mkdir()
    (folder / "broken.py").write_text(BROKEN_SOLVER, encoding="utf-8")
    (folder / "exam.toml").write_text('id = "e"\ntitle = "E"\ndate = 2025-04-14\n'
                                      '[[exercise]]\nid = "broken-solver"\npoints = 1\n',
                                      encoding="utf-8")
    (folder / "roster.csv").write_text("student_id,name\ns1,A\n", encoding="utf-8")
    args = ["--exercises", str(folder), *(a.format(folder=folder) for a in command)]
    result = CliRunner().invoke(main, args)
    assert result.exit_code != 0
    assert "Traceback" not in result.output
    lines = [line for line in result.output.splitlines() if "the solver fails" in line]
    assert lines, result.output
    for line in lines:
        assert re.search(rf"{re.escape(str(folder / 'broken.py'))}, line 5: exercise "
                         r"'broken-solver', seed \d+: the solver fails: ZeroDivisionError: "
                         r"float division by zero$", line.strip().removeprefix("Error: ")), line
