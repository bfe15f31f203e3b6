"""A course's own relations beside its exercise files (issue 31, item 4): the example
course in ``examples/course/`` (a conical pendulum whose keys come from the course's
``_relations`` package, tested there against Newton's law on the circle) is verified,
shown and tested as an outside instructor would, and two courses' ``_relations`` never
meet."""

from __future__ import annotations

import shutil
import subprocess
import sys
from pathlib import Path

import pytest
from click.testing import CliRunner

from dynagrade.cli import main
from dynagrade.exercise import load_file, open_bank
from dynagrade.exercise.loader import exercise_files

EXAMPLE = Path(__file__).resolve().parents[1] / "examples" / "course"


@pytest.fixture
def course(tmp_path) -> Path:
    """A copy of the example course folder."""
    folder = tmp_path / "course"
    shutil.copytree(EXAMPLE, folder, ignore=shutil.ignore_patterns("__pycache__"))
    return folder


def test_verify_and_show_use_the_courses_own_relations(course):
    runner = CliRunner()
    verified = runner.invoke(main, ["--exercises", str(course), "verify", "conical-pendulum",
                                    "--variants", "60"])
    assert verified.exit_code == 0, verified.output
    assert "ok    conical-pendulum: 60 variants" in verified.output
    shown = runner.invoke(main, ["--exercises", str(course), "show", "conical-pendulum",
                                 "--set", "L=1", "--set", "theta=60", "--set", "m=2",
                                 "--answers"])
    assert shown.exit_code == 0, shown.output
    # L = 1 m, theta = 60 deg: omega = sqrt(9.81/0.5) = 4.42945 rad/s, S = 2*9.81/0.5 = 39.24 N
    assert "4.42945 rad/s" in shown.output and "39.24 N" in shown.output


def test_the_courses_relations_pass_the_tests_beside_them(course):
    # the instructor's command, run in the course folder: pytest _relations
    run = subprocess.run([sys.executable, "-m", "pytest", "-q", "-p", "no:cacheprovider",
                          "_relations"], cwd=course, capture_output=True, text=True,
                         timeout=120)
    assert run.returncode == 0, run.stdout + run.stderr
    assert "4 passed" in run.stdout


def test_a_relation_that_breaks_its_route_fails_the_courses_tests(course):
    relations = course / "_relations" / "__init__.py"
    relations.write_text(relations.read_text(encoding="utf-8").replace(
        "m * g / np.cos(theta)", "m * g * np.cos(theta)"), encoding="utf-8")
    run = subprocess.run([sys.executable, "-m", "pytest", "-q", "-p", "no:cacheprovider",
                          "_relations"], cwd=course, capture_output=True, text=True,
                         timeout=120)
    assert run.returncode == 1 and "failed" in run.stdout


def test_the_courses_modules_are_no_exercise_files(course):
    assert [p.name for p in exercise_files(course)] == ["conical_pendulum.py"]


def test_two_courses_each_with_relations_of_one_name_keep_their_own(tmp_path):
    # course a has the package _relations/, course b a module _relations.py whose tension
    # is twice a's (a string doubled over): loaded side by side, each exercise uses its own
    a, b = tmp_path / "a", tmp_path / "b"
    shutil.copytree(EXAMPLE, a, ignore=shutil.ignore_patterns("__pycache__"))
    b.mkdir()
    (b / "_relations.py").write_text(
        (EXAMPLE / "_relations" / "__init__.py").read_text(encoding="utf-8").replace(
            "return m * g / np.cos(theta)", "return 2 * m * g / np.cos(theta)"),
        encoding="utf-8")
    (b / "doubled.py").write_text(
        (EXAMPLE / "conical_pendulum.py").read_text(encoding="utf-8")
        .replace('id="conical-pendulum"', 'id="doubled-string"')
        .replace('Recompute("S", lambda p, s: p.m', 'Recompute("S", lambda p, s: 2 * p.m'),
        encoding="utf-8")
    path_before, modules_before = list(sys.path), set(sys.modules)
    bank = open_bank([a, b])
    settings = {"m": 2, "L": 1, "theta": 60}
    single = bank.get("conical-pendulum").variant_set(0, settings).answers["S"]
    doubled = bank.get("doubled-string").variant_set(0, settings).answers["S"]
    assert (single, doubled) == (pytest.approx(39.24), pytest.approx(78.48))
    # nothing went on sys.path, no top-level _relations exists, and each folder's module
    # is its own (a's package, b's file)
    assert sys.path == path_before and "_relations" not in sys.modules
    loaded = {name: sys.modules[name].__file__ for name in set(sys.modules) - modules_before
              if name.endswith("._relations")}
    assert sorted(Path(f).relative_to(tmp_path).as_posix() for f in loaded.values()) == \
        ["a/_relations/__init__.py", "b/_relations.py"]


def test_an_absolute_import_of_a_course_module_is_not_found(tmp_path):
    # the folder is never on sys.path: "import _relations" cannot find the course's file,
    # so no course file can shadow a library either; the error names the file and line
    shutil.copytree(EXAMPLE, tmp_path / "c", ignore=shutil.ignore_patterns("__pycache__"))
    path = tmp_path / "c" / "conical_pendulum.py"
    path.write_text(path.read_text(encoding="utf-8").replace(
        "from ._relations import", "from _relations import"), encoding="utf-8")
    with pytest.raises(Exception, match=r"conical_pendulum\.py, line \d+: "
                                        r"ModuleNotFoundError: No module named '_relations'"):
        load_file(path)


def test_the_authoring_guide_shows_the_example_courses_code():
    # every code block of the guide's section that names an example file is in that file
    import re

    guide = (Path(__file__).resolve().parents[1] / "docs" / "authoring.md").read_text("utf-8")
    section = guide[guide.index("### Your course's own relations"):guide.index("## Parts")]
    blocks = re.findall(r"```python\n# (\S+)\n(.*?)```", section, re.S)
    assert [name for name, _ in blocks] == ["_relations/__init__.py",
                                            "_relations/test_relations.py",
                                            "conical_pendulum.py"]
    for name, code in blocks:
        assert code in (EXAMPLE / name).read_text(encoding="utf-8"), name
