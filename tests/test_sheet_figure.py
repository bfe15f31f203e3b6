"""`dynagrade sheet -o FILE` writes the exercise's figure beside the fill-in file, as
`<exercise-id>.svg`, names it in the file's header, and it is the drawing an exam shows.
(The exam's fill-in files: tests/test_exam_generate.py.)"""

from __future__ import annotations

from click.testing import CliRunner

from dynagrade.cli import main
from dynagrade.exercise import open_bank
from dynagrade.exercise.seeds import student_seed
from dynagrade.exercise.sheet import parse_sheet
from dynagrade.render.figures import figure_svg

BANK = open_bank()


def _sheet(tmp_path, exercise_id, *extra):
    path = tmp_path / "answers" / "mine.py"
    path.parent.mkdir()
    result = CliRunner().invoke(main, ["sheet", exercise_id, "--student", "s-7", "-o",
                                       str(path), *extra])
    assert result.exit_code == 0, result.output
    return path, result


def test_sheet_writes_the_figure_beside_the_file_and_names_it(tmp_path):
    path, result = _sheet(tmp_path, "crank-slider-velocity")
    figure = path.parent / "crank-slider-velocity.svg"
    exercise = BANK.get("crank-slider-velocity")
    variant = exercise.variant(student_seed(exercise.id, "s-7"))
    assert figure.read_text(encoding="utf-8") == figure_svg(exercise, variant)
    text = path.read_text(encoding="utf-8")
    header = text.split('"""')[1]
    assert "Figure: crank-slider-velocity.svg, in the folder of this file." in header
    assert sorted(p.name for p in path.parent.iterdir()) == ["crank-slider-velocity.svg",
                                                              "mine.py"]
    # the header line is part of the docstring: the file still reads as the same sheet
    sheet = parse_sheet(text)
    assert (sheet.exercise_id, sheet.seed) == (exercise.id, variant.seed)


def test_sheet_of_an_exercise_without_a_figure_writes_the_file_alone(tmp_path):
    path, _ = _sheet(tmp_path, "frictional-sliding-stop")
    assert BANK.get("frictional-sliding-stop").figure is None
    assert [p.name for p in path.parent.iterdir()] == ["mine.py"]
    assert "Figure:" not in path.read_text(encoding="utf-8")


def test_sheet_printed_says_how_to_get_the_figure(tmp_path):
    result = CliRunner().invoke(main, ["sheet", "crank-slider-velocity", "--student", "s-7"])
    assert result.exit_code == 0
    assert "Figure:" not in result.stdout
    assert "write the sheet with -o FILE" in result.stderr


EXAM_TOML = """\
id = "figure-beside-test"
title = "Figures beside fill-in files"
date = 2025-04-14

[[exercise]]
id = "crank-slider-velocity"
points = 4
"""


def test_the_server_shows_the_figure_beside_the_fill_in_file_and_of_older_exams(tmp_path):
    from dynagrade.generation.generate import generate_exam
    from dynagrade.render.figures import inline_svg
    from dynagrade.serve.exam_data import ExamData

    (tmp_path / "exam.toml").write_text(EXAM_TOML, encoding="utf-8")
    (tmp_path / "roster.csv").write_text("student_id,name\ns-1,Ada\n", encoding="utf-8")
    generate_exam(tmp_path / "exam.toml", tmp_path / "roster.csv", tmp_path / "out",
                  pdf=False, jobs=1, secret="5e" * 32)
    folder = tmp_path / "out" / "students" / "s-1"
    drawn = (folder / "crank-slider-velocity.svg").read_text(encoding="utf-8")
    data = ExamData(tmp_path / "out" / "manifest.json", BANK)
    shown = inline_svg(drawn, "figure-crank-slider-velocity-")
    assert data.figure_svg("s-1", "crank-slider-velocity") == shown
    # an exam generated before the figure moved beside the file kept it in figures/
    (folder / "figures").mkdir()
    (folder / "crank-slider-velocity.svg").rename(folder / "figures" / "crank-slider-velocity.svg")
    assert data.figure_svg("s-1", "crank-slider-velocity") == shown
    (folder / "figures" / "crank-slider-velocity.svg").unlink()
    assert data.figure_svg("s-1", "crank-slider-velocity") is None
