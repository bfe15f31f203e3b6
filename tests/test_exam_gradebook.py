"""Gradebooks of a graded class: grades.csv with names, emails, empty cells for the absent
and points rounded as the exam says; the Moodle and Canvas layouts checked against the
column rules docs/exams.md documents; the staff's overrides; and every output showing the
same part points.

The class: an exam of projectile-range (6 points) and car-in-a-looping (8 points) with
``round = 0.5``, a roster saved by Excel (byte-order mark, semicolons, CRLF) and a CSV of
responses: s1 answers everything right, s2 only projectile-range's x_max, s3 nothing.

Part points worked by hand (largest remainder in half points): 6 points are 12 halves
over 2:1:1:1, quotas 4.8, 2.4, 2.4, 2.4 → 4, 2, 2, 2 and the two halves left go to .8 and
the first .4: 2.5, 1.5, 1, 1. 8 points are 16 halves over 2:1:1:1:1:1, quotas 4.571 and
2.286 → 4 + 5 × 2 and the two left go to .571 and the first .286: 2.5, 1.5, 1, 1, 1, 1.
"""

from __future__ import annotations

import csv
import io
import json
import re
from pathlib import Path
from types import SimpleNamespace

import pytest
from click.testing import CliRunner
from hypothesis import given, strategies as st

from dynagrade.cli import main
from dynagrade.classgrade.grade import grade_class
from dynagrade.generation.generate import generate_exam
from dynagrade.classgrade.gradebook import FIXED_COLUMNS, RowStatus, gradebook_csv, gradebook_row
from dynagrade.exercise.results import ExerciseResult, GradedPart, Status
from dynagrade.classgrade.overrides import OverrideError
from dynagrade.exam.points import Rounding
from dynagrade.exercise.numbers import answer_text

EXAM = """\
id = "gradebook-exam"
title = "Dynamics: gradebook test"
date = 2025-04-14
round = 0.5

[[exercise]]
id = "projectile-range"
points = 6

[[exercise]]
id = "car-in-a-looping"
points = 8
"""
#: as Excel's "CSV UTF-8" saves it in a European locale
ROSTER = ("\ufeffstudent_id;name;email\r\ns1;Ada Muster;ada@example.org\r\n"
          "s2;Bob Beispiel;bob@example.org\r\ns3;Cleo Fehlt;cleo@example.org\r\n")
PART_POINTS = {"projectile-range": {"x_max": 2.5, "h_max": 1.5, "t_flight": 1.0,
                                    "x_max_formula": 1.0},
               "car-in-a-looping": {"v_min_entry": 2.5, "N_max": 1.5, "v_phi": 1.0,
                                    "N_phi": 1.0, "M_A": 1.0, "v_min_formula": 1.0}}
TITLE = "Dynamics: gradebook test"


@pytest.fixture(scope="module")
def exam(tmp_path_factory, bank):
    folder = tmp_path_factory.mktemp("gradebook")
    (folder / "exam.toml").write_text(EXAM, encoding="utf-8")
    (folder / "roster.csv").write_bytes(ROSTER.encode("utf-8"))
    generate_exam(folder / "exam.toml", folder / "roster.csv", folder / "out", bank=bank,
                  jobs=1, pdf=False)
    manifest = json.loads((folder / "out" / "manifest.json").read_text(encoding="utf-8"))
    answers = {(s["student_id"], v["exercise"]): v["answers"]
               for s in manifest["students"] for v in s["variants"]}
    rows = [("s1", e, part, answer_text(value, 10))
            for e in PART_POINTS for part, value in answers[("s1", e)].items()]
    rows.append(("s2", "projectile-range", "x_max",
                 answer_text(answers[("s2", "projectile-range")]["x_max"], 10)))
    responses = folder / "responses.csv"
    with open(responses, "w", newline="", encoding="utf-8") as handle:
        writer = csv.writer(handle)
        writer.writerow(["student_id", "exercise_id", "part", "answer"])
        writer.writerows(rows)
    return {"folder": folder, "manifest": folder / "out" / "manifest.json",
            "responses": responses, "bank": bank}


def _grade(exam, out, overrides=None, formats=("moodle", "canvas")):
    return grade_class(exam["manifest"], [exam["responses"]], out, bank=exam["bank"], jobs=1,
                       overrides=overrides, formats=formats)


def test_an_override_keeps_the_graders_points_beside_the_staffs(graded):
    """The override of s2's h_max (1 point, "right method, unit missing") once overwrote
    the automatic score, which then survived only in the feedback text."""
    result = graded["outcome"].feedback["s2"].results["projectile-range"]
    part = result.part("h_max")
    assert part.score == 1.0 and part.auto_score == 0.0 and part.status == "not answered"
    assert part.override.comment == "right method, unit missing"
    assert part.override.author.endswith("overrides.csv")


def _read(path: Path) -> list[list[str]]:
    return list(csv.reader(io.StringIO(path.read_text(encoding="utf-8"), newline="")))


@pytest.fixture(scope="module")
def graded(exam):
    overrides = exam["folder"] / "overrides.csv"
    overrides.write_text("student_id,exercise,part,points,comment\n"
                         's2,projectile-range,h_max,1,"right method, unit missing"\n',
                         encoding="utf-8")
    out = exam["folder"] / "grading"
    outcome = _grade(exam, out, overrides)
    return {"out": out, "outcome": outcome}


def test_grades_csv_has_names_emails_rounded_points_and_empty_cells_for_the_absent(graded):
    rows = _read(graded["out"] / "grades.csv")
    assert rows[0] == ["student_id", "name", "email", "projectile-range", "car-in-a-looping",
                       "total", "max_total", "percent", "status"]
    # s1: everything right; s2: x_max (2.5) and the overridden h_max (1): 3.5 of 14 is 25 %
    assert rows[1:] == [
        ["s1", "Ada Muster", "ada@example.org", "6", "8", "14", "14", "100.00", "graded"],
        ["s2", "Bob Beispiel", "bob@example.org", "3.5", "0", "3.5", "14", "25.00",
         "incomplete"],
        ["s3", "Cleo Fehlt", "cleo@example.org", "", "", "", "14", "", "absent"],
    ]


def test_the_moodle_gradebook_follows_moodles_csv_import_column_rules(graded):
    rows = _read(graded["out"] / "grades-moodle.csv")
    # the columns Moodle's import maps: users from "ID number" or "Email address", the
    # grade item, and its feedback
    assert rows[0] == ["ID number", "Email address", "Full name", TITLE, f"Feedback: {TITLE}"]
    assert len(rows) == 4 and all(len(r) == 5 for r in rows)
    # Moodle aborts the whole import at a row whose identifier it cannot match
    assert all(r[0] and r[1] for r in rows[1:])
    # a grade is a plain number with a decimal point, or empty: Moodle's "no grade"
    assert [r[3] for r in rows[1:]] == ["14", "3.5", ""]
    assert all(re.fullmatch(r"\d+(\.\d+)?", r[3]) for r in rows[1:3])
    assert rows[2][4].startswith("3.5 / 14 points (projectile-range 3.5, car-in-a-looping 0)")
    assert "right method, unit missing" in rows[2][4]
    assert rows[3][4] == "absent: nothing handed in"


def test_a_moodle_gradebook_for_a_roster_without_emails_says_to_map_on_the_id_number(
        exam, tmp_path, bank):
    (tmp_path / "exam.toml").write_text(EXAM, encoding="utf-8")
    (tmp_path / "roster.csv").write_text("student_id,name\nn1,No Mail\n", encoding="utf-8")
    generate_exam(tmp_path / "exam.toml", tmp_path / "roster.csv", tmp_path / "out", bank=bank,
                  jobs=1, pdf=False)
    outcome = grade_class(tmp_path / "out" / "manifest.json", [], tmp_path / "grading",
                          bank=bank, jobs=1, formats=("moodle",))
    warnings = [p.message for p in outcome.problems if p.source == "grades-moodle.csv"]
    assert warnings == ["1 student(s) have no email on the roster (n1); in Moodle's import "
                        "map users from 'ID number', not 'Email address'"]
    assert _read(tmp_path / "grading" / "grades-moodle.csv")[1][:2] == ["n1", ""]
    assert not [p for p in _grade(exam, tmp_path / "again").problems
                if p.source == "grades-moodle.csv"]


def test_the_canvas_gradebook_follows_canvass_import_column_rules(graded):
    rows = _read(graded["out"] / "grades-canvas.csv")
    assert rows[0] == ["Student", "ID", "SIS User ID", "SIS Login ID", "Section", TITLE]
    assert rows[1] == ["Points Possible", "", "", "", "", "14"]
    assert [r[2] for r in rows[2:]] == ["s1", "s2", "s3"]  # matched on the SIS User ID
    assert [r[0] for r in rows[2:]] == ["Ada Muster", "Bob Beispiel", "Cleo Fehlt"]
    assert [r[5] for r in rows[2:]] == ["14", "3.5", ""]


def test_every_platform_gradebook_reads_back_with_the_numbers_of_grades_csv(graded):
    """Export, read back with csv: each student's points are those of grades.csv."""
    totals = {r[0]: r[5] for r in _read(graded["out"] / "grades.csv")[1:]}
    moodle = {r[0]: r[3] for r in _read(graded["out"] / "grades-moodle.csv")[1:]}
    canvas = {r[2]: r[5] for r in _read(graded["out"] / "grades-canvas.csv")[2:]}
    assert moodle == totals == canvas
    assert {k: float(v) for k, v in totals.items() if v} == {"s1": 14.0, "s2": 3.5}


def test_an_override_sets_the_points_and_its_comment_reaches_feedback_and_report(graded):
    markdown = (graded["out"] / "feedback" / "s2.md").read_text(encoding="utf-8")
    html = (graded["out"] / "feedback" / "s2.html").read_text(encoding="utf-8")
    for text in (markdown, html):
        assert "Points set by the staff: 1 (graded 0): right method, unit missing" in text
    assert "3.5 / 6 points" in markdown
    report = graded["out"] / "report.html"
    assert "1 part overridden by the staff" in report.read_text(encoding="utf-8")
    assert graded["outcome"].overridden == 1


def test_every_output_shows_the_same_part_points(exam, graded):
    """The sheet, the fill-in file, the key, the feedback and the gradebook agree with the
    points split by hand."""
    out = exam["manifest"].parent
    sheet = (out / "students" / "s1" / "sheet.md").read_text(encoding="utf-8")
    feedback = (graded["out"] / "feedback" / "s1.md").read_text(encoding="utf-8")
    key = {(r["exercise_id"], r["part"]): float(r["points"]) for r in csv.DictReader(
        io.StringIO((out / "key.csv").read_text(encoding="utf-8"))) if r["student_id"] == "s1"}
    for exercise_id, parts in PART_POINTS.items():
        fill_in = (out / "students" / "s1" / f"{exercise_id}.py").read_text(encoding="utf-8")
        for part, points in parts.items():
            shown = f"{points:g}"
            assert re.search(rf"- `{part}`: .* — {shown} points?\n", sheet), part
            assert re.search(rf"\({shown} points?\)\n{part} = None", fill_in), part
            assert key[(exercise_id, part)] == points
            assert re.search(rf"\| `{part}` \|.*\| {shown} / {shown} \|", feedback), part
    grades = _read(graded["out"] / "grades.csv")
    assert grades[1][3:5] == [f"{sum(PART_POINTS[e].values()):g}" for e in PART_POINTS]


def test_bad_override_rows_are_all_listed_and_the_previous_grading_is_kept(exam, graded):
    bad = exam["folder"] / "bad-overrides.csv"
    bad.write_bytes("\ufeffstudent_id;exercise;part;points;comment\r\n"
                    "s9;projectile-range;x_max;1;\r\n"
                    "s1;projectile;x_max;1;\r\n"
                    "s1;projectile-range;x_maximum;1;\r\n"
                    "s1;projectile-range;x_max;3;\r\n"
                    "s1;projectile-range;h_max;0,75;\r\n"
                    "s1;projectile-range;t_flight;one;\r\n"
                    "s1;projectile-range\r\n"
                    "s1;projectile-range;h_max;1,5;fine\r\n"
                    "s1;projectile-range;h_max;1;twice\r\n".encode("utf-8"))
    before = {p.name: p.read_bytes() for p in graded["out"].iterdir() if p.is_file()}
    with pytest.raises(OverrideError) as caught:
        _grade(exam, graded["out"], bad)
    message = str(caught.value)
    assert message.startswith("8 bad override row(s); nothing was graded or written")
    for expected in ("row 2: student 's9' is not on the exam's roster",
                     "row 3: exercise 'projectile' is not in the exam",
                     "row 4: exercise 'projectile-range' has no part 'x_maximum'",
                     "row 5: points 3 is outside 0 to 2.5, the points of part 'x_max'",
                     "row 6: points 0,75 is not one of the exam's multiples of 0.5",
                     "row 7: points 'one' is not a number",
                     "row 8: 2 columns, the header has 5",
                     "row 10: s1's part 'h_max' of 'projectile-range' is already overridden "
                     "on row 9"):
        assert expected in message
    after = {p.name: p.read_bytes() for p in graded["out"].iterdir() if p.is_file()}
    assert after == before


def test_an_override_of_an_exercise_the_student_did_not_hand_in_is_refused(exam, tmp_path):
    overrides = tmp_path / "overrides.csv"
    overrides.write_text("student_id,exercise,part,points\n"
                         "s2,car-in-a-looping,N_max,1\ns3,projectile-range,x_max,2\n",
                         encoding="utf-8")
    with pytest.raises(OverrideError) as caught:
        _grade(exam, tmp_path / "grading", overrides)
    assert "row 2: s2 handed in nothing gradable for 'car-in-a-looping'" in str(caught.value)
    assert "row 3: s3 handed in nothing gradable" in str(caught.value)
    assert not (tmp_path / "grading").exists()


def test_the_command_line_writes_the_platform_gradebooks_and_refuses_bad_overrides(
        exam, tmp_path):
    out = tmp_path / "grading"
    result = CliRunner().invoke(main, [
        "grade", "--manifest", str(exam["manifest"]), str(exam["responses"]), "-o", str(out),
        "--format", "moodle", "--format", "canvas", "--assignment", "Midterm (12345)"])
    assert result.exit_code == 0, result.output
    assert _read(out / "grades-canvas.csv")[0][5] == "Midterm (12345)"
    assert _read(out / "grades-moodle.csv")[0][3:] == ["Midterm (12345)",
                                                      "Feedback: Midterm (12345)"]
    bad = tmp_path / "overrides.csv"
    bad.write_text("student_id,exercise,part,points\ns9,projectile-range,x_max,1\n",
                   encoding="utf-8")
    result = CliRunner().invoke(main, [
        "grade", "--manifest", str(exam["manifest"]), str(exam["responses"]), "-o", str(out),
        "--overrides", str(bad)])
    assert result.exit_code != 0
    assert "row 2: student 's9' is not on the exam's roster" in result.output
    assert "Traceback" not in result.output
    result = CliRunner().invoke(main, ["grade", "--manifest", str(exam["manifest"]),
                                       str(exam["responses"]), "--format", "moodle"])
    assert result.exit_code == 2 and "--format and --assignment need -o" in result.output
    result = CliRunner().invoke(main, ["grade", "--manifest", str(exam["manifest"]),
                                       str(exam["responses"]), "-o", str(out),
                                       "--assignment", "Midterm"])
    assert result.exit_code == 2 and "give --format too" in result.output


@given(step=st.sampled_from([0.01, 0.1, 0.25, 0.5, 1.0]),
       exercises=st.lists(st.lists(st.floats(0, 10), min_size=1, max_size=6), min_size=1,
                          max_size=5))
def test_every_cell_is_a_multiple_of_the_step_and_the_total_is_the_sum_of_the_cells(
        step, exercises):
    """Each part's score is rounded to the step, each exercise cell is the exact sum of its
    rounded parts, and the total is the exact sum of the exercise cells."""
    rounding = Rounding(step)
    ids = [f"e{i}" for i in range(len(exercises))]
    results = {e: _result(e, scores) for e, scores in zip(ids, exercises)}
    row = gradebook_row("s", results, ids, 100.0, rounding=rounding)
    for e, scores in zip(ids, exercises):
        parts = [rounding.steps(score) for score in scores]  # nearest steps, by hand below
        assert all(abs(n * step - score) <= step / 2 + 1e-9 for n, score in zip(parts, scores))
        assert rounding.steps(row.cells[e]) == sum(parts) and rounding.is_multiple(row.cells[e])
    assert rounding.steps(row.total) == sum(rounding.steps(row.cells[e]) for e in ids)
    assert row.total == rounding.points(sum(rounding.steps(row.cells[e]) for e in ids))


def _result(exercise_id: str, scores) -> ExerciseResult:
    """An exercise whose parts (worth 10 points each) earned ``scores``, unrounded."""
    return ExerciseResult(exercise_id, 1, tuple(
        GradedPart(f"p{i}", "", Status.PARTIAL, score, 10.0, "1", "")
        for i, score in enumerate(scores)))


@pytest.mark.parametrize("exercise_id", FIXED_COLUMNS[1:])
def test_an_exercise_named_like_a_fixed_column_leaves_that_column_alone(exercise_id):
    """An exercise whose id is ``total`` (valid kebab-case) once overwrote the row's total
    with its own points; the cells are keyed apart now, and the CSV heads its column
    ``exercise:<id>`` so that no header stands twice."""
    rounding = Rounding(0.5)
    results = {exercise_id: _result(exercise_id, [1.0]), "other": _result("other", [2.0])}
    row = gradebook_row("s1", results, [exercise_id, "other"], 20.0, name="Ada",
                        email="ada@example.org", rounding=rounding)
    assert (row.cells[exercise_id], row.total, row.status) == (1.0, 3.0, RowStatus.GRADED)
    assert (row.name, row.email, row.percent) == ("Ada", "ada@example.org", 15.0)
    outcome = SimpleNamespace(exercise_ids=[exercise_id, "other"], rows=[row],
                              rounding=rounding)
    header, cells = list(csv.reader(io.StringIO(gradebook_csv(outcome))))
    assert len(set(header)) == len(header)
    assert header[3:5] == [f"exercise:{exercise_id}", "other"]
    assert dict(zip(header, cells))["total"] == "3"
    assert dict(zip(header, cells))[f"exercise:{exercise_id}"] == "1"
