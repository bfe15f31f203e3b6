"""Grading a class from the exam manifest: the gradebook a known class must get, problems
reported for bad submissions, reproducible outputs, and the single-file `grade` intact."""

from __future__ import annotations

import csv
import importlib.util
import io
import json
import math
from pathlib import Path

import pytest
from click.testing import CliRunner

from dynagrade.cli import grade_main, main
from dynagrade.classgrade.grade import grade_class
from dynagrade.generation.generate import generate_exam

ROOT = Path(__file__).resolve().parent.parent
KINDS = ["correct", "half", "empty", "corrupt", "duplicate", "csv"]
ROSTER_IDS = [f"c-{i}" for i in range(8)]  # the last two are absent


def _make_submissions():
    spec = importlib.util.spec_from_file_location(
        "make_submissions_for_tests", ROOT / "examples" / "make_submissions.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    module.PLAN = tuple((kind, 1) for kind in KINDS)
    return module


@pytest.fixture(scope="module")
def graded(tmp_path_factory, bank, exam_toml):
    folder = tmp_path_factory.mktemp("class")
    roster = folder / "roster.csv"
    roster.write_text("student_id,name\n" + "".join(f"{s},Student {s}\n" for s in ROSTER_IDS),
                      encoding="utf-8")
    exam = folder / "exam.toml"
    exam.write_text(exam_toml, encoding="utf-8")
    out = folder / "out"
    generate_exam(exam, roster, out, bank=bank, jobs=1, pdf=False)
    _make_submissions().main(str(out))
    outcome = grade_class(out / "manifest.json", [out / "submissions"], out / "grading",
                          bank=bank, jobs=1)
    manifest = json.loads((out / "manifest.json").read_text(encoding="utf-8"))
    return {"out": out, "outcome": outcome, "manifest": manifest}


#: each part's points in the exam, split by hand with the largest-remainder method in
#: hundredths: 6 points over 2:1:1:1 divide exactly; 8 over 2:1:1:1:1:1 gives quotas 228.57
#: and 114.29 hundredths, cut to 228 + 5 × 114 = 798, the two left going to .571 (the first
#: part) and the first of the tied .286 (the second)
PART_POINTS = {"projectile-range": [2.4, 1.2, 1.2, 1.2],
               "sliding-up-a-slope": [2.4, 1.2, 1.2, 1.2],
               "car-in-a-looping": [2.29, 1.15, 1.14, 1.14, 1.14, 1.14]}


def expected_gradebook(bank, exam_points: dict[str, float]) -> dict[str, dict]:
    """The gradebook worked out from the submission plan and the parts' points split by
    hand (:data:`PART_POINTS`); an absent student has no points at all (None)."""
    for exercise_id, points in PART_POINTS.items():
        assert len(points) == len(bank.get(exercise_id).parts)
        assert math.isclose(sum(points), exam_points[exercise_id])

    ids = list(exam_points)
    rows = {}
    for student_id, kind in zip(ROSTER_IDS, KINDS + ["absent", "absent"]):
        if kind in ("correct", "duplicate", "csv"):
            scores = {e: exam_points[e] for e in ids}
        elif kind == "half":
            scores = {e: sum(p for i, p in enumerate(PART_POINTS[e]) if i % 2 == 0)
                      for e in ids}
        elif kind == "corrupt":
            scores = {e: (0.0 if e == ids[0] else exam_points[e]) for e in ids}
        elif kind == "empty":
            scores = {e: 0.0 for e in ids}
        else:
            rows[student_id] = {**dict.fromkeys(ids), "total": None, "status": "absent",
                                "percent": None}
            continue
        status = {"corrupt": "incomplete"}.get(kind, "graded")
        total = sum(scores.values())
        rows[student_id] = {**scores, "total": total, "status": status,
                            "percent": 100 * total / sum(exam_points.values())}
    return rows


def _cell(text: str) -> float | None:
    return None if text == "" else float(text)


def test_the_class_gets_exactly_the_expected_gradebook(graded, bank):
    exam_points = {"projectile-range": 6.0, "sliding-up-a-slope": 6.0, "car-in-a-looping": 8.0}
    expected = expected_gradebook(bank, exam_points)
    text = (graded["out"] / "grading" / "grades.csv").read_text(encoding="utf-8")
    rows = list(csv.DictReader(io.StringIO(text)))
    assert list(rows[0]) == ["student_id", "name", "email", *exam_points, "total",
                             "max_total", "percent", "status"]
    assert [r["student_id"] for r in rows] == ROSTER_IDS
    assert [r["name"] for r in rows] == [f"Student {s}" for s in ROSTER_IDS]
    for row in rows:
        want = expected[row["student_id"]]
        for column in (*exam_points, "total"):
            if want[column] is None:
                assert row[column] == "", (row["student_id"], column)
            else:
                assert math.isclose(float(row[column]), want[column], abs_tol=1e-9), \
                    (row["student_id"], column, row[column], want[column])
        if want["percent"] is None:
            assert row["percent"] == ""
        else:
            assert math.isclose(float(row["percent"]), want["percent"], abs_tol=0.006)
        assert float(row["max_total"]) == 20.0
        assert row["status"] == want["status"], row["student_id"]


def test_bad_submissions_are_reported_and_skipped(graded):
    problems = graded["outcome"].problems
    by_kind = [(p.level, p.student_id, p.message.split(":")[0]) for p in problems]
    # the corrupt file is named by the folder it was found in (c-3, the corrupt kind)
    assert ("error", "c-3", "corrupt, skipped") in by_kind
    assert ("warning", "c-4", "duplicate") in by_kind
    assert ("error", "x00-000", "skipped") in by_kind
    assert any(p.level == "error" and p.student_id == "c-0"
               and p.message.startswith("foreign, skipped") for p in problems)
    # c-1's folder holds c-0's sheet: impersonating, and nobody is credited with it
    assert ("error", "c-1", "impersonating, skipped") in by_kind
    duplicate = next(p for p in problems if p.message.startswith("duplicate"))
    assert duplicate.source.endswith("2-projectile-range.py")
    assert "1-projectile-range.py" in duplicate.message
    logged = (graded["out"] / "grading" / "problems.csv").read_text(encoding="utf-8")
    assert len(list(csv.reader(io.StringIO(logged)))) == len(problems) + 1


def test_item_statistics_match_the_class(graded):
    stats = {(s.exercise_id, s.part): s for s in graded["outcome"].stats}
    # projectile-range was submitted by correct, half, empty, duplicate and csv students;
    # its first part is right for all but the empty one, its second only for three
    assert stats[("projectile-range", "x_max")].answered == 5
    assert math.isclose(stats[("projectile-range", "x_max")].difficulty, 4 / 5)
    assert math.isclose(stats[("projectile-range", "h_max")].difficulty, 3 / 5)
    wrong = stats[("projectile-range", "h_max")].wrong_answers
    assert len(wrong) == 1 and wrong[0][1] == 1  # the half-correct student's answer
    report = (graded["out"] / "grading" / "report.html").read_text(encoding="utf-8")
    assert report.count("<svg") == 2 and "point-biserial" in report
    for student_id in ROSTER_IDS:
        for suffix in ("md", "html"):
            assert (graded["out"] / "grading" / "feedback" / f"{student_id}.{suffix}").exists()


def test_class_grading_writes_answers_csv_and_copies_csv_beside_the_gradebook(graded):
    """answers.csv holds every graded part of the students present (dynagrade discover
    reads it); copies.csv is written even when no pair is listed (issue 32)."""
    from dynagrade.classgrade.answered import read_answered
    from dynagrade.classgrade.copies import COPIES_HEADER

    grading = graded["out"] / "grading"
    records = read_answered(grading / "answers.csv")
    assert records == graded["outcome"].records()
    present = {r.student_id for r in graded["outcome"].rows if r.status != "absent"}
    assert {r.student_id for r in records} == present
    assert (grading / "copies.csv").read_text(encoding="utf-8").splitlines()[0] == \
        ",".join(COPIES_HEADER)


def test_a_rerun_after_an_interruption_writes_the_same_gradebook(graded, bank, tmp_path):
    grading = graded["out"] / "grading"
    before = {p.name: p.read_bytes() for p in grading.iterdir() if p.is_file()}
    (grading / "grades.csv").unlink()
    (grading / ".report.html.999.tmp").write_text("half-written")
    (grading / "feedback" / "c-0.md").write_text("truncated")
    grade_class(graded["out"] / "manifest.json", [graded["out"] / "submissions"], grading,
                bank=bank, jobs=1)
    after = {p.name: p.read_bytes() for p in grading.iterdir() if p.is_file()
             and not p.name.endswith(".999.tmp")}
    assert after == before
    assert (grading / "feedback" / "c-0.md").read_text(encoding="utf-8").startswith("# ")
    assert not [p for p in grading.rglob("*.tmp") if ".999." not in p.name]


def test_the_command_line_grades_a_class_and_single_files_as_before(graded):
    out = graded["out"]
    runner = CliRunner()
    result = runner.invoke(main, ["grade", "--manifest", str(out / "manifest.json"),
                                  str(out / "submissions" / "c-0"), "-o",
                                  str(out / "cli-grading"), "--jobs", "1"])
    assert result.exit_code == 0, result.output
    rows = list(csv.DictReader(io.StringIO(
        (out / "cli-grading" / "grades.csv").read_text(encoding="utf-8"))))
    assert [r["status"] for r in rows] == ["graded"] + ["absent"] * 7
    sheet = out / "submissions" / "c-0" / "projectile-range.py"
    # an exam's file: the self-check reads every answer and gives no verdict
    single = runner.invoke(grade_main, [str(sheet), "--json"])
    assert single.exit_code == 0, single.output
    checked = json.loads(single.output[single.output.index("{"):])
    assert checked["exercise"] == "projectile-range" and checked["mode"] == "exam"
    assert all(part["readable"] for part in checked["parts"])
    assert not {"correct", "score", "expected", "reference"} & {
        key for part in checked["parts"] for key in part} and "score" not in checked
    assert "when the staff grade" in checked["message"]
    # a practice sheet of the same exercise, answered right: full verdicts
    practice = out / "practice.py"
    assert runner.invoke(main, ["sheet", "projectile-range", "--student", "c-0", "-o",
                                str(practice)]).exit_code == 0
    solved = json.loads(runner.invoke(main, ["show", "projectile-range", "--student", "c-0",
                                             "--answers", "--json"]).output)["answers"]
    text = practice.read_text(encoding="utf-8")
    for name, value in solved.items():
        text = text.replace(f"\n{name} = None\n", f"\n{name} = {json.dumps(str(value))}\n")
    practice.write_text(text, encoding="utf-8")
    single = runner.invoke(grade_main, [str(practice), "--json"])
    assert single.exit_code == 0, single.output
    verdict = json.loads(single.output[single.output.index("{"):])
    assert verdict["exercise"] == "projectile-range"
    assert verdict["score"] == verdict["max_score"]
    folder = runner.invoke(main, ["grade", str(out / "submissions")])
    assert folder.exit_code != 0 and "is a directory" in folder.output
    no_manifest = runner.invoke(main, ["grade", str(sheet), "-o", str(out / "x")])
    assert no_manifest.exit_code != 0 and "need --manifest" in no_manifest.output


def test_response_csvs_report_bad_rows_and_let_a_later_row_win(graded, tmp_path):
    from dynagrade.exam.manifest import from_dict
    from dynagrade.classgrade.submissions import collect

    manifest = graded["manifest"]
    student = manifest["students"][0]
    variant = student["variants"][0]
    name = manifest["exercises"][0]["parts"][0]["name"]
    responses = tmp_path / "responses.csv"
    responses.write_text(
        "student_id,exercise_id,part,answer\n"
        f"{student['student_id']},{variant['exercise']},{name},1\n"
        f"{student['student_id']},{variant['exercise']},{name},2\n"
        f"{student['student_id']},{variant['exercise']},no_such_part,3\n"
        f"nobody,{variant['exercise']},{name},4\n"
        f"{student['student_id']},not-in-exam,{name},5\n"
        f"{student['student_id']},{variant['exercise']}\n", encoding="utf-8")
    wrong_header = tmp_path / "wrong.csv"
    wrong_header.write_text("student,exercise,part,answer\n", encoding="utf-8")
    chosen, problems = collect([responses, wrong_header], from_dict(manifest))
    submission = chosen[(student["student_id"], variant["exercise"])]
    assert submission.answers == {name: "2"}
    messages = [(p.source.rsplit(", ", 1)[-1], p.level, p.message.split(":")[0])
                for p in problems]
    assert messages == [("row 3", "warning", "duplicate"), ("row 4", "warning",
                                                            "no part named 'no_such_part' in "
                                                            + variant["exercise"] + "; ignored"),
                        ("row 5", "error", "skipped"), ("row 6", "error", "foreign, skipped"),
                        ("row 7", "error", "skipped"), ("row 1", "error", "corrupt, skipped")]


def test_the_exam_command_reports_a_malformed_roster_and_writes_nothing(tmp_path, exam_toml):
    exam = tmp_path / "exam.toml"
    exam.write_text(exam_toml, encoding="utf-8")
    roster = tmp_path / "roster.csv"
    roster.write_text("student_id,name\ns1,A\ns1,B\n", encoding="utf-8")
    result = CliRunner().invoke(main, ["exam", str(exam), "--roster", str(roster), "-o",
                                       str(tmp_path / "out")])
    assert result.exit_code == 1
    assert f"{roster}, row 3, column 1 (student_id): 's1' is already on row 2" in result.output
    assert not (tmp_path / "out").exists()
