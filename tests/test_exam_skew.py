"""The exam's warnings about skewed variants: an exercise redrawn more than a tenth of the
time, a part whose answer is the same for the whole class."""

from __future__ import annotations

import json
import math

from click.testing import CliRunner

from dynagrade.cli import main
from dynagrade.generation.generate import generate_exam
from dynagrade.exam.manifest import load
from dynagrade.generation.skew import skew_warnings
from dynagrade.exercise.loader import open_bank

# A block on a rough incline (Example 1.8): it comes to rest when mu > tan(alpha). The
# misconception "friction forgotten" answers "no" (it never stops), which is the key
# wherever mu < tan(alpha): there it is no mistake, and without a regime every such
# variant is redrawn, so the whole class is told that the block stops.
STOPS = '''
"""Does a block sliding down a rough incline come to rest? (Example 1.8)"""
import math

from dynagrade.exercise import Exercise, Misconception, Options, Uniform


def stops(p):
    return "yes" if p.mu > math.tan(p.alpha) else "no"


EXERCISE = Exercise(
    id="block-comes-to-rest", title="Does it stop?", source="Example 1.8",
    params=(Uniform("alpha", 10, 50, step=1, unit="deg", symbol=r"\\alpha"),
            Uniform("mu", 0.1, 0.9, step=0.05, symbol=r"\\mu")),
    statement="A block slides down a slope at $\\\\alpha$ = {{ alpha }} with "
              "$\\\\mu$ = {{ mu }}.\\n\\n1. Does it come to rest?",
    solve=lambda p: {"stops": stops(p)},
    parts=(Options("stops", "comes to rest", options=("yes", "no"),
                   misconceptions=(Misconception(
                       "friction forgotten", lambda p: "no",
                       "Friction mu N acts up the slope while the block slides."APPLIES),)),),
)
'''
REGIME = ",\n                       applies=lambda p: stops(p) == 'yes'"


def _exam_and_roster(tmp_path, exercise_id: str, students: int):
    """An exam of the one exercise, and a roster of ``students``."""
    exam = tmp_path / "exam.toml"
    exam.write_text(f'id = "q"\ntitle = "Q"\ndate = 2025-01-01\n[[exercise]]\n'
                    f'id = "{exercise_id}"\npoints = 2\n', encoding="utf-8")
    roster = tmp_path / "roster.csv"
    roster.write_text("student_id,name\n" + "".join(f"s{i},S {i}\n" for i in range(students)),
                      encoding="utf-8")
    return exam, roster


def _exam(tmp_path, regime: bool, students: int = 40):
    folder = tmp_path / "bank"
    folder.mkdir()
    (folder / "stops.py").write_text(STOPS.replace("APPLIES", REGIME if regime else ""),
                                     encoding="utf-8")
    return (folder, *_exam_and_roster(tmp_path, "block-comes-to-rest", students))


def _share_that_never_stops() -> float:
    """The share of the (alpha, mu) grid where mu < tan(alpha), counted by hand."""
    grid = [(alpha, 0.1 + 0.05 * k) for alpha in range(10, 51) for k in range(17)]
    return sum(mu < math.tan(math.radians(alpha)) for alpha, mu in grid) / len(grid)


def test_without_a_regime_the_class_gets_one_answer_and_the_exam_warns(tmp_path):
    folder, exam, roster = _exam(tmp_path, regime=False)
    report = generate_exam(exam, roster, tmp_path / "out", bank=open_bank([folder]), jobs=1,
                           pdf=False, secret="fixed")
    manifest = load(tmp_path / "out" / "manifest.json")
    answers = {s.variants[0].answers["stops"] for s in manifest.students}
    assert answers == {"yes"}  # every "no" variant was redrawn
    # about half the grid never stops, so about half the draws were redrawn
    assert 0.3 < _share_that_never_stops() < 0.7
    assert report.redraws > 0.1 * (40 + report.redraws)
    assert len(report.skew) == 2
    redrawn, same = report.skew
    assert redrawn.startswith(f"block-comes-to-rest: {report.redraws} of "
                              f"{40 + report.redraws} draws")
    assert "friction forgotten" in redrawn and "applies=" in redrawn
    assert same.startswith("block-comes-to-rest, part stops: every one of the 40 students "
                           "has the same answer (yes)")


def test_with_applies_nothing_is_redrawn_and_both_answers_occur(tmp_path):
    folder, exam, roster = _exam(tmp_path, regime=True)
    report = generate_exam(exam, roster, tmp_path / "out", bank=open_bank([folder]), jobs=1,
                           pdf=False, secret="fixed")
    manifest = load(tmp_path / "out" / "manifest.json")
    assert report.redraws == 0 and report.skew == []
    assert {s.variants[0].answers["stops"] for s in manifest.students} == {"yes", "no"}


def test_the_command_prints_each_warning_on_one_line_of_stderr(tmp_path):
    folder, exam, roster = _exam(tmp_path, regime=False)
    secret = tmp_path / "secret"
    secret.write_text("fixed-" * 6, encoding="utf-8")
    result = CliRunner().invoke(main, ["exam", str(exam), "--roster", str(roster), "-o",
                                       str(tmp_path / "out"), "--no-pdf", "--jobs", "1",
                                       "--exercises", str(folder),
                                       "--secret-file", str(secret)])
    assert result.exit_code == 0, result.output
    lines = [line for line in result.stderr.splitlines() if line.startswith("warning: ")]
    assert len(lines) == 2
    assert lines[0].startswith("warning: block-comes-to-rest: ")
    assert lines[1].startswith("warning: block-comes-to-rest, part stops: ")
    assert "2 warning(s) above" in result.stderr


def test_a_small_class_sharing_a_choice_is_not_warned_about(tmp_path):
    folder, exam, roster = _exam(tmp_path, regime=True, students=4)
    generate_exam(exam, roster, tmp_path / "out", bank=open_bank([folder]), jobs=1,
                  pdf=False, secret="fixed")
    manifest = load(tmp_path / "out" / "manifest.json")
    one_answer = manifest.students[0].variants[0].answers["stops"]
    # whatever the four got, four students are too few to warn about one shared answer
    assert [w for w in skew_warnings(manifest) if "same answer" in w] == []
    assert one_answer in ("yes", "no")


def test_formula_parts_are_the_same_for_everyone_by_design_and_not_warned_about(tmp_path,
                                                                                bank):
    exam, roster = _exam_and_roster(tmp_path, "projectile-range", 8)
    report = generate_exam(exam, roster, tmp_path / "out", bank=bank, jobs=1, pdf=False,
                           secret="fixed")
    manifest = json.loads((tmp_path / "out" / "manifest.json").read_text(encoding="utf-8"))
    formulas = {s["variants"][0]["answers"]["x_max_formula"] for s in manifest["students"]}
    assert len(formulas) == 1
    assert report.skew == []
