"""Naming exercise folders: ``--exercises`` before or after any subcommand,
``$DYNAGRADE_EXERCISES``, and the project file ``dynagrade.toml`` with its defaults.
Precedence: command line > environment > file > built-in."""

from __future__ import annotations

import pytest
from click.testing import CliRunner

from dynagrade.cli import grade_main, main
from dynagrade.config import ConfigError, find_project_file, load_project, read_project
from dynagrade.exercise.loader import ENVIRONMENT_VARIABLE

TINY = '''
from dynagrade.exercise import Exercise, Numeric, Uniform

EXERCISE = Exercise(
    id="tiny", title="{title}", source="Section 1.1",
    params=(Uniform("x", 1, 9, step=1, unit="m"),),
    statement="Twice $x$ = {{{{ x }}}}?",
    solve=lambda p: {{"y": 2 * p.x}},
    parts=(Numeric("y", "twice x", unit="m"),),
)
'''


def _folder(root, name: str, title: str):
    folder = root / name
    folder.mkdir(parents=True)
    (folder / "tiny.py").write_text(TINY.format(title=title), encoding="utf-8")
    return folder


@pytest.fixture
def project(tmp_path, monkeypatch):
    """A project folder with ``dynagrade.toml`` naming its folder ``from-file``; the
    commands run two folders below it, with no ``$DYNAGRADE_EXERCISES``."""
    _folder(tmp_path, "from-file", "File's")
    (tmp_path / "dynagrade.toml").write_text('exercises = ["from-file"]\n', encoding="utf-8")
    work = tmp_path / "a" / "b"
    work.mkdir(parents=True)
    monkeypatch.chdir(work)
    monkeypatch.delenv(ENVIRONMENT_VARIABLE, raising=False)
    return tmp_path


def _run(*args, command=main):
    return CliRunner().invoke(command, [str(a) for a in args])


def _title(*args) -> str:
    result = _run(*args)
    assert result.exit_code == 0, result.output
    return result.output


# -- where exercises are found ------------------------------------------------------------


def test_the_project_file_is_found_upward_and_its_folders_are_relative_to_it(project):
    assert find_project_file() == project / "dynagrade.toml"
    assert load_project().exercises == ((project / "from-file").resolve(),)
    assert "File's" in _title("show", "tiny", "--seed", 1)


def test_without_a_project_file_there_is_nothing_to_read(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    if find_project_file() is None:  # no dynagrade.toml above the temporary folder
        assert load_project().exercises == () and load_project().defaults() == {}


def test_the_environment_wins_over_the_file(project, monkeypatch):
    monkeypatch.setenv(ENVIRONMENT_VARIABLE, str(_folder(project, "from-env", "Env's")))
    assert "Env's" in _title("show", "tiny")


def test_the_command_line_wins_over_the_environment_before_or_after_the_subcommand(
        project, monkeypatch):
    monkeypatch.setenv(ENVIRONMENT_VARIABLE, str(_folder(project, "from-env", "Env's")))
    mine = _folder(project, "from-cli", "Command line's")
    assert "Command line's" in _title("--exercises", mine, "show", "tiny")
    assert "Command line's" in _title("show", "tiny", "--exercises", mine)


def test_folders_before_the_subcommand_come_before_those_after_it(project):
    first = _folder(project, "first", "First")
    second = _folder(project, "second", "Second")
    assert "First" in _title("--exercises", first, "show", "--exercises", second, "tiny")


def test_grade_reads_the_project_file_and_takes_exercises_after_the_file(project, tmp_path):
    sheet = tmp_path / "a" / "b" / "tiny-sheet.py"
    result = _run("sheet", "tiny", "--student", "s1", "-o", sheet)
    assert result.exit_code == 0, result.output
    result = _run(sheet, command=grade_main)
    assert result.exit_code == 0, result.output
    assert "File's" in result.output
    mine = _folder(project, "from-cli", "Command line's")
    assert "Command line's" in _run(sheet, "--exercises", mine, command=grade_main).output


@pytest.mark.parametrize("subcommand", sorted(main.commands))
def test_every_subcommand_accepts_exercises_after_it(subcommand, tmp_path):
    result = _run(subcommand, "--exercises", tmp_path, "--help")
    assert result.exit_code == 0, result.output
    assert "--exercises" in result.output


# -- defaults -------------------------------------------------------------------------------


def test_the_file_sets_verify_variants_and_the_command_line_overrides_it(project):
    (project / "dynagrade.toml").write_text(
        'exercises = ["from-file"]\n[verify]\nvariants = 3\n', encoding="utf-8")
    assert "tiny: 3 variants" in _title("verify", "tiny", "--allow-missing-solutions")
    assert "tiny: 2 variants" in _title("verify", "tiny", "--allow-missing-solutions",
                                        "--variants", 2)


def test_the_file_sets_the_exams_output_folder_relative_to_itself(project):
    (project / "dynagrade.toml").write_text(
        'exercises = ["from-file"]\njobs = 1\n[exam]\noutput = "exam-out"\n'
        '[grade]\noutput = "graded"\n', encoding="utf-8")
    (project / "exam.toml").write_text('id = "t"\ntitle = "T"\ndate = 2025-01-01\n'
                                       '[[exercise]]\nid = "tiny"\npoints = 1\n')
    (project / "roster.csv").write_text("student_id,name\ns1,S One\n")
    result = _run("exam", project / "exam.toml", "--roster", project / "roster.csv",
                  "--no-pdf")
    assert result.exit_code == 0, result.output
    assert (project / "exam-out" / "manifest.json").is_file()
    # a grading folder from the file does not make grading one practice file an error
    sheet = project / "tiny-sheet.py"
    _run("sheet", "tiny", "--student", "s1", "-o", sheet)
    result = _run("grade", sheet)
    assert result.exit_code == 0, result.output


# -- a broken file is one line naming the file, the line and the key -------------------------


@pytest.mark.parametrize("text, message", [
    ('exercises = ["from-file"]\njobs = 0\n',
     "line 2, key 'jobs': must be a whole number of at least 1, got 0"),
    ('exercises = ["nowhere"]\n', "line 1, key 'exercises': the folder "),
    ('exercises = 3\n', "line 1, key 'exercises': must be a list of folders, got 3"),
    ('jobs = 2\n[exam]\nouptut = "out"\n',
     "line 3, key 'exam.ouptut': unknown key; the keys are output, secret_file"),
    ('[verify]\nvariants = "many"\n',
     "line 2, key 'verify.variants': must be a whole number of at least 1, got 'many'"),
    ('language = "de"\n', "line 1, key 'language': unknown key"),
    ('exam = 1\n', "line 1, key 'exam': must be a table ([exam])"),
    ('exercises = ["from-file"\n', "not valid TOML"),
])
def test_a_broken_project_file_is_one_line_naming_file_line_and_key(project, text, message):
    path = project / "dynagrade.toml"
    path.write_text(text, encoding="utf-8")
    with pytest.raises(ConfigError) as caught:
        read_project(path)
    assert str(caught.value).startswith(f"{path}")
    assert message in str(caught.value)
    result = _run("list")
    assert result.exit_code == 1
    assert result.output.strip().splitlines() == [f"Error: {caught.value}"]
