"""``dynagrade exam --solutions``: each student's worked solutions with their own numbers,
as Markdown, HTML and PDF, and one PDF of all of them for the staff."""

from __future__ import annotations

import json
import shutil
import subprocess
from pathlib import Path

import pytest
from click.testing import CliRunner

from dynagrade.cli import main
from dynagrade.render.solutions import NO_SOLUTION

EXAM = """\
id = "solutions-test"
title = "Dynamics: solutions test"
date = 2025-04-14

[[exercise]]
id = "projectile-range"
points = 5

[[exercise]]
id = "ballistic-pendulum"
points = 5
"""
ROSTER = "student_id,name\nq-001,Emmy Noether\nq-002,Leonhard Euler\n"


@pytest.fixture(scope="module")
def generated(tmp_path_factory):
    folder = tmp_path_factory.mktemp("solutions")
    (folder / "exam.toml").write_text(EXAM, encoding="utf-8")
    (folder / "roster.csv").write_text(ROSTER, encoding="utf-8")
    out = folder / "out"
    result = CliRunner().invoke(main, ["exam", str(folder / "exam.toml"), "--roster",
                                       str(folder / "roster.csv"), "-o", str(out),
                                       "--jobs", "1", "--solutions"])
    assert result.exit_code == 0, result.output
    manifest = json.loads((out / "manifest.json").read_text(encoding="utf-8"))
    return out, manifest


def _shown_answers(bank, entry):
    exercise = bank.get(entry["exercise"])
    return [part.shown_answer(entry["answers"][part.name]) for part in exercise.parts]


def test_every_student_gets_their_own_worked_solutions_as_markdown_and_html(generated, bank):
    out, manifest = generated
    for student in manifest["students"]:
        folder = out / "students" / student["student_id"]
        markdown = (folder / "solution.md").read_text(encoding="utf-8")
        html = (folder / "solution.html").read_text(encoding="utf-8")
        assert student["name"] in markdown and student["name"] in html
        for entry in student["variants"]:
            for shown in _shown_answers(bank, entry):
                assert shown in markdown, (student["student_id"], shown)
        assert "<math" in html and "$" not in html
        assert NO_SOLUTION not in markdown


def test_the_two_students_solutions_differ_in_their_numbers(generated):
    out, manifest = generated
    first, second = (
        (out / "students" / s["student_id"] / "solution.md").read_text(encoding="utf-8")
        for s in manifest["students"])
    assert first != second


@pytest.mark.skipif(shutil.which("pdftotext") is None,
                    reason="pdftotext missing: install the apt package poppler-utils")
def test_the_solution_pdfs_show_each_students_answers_and_the_staff_pdf_all(generated, bank):
    out, manifest = generated

    def text(path: Path) -> str:
        return subprocess.run(["pdftotext", str(path), "-"], check=True,
                              capture_output=True, text=True, timeout=60).stdout

    combined = text(out / "solutions.pdf")
    for student in manifest["students"]:
        pdf = text(out / "students" / student["student_id"] / "solution.pdf")
        assert student["name"] in pdf and student["name"] in combined
        for entry in student["variants"]:
            numeric = next(p for p in bank.get(entry["exercise"]).parts
                           if p.kind == "numeric")
            number = numeric.answer_text(entry["answers"][numeric.name], 6)
            assert number in pdf, (student["student_id"], number)
    assert combined.count("Exercise 2:") == len(manifest["students"])


def test_without_the_option_no_solution_is_written(tmp_path):
    (tmp_path / "exam.toml").write_text(EXAM, encoding="utf-8")
    (tmp_path / "roster.csv").write_text(ROSTER, encoding="utf-8")
    result = CliRunner().invoke(main, ["exam", str(tmp_path / "exam.toml"), "--roster",
                                       str(tmp_path / "roster.csv"), "-o",
                                       str(tmp_path / "out"), "--jobs", "1", "--no-pdf"])
    assert result.exit_code == 0, result.output
    assert not list((tmp_path / "out").rglob("solution*"))


# -- class grading's feedback ------------------------------------------------------------


def _graded_feedback(folder: Path, setting: str | None, bank) -> tuple[dict, Path]:
    from dynagrade.classgrade.grade import grade_class
    from dynagrade.generation.generate import generate_exam

    line = f'solutions = "{setting}"\n' if setting else ""
    (folder / "exam.toml").write_text(EXAM.replace('date = 2025-04-14\n',
                                                   f"date = 2025-04-14\n{line}"),
                                      encoding="utf-8")
    (folder / "roster.csv").write_text(ROSTER, encoding="utf-8")
    out = folder / "out"
    generate_exam(folder / "exam.toml", folder / "roster.csv", out, bank=bank, jobs=1,
                  pdf=False)
    submitted = folder / "submitted" / "q-001"
    submitted.mkdir(parents=True)
    for exercise_id in ("projectile-range", "ballistic-pendulum"):
        source = out / "students" / "q-001" / f"{exercise_id}.py"
        (submitted / source.name).write_text(source.read_text(encoding="utf-8"), "utf-8")
    grade_class(out / "manifest.json", [folder / "submitted"], out / "grading", bank=bank,
                jobs=1)
    manifest = json.loads((out / "manifest.json").read_text(encoding="utf-8"))
    return manifest, out / "grading" / "feedback"


def test_feedback_ends_with_each_students_worked_solutions_when_the_exam_says_so(
        tmp_path, bank):
    manifest, feedback = _graded_feedback(tmp_path, "with-feedback", bank)
    assert manifest["exam"]["policy"]["solutions"] == "with-feedback"
    for student in manifest["students"]:
        markdown = (feedback / f"{student['student_id']}.md").read_text(encoding="utf-8")
        html = (feedback / f"{student['student_id']}.html").read_text(encoding="utf-8")
        solutions = markdown[markdown.index("## Worked solutions"):]
        for entry in student["variants"]:
            for shown in _shown_answers(bank, entry):
                assert shown in solutions, (student["student_id"], shown)
        # at the end: after the last exercise's verdicts (or its "Not submitted")
        assert markdown.index("## Worked solutions") > \
            markdown.index("## Ballistic pendulum (`ballistic-pendulum`)")
        assert html.index(">Worked solutions</h2>") > html.index(">Ballistic pendulum <small>")
        assert "<math" in html[html.index(">Worked solutions</h2>"):]


def test_an_exam_shows_no_solution_in_the_feedback_unless_it_says_so(tmp_path, bank):
    _, feedback = _graded_feedback(tmp_path, None, bank)
    for path in feedback.iterdir():
        assert "Worked solutions" not in path.read_text(encoding="utf-8"), path.name


@pytest.mark.parametrize("keys, expected", [
    ("", "never"),
    ('mode = "exam"\n', "never"),
    ('mode = "homework"\n', "with-feedback"),
    ('mode = "practice"\n', "with-feedback"),
    ('mode = "homework"\nsolutions = "never"\n', "never"),
    ('solutions = "after-close"\n', "after-close"),
])
def test_when_solutions_are_shown_defaults_to_the_exams_mode(tmp_path, keys, expected):
    from dynagrade.exam.policy import Policy
    from dynagrade.exam.spec import read_exam_spec

    path = tmp_path / "exam.toml"
    path.write_text(EXAM.replace('date = 2025-04-14\n', f"date = 2025-04-14\n{keys}"),
                    "utf-8")
    policy = read_exam_spec(path).policy
    assert policy.solutions == expected
    assert Policy.from_json(policy.to_json()).solutions == expected


def test_a_manifest_policy_written_before_the_setting_existed_reads_the_modes_default():
    from dynagrade.exam.policy import Policy

    stored = {"mode": "homework", "opens": None, "closes": None, "attempts": 3,
              "penalty": 0.0, "feedback": "immediate", "counts": "best"}
    assert Policy.from_json(stored).solutions == "with-feedback"
    assert Policy.from_json({**stored, "mode": "exam", "feedback": "after-close"}
                            ).solutions == "never"


def test_an_unknown_solutions_setting_is_refused_with_its_line(tmp_path):
    from dynagrade.exam.spec import ExamSpecError, read_exam_spec

    path = tmp_path / "exam.toml"
    path.write_text(EXAM.replace('date = 2025-04-14\n',
                                 'date = 2025-04-14\nsolutions = "always"\n'), "utf-8")
    with pytest.raises(ExamSpecError, match=r"line 4, field 'solutions': 'always'; choose "
                                            r"one of with-feedback, after-close"):
        read_exam_spec(path)


@pytest.mark.parametrize("setting, closed, verdicts, spent, shown", [
    ("never", True, True, True, False),
    ("after-close", False, True, True, False),
    ("after-close", True, True, False, True),
    ("after-last-attempt", False, True, False, False),
    ("after-last-attempt", False, False, True, True),
    ("after-last-attempt", True, False, False, True),
    ("with-feedback", False, True, False, False),
    ("with-feedback", False, False, True, False),
    ("with-feedback", False, True, True, True),
    ("with-feedback", True, True, False, True),
])
def test_the_server_shows_a_solution_only_once_the_student_can_no_longer_answer(
        setting, closed, verdicts, spent, shown):
    from dynagrade.exam.solution_policy import solution_visible

    assert solution_visible(setting, closed, verdicts, spent) is shown
