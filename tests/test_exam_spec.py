"""Reading exam.toml and the roster: every malformed input is refused with a message that
names the file and the line/row and field/column at fault."""

from __future__ import annotations

import pytest

from dynagrade.generation.generate import load_exam
from dynagrade.exam.spec import ExamSpecError, parse_roster, read_exam_spec, read_roster
from dynagrade.exercise.loader import open_bank

ROSTER = "student_id,name,email\ns1,Ada Lovelace,ada@example.org\ns2,Alan Turing,\n"

GOOD = """\
id = "midterm"
title = "Midterm"
date = 2025-04-14
instructions = "Answer everything."

[[exercise]]
id = "projectile-range"
points = 6

[[exercise]]
id = "car-in-a-looping"
points = 4
[exercise.set]
R = 5.0
"""


@pytest.fixture(scope="module")
def bank():
    return open_bank()


def write(tmp_path, text, name="exam.toml"):
    path = tmp_path / name
    path.write_bytes(text.encode("utf-8") if isinstance(text, str) else text)
    return path


def test_a_well_formed_exam_is_read_with_its_exercises_points_and_overrides(tmp_path, bank):
    spec = read_exam_spec(write(tmp_path, GOOD), bank.get)
    assert (spec.id, spec.title, spec.date) == ("midterm", "Midterm", "2025-04-14")
    assert [(e.id, e.points, e.set) for e in spec.exercises] == [
        ("projectile-range", 6.0, {}), ("car-in-a-looping", 4.0, {"R": 5.0})]
    assert spec.total_points == 10.0


@pytest.mark.parametrize("text, expected", [
    (GOOD.replace('id = "midterm"\n', ""), "top-level key 'id'"),
    (GOOD.replace('id = "car-in-a-looping"', 'id = "projectile-range"'),
     "line 10, [[exercise]] #2, field 'id': 'projectile-range' is already exercise #1"),
    (GOOD.replace('id = "projectile-range"', 'id = "no-such-exercise"'),
     "line 6, [[exercise]] #1, field 'id': no exercise with id 'no-such-exercise'"),
    (GOOD.replace("points = 6\n", ""), "line 6, [[exercise]] #1 (projectile-range), field "
                                       "'points': missing"),
    (GOOD.replace("R = 5.0", "Rr = 5.0"), "field 'set.Rr'"),
    (GOOD.replace("R = 5.0", 'R = "five"'), "field 'set.R': 'five' is not a number"),
    (GOOD.replace("date = 2025-04-14", 'date = "14.4.2025"'), "line 3, field 'date'"),
    (GOOD.replace("[[exercise]]\nid = \"projectile", "[[exercise]\nid = \"projectile"),
     "not valid TOML"),
    (GOOD.replace('[[exercise]]\nid = "projectile-range"\n', '[[exercise]]\n'),
     "line 6, [[exercise]] #1, field 'id': missing"),
])
def test_a_malformed_exam_is_refused_naming_the_file_line_and_field(tmp_path, bank, text,
                                                                      expected):
    path = write(tmp_path, text)
    with pytest.raises(ExamSpecError) as error:
        read_exam_spec(path, bank.get)
    assert str(path) in str(error.value)
    assert expected in str(error.value)


def test_an_exam_with_a_byte_order_mark_is_refused(tmp_path, bank):
    path = write(tmp_path, b"\xef\xbb\xbf" + GOOD.encode())
    with pytest.raises(ExamSpecError, match="line 1: the file starts with a byte-order mark"):
        read_exam_spec(path, bank.get)


def test_an_override_that_breaks_a_constraint_is_refused_naming_the_exercise(tmp_path, bank):
    # sqrt(5 g R) for R = 10 m is 22.1 m/s: an entry speed of 12 m/s cannot be kept
    exam = write(tmp_path, GOOD.replace("R = 5.0", "R = 10.0\nv0 = 12.0"))
    roster = write(tmp_path, ROSTER, "roster.csv")
    with pytest.raises(ExamSpecError, match=r"line 10, \[\[exercise\]\] car-in-a-looping, "
                                            r"field 'set': the values set break a constraint"):
        load_exam(exam, roster, bank)


def test_a_roster_is_read_in_file_order_with_optional_email(tmp_path):
    students = read_roster(write(tmp_path, ROSTER, "roster.csv"))
    assert [(s.student_id, s.name, s.email) for s in students] == [
        ("s1", "Ada Lovelace", "ada@example.org"), ("s2", "Alan Turing", "")]
    assert [s.student_id for s in parse_roster(b"student_id,name\nx,X\n")] == ["x"]


@pytest.mark.parametrize("raw, expected", [
    (b"", "the roster is empty"),
    (b"student_id,name\n", "the roster is empty (a header and no students)"),
    (b"id,name\ns1,A\n", "row 1, column 1: the header is 'id,name'"),
    (b"name,mail\nA,a@b\n", "row 1, column 2: the header is 'name,mail'; it needs a "
                            "column of student ids"),
    (b"student_id,mail\ns1,a@b\n", "row 1, column 2: the header is 'student_id,mail'; "
                                   "it needs a column of names"),
    ("student_id,name\n{}\n".format("s" * 65 + ",A").encode(),
     "row 2, column 1 (student_id): 65 characters is longer than the 64"),
    (b"student_id,name\nCON,A\n", "row 2, column 1 (student_id): 'CON' cannot be a folder"),
    (b"student_id,name\n..,A\n", "row 2, column 1 (student_id): '..' may hold only"),
    (b"Surname;First name;ID number\r\nA;B;x1\r\nC;D;x1\r\n",
     "row 3, column 3 (ID number): 'x1' is already on row 2"),
    (b"student_id,name\ns1,A\ns1,B\n", "row 3, column 1 (student_id): 's1' is already on row 2"),
    (b"student_id,name\n,A\n", "row 2, column 1 (student_id): missing"),
    (b"student_id,name\ns1,\n", "row 2, column 2 (name): missing"),
    (b"student_id,name\ns 1,A\n", "row 2, column 1 (student_id): 's 1' may hold only"),
    (b"student_id,name\ns1,A,extra\n", "row 2: 3 columns, the header has 2"),
    (b"student_id,name\ns1,\xff\n", "row 2: not UTF-8 text"),
])
def test_a_malformed_roster_is_refused_naming_the_row_and_column(raw, expected):
    with pytest.raises(ExamSpecError) as error:
        parse_roster(raw, "roster.csv")
    assert str(error.value).startswith("roster.csv")
    assert expected in str(error.value)


# -- rosters as people save them (issue 11, item 6) ----------------------------------------


def test_a_roster_saved_by_excel_with_bom_semicolons_and_crlf_is_read():
    raw = "\ufeffstudent_id;name;email\r\ns1;Müller, Anna;a@x.ch\r\ns2;Bob;\r\n"
    students = parse_roster(raw.encode("utf-8"), "roster.csv")
    assert [(s.student_id, s.name, s.email) for s in students] == [
        ("s1", "Müller, Anna", "a@x.ch"), ("s2", "Bob", "")]


def test_a_moodle_export_maps_id_number_names_and_email_and_names_the_rest():
    raw = ("First name,Surname,ID number,Institution,Department,Email address\r\n"
           "Ada,Lovelace,21-123-456,ETH,D-MAVT,ada@ethz.ch\r\n")
    notices = []
    students = parse_roster(raw.encode("utf-8"), "moodle.csv", notices)
    assert students[0].to_json() == {"student_id": "21-123-456", "name": "Ada Lovelace",
                                     "email": "ada@ethz.ch"}
    assert notices == ["moodle.csv: the columns 'Institution', 'Department' are not used"]


def test_a_canvas_export_takes_the_sis_user_id_not_canvas_internal_id():
    raw = ("Student\tID\tSIS User ID\tSIS Login ID\tSection\n"
           "Turing, Alan\t88123\ts-2\talan\tDynamics\n")
    notices = []
    students = parse_roster(raw.encode("utf-8"), "canvas.tsv", notices)
    assert (students[0].student_id, students[0].name) == ("s-2", "Turing, Alan")
    # Canvas's internal ID is the user id its submission downloads are named by
    assert students[0].platform_ids == (("canvas", "88123"),)
    assert notices == ["canvas.tsv: the columns 'SIS Login ID', 'Section' are not used"]


def test_an_exam_id_with_a_trailing_newline_is_refused(tmp_path, bank):
    path = write(tmp_path, GOOD.replace('id = "midterm"', 'id = "midterm\\n"'))
    with pytest.raises(ExamSpecError, match="line 1, field 'id'"):
        read_exam_spec(path, bank.get)


# -- specs that cannot produce a sound exam (issue 11, item 9) -----------------------------


@pytest.mark.parametrize("change, message", [
    (("points = 6", "points = 1e308"), r"line 6, \[\[exercise\]\] #1 \(projectile-range\), "
                                       r"field 'points': 1e\+308; give a positive number"),
    (("points = 6", "points = nan"), "field 'points': nan"),
    (("points = 6", "points = 6\n[exercise.set]\ng = 0"),
     r"field 'set.g': 0 is outside the parameter's physical domain \(g > 0\)"),
    (("points = 6", "points = 6\n[exercise.set]\ng = -9.81"),
     r"field 'set.g': -9.81 is outside the parameter's physical domain \(g > 0\)"),
    (("R = 5.0", "R = 5.0\nm = -2"), r"field 'set.m': -2 is outside .* \(m > 0\)"),
])
def test_values_that_cannot_give_a_sound_exam_are_refused_with_line_and_field(
        tmp_path, bank, change, message):
    path = write(tmp_path, GOOD.replace(*change))
    with pytest.raises(ExamSpecError, match=message):
        read_exam_spec(path, bank.get)


def test_values_that_make_the_reference_answer_unsolvable_are_refused(tmp_path, bank):
    exam = write(tmp_path, GOOD.replace("R = 5.0", "R = 0.0"))
    roster = write(tmp_path, ROSTER, "roster.csv")
    with pytest.raises(ExamSpecError, match=r"line 10, \[\[exercise\]\] car-in-a-looping, "
                                            r"field 'set': the exercise cannot be solved"):
        load_exam(exam, roster, bank)


def test_the_exam_command_reports_a_negative_g_and_a_long_roster_id_without_traceback(
        tmp_path):
    from click.testing import CliRunner

    from dynagrade.cli import main

    exam = write(tmp_path, GOOD.replace("points = 6", "points = 6\n[exercise.set]\ng = -9.81"))
    roster = write(tmp_path, ROSTER, "roster.csv")
    result = CliRunner().invoke(main, ["exam", str(exam), "--roster", str(roster), "-o",
                                       str(tmp_path / "out"), "--no-pdf"])
    assert result.exit_code == 1 and "g > 0" in result.output
    long_id = write(tmp_path, "student_id,name\n" + "x" * 300 + ",A\n", "long.csv")
    result = CliRunner().invoke(main, ["exam", str(write(tmp_path, GOOD, "ok.toml")),
                                       "--roster", str(long_id), "-o", str(tmp_path / "out")])
    assert result.exit_code == 1 and "row 2, column 1 (student_id): 300 characters" \
        in result.output
    assert "Traceback" not in result.output and not (tmp_path / "out").exists()
    assert not list(tmp_path.glob(".out*"))
