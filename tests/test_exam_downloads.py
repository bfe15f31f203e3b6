"""A platform's bulk download graded as it comes: Moodle's "Download all submissions" and
Canvas's "Download Submissions" zips, built here in each platform's naming scheme. Each
file goes to the roster student whose platform id is in its name, and nothing else: files
the roster cannot place and students with two files for one exercise are reported, and
the zip is read as data (no entry written to disk, links, climbing names and bombs
refused)."""

from __future__ import annotations

import csv
import io
import json
import os
import stat
import zipfile
from pathlib import Path

import pytest
from click.testing import CliRunner

from dynagrade.cli import main
from dynagrade.classgrade.grade import grade_class
from dynagrade.classgrade.downloads import (DownloadError, EntryName, canvas_entry,
                                      detect_platform, moodle_entry)
from dynagrade.generation.generate import generate_exam
from dynagrade.exam.manifest import load
from dynagrade.exam.roster import RosterError, parse_roster

ROSTER = ["s1", "s2", "s3"]
#: the roster as Moodle's grading worksheet and Canvas's gradebook export give the ids
PLATFORM_ROSTER = ("student_id,name,moodle_id,canvas_id\n"
                   "s1,Anna Muster,Participant 101,5001\n"
                   "s2,Ben Beispiel,102,5002\n"
                   "s3,Chloé Exemple,103,5003\n")


@pytest.fixture(scope="module")
def exam(tmp_path_factory, bank, exam_toml):
    """A generated exam for three students, without PDFs, and the platform roster."""
    folder = tmp_path_factory.mktemp("downloads")
    (folder / "roster.csv").write_text(PLATFORM_ROSTER, encoding="utf-8")
    (folder / "exam.toml").write_text(exam_toml, encoding="utf-8")
    generate_exam(folder / "exam.toml", folder / "roster.csv", folder / "out", bank=bank,
                  jobs=1, pdf=False, secret="c0ffee" * 11)
    return folder


def filled(exam: Path, student: str, exercise: str, student_line: str | None = None) -> str:
    """The student's own fill-in file with every part answered right."""
    manifest = load(exam / "out" / "manifest.json")
    variant = next(s for s in manifest.students if s.student_id == student).variant(exercise)
    text = (exam / "out" / "students" / student / f"{exercise}.py").read_text(encoding="utf-8")
    for name, value in variant.answers.items():
        shown = ("[" + ", ".join(f"{v:.10g}" for v in value) + "]" if isinstance(value, tuple)
                 else f"{value:.10g}" if isinstance(value, float) else str(value))
        text = text.replace(f"\n{name} = None\n", f"\n{name} = {json.dumps(shown)}\n")
    if student_line is not None:
        text = text.replace(f"STUDENT = {student!r}", f"STUDENT = {student_line!r}")
    return text


def make_zip(path: Path, entries: dict[str, str | bytes]) -> Path:
    with zipfile.ZipFile(path, "w", zipfile.ZIP_DEFLATED) as archive:
        for name, content in entries.items():
            archive.writestr(name, content)
    return path


def grade(exam: Path, archive: Path, platform: str | None = None):
    return grade_class(exam / "out" / "manifest.json", [archive], roster=exam / "roster.csv",
                       platform=platform)


def points(outcome) -> dict[str, dict]:
    """Each student's exercise points and status, by student id."""
    return {row.student_id: {**row.cells, "status": row.status} for row in outcome.rows}


def full(exam: Path, exercise: str) -> float:
    manifest = load(exam / "out" / "manifest.json")
    return next(float(e.points) for e in manifest.exercises if e.id == exercise)


# -- the names each platform gives -----------------------------------------------------------


def test_moodle_names_with_folders_without_them_and_under_blind_marking_are_read():
    file = "projectile-range.py"
    expected = EntryName("101", "Anna Muster", file)
    # Moodle 4.1 on: a folder per student and plugin; before: the folder ends with "_"
    assert moodle_entry(f"Anna Muster_101_assignsubmission_file/{file}") == expected
    assert moodle_entry(f"Anna Muster_101_assignsubmission_file_/{file}") == expected
    assert moodle_entry(f"Anna Muster_101_assignsubmission_file/sub/{file}") == expected
    # "download submissions in folders" off: one flat name
    assert moodle_entry(f"Anna Muster_101_assignsubmission_file_{file}") == expected
    assert moodle_entry(f"Participant_101_assignsubmission_file/{file}") == \
        EntryName("101", "Participant", file)
    assert moodle_entry(f"Anna Muster_assignsubmission_file/{file}") is None
    assert moodle_entry(f"annamuster_5001_900_{file}") is None


def test_canvas_names_with_late_and_a_resubmission_suffix_are_read():
    assert canvas_entry("musteranna_5001_900123_projectile-range.py") == \
        EntryName("5001", "musteranna", "projectile-range.py")
    assert canvas_entry("musteranna_late_5001_900123_projectile-range-1.py") == \
        EntryName("5001", "musteranna", "projectile-range-1.py", late=True)
    assert canvas_entry("musteranna_LATE_5001_900123_a_1_2.py").identifier == "5001"
    assert canvas_entry("Anna Muster_101_assignsubmission_file/x.py") is None


def test_the_platform_is_told_from_the_names_and_a_mix_is_refused():
    moodle = ["Anna Muster_101_assignsubmission_file/a.py"]
    canvas = ["musteranna_5001_900_a.py"]
    assert detect_platform(moodle + ["readme.txt"], "d.zip") == "moodle"
    assert detect_platform(canvas, "d.zip") == "canvas"
    with pytest.raises(DownloadError, match="--platform moodle or --platform canvas"):
        detect_platform(moodle + canvas, "d.zip")
    with pytest.raises(DownloadError, match="no entry is named as Moodle's or Canvas's"):
        detect_platform(["a.py"], "d.zip")


# -- the roster's platform ids ---------------------------------------------------------------


def test_the_roster_reads_platform_ids_and_refuses_bad_or_shared_ones():
    students = parse_roster(PLATFORM_ROSTER.encode())
    assert [s.platform_ids for s in students] == [
        (("moodle", "101"), ("canvas", "5001")), (("moodle", "102"), ("canvas", "5002")),
        (("moodle", "103"), ("canvas", "5003"))]
    # Canvas's gradebook export: its "ID" is the user id, beside "SIS User ID"
    canvas = parse_roster(b"Student,ID,SIS User ID,SIS Login ID,Section\n"
                          b"\"Muster, Anna\",5001,s1,amuster,A\n")
    assert canvas[0].student_id == "s1" and canvas[0].platform_ids == (("canvas", "5001"),)
    # a bare ID without SIS User ID is nobody's platform id
    assert parse_roster(b"student_id,name,ID\ns1,Anna,5001\n")[0].platform_ids == ()
    # an empty cell: the student has no id there
    assert parse_roster(b"student_id,name,moodle_id\ns1,Anna,\n")[0].platform_ids == ()
    with pytest.raises(RosterError, match=r"row 2, column 3 \(moodle_id\): 'abc' is not a "
                                          r"Moodle id"):
        parse_roster(b"student_id,name,moodle_id\ns1,Anna,abc\n")
    with pytest.raises(RosterError, match=r"row 3, column 3 \(canvas_id\): Canvas id 7 is "
                                          r"already on row 2"):
        parse_roster(b"student_id,name,canvas_id\ns1,Anna,7\ns2,Ben,07\n")


# -- grading a download ----------------------------------------------------------------------


def test_a_moodle_download_is_graded_by_participant_id(exam, tmp_path):
    archive = make_zip(tmp_path / "moodle.zip", {
        "Anna Muster_101_assignsubmission_file/projectile-range.py":
            filled(exam, "s1", "projectile-range"),
        "Ben Beispiel_102_assignsubmission_file_/projectile-range.py":
            filled(exam, "s2", "projectile-range"),
        "Chloé Exemple_103_assignsubmission_file_car-in-a-looping.py":
            filled(exam, "s3", "car-in-a-looping"),
        "Chloé Exemple_103_assignsubmission_onlinetext/onlinetext.html": "<p>hello</p>",
    })
    outcome = grade(exam, archive)
    rows = points(outcome)
    assert rows["s1"]["projectile-range"] == pytest.approx(full(exam, "projectile-range"))
    assert rows["s2"]["projectile-range"] == pytest.approx(full(exam, "projectile-range"))
    assert rows["s3"]["car-in-a-looping"] == pytest.approx(full(exam, "car-in-a-looping"))
    assert rows["s3"]["projectile-range"] == 0.0
    assert outcome.problems == []


def test_a_canvas_download_is_graded_by_user_id_late_and_resubmitted_files_included(
        exam, tmp_path):
    archive = make_zip(tmp_path / "submissions.zip", {
        "musteranna_5001_700001_projectile-range.py": filled(exam, "s1", "projectile-range"),
        "beispielben_late_5002_700002_projectile-range-1.py":
            filled(exam, "s2", "projectile-range"),
    })
    outcome = grade(exam, archive)
    rows = points(outcome)
    assert rows["s1"]["projectile-range"] == pytest.approx(full(exam, "projectile-range"))
    assert rows["s2"]["projectile-range"] == pytest.approx(full(exam, "projectile-range"))
    assert rows["s3"]["status"] == "absent"
    # the late one is graded, and the staff are told it was late
    assert [(p.level, p.student_id, p.message) for p in outcome.problems] == [
        ("warning", "s2", "Canvas marks this submission late; graded all the same")]


def test_files_the_roster_cannot_place_are_reported_and_credited_to_nobody(exam, tmp_path):
    archive = make_zip(tmp_path / "moodle.zip", {
        # participant 999 is on no roster row, though the file is s1's own
        "Anna Muster_999_assignsubmission_file/projectile-range.py":
            filled(exam, "s1", "projectile-range"),
        # a file someone added by hand, outside Moodle's names
        "projectile-range.py": filled(exam, "s2", "projectile-range"),
        "Ben Beispiel_102_assignsubmission_file/car-in-a-looping.py":
            filled(exam, "s2", "car-in-a-looping"),
    })
    outcome = grade(exam, archive, platform="moodle")
    rows = points(outcome)
    assert rows["s1"]["status"] == "absent" and rows["s2"]["projectile-range"] == 0.0
    messages = {Path(p.source).parent.name + "/" + Path(p.source).name: (p.level, p.message)
                for p in outcome.problems}
    assert messages == {
        "Anna Muster_999_assignsubmission_file/projectile-range.py":
            ("error", "unmatched, not credited: no student on the roster has Moodle id 999"),
        "moodle.zip/projectile-range.py":
            ("error", "unmatched, not credited: not named as Moodle names a student's file"),
    }


def test_a_student_with_two_files_for_one_exercise_gets_neither_and_both_are_reported(
        exam, tmp_path):
    archive = make_zip(tmp_path / "moodle.zip", {
        "Anna Muster_101_assignsubmission_file/projectile-range.py":
            filled(exam, "s1", "projectile-range"),
        "Anna Muster_101_assignsubmission_file/projectile-range (1).py":
            filled(exam, "s1", "projectile-range"),
        "Anna Muster_101_assignsubmission_file/car-in-a-looping.py":
            filled(exam, "s1", "car-in-a-looping"),
    })
    outcome = grade(exam, archive)
    row = points(outcome)["s1"]
    assert row["projectile-range"] == 0.0
    assert row["car-in-a-looping"] == pytest.approx(full(exam, "car-in-a-looping"))
    two = [p for p in outcome.problems if p.message.startswith("two files")]
    assert sorted(Path(p.source).name for p in two) == ["projectile-range (1).py",
                                                        "projectile-range.py"]
    assert all(p.level == "error" and p.student_id == "s1"
               and p.exercise_id == "projectile-range" for p in two)
    # the student's feedback says the files were handed in and why they were not graded
    assert set(outcome.feedback["s1"].rejected) == {"projectile-range"}


def test_a_file_naming_another_student_in_a_students_entry_is_credited_to_nobody(
        exam, tmp_path):
    archive = make_zip(tmp_path / "canvas.zip", {
        "musteranna_5001_700001_projectile-range.py":
            filled(exam, "s2", "projectile-range"),  # s2's sheet (STUDENT s2) in s1's name
        # s1's sheet with its STUDENT line changed to s2, in s2's name: s1's variant token
        "beispielben_5002_700002_projectile-range.py":
            filled(exam, "s1", "projectile-range", student_line="s2"),
    })
    outcome = grade(exam, archive)
    rows = points(outcome)
    assert rows["s1"]["projectile-range"] == 0.0 and rows["s2"]["projectile-range"] == 0.0
    kinds = sorted((p.student_id, p.message.split(":")[0]) for p in outcome.problems)
    assert kinds == [("s1", "impersonating, skipped"), ("s2", "foreign, skipped")]


def test_a_moodle_name_other_than_the_rosters_is_a_warning_and_the_id_decides(exam, tmp_path):
    archive = make_zip(tmp_path / "moodle.zip", {
        "Someone Else_101_assignsubmission_file/projectile-range.py":
            filled(exam, "s1", "projectile-range"),
        "Muster Anna_101_assignsubmission_file/car-in-a-looping.py":  # same words: no warning
            filled(exam, "s1", "car-in-a-looping"),
    })
    outcome = grade(exam, archive)
    assert points(outcome)["s1"]["status"] == "incomplete"
    assert [(p.level, p.student_id) for p in outcome.problems] == [("warning", "s1")]
    assert "names 'Someone Else', the roster 'Anna Muster'" in outcome.problems[0].message


# -- the zip is data --------------------------------------------------------------------------


def _link_entry(archive: zipfile.ZipFile, name: str, target: str) -> None:
    info = zipfile.ZipInfo(name)
    info.external_attr = (stat.S_IFLNK | 0o777) << 16
    archive.writestr(info, target)


def test_climbing_names_links_and_bombs_are_refused_and_nothing_is_written(exam, tmp_path):
    work = tmp_path / "work"
    work.mkdir()
    archive = work / "moodle.zip"
    sheet = filled(exam, "s1", "projectile-range")
    with zipfile.ZipFile(archive, "w", zipfile.ZIP_DEFLATED) as z:
        z.writestr("Anna Muster_101_assignsubmission_file/../../evil.py", sheet)
        z.writestr("/tmp/Anna Muster_101_assignsubmission_file/abs.py", sheet)
        _link_entry(z, "Anna Muster_101_assignsubmission_file/link.py", "/etc/passwd")
        # 5 MB of one byte repeated compresses about a thousand times: a bomb
        z.writestr("Anna Muster_101_assignsubmission_file/bomb.csv", b"0" * 5_000_000)
        # a fill-in file larger than a fill-in file may be (1 MB)
        z.writestr("Anna Muster_101_assignsubmission_file/huge.py", "#" + "x1" * 600_000)
        z.writestr("Anna Muster_101_assignsubmission_file/projectile-range.py", sheet)
    before = sorted(p for p in tmp_path.rglob("*"))
    outcome = grade(exam, archive)
    reasons = {Path(p.source).name: p.message for p in outcome.problems}
    assert reasons == {
        "evil.py": "refused: its name points outside the download",
        "abs.py": "refused: its name points outside the download",
        "link.py": "refused: a link is not followed",
        "bomb.csv": reasons["bomb.csv"],
        "huge.py": "refused: 1200001 bytes is too large (the limit is 1000000)",
    }
    assert reasons["bomb.csv"].startswith("refused: it expands") and "zip bomb" in reasons["bomb.csv"]
    # the one sound file still counts, and no entry was written anywhere
    assert points(outcome)["s1"]["projectile-range"] == pytest.approx(full(exam, "projectile-range"))
    assert sorted(p for p in tmp_path.rglob("*")) == before
    assert not (tmp_path / "evil.py").exists() and not Path("/tmp/Anna Muster_101_assignsubmission_file").exists()


def test_a_damaged_entry_costs_only_itself(exam, tmp_path):
    archive = tmp_path / "canvas.zip"
    damaged = "beispielben_5002_700002_projectile-range.py"
    with zipfile.ZipFile(archive, "w", zipfile.ZIP_STORED) as z:
        z.writestr(damaged, filled(exam, "s2", "projectile-range"))
        z.writestr("musteranna_5001_700001_projectile-range.py",
                   filled(exam, "s1", "projectile-range"))
    data = bytearray(archive.read_bytes())
    at = data.index(b"EXERCISE")  # inside the first (stored) entry's bytes
    data[at] = ord("X")  # its CRC no longer matches
    archive.write_bytes(bytes(data))
    outcome = grade(exam, archive)
    assert [(Path(p.source).name, p.student_id) for p in outcome.problems] == [(damaged, "s2")]
    assert outcome.problems[0].message.startswith("refused: the entry cannot be read")
    rows = points(outcome)
    assert rows["s1"]["projectile-range"] == pytest.approx(full(exam, "projectile-range"))
    assert rows["s2"]["projectile-range"] == 0.0
    # s2's feedback says the file was handed in and why it was not graded
    assert set(outcome.feedback["s2"].rejected) == {"projectile-range"}


def test_an_archive_with_too_many_entries_or_not_a_zip_is_an_error_naming_it(exam, tmp_path,
                                                                             monkeypatch):
    import dynagrade.classgrade.downloads as downloads

    monkeypatch.setattr(downloads, "MAX_ENTRIES", 3)
    archive = make_zip(tmp_path / "many.zip", {f"x{i}.txt": "" for i in range(4)})
    with pytest.raises(DownloadError, match=r"many.zip: 4 entries, more than the 3"):
        grade(exam, archive)
    broken = tmp_path / "broken.zip"
    broken.write_bytes(b"PK\x03\x04 not really")
    with pytest.raises(DownloadError, match="broken.zip: not a readable zip file"):
        grade(exam, broken)


def test_a_roster_without_the_platforms_ids_or_a_fifo_for_a_zip_is_an_error_naming_it(
        exam, tmp_path):
    archive = make_zip(tmp_path / "canvas.zip", {
        "musteranna_5001_700001_projectile-range.py": filled(exam, "s1", "projectile-range")})
    plain = tmp_path / "plain.csv"
    plain.write_text("student_id,name,moodle_id\ns1,Anna Muster,101\n", encoding="utf-8")
    with pytest.raises(DownloadError, match=r"canvas.zip: a Canvas download, but .*plain.csv "
                                            r"gives no exam student a Canvas id; add a "
                                            r"canvas_id column"):
        grade_class(exam / "out" / "manifest.json", [archive], roster=plain)
    fifo = tmp_path / "fifo.zip"
    os.mkfifo(fifo)
    with pytest.raises(DownloadError, match=r"fifo.zip: cannot read the download \(it is a "
                                            r"FIFO \(named pipe\), not a regular file\)"):
        grade(exam, fifo)


def test_the_command_line_grades_a_download_and_says_what_is_missing_without_a_traceback(
        exam, tmp_path):
    archive = make_zip(tmp_path / "moodle.zip", {
        "Anna Muster_101_assignsubmission_file/projectile-range.py":
            filled(exam, "s1", "projectile-range")})
    manifest = str(exam / "out" / "manifest.json")
    runner = CliRunner()
    missing = runner.invoke(main, ["grade", "--manifest", manifest, str(archive)])
    assert missing.exit_code == 1 and "Traceback" not in missing.output
    assert "give --roster with a moodle_id or canvas_id column" in missing.output
    out = tmp_path / "grading"
    result = runner.invoke(main, ["grade", "--manifest", manifest, "--roster",
                                  str(exam / "roster.csv"), "--platform", "moodle",
                                  str(archive), "-o", str(out)])
    assert result.exit_code == 0, result.output
    rows = {r["student_id"]: r for r in csv.DictReader(io.StringIO(
        (out / "grades.csv").read_text(encoding="utf-8")))}
    assert float(rows["s1"]["projectile-range"]) == pytest.approx(full(exam, "projectile-range"))
    assert rows["s1"]["status"] == "incomplete" and rows["s2"]["status"] == "absent"
    usage = runner.invoke(main, ["grade", "--roster", str(exam / "roster.csv"), str(archive)])
    assert usage.exit_code == 2 and "need --manifest" in usage.output
