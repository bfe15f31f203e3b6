"""`grade FILE` and `dynagrade list` start fast because they import only what they use:
each is run in a fresh process that then lists the packages it imported. Grading a
practice sheet whose units are all common ones needs neither the templates (jinja2),
nor rich, nor pint's registry, nor sympy, scipy, matplotlib or typst; listing the bank
reads its files without running them, so it needs not even numpy. Every unit the bank's
parameters and parts use is one the grader knows without pint. (Their times are measured by
bench/grading.py, never here.)"""

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest
from click.testing import CliRunner

import dynagrade
from dynagrade.cli import main

#: where the dynagrade under test is imported from, for the fresh processes
SOURCE = Path(dynagrade.__file__).resolve().parent.parent
NOT_NEEDED = ("jinja2", "rich", "pint", "sympy", "scipy", "matplotlib", "mpmath", "typst")

RUN_AND_LIST_PACKAGES = """
import io, json, sys, contextlib
from dynagrade import cli
command, sys.argv = getattr(cli, sys.argv[1]), sys.argv[1:]
out = io.StringIO()
with contextlib.redirect_stdout(out):
    try:
        command()
    except SystemExit as stop:
        code = stop.code
print(json.dumps({"exit": code, "output": out.getvalue(),
                  "packages": sorted({name.partition(".")[0] for name in sys.modules})}))
"""


def _run_fresh(*args: str, cwd: Path) -> dict:
    """The exit status, output and imported top-level packages of a dynagrade command
    (``grade_main`` or ``main`` and its arguments) run in a fresh Python process."""
    env = dict(os.environ, PYTHONPATH=str(SOURCE))
    done = subprocess.run([sys.executable, "-c", RUN_AND_LIST_PACKAGES, *args],
                          capture_output=True, text=True, cwd=cwd, env=env, timeout=300)
    assert done.returncode == 0, done.stderr[-2000:]
    return json.loads(done.stdout.strip().splitlines()[-1])


@pytest.fixture
def answered_sheet(tmp_path) -> Path:
    """A practice sheet of projectile-range (units m and s only) with every part
    answered: three numbers and a formula."""
    sheet = tmp_path / "exercise.py"
    written = CliRunner().invoke(main, ["sheet", "projectile-range", "--student", "s1",
                                        "-o", str(sheet)])
    assert written.exit_code == 0, written.output
    text = sheet.read_text(encoding="utf-8")
    for name in ("x_max", "h_max", "t_flight"):
        text = text.replace(f"{name} = None", f'{name} = "12.5"')
    text = text.replace("x_max_formula = None", 'x_max_formula = "v0^2*sin(2*alpha)/g"')
    sheet.write_text(text, encoding="utf-8")
    return sheet


def test_grading_a_file_imports_no_template_engine_terminal_library_units_or_cas(
        answered_sheet):
    report = _run_fresh("grade_main", str(answered_sheet), cwd=answered_sheet.parent)
    assert report["exit"] == 0, report["output"]
    assert sorted(set(report["packages"]).intersection(NOT_NEEDED)) == []
    assert "x_max_formula  correct  1 / 1" in report["output"]
    assert "total 1 / 5" in report["output"]


def test_grading_an_exercise_with_a_parameter_in_gpa_loads_no_units_registry(tmp_path):
    # rod-struck-at-end's Young's modulus is in GPa, as in eight more exercises of the
    # bank: a unit outside the common ones that need no pint would load its registry
    # (half a second) for every variant drawn.
    sheet = tmp_path / "exercise.py"
    written = CliRunner().invoke(main, ["sheet", "rod-struck-at-end", "--student", "s1",
                                        "-o", str(sheet)])
    assert written.exit_code == 0, written.output
    report = _run_fresh("grade_main", str(sheet), cwd=tmp_path)
    assert report["exit"] == 0, report["output"]
    assert "pint" not in report["packages"]
    assert "total 0 / " in report["output"]  # nothing answered yet


def test_listing_the_bank_runs_no_exercise_file_and_imports_not_even_numpy(tmp_path):
    report = _run_fresh("main", "list", cwd=tmp_path)
    assert report["exit"] == 0, report["output"]
    assert sorted(set(report["packages"]).intersection(NOT_NEEDED + ("numpy",))) == []
    assert [name for name in report["packages"] if name.startswith("dynagrade_exercise")] == []
    assert "projectile-range" in report["output"]


def test_every_unit_of_the_bank_is_read_without_pint(bank, monkeypatch):
    from dynagrade.grading import units
    from dynagrade.grading.quantity import unit_info

    def no_pint():
        raise AssertionError("pint's registry was asked for")

    monkeypatch.setattr(units, "registry", no_pint)
    units._lookup.cache_clear()
    unit_info.cache_clear()
    used = {p.unit for e in bank.listing() for p in (*e.params, *e.parts) if p.unit}
    assert "GPa" in used and "m/s^2" in used
    for unit in sorted(used):
        factor, _ = unit_info(unit)
        assert factor > 0, unit
