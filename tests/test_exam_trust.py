"""A course can trust class grading: no answer, file or folder crashes the run,
misattributes, leaks or silently loses a grade (issue 11, items 2, 3, 5, 7 and 8)."""

from __future__ import annotations

import csv
import io
import json
import os
import random
import signal
import subprocess
import sys
import time
from dataclasses import replace
from pathlib import Path

import pytest
from click.testing import CliRunner

from dynagrade.cli import main
from dynagrade.classgrade.grade import grade_class
from dynagrade.generation.generate import generate_exam
from dynagrade.exam.manifest import dump, load

ROSTER = ["s1", "s2", "s3"]


@pytest.fixture(scope="module")
def exam(tmp_path_factory, bank, exam_toml):
    """A generated exam for three students, without PDFs."""
    folder = tmp_path_factory.mktemp("trust")
    roster = folder / "roster.csv"
    roster.write_text("student_id,name\n" + "".join(f"{s},Student {s}\n" for s in ROSTER),
                      encoding="utf-8")
    (folder / "exam.toml").write_text(exam_toml, encoding="utf-8")
    generate_exam(folder / "exam.toml", roster, folder / "out", bank=bank, jobs=1, pdf=False,
                  secret="c0ffee" * 11)  # fixed, so that every run checks the same variants
    return folder / "out"


def _number(value) -> str:
    return "[" + ", ".join(f"{v:.10g}" for v in value) + "]" if isinstance(value, tuple) \
        else f"{value:.10g}" if isinstance(value, float) else str(value)


def filled(exam: Path, student: str, exercise: str, correct: bool = True,
           student_line: str | None = None) -> str:
    """The student's own fill-in file with every part answered (right or 2x wrong)."""
    manifest = load(exam / "manifest.json")
    variant = next(s for s in manifest.students if s.student_id == student).variant(exercise)
    text = (exam / "students" / student / f"{exercise}.py").read_text(encoding="utf-8")
    for name, value in variant.answers.items():
        if not correct and isinstance(value, float):
            value = 2 * value + 1
        text = text.replace(f"\n{name} = None\n", f"\n{name} = {json.dumps(_number(value))}\n")
    if student_line is not None:
        text = text.replace(f"STUDENT = {student!r}", f"STUDENT = {student_line!r}")
    return text


def put(folder: Path, relative: str, text: str, modified: float | None = None) -> Path:
    path = folder / relative
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text, encoding="utf-8")
    if modified is not None:
        os.utime(path, (modified, modified))
    return path


def gradebook(folder: Path) -> dict[str, dict]:
    rows = csv.DictReader(io.StringIO((folder / "grades.csv").read_text(encoding="utf-8")))
    return {row["student_id"]: row for row in rows}


# -- item 2: faults stay where they happen -------------------------------------------------


def test_an_answer_whose_grading_raises_costs_only_its_part_and_the_gradebook_is_complete(
        exam, tmp_path, monkeypatch):
    """Reproducer: one student's answer aborted class grading for everybody (no
    grades.csv, the old one silently left in place)."""
    import dynagrade.exercise.scoring as scoring

    subs = tmp_path / "subs"
    for student in ROSTER:
        put(subs, f"{student}/projectile-range.py", filled(exam, student, "projectile-range"))
    poisoned = subs / "s2" / "projectile-range.py"
    poisoned.write_text(poisoned.read_text(encoding="utf-8").replace(
        "\nx_max = ", '\nx_max = "deg^deg" #', 1), encoding="utf-8")
    real = scoring.grade

    def grade(spec, expected, text):
        if text == "deg^deg":
            raise ZeroDivisionError("division by zero")
        return real(spec, expected, text)

    monkeypatch.setattr(scoring, "grade", grade)
    out = tmp_path / "grading"
    put(out, "grades.csv", "student_id\nold-run\n")
    result = CliRunner().invoke(main, ["grade", "--manifest", str(exam / "manifest.json"),
                                       str(subs), "-o", str(out), "--jobs", "1"])
    assert result.exit_code == 0, result.output
    book = gradebook(out)
    assert sorted(book) == ROSTER  # every student, none of the old run
    # projectile-range's parts have 2 + 1 + 1 + 1 points, scaled to the exam's 6: x_max
    # is worth 2 * 6 / 5 = 2.4, which is exactly what s2 loses
    assert float(book["s1"]["projectile-range"]) == 6.0
    assert float(book["s2"]["projectile-range"]) == pytest.approx(3.6)
    problems = list(csv.DictReader(io.StringIO(
        (out / "problems.csv").read_text(encoding="utf-8"))))
    assert [(p["student_id"], p["exercise_id"]) for p in problems if p["level"] == "error"] \
        == [("s2", "projectile-range")]
    assert "part x_max" in problems[0]["message"] and "ZeroDivisionError" in \
        problems[0]["message"]
    feedback = (out / "feedback" / "s2.md").read_text(encoding="utf-8")
    assert "| error |" in feedback and "could not be graded" in feedback
    strict = CliRunner().invoke(main, ["grade", "--manifest", str(exam / "manifest.json"),
                                       str(subs), "-o", str(out), "--jobs", "1", "--strict"])
    assert strict.exit_code == 1 and gradebook(out).keys() == book.keys()


def test_grading_that_cannot_start_exits_non_zero_with_a_located_message(exam, tmp_path):
    broken = put(tmp_path, "manifest.json", "{}")
    result = CliRunner().invoke(main, ["grade", "--manifest", str(broken), str(tmp_path),
                                       "-o", str(tmp_path / "g")])
    assert result.exit_code == 1 and str(broken) in result.output
    assert "Traceback" not in result.output


# -- item 3: attribution by where the file came from ---------------------------------------


def test_a_file_naming_a_classmate_is_impersonating_and_credited_to_nobody(exam, tmp_path):
    """Reproducer: any student could overwrite a classmate's submission by writing the
    classmate's STUDENT line (and seed) into a file of their own."""
    subs = tmp_path / "subs"
    put(subs, "s1/projectile-range.py", filled(exam, "s1", "projectile-range", correct=False))
    # s2 hands in a correct copy of s1's own sheet, STUDENT line and all
    put(subs, "s2/projectile-range.py", filled(exam, "s1", "projectile-range"))
    outcome = grade_class(exam / "manifest.json", [subs])
    rows = {row.student_id: {**row.cells, "status": row.status} for row in outcome.rows}
    # s1's own file counts: wrong numbers, only the formula (1 of 5 points, 1.2 of 6) right
    assert rows["s1"]["projectile-range"] == pytest.approx(1.2)
    assert rows["s2"]["projectile-range"] == 0.0 and rows["s2"]["status"] == "rejected"
    impersonating = [p for p in outcome.problems if p.message.startswith("impersonating")]
    assert [(p.student_id, p.exercise_id) for p in impersonating] == \
        [("s2", "projectile-range")]
    assert "'s1'" in impersonating[0].message


def test_a_responses_csv_in_a_students_folder_may_hold_only_their_rows(exam, tmp_path):
    subs = tmp_path / "subs"
    put(subs, "s3/answers.csv", "student_id,exercise_id,part,answer\n"
        "s1,projectile-range,x_max,1\ns3,projectile-range,x_max,2\n")
    outcome = grade_class(exam / "manifest.json", [subs])
    rows = {row.student_id: {**row.cells, "status": row.status} for row in outcome.rows}
    assert rows["s1"]["status"] == "absent"
    assert [(p.student_id, p.source.rsplit(", ", 1)[1]) for p in outcome.problems
            if p.message.startswith("impersonating")] == [("s3", "row 2")]


def test_a_responses_csv_of_every_attempt_grades_only_the_rows_that_count(exam, tmp_path):
    manifest = load(exam / "manifest.json")
    key = next(s for s in manifest.students if s.student_id == "s1") \
        .variant("projectile-range").answers["x_max"]
    subs = tmp_path / "subs"
    put(subs, "server.csv", "student_id,exercise_id,part,answer,attempt,submitted_at,counts\n"
        f"s1,projectile-range,x_max,{2 * key},1,2025-04-14T10:02:13+02:00,no\n"
        f"s1,projectile-range,x_max,{key!r},2,2025-04-14T10:05:00+02:00,yes\n"
        f"s2,projectile-range,x_max,{key!r},1,2025-04-14T10:06:00+02:00,maybe\n")
    outcome = grade_class(exam / "manifest.json", [subs])
    result = outcome.feedback["s1"].results["projectile-range"]
    assert result.part("x_max").answer == repr(key) and result.part("x_max").correct
    assert outcome.feedback["s2"].results["projectile-range"] is None  # its row is refused
    assert [p.source.rsplit(", ", 1)[1] for p in outcome.problems
            if "counts" in p.message] == ["row 4"]


def test_the_file_modified_last_counts_not_the_last_in_path_order(exam, tmp_path):
    subs = tmp_path / "subs"
    newer = put(subs, "s1/a-projectile-range.py", filled(exam, "s1", "projectile-range"),
                modified=2_000_000_000)
    older = put(subs, "s1/b-projectile-range.py",
                filled(exam, "s1", "projectile-range", correct=False), modified=1_000_000_000)
    outcome = grade_class(exam / "manifest.json", [subs])
    assert {row.student_id: row for row in outcome.rows}["s1"].cells["projectile-range"] == 6.0
    duplicate = next(p for p in outcome.problems if p.message.startswith("duplicate"))
    assert duplicate.source == str(newer) and str(older) in duplicate.message


def test_a_file_in_no_students_folder_is_not_attributed_by_its_student_line(exam, tmp_path):
    subs = tmp_path / "subs"
    put(subs, "loose/projectile-range.py", filled(exam, "s1", "projectile-range"))
    outcome = grade_class(exam / "manifest.json", [subs])
    assert {row.student_id: row for row in outcome.rows}["s1"].status == "absent"
    assert outcome.problems[0].message.startswith("skipped: not in the folder of a student")


# -- item 5: the feedback of a file with problems ------------------------------------------


def test_a_corrupt_file_is_named_in_the_students_feedback_never_not_submitted(exam, tmp_path):
    subs = tmp_path / "subs"
    put(subs, "s1/projectile-range.py", "EXERCISE = = 'projectile-range'\n")
    out = tmp_path / "grading"
    outcome = grade_class(exam / "manifest.json", [subs], out)
    problem = outcome.problems[0]
    assert (problem.student_id, problem.exercise_id) == ("s1", "projectile-range")
    feedback = (out / "feedback" / "s1.md").read_text(encoding="utf-8")
    section = feedback.split("(`projectile-range`)")[1].split("##")[0]
    assert "Handed in, but could not be graded" in section and "line 1" in section
    assert "Not submitted" not in section


def test_one_unquoted_answer_in_an_exam_file_costs_only_that_part(exam, tmp_path):
    subs = tmp_path / "subs"
    text = filled(exam, "s1", "projectile-range").replace("\r\n", "\n")
    text = text.replace('\nx_max = "', "\nx_max = 1 m + ", 1).replace(
        "\nx_max = 1 m + " + text.split('\nx_max = "')[1].split('"')[0] + '"',
        "\nx_max = 12.5 m", 1)
    put(subs, "s1/projectile-range.py", "\ufeff" + text.replace("\n", "\r\n"))
    outcome = grade_class(exam / "manifest.json", [subs])
    # everything but x_max (2 of the exercise's 5 points, 2.4 of the exam's 6) counts
    assert {row.student_id: row for row in outcome.rows}["s1"].cells["projectile-range"] == \
        pytest.approx(3.6)


# -- item 7: files are data -----------------------------------------------------------------


def test_links_to_files_outside_the_folder_are_not_followed_nor_quoted(exam, tmp_path):
    """Reproducer: a .csv or .py linking to /etc/passwd had its first line copied into
    problems.csv and report.html."""
    subs = tmp_path / "subs"
    (subs / "s1").mkdir(parents=True)
    (subs / "s1" / "answers.csv").symlink_to("/etc/passwd")
    (subs / "s1" / "projectile-range.py").symlink_to("/etc/passwd")
    (subs / "s2").symlink_to("/etc")
    out = tmp_path / "grading"
    outcome = grade_class(exam / "manifest.json", [subs], out)
    first_line = Path("/etc/passwd").read_text().splitlines()[0]
    for name in ("problems.csv", "report.html", "grades.csv"):
        assert first_line not in (out / name).read_text(encoding="utf-8")
    messages = sorted(p.message for p in outcome.problems)
    assert messages == ["skipped: a link to a file outside the submissions folder is not "
                        "followed"] * 2 + ["skipped: a link to a folder is not followed"]


def test_a_header_that_is_not_ours_is_not_quoted(exam, tmp_path):
    subs = tmp_path / "subs"
    put(subs, "s1/answers.csv", "secret-token-abc,other\n1,2\n")
    outcome = grade_class(exam / "manifest.json", [subs])
    assert outcome.problems[0].message.startswith("corrupt, skipped: not a responses file")
    assert "secret-token-abc" not in outcome.problems[0].message


def test_a_fifo_among_the_submissions_is_reported_and_not_waited_for(exam, tmp_path):
    subs = tmp_path / "subs"
    (subs / "s1").mkdir(parents=True)
    os.mkfifo(subs / "s1" / "projectile-range.py")
    outcome = grade_class(exam / "manifest.json", [subs])
    assert [p.message for p in outcome.problems] == \
        ["skipped: a FIFO (named pipe) is not a submission"]


# -- item 8: outputs are whole --------------------------------------------------------------


def test_an_output_folder_holds_one_run_and_keeps_the_one_before(exam, tmp_path):
    subs = tmp_path / "subs"
    put(subs, "s1/projectile-range.py", filled(exam, "s1", "projectile-range"))
    out = tmp_path / "grading"
    put(out, "feedback/someone-of-another-run.md", "old")
    grade_class(exam / "manifest.json", [subs], out)
    assert sorted(p.name for p in (out / "feedback").iterdir()) == \
        sorted(f"{s}.{x}" for s in ROSTER for x in ("md", "html"))
    assert (out.with_name("grading.previous") / "feedback" / "someone-of-another-run.md"
            ).exists()
    assert not list(tmp_path.glob(".*partial"))


def test_a_no_pdf_exam_leaves_no_pdf_of_an_earlier_run(tmp_path, bank, exam_toml):
    (tmp_path / "exam.toml").write_text(exam_toml, encoding="utf-8")
    (tmp_path / "roster.csv").write_text("student_id,name\na1,A\n", encoding="utf-8")
    out = tmp_path / "out"
    put(out, "students/a1/sheet.pdf", "%PDF of an earlier run")
    put(out, "sheets.pdf", "%PDF of an earlier run")
    result = CliRunner().invoke(main, ["exam", str(tmp_path / "exam.toml"), "--roster",
                                       str(tmp_path / "roster.csv"), "-o", str(out),
                                       "--no-pdf", "--jobs", "1"])
    assert result.exit_code == 0, result.output
    assert list(out.rglob("*.pdf")) == [] and (out / "manifest.json").exists()


@pytest.mark.skipif(os.geteuid() == 0, reason="root writes into read-only folders")
def test_a_read_only_output_folder_is_a_located_error(tmp_path, exam_toml):
    (tmp_path / "exam.toml").write_text(exam_toml, encoding="utf-8")
    (tmp_path / "roster.csv").write_text("student_id,name\na1,A\n", encoding="utf-8")
    locked = tmp_path / "locked"
    locked.mkdir()
    locked.chmod(0o500)
    try:
        result = CliRunner().invoke(main, ["exam", str(tmp_path / "exam.toml"), "--roster",
                                           str(tmp_path / "roster.csv"), "-o",
                                           str(locked / "out"), "--no-pdf"])
    finally:
        locked.chmod(0o700)
    assert result.exit_code == 1 and "cannot write the output folder" in result.output


def test_an_unwritable_output_place_is_a_located_error(tmp_path, exam_toml):
    (tmp_path / "exam.toml").write_text(exam_toml, encoding="utf-8")
    (tmp_path / "roster.csv").write_text("student_id,name\na1,A\n", encoding="utf-8")
    (tmp_path / "a-file").write_text("x")
    result = CliRunner().invoke(main, ["exam", str(tmp_path / "exam.toml"), "--roster",
                                       str(tmp_path / "roster.csv"), "-o",
                                       str(tmp_path / "a-file" / "out"), "--no-pdf"])
    assert result.exit_code == 1 and "cannot write the output folder" in result.output
    assert "Traceback" not in result.output


def _many_students(exam: Path, folder: Path, count: int) -> tuple[Path, Path]:
    """A manifest of ``count`` students (the three generated ones' variants, reused) and
    a responses CSV where every third student is wrong on every numeric part."""
    manifest = load(exam / "manifest.json")
    students = tuple(replace(manifest.students[i % len(ROSTER)], student_id=f"m{i:03d}")
                     for i in range(count))
    path = dump(replace(manifest, students=students), folder / "manifest.json")
    rows = ["student_id,exercise_id,part,answer"]
    for number, student in enumerate(students):
        for variant in student.variants:
            for name, value in variant.answers.items():
                if number % 3 == 0 and isinstance(value, float):
                    value = 2 * value + 1
                rows.append(f'{student.student_id},{variant.exercise},{name},"{_number(value)}"')
    responses = folder / "responses.csv"
    responses.write_text("\n".join(rows) + "\n", encoding="utf-8")
    return path, responses


def _snapshot(folder: Path) -> dict[str, bytes]:
    return {str(p.relative_to(folder)): p.read_bytes()
            for p in sorted(folder.rglob("*")) if p.is_file()}


def test_a_grading_killed_at_any_moment_leaves_one_complete_run(exam, tmp_path, bank):
    """Class grading of 150 students killed with SIGKILL at random moments (from start-up
    to the swap at the end), then run again: the output folder always holds one complete
    run, and its grades are those of an uninterrupted run."""
    manifest, responses = _many_students(exam, tmp_path, 150)
    reference = tmp_path / "reference"
    grade_class(manifest, [responses], reference, bank=bank, jobs=1)
    expected = _snapshot(reference)
    # grades.csv, problems.csv, report.html, answers.csv, copies.csv; two feedback files
    # per student
    assert len(expected) == 5 + 2 * 150
    out = tmp_path / "grading"
    command = [sys.executable, "-m", "dynagrade.cli", "grade", "--manifest", str(manifest),
               str(responses), "-o", str(out), "--jobs", "1"]
    moments = random.Random(11)
    for _ in range(3):
        process = subprocess.Popen(command, stdout=subprocess.DEVNULL,
                                   stderr=subprocess.DEVNULL)
        time.sleep(moments.uniform(0.4, 2.0))
        process.send_signal(signal.SIGKILL)
        process.wait()
        if out.exists():  # whatever run it holds is whole
            assert _snapshot(out) == expected
    grade_class(manifest, [responses], out, bank=bank, jobs=1)
    assert _snapshot(out) == expected
    assert not list(tmp_path.glob(".*partial"))


# -- item 10: roster names are text, not markup ----------------------------------------------


def test_a_roster_name_with_markup_is_shown_literally_in_sheet_md(tmp_path, bank, exam_toml):
    from markdown_it import MarkdownIt  # CommonMark, raw HTML allowed: as viewers render

    (tmp_path / "exam.toml").write_text(exam_toml, encoding="utf-8")
    name = "<script>alert(1)</script> *Bob* [x](javascript:y)"
    (tmp_path / "roster.csv").write_text(f'student_id,name\nb1,"{name}"\n', encoding="utf-8")
    generate_exam(tmp_path / "exam.toml", tmp_path / "roster.csv", tmp_path / "out",
                  bank=bank, jobs=1, pdf=False)
    sheet = (tmp_path / "out" / "students" / "b1" / "sheet.md").read_text(encoding="utf-8")
    html = MarkdownIt("commonmark").render(sheet.split("\n\n")[1])
    assert "<script>" not in html and "<em>" not in html and "href" not in html
    assert "&lt;script&gt;alert(1)&lt;/script&gt; *Bob* [x](javascript:y)" in html


# -- item 4: exam secrecy ------------------------------------------------------------------


def test_the_secret_is_in_the_manifest_and_nowhere_a_student_sees(exam):
    secret = load(exam / "manifest.json").exam.secret
    assert secret == "c0ffee" * 11
    for path in exam.rglob("*"):
        if path.is_file() and path.name != "manifest.json":
            assert secret.encode() not in path.read_bytes(), path


def test_a_sheet_shows_no_seed_so_show_answers_cannot_print_its_key(exam):
    """Reproducer: `dynagrade show ID --seed SEED --answers` with the SEED printed in the
    student's fill-in file printed exactly that student's line of key.csv."""
    manifest = load(exam / "manifest.json")
    for student in manifest.students:
        folder = exam / "students" / student.student_id
        for variant in student.variants:
            texts = [(folder / f"{variant.exercise}.py").read_text(encoding="utf-8"),
                     (folder / "sheet.md").read_text(encoding="utf-8"),
                     (folder / "sheet.html").read_text(encoding="utf-8")]
            assert not any(str(variant.seed) in text for text in texts)
            assert "SEED" not in texts[0] and "VARIANT = " in texts[0]


def test_a_token_moved_to_another_student_or_made_up_is_foreign_and_not_shown(exam, tmp_path):
    subs = tmp_path / "subs"
    own = (exam / "students" / "s1" / "projectile-range.py").read_text(encoding="utf-8")
    s1_token = own.split("VARIANT = '")[1][:24]
    # s2 hands in s1's sheet with the STUDENT line changed to s2: s1's token, s2's folder
    put(subs, "s2/projectile-range.py", filled(exam, "s1", "projectile-range",
                                               student_line="s2"))
    made_up = own.replace(s1_token, "0" * 24)
    put(subs, "s1/projectile-range.py", made_up)
    outcome = grade_class(exam / "manifest.json", [subs])
    assert {row.student_id: row.status for row in outcome.rows} == \
        {"s1": "rejected", "s2": "rejected", "s3": "absent"}
    messages = [p.message for p in outcome.problems]
    assert all(m.startswith("foreign, skipped: not the variant of") for m in messages)
    manifest = load(exam / "manifest.json")
    seeds = [str(v.seed) for s in manifest.students for v in s.variants]
    assert not any(s1_token in m or any(seed in m for seed in seeds) for m in messages)


def test_the_same_secret_file_gives_the_same_exam_and_a_new_file_gets_a_secret(
        tmp_path, exam_toml):
    (tmp_path / "exam.toml").write_text(exam_toml, encoding="utf-8")
    (tmp_path / "roster.csv").write_text("student_id,name\na1,A\n", encoding="utf-8")
    secret_file = tmp_path / "exam.secret"
    runs = []
    for out in ("one", "two"):
        result = CliRunner().invoke(main, ["exam", str(tmp_path / "exam.toml"), "--roster",
                                           str(tmp_path / "roster.csv"), "-o",
                                           str(tmp_path / out), "--no-pdf", "--jobs", "1",
                                           "--secret-file", str(secret_file)])
        assert result.exit_code == 0, result.output
        runs.append(_snapshot(tmp_path / out))
    assert runs[0] == runs[1]
    assert secret_file.stat().st_mode & 0o077 == 0
    assert load(tmp_path / "one" / "manifest.json").exam.secret == \
        secret_file.read_text().strip()
    short = put(tmp_path, "short.secret", "abc")
    result = CliRunner().invoke(main, ["exam", str(tmp_path / "exam.toml"), "--roster",
                                       str(tmp_path / "roster.csv"), "-o",
                                       str(tmp_path / "three"), "--secret-file", str(short)])
    assert result.exit_code == 1 and "at least 32 characters" in result.output


def test_homework_keeps_seeds_and_full_verdicts_and_the_sheets_say_what_grade_does(
        tmp_path, bank, exam_toml):
    (tmp_path / "exam.toml").write_text('mode = "homework"\n' + exam_toml, encoding="utf-8")
    (tmp_path / "roster.csv").write_text("student_id,name\nh1,H\n", encoding="utf-8")
    out = tmp_path / "out"
    generate_exam(tmp_path / "exam.toml", tmp_path / "roster.csv", out, bank=bank, jobs=1,
                  pdf=False)
    variant = load(out / "manifest.json").students[0].variant("projectile-range")
    fill_in = (out / "students" / "h1" / "projectile-range.py").read_text(encoding="utf-8")
    assert f"SEED = {variant.seed}" in fill_in and "VARIANT" not in fill_in
    assert "it shows whether each answer is right" in \
        (out / "students" / "h1" / "sheet.md").read_text(encoding="utf-8")
    answered = filled(out, "h1", "projectile-range")
    path = put(tmp_path, "subs/h1/projectile-range.py", answered)
    verdict = json.loads(CliRunner().invoke(main, ["grade", str(path), "--json"]).output)
    assert verdict["score"] == verdict["max_score"] == 5  # the exercise's own 2+1+1+1
    outcome = grade_class(out / "manifest.json", [tmp_path / "subs"])
    assert outcome.rows[0].cells["projectile-range"] == 6.0


def test_an_exam_sheet_says_the_self_check_only_reads(exam):
    markdown = (exam / "students" / "s1" / "sheet.md").read_text(encoding="utf-8")
    assert "whether it is right you learn when the staff grade" in markdown
    assert "shows whether each answer is right" not in markdown
    fill_in = (exam / "students" / "s1" / "projectile-range.py").read_text(encoding="utf-8")
    assert "whether it is right you learn when the staff" in fill_in


def test_grade_on_an_exam_file_says_how_each_answer_reads_never_whether_it_is_right(
        exam, tmp_path):
    text = filled(exam, "s1", "projectile-range")
    text = text.replace('\nh_max = "', '\nh_max = "3 kg" #', 1)
    path = put(tmp_path, "s1/projectile-range.py", text)
    result = CliRunner().invoke(main, ["grade", str(path), "--json"])
    assert result.exit_code == 0, result.output
    checked = json.loads(result.output)
    by_name = {part["name"]: part for part in checked["parts"]}
    assert set(by_name["x_max"]) == {"name", "readable", "message"}
    assert by_name["x_max"]["readable"] and not by_name["h_max"]["readable"]
    assert "unit" in by_name["h_max"]["message"]
    assert "correct" not in result.output and "score" not in result.output


def test_the_current_folder_is_refused_as_an_output_folder(exam, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    result = CliRunner().invoke(main, ["grade", "--manifest", str(exam / "manifest.json"),
                                       str(tmp_path), "-o", "."])
    assert result.exit_code == 1 and "a folder of its own" in result.output
